//! Case text (and `--set` overrides) → validated case → prepared bodies → Hertz estimates →
//! preflight → contact grid: no panic, and a case that passes holds finite numbers only.
//!
//! Input: the YAML text, then optionally a NUL byte and one `key.path=value` override per line.
#![no_main]

use libfuzzer_sys::fuzz_target;
use std::path::Path;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let (yaml, set) = text.split_once('\0').unwrap_or((text, ""));
    let overrides: Vec<String> = set.lines().map(str::to_string).collect();
    // As if the case lived in cases/: the shipped cases' mesh paths then resolve.
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/fuzz.yaml");
    let Ok(case) = rollbem::case::parse(yaml, &path, &overrides) else {
        return;
    };
    assert_eq!(rollbem::app::finite::first_non_finite(&case.case), None);
    let Ok(bodies) = rollbem::app::prepare_bodies(&case) else {
        return;
    };
    let est = rollbem::app::estimates(&case, &bodies);
    if rollbem::app::preflight::check(&case, &est, &bodies).is_ok() {
        let grid = rollbem::app::contact_grid(&case, &est, &bodies);
        assert!(grid.nodes.iter().all(|x| x.is_finite()));
    }
});
