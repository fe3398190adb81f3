//! The slip column at the ends of the contact grid. The upstream end node's row of the contact
//! problem is the datum of the tangential displacement w, not a slip (src/contact/slip_operator.rs);
//! its slip velocity is the downstream derivative of the same order. It must be a slip velocity
//! like its neighbours': no spike (the end node once carried w/h, 250 times its neighbours' slip in
//! carter_051), and it must agree with the slip recomputed independently from the
//! boundary-integral derivative of the displacements (`slip_hbem`) as well as its neighbours do.

use super::common::solve;

/// The upstream end node of a solution: the last node when rolling in +x (material flows in −x),
/// the first when rolling in −x; and the step towards the contact.
fn upstream_end(s: &rollbem::app::Solved) -> (usize, isize) {
    let op = &s.problem.slip_operator;
    let inward = if op.upstream_end == 0 { 1 } else { -1 };
    (op.upstream_end, inward)
}

/// Checks the end node of one run against its three neighbours.
fn assert_no_spike(name: &str, overrides: &[&str]) {
    let s = solve(name, overrides);
    let sol = &s.solution;
    let (end, inward) = upstream_end(&s);
    let node = |k: usize| (end as isize + inward * k as isize) as usize;
    let slip = |k: usize| sol.slip[node(k)];
    // Smooth: the last step of the slip is no larger than twice the step before it (a smooth
    // function sampled at equal spacing changes by about the same amount from node to node; the
    // old datum row jumped by 50–3000 times the step before it).
    let (last, before) = ((slip(0) - slip(1)).abs(), (slip(1) - slip(2)).abs());
    let scale = sol.slip.iter().fold(0.0_f64, |a, b| a.max(b.abs()));
    assert!(
        last <= 2.0 * before + 1e-12 * scale,
        "{name} {overrides:?}: the slip jumps by {last:e} at the upstream end node {end} (the step before: {before:e})"
    );
    // Against the independent boundary-integral slip: at the end no worse than at the three
    // nodes next to it (both are O(h²) approximations of the same derivative there).
    let hbem = sol
        .slip_strain
        .as_ref()
        .expect("both models give the boundary-integral slip");
    let error = |k: usize| (slip(k) - hbem[node(k)]).abs();
    let neighbours = (1..=3).map(error).fold(0.0_f64, f64::max);
    assert!(
        error(0) <= neighbours,
        "{name} {overrides:?}: end node slip {:e} against the boundary-integral slip {:e}; the three nodes next to it agree within {neighbours:e}",
        slip(0),
        hbem[end]
    );
    // The solution itself does not depend on how the end node's slip is reported: the node is
    // open, so its slip only describes the surfaces' relative motion.
    assert_eq!(sol.pressure[end], 0.0, "{name}: the end node lies outside the contact");
}

#[test]
fn carter_both_rolling_directions_and_both_schemes() {
    assert_no_spike("carter_051", &[]);
    assert_no_spike("carter_051", &["contact.rolling_direction=-x"]);
    assert_no_spike("carter_051", &["contact.slip_derivative=first_order"]);
    assert_no_spike(
        "carter_051",
        &["contact.slip_derivative=first_order", "contact.rolling_direction=-x"],
    );
}

#[test]
fn dissimilar_and_bem_bodies() {
    assert_no_spike("dissimilar_beta0288_004", &[]);
    assert_no_spike("carter_051_true", &[]);
    assert_no_spike("tyre_b05_compressible", &[]);
}
