//! What rollbem accepts as input and what it refuses before solving: the case's keys and ranges
//! (`keys`), the refusals that hang on a body's kind (`kinds`), meshes with one defect each (`meshes`), and property tests over case texts, numeric values and mesh bytes
//! (`properties`). docs/reliability.md lists the probes; the memory estimate against the measured
//! peak is the program `tests/memory`.
//!
//! Run one file's tests with its module name, e.g. `cargo test --release --test input meshes::`.

#[path = "../common/mod.rs"]
mod common;

mod falling_friction;
mod geometry;
mod keys;
mod kinds;
mod meshes;
mod messages;
mod properties;
mod transient;
