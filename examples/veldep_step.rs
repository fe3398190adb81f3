//! CONTACT's veldep_fric cases 2 and 4 (examples/veldep_fric.inp of CONTACT's public repository
//! eve70a/CONTACT; Vollebregt & Schuttelaars, J. Sound Vib. 331:2141–2155, 2012) in rollbem:
//! the steady state at −0.09999 % on CONTACT's grid (31 elements over ±4.65 mm, node spacing
//! 0.1 mm = DX, first-order slip), then one transient step of 0.1 mm at −0.1 % from the steady
//! branch, from below and from above. Reproduces the rollbem numbers of docs/friction.md,
//! "Against CONTACT", bullet "Cases 2 and 4":
//!
//! ```text
//! cargo run --release --example veldep_step                      # upstream-end datum
//! DATUM=295.068 cargo run --release --example veldep_step        # CONTACT's DY = 200 mm
//! ELEMENTS=62 DATUM=295.068 cargo run --release --example veldep_step
//! cargo run --release --example veldep_step -- veldep_fric.0004.mat
//! ```
//!
//! `DATUM` is the datum length of `History::set_datum_length` (DY·e^(ν/(1−ν)) for CONTACT's
//! strip of width DY), `ELEMENTS` the grid's elements (31). With a CONTACT `.mat` file of the
//! step on DX = 0.1 mm (case 4 of veldep_fric.inp, MATFIL = 1) its tractions are put on
//! rollbem's nodes (the same points), its displacement UX is printed beside rollbem's
//! half-plane pair's under the same tractions with the datum length `DATUM` (295.068 by default)
//! and rollbem's step is solved warm from them. `STEPS=n` rolls n further steps from above after
//! the step from above (CONTACT's cases 5, 6, …), `WARM_AFTER=1` warm from the second step on. `DUMP=1`
//! writes x, p, q, slip velocity and μ per node to /tmp/rollbem_<side>.txt.
use rollbem::contact::falling::InitialSlip;
use rollbem::contact::{NormalControl, TangentialControl};
use rollbem::transient::{History, Step};

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let mat = args.get(1).cloned();
    let (mu_s, mu_k, speed) = (0.30, 0.18, 45_000.0);
    let s_h = 100.0 / std::f64::consts::LN_2;
    let overrides = [
        format!("contact.falling_friction.slip_velocity={s_h}"),
        "contact.slip_derivative=first_order".to_string(),
        format!(
            "contact.grid.elements={}",
            std::env::var("ELEMENTS").unwrap_or("31".into())
        ),
        "contact.grid.half_length=4.65".to_string(),
    ];
    let case = rollbem::case::load(std::path::Path::new("cases/veldep_fric.yaml"), &overrides).expect("loads");
    let scene = rollbem::scene::Scene::from_case(&case).expect("scene");
    let (_, problem) = scene.assemble().expect("assembles");
    let (steady, report) = rollbem::contact::methods::solve(&problem, &scene.solver);
    assert!(report.converged);
    let ratio0 = problem.grid.integrate(&steady.shear).abs() / (mu_s * problem.grid.integrate(&steady.pressure));
    println!(
        "steady {ratio0:.4}, flow sign {}, upstream end node {}",
        problem.flow_sign, problem.slip_operator.upstream_end
    );
    let force = match scene.normal {
        NormalControl::Force(p) => p,
        _ => unreachable!(),
    };
    let step = Step {
        distance: 0.1,
        normal: NormalControl::Force(force),
        tangential: TangentialControl::Creep(-0.001),
    };
    let mut above_hist = None;
    for side in [InitialSlip::Warm, InitialSlip::Below, InitialSlip::Above] {
        let mut h = History::from_steady(&scene, steady.clone()).expect("a history");
        h.set_initial_slip(side);
        h.set_datum_length(std::env::var("DATUM").ok().and_then(|v| v.parse().ok()));
        let z = match h.advance(step) {
            Ok(s) => {
                let e = &s.energy;
                println!(
                    "  energy: work {:.4e}, dissipation {:.4e}, stored change {:.4e}, imbalance {:.3e}",
                    e.work,
                    e.dissipation,
                    e.tangential_stored_change,
                    e.tangential_imbalance()
                );
                s.state
            }
            Err(e) => {
                println!("{side:?}: {e}");
                continue;
            }
        };
        let pb = h.problem();
        let slip = pb.slip(&z.pressure, &z.shear, z.creep);
        let smax = slip.iter().fold(0.0_f64, |a, s| a.max(s.abs()));
        let n_con = z.pressure.iter().filter(|&&p| p > 0.0).count();
        let n_slip = slip
            .iter()
            .zip(&z.pressure)
            .filter(|(s, &p)| p > 0.0 && s.abs() > 1e-6 * smax)
            .count();
        let r = pb.grid.integrate(&z.shear).abs() / (mu_s * pb.grid.integrate(&z.pressure));
        println!(
            "{side:?}: {r:.4}, {n_slip} of {n_con} slip, iterations {}",
            h.report().unwrap().iterations
        );
        if std::env::var("DUMP").is_ok() {
            let path = format!("/tmp/rollbem_{side:?}.txt");
            let mut out = String::new();
            for (i, &si) in slip.iter().enumerate() {
                let mu = mu_k + (mu_s - mu_k) * (-speed * si.abs() / s_h).exp();
                out += &format!(
                    "{:.4} {:.6e} {:.6e} {:.6e} {:.6}\n",
                    pb.grid.nodes[i],
                    z.pressure[i],
                    z.shear[i],
                    speed * si,
                    mu
                );
            }
            std::fs::write(&path, out).unwrap();
        }
        if side == InitialSlip::Above {
            // CONTACT's cases 5, 6, ...: further steps from above (`STEPS`, 0 by default).
            let more: usize = std::env::var("STEPS").ok().and_then(|v| v.parse().ok()).unwrap_or(0);
            let mut h2 = History::from_steady(&scene, steady.clone()).expect("a history");
            h2.set_initial_slip(side);
            h2.set_datum_length(std::env::var("DATUM").ok().and_then(|v| v.parse().ok()));
            let mut ratios = Vec::new();
            for _ in 0..=more.min(1000) {
                let s = match h2.advance(step) {
                    Ok(s) => s,
                    Err(e) => {
                        println!("step {}: {e}", ratios.len() + 1);
                        break;
                    }
                };
                let pb2 = h2.problem();
                ratios.push(pb2.grid.integrate(&s.state.shear).abs() / (mu_s * pb2.grid.integrate(&s.state.pressure)));
                if std::env::var("WARM_AFTER").is_ok() {
                    h2.set_initial_slip(InitialSlip::Warm);
                }
            }
            if more > 0 {
                let text: Vec<String> = ratios.iter().map(|r| format!("{r:.4}")).collect();
                println!("steps from above: {}", text.join(" "));
            }
            above_hist = Some((h, z));
        }
    }
    // Warm start from CONTACT's state (its .mat file of the step).
    if let (Some(mat), Some((h, z))) = (mat, above_hist) {
        let text = std::fs::read_to_string(&mat).expect("mat");
        let pb = h.problem();
        let mut p = vec![0.0; pb.n_nodes()];
        let mut q = vec![0.0; pb.n_nodes()];
        let mut ux = vec![f64::NAN; pb.n_nodes()];
        // Element i (1-based) centre: XL + (i - 0.5) DX with XL = -4.65, DX = 0.1.
        let dx = pb.grid.node_spacing();
        let sign = z.shear.iter().sum::<f64>().signum();
        for line in text.lines().filter(|l| !l.trim_start().starts_with('%')) {
            let f: Vec<f64> = line.split_whitespace().filter_map(|t| t.parse().ok()).collect();
            if f.len() < 11 || f[1] < 1.0 || f[4] < 1.0 {
                continue;
            }
            let x = -4.65 + (f[0] - 0.5) * dx;
            if let Some(k) = pb.grid.nodes.iter().position(|&xn| (xn - x).abs() < 1e-6) {
                p[k] = f[4];
                q[k] = sign * f[5].abs();
                ux[k] = f[8];
            }
        }
        let raw = pb.relative_tangential(&p, &q);
        let u = pb.slip_operator.upstream_end;
        let k = rollbem::body::half_space::influence_matrix(&pb.grid, rollbem::body::half_space::Kernel::Log);
        let nu: f64 = 0.28;
        let b_pair = 2.0 * 2.0 * (1.0 - nu * nu) / (std::f64::consts::PI * 2.0 * 82000.0 * (1.0 + nu));
        let ell: f64 = std::env::var("DATUM")
            .ok()
            .and_then(|v| v.parse().ok())
            .unwrap_or(295.068);
        let c: f64 = (0..pb.n_nodes())
            .map(|j| -b_pair * (k[(u, j)] - pb.grid.weights[j] * ell.ln()) * q[j])
            .sum();
        let qtot = pb.grid.integrate(&q);
        for i in (6..87).step_by(10) {
            let wl = raw[i] - raw[u] + c;
            println!(
                "x {:.2}: CONTACT UX {:.6e}, rollbem w_L {:.6e}, implied ln L shift {:.4}",
                pb.grid.nodes[i],
                ux[i],
                wl,
                (ux[i].abs() - wl.abs()) / (b_pair * qtot.abs())
            );
        }
        let ratio = pb.grid.integrate(&q).abs() / (mu_s * pb.grid.integrate(&p));
        println!("CONTACT's state on rollbem's nodes: {ratio:.4}");
        let slip = pb.slip(&p, &q, -0.001);
        let mut warm = z.clone();
        warm.pressure = p.clone();
        warm.shear = q.clone();
        warm.slip = slip;
        warm.gap = pb.gap(&p, &q, z.overlap);
        let law = pb.falling.unwrap();
        let mut ws = rollbem::contact::Workspace::new();
        let (s2, rep) = rollbem::contact::falling::solve(pb, &law, &scene.solver.newton, Some(warm), &mut ws);
        let r2 = pb.grid.integrate(&s2.shear).abs() / (mu_s * pb.grid.integrate(&s2.pressure));
        println!(
            "rollbem warm from CONTACT's state: {r2:.4} converged {} ({} iterations, {:?})",
            rep.converged, rep.iterations, rep.fallbacks
        );
    }
}
