//! # rollbem — 2D steady rolling contact of elastic cylinders
//!
//! rollbem solves the coupled normal–tangential steady rolling contact problem between two
//! cylinders in plane strain with Coulomb friction, by the generalized Newton method with line
//! search of González & Abascal (IJNME 49, 2000).
//!
//! ## Data flow (docs/architecture.md maps the stages to files)
//! ```text
//! case (YAML) ─▶ scene: both bodies as BodySetup, the contact grid, controls, estimates
//!            ─▶ body models (half_space | bem | rigid) ─▶ Flexibility at the contact grid
//!            ─▶ ContactProblem (gap and slip affine in the tractions, paper Eq. 21)
//!            ─▶ contact::methods::solve (newton | newton_plain | norm_tang | gauss_seidel)
//!            ─▶ post: ContactSolution, zones and regime, friction check, body fields
//!            ─▶ output (JSON, CSV, SVG, VTK, the terminal table)
//! ```
//! [`app::solve_case`] runs the stages up to post-processing for a case file or text;
//! [`app::run`] also writes the outputs.
//!
//! ## Conventions (docs/theory.md)
//! x along the common tangent, y from B into A. Pressure p ≥ 0 compressive; shear q is the
//! traction B exerts on A, positive in +x. Creepage ξ = (V_A − V_B)/V; slip s is the velocity of
//! A's surface relative to B's divided by |V|. Overlap δ0 > 0 presses the bodies together.
//! Units are whatever the case uses consistently (the shipped cases: mm, N, MPa).

pub mod adapt;
pub mod advice;
pub mod analytic;
pub mod app;
pub mod bem;
pub mod body;
pub mod cancel;
pub mod case;
pub mod check;
pub mod cli;
pub mod contact;
pub mod error;
pub mod files;
pub mod grid;
pub mod interior;
pub mod limits;
pub mod linalg;
pub mod logging;
pub mod material;
pub mod mesh;
pub mod output;
pub mod post;
pub mod quadrature;
pub mod reference;
pub mod scene;
pub mod sequence;
pub mod study;
pub mod sweep;
pub mod transient;
