//! ASCII MSH 4.1 sections (after a fixed ASCII header) → reader → checks and orientation:
//! no panic, and a mesh that passes has finite coordinates and closed, simple loops.
#![no_main]

use libfuzzer_sys::fuzz_target;

const HEADER: &[u8] = b"$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";

fuzz_target!(|data: &[u8]| {
    let mut bytes = HEADER.to_vec();
    bytes.extend_from_slice(data);
    if let Ok(mut mesh) = rollbem::mesh::parse_msh_bytes(&bytes, "fuzz.msh") {
        if rollbem::mesh::validate_and_orient(&mut mesh).is_ok() {
            assert!(mesh.nodes.iter().flatten().all(|v| v.is_finite()));
            assert!(rollbem::mesh::boundary_loops(&mesh).is_ok());
        }
    }
});
