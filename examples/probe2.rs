use rollbem::body::half_space::HalfSpace;
use rollbem::contact::*;
use rollbem::contact::newton::*;
use rollbem::contact::solution::*;
use rollbem::grid::*;
use rollbem::material::*;
use rollbem::analytic::*;
fn main() {
    let args: Vec<String> = std::env::args().collect();
    let ne: usize = args[1].parse().unwrap();
    let der = if args[2] == "1" { SlipDerivative::FirstOrder } else { SlipDerivative::SecondOrder };
    let ratio: f64 = args[3].parse().unwrap();
    let steel = Elastic::new(210000.0, 0.3);
    let a_body = HalfSpace{material: steel, radius: 100.0};
    let e_star = contact_modulus(Some(&steel), Some(&steel));
    let r = 50.0; let p = hertz_load(1.0, r, e_star); let mu = 0.1;
    let grid = ContactGrid::uniform(ElementKind::DiscontinuousQuadratic, ne, -1.3, 1.3);
    let pb = ContactProblem::assemble(grid, &a_body, &a_body, der, mu, RollingDirection::PlusX, NormalControl::Force(p), TangentialControl::Ratio(ratio));
    let (z, rep) = solve(&pb, &NewtonSettings{formulation: Formulation::Psi, ..Default::default()});
    let sol = ContactSolution::from_state(&pb, &z);
    let c = Carter{half_width:1.0, peak_pressure: hertz_peak_pressure(p,1.0), friction: mu, ratio, leading_edge_sign: 1.0};
    let p0 = c.peak_pressure;
    println!("conv {} it {}", rep.converged, rep.iterations);
    for i in 0..sol.x.len() { let x = sol.x[i]; if x.abs() < 1.05 {
        println!("{:8.4} p={:8.4} ph={:8.4} q={:8.5} qc={:8.5} dq={:+.4} s={:+.5} sh={:+.5} {:?}", x, sol.pressure[i]/p0, hertz_pressure(x,1.0,p0)/p0, sol.shear[i]/(mu*p0), c.shear(x)/(mu*p0), (sol.shear[i]-c.shear(x))/(mu*p0), sol.slip[i]*r/(mu*1.0), sol.slip_strain.as_ref().unwrap()[i]*r/mu, sol.state[i]); }}
}
