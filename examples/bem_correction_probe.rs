//! Probe: can a BEM body's flexibility on a fine contact grid be had as the half-plane's (exact,
//! cheap) plus the smooth remainder F_BEM − F_hp taken from the coarse grid and interpolated?
//! Prints, for a case at a tolerance, the difference between the full BEM solution on the final
//! grid and the corrected half-space one on the same grid, and the half-space alone.
//!
//! Run: `cargo run --release --example bem_correction_probe -- CASE TOL`.

use rollbem::body::half_space::HalfSpace;
use rollbem::body::{BodyModel, Flexibility, Side, StrainOperator};
use rollbem::contact::{methods, ContactProblem};
use rollbem::grid::ContactGrid;
use rollbem::post::ContactSolution;
use rollbem::scene::Scene;
use faer::Mat;
use nalgebra::DMatrix;
use std::time::Instant;

/// A half-plane plus a smooth remainder interpolated from a coarse grid.
struct Corrected<'a> {
    half: HalfSpace,
    coarse: &'a ContactGrid,
    /// F_BEM − F_hp on the coarse grid, divided by the coarse column weights (kernel samples).
    samples: [Mat<f64>; 4],
    profile_of: &'a dyn BodyModel,
    /// A finer level's grid and samples for Richardson's extrapolation (first order).
    finer: Option<(ContactGrid, [Mat<f64>; 4])>,
    with_correction: bool,
}

fn interpolation_matrix(from: &ContactGrid, to: &ContactGrid) -> Mat<f64> {
    let mut m = Mat::zeros(to.n_nodes(), from.n_nodes());
    for (i, &x) in to.nodes.iter().enumerate() {
        for (j, n) in from.interpolation_row(x) {
            m[(i, j)] = n;
        }
    }
    m
}

/// Chebyshev basis T_0..T_d at the nodes, mapped from [lo, hi].
fn cheb(nodes: &[f64], lo: f64, hi: f64, d: usize) -> DMatrix<f64> {
    DMatrix::from_fn(nodes.len(), d + 1, |i, k| {
        let t = (2.0 * nodes[i] - lo - hi) / (hi - lo);
        (k as f64 * t.clamp(-1.0, 1.0).acos()).cos()
    })
}

/// Chebyshev coefficients of the least-squares fit of the samples (degree d in x and in s).
fn fit(samples: &Mat<f64>, grid: &ContactGrid, lo: f64, hi: f64, d: usize) -> DMatrix<f64> {
    let tc = cheb(&grid.nodes, lo, hi, d);
    let m = grid.n_nodes();
    let rc = DMatrix::from_fn(m, m, |i, j| samples[(i, j)]);
    let pinv = (tc.transpose() * &tc).try_inverse().unwrap() * tc.transpose();
    &pinv * rc * pinv.transpose()
}

fn degree() -> usize {
    std::env::var("PROBE_DEGREE").ok().and_then(|s| s.parse().ok()).unwrap_or(0)
}

impl Corrected<'_> {
    fn on(&self, grid: &ContactGrid, k: usize) -> Mat<f64> {
        let d = degree();
        let mut r = if d > 0 {
            let (lo, hi) = (self.coarse.edges[0], *self.coarse.edges.last().unwrap());
            let mut c = fit(&self.samples[k], self.coarse, lo, hi, d);
            if let Some((g1, s1)) = &self.finer {
                c = 2.0 * fit(&s1[k], g1, lo, hi, d) - c;
            }
            let tf = cheb(&grid.nodes, lo, hi, d);
            let rf = &tf * c * tf.transpose();
            Mat::from_fn(grid.n_nodes(), grid.n_nodes(), |i, j| rf[(i, j)])
        } else {
            let ix = interpolation_matrix(self.coarse, grid);
            &ix * &self.samples[k] * ix.transpose()
        };
        for j in 0..r.ncols() {
            let w = grid.weights[j];
            for v in r.col_mut(j).iter_mut() {
                *v *= w;
            }
        }
        r
    }
}

