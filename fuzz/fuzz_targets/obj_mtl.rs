//! OBJ + MTL loading. Input: one flag byte (bit 0: smooth normals, bit 1: use the MTL
//! materials), the OBJ text, then optionally a NUL byte and the text of `m.mtl` (which the
//! OBJ's `mtllib m.mtl` loads). Both are written to a scratch directory in memory, because
//! rtc reads meshes by path. The mesh is loaded, ray-cast from 14 directions (nearest hit,
//! any hit, all hits), tested for closedness, and rendered 4×4 as a scene object.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&flags, rest)) = data.split_first() else {
        return;
    };
    let (obj, mtl) = match rest.iter().position(|&b| b == 0) {
        Some(i) => (&rest[..i], &rest[i + 1..]),
        None => (rest, &[][..]),
    };
    let dir = rtc_fuzz::scratch();
    let (obj_path, mtl_path) = (dir.join("m.obj"), dir.join("m.mtl"));
    std::fs::write(&obj_path, obj).expect("write the OBJ");
    std::fs::write(&mtl_path, mtl).expect("write the MTL");
    rtc_fuzz::mesh::exercise(&obj_path, flags & 1 != 0, flags & 2 != 0);
});
