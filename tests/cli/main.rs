//! The `rollbem` program and its multi-run commands: exit codes, messages and files of `run`
//! and `check`, the safety of the user's files, sweeps (shards, merge, resume), and the two
//! studies.
//!
//! Run one file's tests with its module name, e.g. `cargo test --release --test cli sweep::`.

#[path = "../common/mod.rs"]
mod common;

mod commands;
mod files;
mod memory_limit;
mod mesh;
mod stability;
mod stall;
mod study;
mod sweep;
mod transient;
mod units;
mod validity;
mod verbosity;
