//! The layer body model: an elastic or viscoelastic cover bonded to a rigid core.

pub mod compliance;
