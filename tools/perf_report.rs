//! Speed against accuracy on CONTACT's carter2d problem (cases/carter2d_contact.yaml):
//! per-size iterations, per-iteration cost, time split, whole-process wall time of the
//! `rollbem run` binary (best of 5), RMS shear error against Carter (μp0) and creepage error.
//!
//! Run: `cargo build --release && cargo run --release --example perf_report`.

use rollbem::app;
use rollbem::case;
use std::path::PathBuf;
use std::process::Command;
use std::time::Instant;

fn main() {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR"));
    let case_path = root.join("cases/carter2d_contact.yaml");
    let exe = root.join("target/release/rollbem");
    let out = std::env::temp_dir().join("rollbem_perf");
    println!("| elements | nodes | iterations | largest system | assembly [ms] | solve [ms] | per iteration [ms] | whole process [s] | RMS q error (μp0) | creep error | CONTACT creep error 0.24Δx/a |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|");
    for n in [21usize, 41, 81, 161, 321] {
        let derivative = std::env::args().nth(1).unwrap_or_else(|| "second_order".into());
        let set = vec![
            format!("contact.grid.elements={n}"),
            format!("contact.slip_derivative={derivative}"),
        ];
        let loaded = case::load(&case_path, &set).unwrap();
        let s = app::solve(&loaded).unwrap();
        assert!(s.report.converged);
        let c = app::carter_reference(&loaded, &s.estimates).unwrap();
        let mu_p0 = c.friction * c.peak_pressure;
        let errs: Vec<f64> = s
            .solution
            .x
            .iter()
            .zip(&s.solution.shear)
            .filter(|(x, _)| x.abs() < c.half_width)
            .map(|(x, q)| (q - c.shear(*x)) / mu_p0)
            .collect();
        let rms = (errs.iter().map(|e| e * e).sum::<f64>() / errs.len() as f64).sqrt();
        let xi = c.creep(s.estimates.effective_radius);
        let mut best = f64::INFINITY;
        for _ in 0..5 {
            let t = Instant::now();
            let mut args = vec![
                "run".to_string(),
                case_path.to_string_lossy().into_owned(),
                "--out".into(),
                out.to_string_lossy().into_owned(),
            ];
            for v in &set {
                args.push("--set".into());
                args.push(v.clone());
            }
            let status = Command::new(&exe)
                .args(&args)
                .output()
                .expect("run the release binary (cargo build --release first)");
            assert!(status.status.success());
            best = best.min(t.elapsed().as_secs_f64());
        }
        let largest = s.report.history.iter().map(|h| h.system_size).max().unwrap_or(0);
        println!(
            "| {n} | {} | {} | {largest} | {:.1} | {:.1} | {:.2} | {best:.3} | {rms:.2e} | {:+.2e} | {:.2e} |",
            s.problem.n_nodes(),
            s.report.iterations,
            1e3 * s.timings.assembly_s,
            1e3 * s.timings.solve_s,
            1e3 * s.timings.solve_s / s.report.iterations as f64,
            s.solution.creep / xi - 1.0,
            0.24 * s.problem.grid.element_length() / c.half_width,
        );
    }
}
