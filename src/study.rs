//! Studies over many runs of one scene (issue 6): speed against accuracy of the body models.
//!
//! * [`accuracy`] — `rollbem study accuracy`: each body model the scene allows at a ladder of
//!   discretizations, its error against the reference and its wall time (accuracy.csv/.svg).

pub mod accuracy;
