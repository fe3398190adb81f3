//! Friction falling with the slip velocity (src/contact/falling.rs): with μ_k = μ_s the law is
//! Coulomb's constant friction and the run must equal the constant-μ solver's (Carter 1926)
//! bit for bit; with μ_k < μ_s every node of the solution must satisfy the falling law
//! μ(V|s|) = μ_k + (μ_s − μ_k) exp(−V|s|/s_h) (Vollebregt & Schuttelaars 2012, Eq. 2), checked
//! here from the tractions and the slip recomputed from them, not from the solver's own μ_i.

use crate::common::solve;

/// carter_051 (μ = 0.1, Q/μP = 0.51) with the law and speed set.
fn falling(kinetic: f64, slip_velocity: f64, speed: f64) -> rollbem::post::Solved {
    let law = format!("contact.falling_friction={{kinetic: {kinetic}, slip_velocity: {slip_velocity}}}");
    solve("carter_051", &[&law, &format!("load.speed={speed}")])
}

/// μ_k = μ_s: the nodal μ_i equal μ_s exactly (the exponential's factor is zero), so the first
/// frozen solve is the constant-μ solve and the fixed point stops after it: pressure, shear,
/// overlap and creepage equal bit for bit.
#[test]
fn kinetic_equal_to_static_is_carter_bit_for_bit() {
    let constant = solve("carter_051", &[]);
    let law = falling(0.1, 0.3, 100.0);
    let (a, b) = (&constant.solution, &law.solution);
    assert_eq!(a.pressure, b.pressure);
    assert_eq!(a.shear, b.shear);
    assert_eq!(a.creep, b.creep);
    assert_eq!(a.overlap, b.overlap);
    assert_eq!(constant.report.iterations, law.report.iterations);
}

/// μ_s = 0.1 → μ_k = 0.05, s_h = 0.3 mm/s at V = 100 mm/s and 10 mm/s (the largest V|s| is
/// about 0.1 and 0.01 mm/s: μ falls by up to about a third and 3 % of μ_s − μ_k). At every
/// contact node |q| ≤ μ(V|s|) p, and at every slipping node (|s| above 1e-6 of the largest)
/// |q| = μ(V|s|) p within 1e-8 μ_s p0: the fixed point stops when no μ_i moves by more than
/// 1e-10 μ_s and the Newton residual is 1e-10 p_ref, the slip recomputed from the tractions
/// carries the round-off of the influence sums (about 1e-12 of the largest slip here).
#[test]
fn falling_law_holds_at_every_node() {
    let (mu_s, mu_k, s_h) = (0.1, 0.05, 0.3);
    for speed in [100.0, 10.0] {
        let solved = falling(mu_k, s_h, speed);
        let (pb, z) = (&solved.problem, &solved.solution);
        let slip = pb.slip(&z.pressure, &z.shear, z.creep);
        let p0 = z.pressure.iter().fold(0.0_f64, |a, &b| a.max(b));
        let smax = slip
            .iter()
            .zip(&z.pressure)
            .filter(|(_, &p)| p > 0.0)
            .fold(0.0_f64, |a, (s, _)| a.max(s.abs()));
        let (mut slipping, mut lowest) = (0, mu_s);
        for (i, &s) in slip.iter().enumerate() {
            let p = z.pressure[i].max(0.0);
            if p <= 1e-12 * p0 {
                continue;
            }
            let mu = mu_k + (mu_s - mu_k) * (-speed * s.abs() / s_h).exp();
            let q = z.shear[i].abs();
            assert!(
                q <= mu * p + 1e-8 * mu_s * p0,
                "V = {speed}, node {i}: |q| = {q} above μp = {}",
                mu * p
            );
            if s.abs() > 1e-6 * smax {
                slipping += 1;
                lowest = lowest.min(mu);
                assert!(
                    (q - mu * p).abs() <= 1e-8 * mu_s * p0,
                    "V = {speed}, node {i}: |q| = {q}, μ(V|s|) p = {}",
                    mu * p
                );
            }
        }
        assert!(slipping >= 5, "V = {speed}: only {slipping} slipping nodes");
        eprintln!(
            "V = {speed}: {slipping} slipping nodes, lowest μ {lowest:.6}, creepage {:.6e}",
            z.creep
        );
        // The law acts: at V = 100 the lowest μ lies well below μ_s (else the test checks Coulomb).
        if speed == 100.0 {
            assert!(lowest < mu_s - 0.1 * (mu_s - mu_k), "lowest μ {lowest}");
        }
    }
}
