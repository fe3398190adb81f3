//! Quadrature rules, apart from any integrand.
//!
//! * [`legendre`] — Gauss–Legendre rules on [−1, 1];
//! * [`log_gauss`](mod@log_gauss) — Gauss rules for the weight ln(1/t) on [0, 1] (the weakly
//!   singular part of the BEM displacement kernel);
//! * [`adaptive`] — the adaptive Gauss rule for integrands that are analytic on an element of a
//!   quadratic boundary except at complex points near it: the number of points and the interval
//!   halving follow from the Bernstein ellipse of the nearest singularity (Trefethen,
//!   *Approximation Theory and Approximation Practice*, Thm 19.3);
//! * [`far_field`] — a cheap lower bound on that ellipse and the whole-element rules it allows
//!   for sources far from the element;
//! * [`complex_roots`] — the complex singularities of 1/r and of the Jacobian of a quadratic
//!   element, found exactly.
//!
//! An element is given by its three nodes `[start, end, mid]` ([`QuadraticNodes`]): the
//! quadratic map x(ξ) = x_mid + ξ (x_end − x_start)/2 + ξ² ((x_start + x_end)/2 − x_mid),
//! ξ ∈ [−1, 1]. Lengths are in the mesh's unit; the rules are dimensionless.

pub mod adaptive;
pub mod complex_roots;
pub mod far_field;
pub mod legendre;
pub mod log_gauss;

pub use adaptive::{Quadrature, QuadratureOptions, MAX_DEPTH};
pub use far_field::{FarFieldRules, SingularityBound};
pub use legendre::gauss_legendre;
pub use log_gauss::log_gauss;

/// The nodes `[start, end, mid]` [length] of a quadratic element, in the order of the mesh's
/// three-node line elements.
pub type QuadraticNodes = [[f64; 2]; 3];
