//! Case text (and `--set` overrides) → validated case → scene (bodies and meshes, preflight,
//! Hertz estimates, contact grid): no panic, and what passes holds finite numbers only.
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
    assert_eq!(rollbem::post::finite::first_non_finite(&case.case), None);
    // Bodies (meshes read), preflight, estimates and the contact grid: no panic, finite grid.
    if let Ok(scene) = rollbem::scene::Scene::from_case(&case) {
        assert!(scene.grid.nodes.iter().all(|x| x.is_finite()));
        assert_eq!(rollbem::post::finite::first_non_finite(&scene.estimates), None);
    }
});
