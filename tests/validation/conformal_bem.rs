//! BEM bodies in conformal and internal contact against the series of src/analytic.

use crate::common::case_path;
use rollbem::analytic::creepage::{free_rolling_creepage, ShaftRoller};
use rollbem::app;
use rollbem::material::Elastic;
use rollbem::study::accuracy::{solve_model, SceneModel};

#[test]
fn free_rolling_creepage_of_unequal_rollers_scratch() {
    let steel = Elastic::new(210_000.0, 0.3);
    let series = free_rolling_creepage(
        &ShaftRoller {
            radius: 60.0,
            shaft_radius: 8.0,
            material: steel,
        },
        &ShaftRoller {
            radius: 90.0,
            shaft_radius: 12.0,
            material: steel,
        },
        0.5,
    )
    .unwrap();
    println!(
        "series: local {:.5e} global {:.5e} P {}",
        series.local_normal, series.global_axes, series.load
    );
    for axes in ["contact", "global"] {
        for n in [21, 41, 81] {
            let c = app::load_case(
                &case_path("carter_051"),
                &[
                    "bodies.A.radius=60".to_string(),
                    "bodies.B.radius=90".to_string(),
                    format!("load.normal.force={}", series.load),
                    "load.tangential.ratio=0".to_string(),
                    "contact.friction=0.5".to_string(),
                    format!("contact.traction_axes={axes}"),
                ],
            )
            .unwrap();
            let o = solve_model(&c, SceneModel::TrueGeometry, n, 8.0 / 60.0).unwrap();
            println!(
                "{axes} n={n}: creep {:.5e} converged {}",
                o.solution.creep, o.solution_converged
            );
        }
    }
}

#[test]
fn bore_scratch() {
    use rollbem::analytic::conformal::{DiscInBore, Ring, Roller};
    let steel = Elastic::new(210_000.0, 0.3);
    let scene = DiscInBore::new(
        Roller { radius: 40.0, shaft_radius: 5.0, material: steel },
        Ring { bore_radius: 50.0, rim_radius: 65.0, material: steel },
    );
    for axes in ["contact", "global"] {
    for a in [1.0f64, 0.4, 0.1] {
    let n = 41;
        let p = 453.114325 * a * a;
        let c = app::load_case(
            &case_path("carter_051"),
            &[
                "bodies.A.radius=40".to_string(),
                "bodies.B.radius=-50".to_string(),
                format!("load.normal.force={p}"),
                "load.tangential.ratio=0.5".to_string(),
                "contact.friction=0.2".to_string(),
                format!("contact.traction_axes={axes}"),
            ],
        )
        .unwrap();
        let o = solve_model(&c, SceneModel::TrueGeometry, n, 5.0 / 40.0).unwrap();
        let hs = solve_model(&c, SceneModel::HalfSpace, n, 5.0 / 40.0).unwrap();
        let s = &o.solution;
        let [x0, x1] = s.contact_extent().unwrap();
        let p0 = s.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        let carter = 0.2 * a / 200.0 * (1.0 - 0.5f64.sqrt());
        let rms = (s.shear.iter().zip(&hs.solution.shear).map(|(a, b)| (a - b).powi(2)).sum::<f64>() / s.shear.len() as f64).sqrt() / (0.2 * 2.0 * p / std::f64::consts::PI / a);
        println!("{axes} a={a} n={n}: a {:.5} p0/hertz {:.5} creep/carter {:.5} hs/carter {:.5} rms dq {:.3e} conv {}", 0.5 * (x1 - x0) / a, p0 / (2.0 * p / std::f64::consts::PI / a), s.creep / carter, hs.solution.creep / carter, rms, o.solution_converged);
    }
    }
    return;
    let series = scene.solve(28_999.3).unwrap();
    println!("series a/R 0.2: roller half width {:.5} peak {:.3}", series.half_width, series.peak_pressure);
    for n in [21, 41, 61, 81] {
        let c = app::load_case(
            &case_path("carter_051"),
            &[
                "bodies.A.radius=40".to_string(),
                "bodies.B.radius=-50".to_string(),
                "load.normal.force=28999.3".to_string(),
                "load.tangential.ratio=0".to_string(),
                "contact.friction=0".to_string(),
            ],
        )
        .unwrap();
        let o = solve_model(&c, SceneModel::TrueGeometry, n, 5.0 / 40.0).unwrap();
        let s = &o.solution;
        let [x0, x1] = s.contact_extent().unwrap();
        let arc = 20.0 * ((x1 / 40.0).asin() - (x0 / 40.0).asin());
        let p0 = s.pressure.iter().fold(0.0_f64, |m, &p| m.max(p));
        println!("conformal n={n}: roller arc half {:.5} ({:+.3e}) pmax {:.3} ({:+.3e}) conv {}", arc, arc / series.half_width - 1.0, p0, p0 / series.peak_pressure - 1.0, o.solution_converged);
    }
}