impl BodyModel for Corrected<'_> {
    fn model_name(&self) -> &'static str {
        "corrected"
    }
    fn flexibility(&self, grid: &ContactGrid, side: Side) -> Flexibility {
        let mut f = half_flexibility(&self.half, grid, side);
        if self.with_correction {
            f.hp += &self.on(grid, 0);
            f.hq += &self.on(grid, 1);
            f.wp += &self.on(grid, 2);
            f.wq += &self.on(grid, 3);
        }
        f
    }
    fn profile(&self, x: f64) -> f64 {
        self.profile_of.profile(x)
    }
    fn strain_operator(&self, _grid: &ContactGrid, _side: Side) -> Option<StrainOperator> {
        None
    }
}

fn half_flexibility(half: &HalfSpace, grid: &ContactGrid, side: Side) -> Flexibility {
    let body = rollbem::body::transfer::Transferred::flat_model_on(Box::new(half.clone()), grid, side).unwrap();
    let mut f = body.model().flexibility(grid, side);
    if std::env::var("PROBE_ARC").is_ok() {
        // A load per unit arc: the column of node j carries ∫N_j ds ≈ w_j / cos θ_j.
        for j in 0..grid.n_nodes() {
            let c = rollbem::body::SurfaceAt::of_circle(half.radius, grid.nodes[j], side).slope_angle.cos();
            for m in [&mut f.hp, &mut f.hq, &mut f.wp, &mut f.wq] {
                for v in m.col_mut(j).iter_mut() {
                    *v /= c;
                }
            }
        }
    }
    f
}

