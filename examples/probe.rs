use rollbem::body::half_space::HalfSpace;
use rollbem::contact::*;
use rollbem::contact::newton::*;
use rollbem::contact::solution::*;
use rollbem::grid::*;
use rollbem::material::*;
use rollbem::analytic::*;
fn main() {
    let steel = Elastic::new(210000.0, 0.3);
    let a_body = HalfSpace{material: steel, radius: 100.0};
    let b_body = HalfSpace{material: steel, radius: 100.0};
    let e_star = contact_modulus(Some(&steel), Some(&steel));
    let r = 50.0; let p = hertz_load(1.0, r, e_star); let mu = 0.1;
    for &ne in &[21usize, 41, 81, 161, 321] {
      for der in [SlipDerivative::FirstOrder, SlipDerivative::SecondOrder] {
       for form in [Formulation::Phi] {
        let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, ne, -1.3, 1.3);
        let t = std::time::Instant::now();
        let pb = ContactProblem::assemble(grid, &a_body, &b_body, der, mu, RollingDirection::PlusX, NormalControl::Force(p), TangentialControl::Ratio(0.51));
        let ta = t.elapsed().as_secs_f64();
        let (z, rep) = solve(&pb, &NewtonSettings{formulation: form, ..Default::default()});
        let ts = t.elapsed().as_secs_f64() - ta;
        let sol = ContactSolution::from_state(&pb, &z);
        let c = Carter{half_width:1.0, peak_pressure: hertz_peak_pressure(p,1.0), friction: mu, ratio: 0.51, leading_edge_sign: 1.0};
        let p0 = c.peak_pressure;
        let qerr = sol.x.iter().zip(&sol.shear).map(|(x,q)| (q - c.shear(*x)).abs()).fold(0.0,f64::max)/(mu*p0);
        let n = sol.x.len() as f64; let rms = (sol.x.iter().zip(&sol.shear).map(|(x,q)| ((q - c.shear(*x))/(mu*p0)).powi(2)).sum::<f64>()/n).sqrt(); let perr = sol.x.iter().zip(&sol.pressure).map(|(x,q)| (q - hertz_pressure(*x,1.0,p0)).abs()).fold(0.0,f64::max)/p0;
        println!("ne={ne} {der:?} {form:?} conv={} it={} res={:.1e} P={:.6} Q={:.6} xi={:.6e} (carter {:.6e}) qerr={:.4} rms={rms:.5} perr={:.4} zones={:?} ta={ta:.3} ts={ts:.3} sizes={:?}",
          rep.converged, rep.iterations, rep.residual, sol.normal_force/p, sol.tangential_force/(0.51*mu*p), sol.creep, c.creep(r), qerr, perr, sol.zones_of(NodeState::Stick), rep.history.iter().map(|h| (h.system_size, h.step)).collect::<Vec<_>>());
       }
      }
    }
}
