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
