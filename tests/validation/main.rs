//! The contact solver on the shipped cases against closed forms and against itself: Hertz and
//! Carter, equilibrium and load controls, Φ against Ψ, the solution methods, the friction
//! limits of free rolling, BEM bodies (true geometry) and the tyred cylinder; and the closed
//! forms themselves (the conformal Michell series, the free-rolling creepage of unequal rollers).
//!
//! Run one file's tests with its module name, e.g. `cargo test --release --test validation
//! hertz_carter::`.

// Each report is a program of its own and declares the shared examples/common/mod.rs itself;
// compiled together here, that file is one module per report.
#![allow(clippy::duplicate_mod)]

#[path = "../common/mod.rs"]
mod common;

pub(crate) mod adaptive;
#[allow(dead_code)]
#[path = "../../examples/bem_tolerance_matrix.rs"]
mod bem_tolerance_matrix;
mod bem_tolerances;
mod body_contract;
mod body_mesh;
#[allow(dead_code)]
#[path = "../../examples/body_mesh_report.rs"]
mod body_mesh_report;
mod bore_creepage;
mod conformal_bem;
mod conformal_series;
mod effectivity;
#[allow(dead_code)]
#[path = "../../examples/effectivity_matrix.rs"]
mod effectivity_matrix;
mod falling_friction;
mod fixed_estimate;
#[allow(dead_code)]
#[path = "../../examples/fixed_grid_report.rs"]
mod fixed_grid_report;
mod floor;
mod free_rolling_creepage;
mod friction_limits;
mod hertz_carter;
mod internal_contact;
mod layer;
mod methods;
mod oscillating;
#[allow(dead_code)]
#[path = "../../examples/oscillating_report.rs"]
mod oscillating_report;
mod parametric;
#[allow(dead_code)]
#[path = "../../examples/parametric_report.rs"]
mod parametric_report;
mod sequence;
mod slip_end;
mod smooth_cuts;
mod solver;
mod stand_in;
mod stand_in_surface;
mod strength;
#[allow(dead_code)]
#[path = "../../examples/strength_report.rs"]
mod strength_report;
mod transient;
mod transient_energy;
mod true_geometry;
mod tyre;
mod viscoelastic;
#[allow(dead_code)]
#[path = "../../examples/viscoelastic_report.rs"]
mod viscoelastic_report;
mod winkler;
