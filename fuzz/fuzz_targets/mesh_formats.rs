//! STL, PLY and glTF loading. Input: one flag byte (bit 0: smooth normals; bit 1: PLY; bit 2:
//! GLB; bit 3: glTF JSON (its buffers and images as `data:` URIs: a relative one names a file
//! the scratch directory lacks); none of bits 1–3: STL; bit 4: `use_mtl`, so vertex colours
//! and base colour images, those inside the file included, are decoded and shown), then the
//! file's bytes, written to the scratch directory in memory as `m.stl`, `m.ply`, `m.glb` or
//! `m.gltf` (rtc reads meshes by path and picks the reader by the extension). The mesh is
//! loaded, ray-cast from 14 directions, tested for closedness, and rendered 4×4 as a scene
//! object, as for `obj_mtl`.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&flags, file)) = data.split_first() else {
        return;
    };
    let name = if flags & 4 != 0 {
        "m.glb"
    } else if flags & 8 != 0 {
        "m.gltf"
    } else if flags & 2 != 0 {
        "m.ply"
    } else {
        "m.stl"
    };
    let path = rtc_fuzz::scratch().join(name);
    std::fs::write(&path, file).expect("write the mesh");
    rtc_fuzz::mesh::exercise(&path, flags & 1 != 0, flags & 16 != 0);
});