fn samples(bem: &Flexibility, hp: &Flexibility, grid: &ContactGrid) -> [Mat<f64>; 4] {
    let one = |a: &Mat<f64>, b: &Mat<f64>| {
        Mat::from_fn(a.nrows(), a.ncols(), |i, j| (a[(i, j)] - b[(i, j)]) / grid.weights[j])
    };
    [one(&bem.hp, &hp.hp), one(&bem.hq, &hp.hq), one(&bem.wp, &hp.wp), one(&bem.wq, &hp.wq)]
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let path = std::path::PathBuf::from(&args[1]);
    let tol: f64 = args[2].parse().unwrap();
    let fixed = rollbem::app::load_case(path.as_path(), &Vec::<String>::new()).unwrap();
    let mut fixed_scene = Scene::from_case(&fixed).unwrap();
    let levels: usize = std::env::var("PROBE_COARSE_BISECT").ok().and_then(|s| s.parse().ok()).unwrap_or(0);
    for _ in 0..levels {
        let g = rollbem::adapt::cells::DyadicGrid::new(&fixed_scene.grid).bisected().grid();
        fixed_scene = fixed_scene.on_grid(g);
    }
    let t0 = Instant::now();
    let coarse_models = fixed_scene.body_models().unwrap();
    let t_coarse = t0.elapsed().as_secs_f64();
    let set = vec![format!("contact.grid.tolerance={tol}")];
    let adaptive = rollbem::app::load_case(path.as_path(), &set).unwrap();
    let scene = Scene::from_case(&adaptive).unwrap();
    let t0 = Instant::now();
    let full = if std::env::var("PROBE_SAME").is_ok() {
        rollbem::adapt::solve(&fixed_scene).unwrap()
    } else {
        rollbem::adapt::solve(&scene).unwrap()
    };
    let t_full = t0.elapsed().as_secs_f64();
    let fine = &full.problem.grid;
    let cg = &fixed_scene.grid;
    let sides = [Side::A, Side::B];
    let mut halves = Vec::new();
    for k in 0..2 {
        let mat = fixed_scene.bodies[k].hertz_material().unwrap();
        halves.push(HalfSpace {
            material: mat,
            radius: fixed_scene.bodies[k].radius(),
        });
    }
    let mut samp = Vec::new();
    for k in 0..2 {
        let bem = coarse_models[k].model().flexibility(cg, sides[k]);
        let hp = half_flexibility(&halves[k], cg, sides[k]);
        samp.push(samples(&bem, &hp, cg));
    }
    if std::env::var("PROBE_DUMP").is_ok() {
        let m = cg.n_nodes();
        let i = m / 2;
        for k in 0..2 {
            println!("body {k} row {i} of R_hp/w (x_i = {:.4}):", cg.nodes[i]);
            for j in 0..m {
                println!("  {:.5} {:.6e} {:.6e} {:.6e} {:.6e}", cg.nodes[j], samp[k][0][(i, j)], samp[k][1][(i, j)], samp[k][2][(i, j)], samp[k][3][(i, j)]);
            }
        }
    }
    let finer = std::env::var("PROBE_RICHARDSON").is_ok().then(|| {
        let g = rollbem::adapt::cells::DyadicGrid::new(&fixed_scene.grid).bisected().grid();
        let sc = fixed_scene.on_grid(g);
        let models = sc.body_models().unwrap();
        let s: Vec<[Mat<f64>; 4]> = (0..2)
            .map(|k| {
                let bem = models[k].model().flexibility(&sc.grid, sides[k]);
                let hp = half_flexibility(&halves[k], &sc.grid, sides[k]);
                samples(&bem, &hp, &sc.grid)
            })
            .collect();
        (sc.grid.clone(), s)
    });
    let ref_sol = ContactSolution::from_state(&full.problem, &full.state);
    let p0 = ref_sol.pressure.iter().cloned().fold(0.0, f64::max);
    let mu = full.problem.friction;
    for with in [true, false] {
        let t0 = Instant::now();
        let models: Vec<Corrected> = (0..2)
            .map(|k| Corrected {
                half: halves[k].clone(),
                coarse: cg,
                samples: samp[k].clone(),
                profile_of: full.models[k].model(),
                finer: finer.as_ref().map(|(g, s)| (g.clone(), s[k].clone())),
                with_correction: with,
            })
            .collect();
        let c = &scene.case.case.contact;
        let pb = ContactProblem::assemble(
            fine.clone(),
            &models[0],
            &models[1],
            c.slip_derivative,
            scene.friction,
            c.rolling_direction,
            scene.normal,
            scene.tangential,
            full.problem.frame.clone(),
        );
        let (state, report) = methods::solve(&pb, &scene.solver);
        let t = t0.elapsed().as_secs_f64();
        let sol = ContactSolution::from_state(&pb, &state);
        if std::env::var("PROBE_EDGE").is_ok() {
            for i in 0..sol.pressure.len() {
                if fine.nodes[i] < -0.9 && fine.nodes[i] > -1.05 {
                    println!("    {:.5} p {:.3} vs {:.3}  q {:.3} vs {:.3}", fine.nodes[i], sol.pressure[i], ref_sol.pressure[i], sol.shear[i], ref_sol.shear[i]);
                }
            }
        }
        let (mut imax, mut dmax) = (0, 0.0);
        for i in 0..sol.pressure.len() {
            let d = (sol.pressure[i] - ref_sol.pressure[i]).abs();
            if d > dmax {
                dmax = d;
                imax = i;
            }
        }
        let lens = rollbem::post::norms::node_lengths(&fine.nodes);
        let rms = |a: &[f64], b: &[f64], s: f64| {
            let (mut num, mut den) = (0.0, 0.0);
            for i in 0..a.len() {
                if a[i] != 0.0 || b[i] != 0.0 {
                    num += lens[i] * (a[i] - b[i]).powi(2);
                    den += lens[i];
                }
            }
            (num / den).sqrt() / s
        };
        println!(
            "  worst p at x = {:.5}: {:.4} vs {:.4}; rms dp {:.2e} rms dq {:.2e}",
            fine.nodes[imax],
            sol.pressure[imax],
            ref_sol.pressure[imax],
            rms(&sol.pressure, &ref_sol.pressure, p0),
            rms(&sol.shear, &ref_sol.shear, mu * p0)
        );
        let dp = sol.pressure.iter().zip(&ref_sol.pressure).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / p0;
        let dq = sol.shear.iter().zip(&ref_sol.shear).map(|(a, b)| (a - b).abs()).fold(0.0, f64::max) / (mu * p0);
        println!(
            "correction {with}: converged {} | max|dp|/p0 {dp:.2e} max|dq|/(mu p0) {dq:.2e} | creep {:.6e} vs {:.6e} (rel {:.2e}) | overlap {:.6e} vs {:.6e} | P {:.6e} vs {:.6e} | {t:.3} s",
            report.converged,
            sol.creep,
            ref_sol.creep,
            (sol.creep - ref_sol.creep).abs() / ref_sol.creep.abs(),
            sol.overlap,
            ref_sol.overlap,
            sol.normal_force,
            ref_sol.normal_force
        );
    }
    println!(
        "fine grid {} nodes; full BEM adaptive {t_full:.2} s; coarse BEM build {t_coarse:.3} s",
        fine.n_nodes()
    );
}
