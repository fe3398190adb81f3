//! The memory estimate that refuses oversized cases against the measured peak of `rollbem run`,
//! in a test program of its own: a child's peak resident set size (`ru_maxrss`) includes the
//! high-water mark of the process that spawned it (Linux carries it over the `exec` of a
//! vfork'ed child), so the tests that measure it must run in a process that stays small, apart
//! from the property tests of `tests/input`.
//!
//! `cargo test --release --test memory -- --ignored --nocapture` prints the calibration table of
//! docs/reliability.md.

mod estimate;
