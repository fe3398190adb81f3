//! The boundary element method and its inputs: Gmsh meshes, the BEM on exact fields (patch,
//! Lamé, layer), condensation to the contact nodes, hypersingular boundary strains and
//! Somigliana interior fields.
//!
//! Run one file's tests with its module name, e.g. `cargo test --release --test bem lame::`.

#[path = "../common/mod.rs"]
mod common;

mod condense;
mod hbem;
mod interior;
mod lame;
mod layer;
mod msh_reader;
mod patch;
