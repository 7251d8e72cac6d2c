//! The parallel OBJ reader (`assets::obj_fast`) against tobj: every OBJ file of the repository
//! and the shared course and model folders, hand-made tricky files and random edits load to the
//! same mesh both ways (corners bit for bit, normals, texture coordinates, materials, warnings,
//! errors), and the reader gives the same data for any chunk size and thread count.

use std::path::{Path, PathBuf};

use proptest::prelude::*;
use rtc::assets::MeshAsset;
use rtc::assets::obj_fast::{ObjData, read_in_chunks};

mod fuzz_support;
use fuzz_support::splice;

/// What a loaded mesh is to everything after loading, with floats as bits.
#[derive(Debug, PartialEq)]
struct Seen {
    corners: Vec<[[u32; 3]; 3]>,
    normals: Vec<[[u32; 3]; 3]>,
    uvs: Vec<[[u32; 2]; 3]>,
    material_of: Vec<u32>,
    materials: Vec<rtc::ir::Material>,
    warnings: Vec<String>,
    bounds: [[u64; 3]; 2],
    closed: bool,
}

fn seen(a: &MeshAsset) -> Seen {
    Seen {
        corners: (0..a.triangles.len())
            .map(|i| a.corners(i).map(|p| p.to_array().map(f32::to_bits)))
            .collect(),
        normals: a
            .normals
            .iter()
            .map(|n| n.map(|v| v.to_array().map(f32::to_bits)))
            .collect(),
        uvs: a
            .uvs
            .iter()
            .map(|n| n.map(|v| v.to_array().map(f32::to_bits)))
            .collect(),
        material_of: a.material_of.clone(),
        materials: a.materials.clone(),
        warnings: a.warnings.clone(),
        bounds: [a.min, a.max].map(|v| v.to_array().map(f64::to_bits)),
        closed: a.is_closed(),
    }
}

/// Both readers, smooth and flat, agree on `path` (a mesh or the same error).
fn agree(path: &Path) {
    for smooth in [false, true] {
        let fast = MeshAsset::load(path, smooth).map(|a| seen(&a));
        let general = MeshAsset::load_general(path, smooth).map(|a| seen(&a));
        assert_eq!(fast, general, "{} (smooth: {smooth})", path.display());
    }
}

/// The reader's data for `text` (no material libraries).
fn fast(text: &[u8], chunk: usize) -> Option<ObjData> {
    read_in_chunks(text, chunk, &mut |_| {}, &mut |_| None)
}

fn objs_below(dir: &Path, out: &mut Vec<PathBuf>) {
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    for e in entries.flatten() {
        let p = e.path();
        if p.is_dir() {
            objs_below(&p, out);
        } else if p.extension().is_some_and(|x| x == "obj") {
            out.push(p);
        }
    }
}

/// A directory of this test process's own.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-obj-fast-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create a temporary directory");
    dir
}

#[test]
fn every_obj_file_at_hand_loads_the_same_both_ways() {
    let mut files = Vec::new();
    objs_below(Path::new("tests/data"), &mut files);
    // The shared folders of this machine when present (large models: a few seconds in debug).
    for dir in ["/work/shared/course", "/work/shared/models"] {
        objs_below(Path::new(dir), &mut files);
    }
    assert!(files.len() >= 9, "{files:?}");
    let mut in_subset = 0;
    for f in &files {
        agree(f);
        let text = std::fs::read(f).expect("read");
        in_subset += usize::from(fast(&text, 1 << 16).is_some());
    }
    // The course models are all in the reader's subset (the fuzz cases are not all).
    assert!(in_subset >= 6, "{in_subset} of {}", files.len());
}

const DUCK_MTL: &str = include_str!("data/course/models/devilduk.mtl");

/// Hand-made files: the corners of tobj's rules, in and out of the subset.
const TRICKY: &[(&str, &str)] = &[
    (
        "negative",
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2\nf -1 1 -2\nv 0 0 1\nf -1 -2 -3\n",
    ),
    (
        "polygons",
        "v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1.5 0\nv -1 1 0\nf 1 2 3 4 5 6\nf 1 2 3 4 5\nf 6 5 4 3\n",
    ),
    (
        "normals_and_uvs",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\nvt 0 0\nvt 1 0 0\nvt 0 1\nvn 0 0 1\nvn 0 0 0\nvn 1 1 1\nf 1/1/1 2/2/1 3/3/1\nf 2/2/3 4/1/3 3/3/2\n",
    ),
    (
        "crlf_comments_groups",
        "# a comment\r\nmtllib m.mtl\r\no one\r\nv 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nv 0 0 1\r\ns 1\r\ng a b\r\nusemtl bill\r\nf 1 2 3\r\n#f 1 2 4\r\ng\r\nusemtl nosuch\r\nf 1 3 4\r\nusemtl bill\r\nf 2 3 4",
    ),
    (
        "trailing_usemtl",
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl bill\n",
    ),
    (
        "degenerate_and_unicode",
        "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\n# caf\u{e9}\nf\u{3000}1 2 3\nf 1\t2 4\nvp 1 2\n\x0bf 2 3 4\n",
    ),
    (
        "missing_mtl",
        "mtllib none.mtl\nusemtl bill\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    ),
    // Read, then rejected as tobj's load is (the same error).
    ("not_finite", "v 0 0 0\nv inf 0 0\nv 0 1 0\nf 1 2 3\n"),
    // Outside the subset: tobj's own rules or errors, reached through the fallback.
    ("forward", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"),
    (
        "mixed_uvs",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.5\nf 1 2 3\nf 2/1 4/1 3/1\n",
    ),
    (
        "w_and_lines",
        "v 0 0 0 2\nv 1 0 0\nv 0 1 0\nl 1 2\nf 1 2 3\n",
    ),
    (
        "inline_comment",
        "v 0 0 0 # origin\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    ),
    (
        "empty_usemtl",
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl\n",
    ),
    ("no_faces", "v 0 0 0\n"),
    ("out_of_range", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"),
];

#[test]
fn tricky_files_load_the_same_both_ways() {
    let dir = scratch("tricky");
    std::fs::write(dir.join("m.mtl"), DUCK_MTL).expect("write");
    let mut in_subset = Vec::new();
    for (name, text) in TRICKY {
        let path = dir.join(format!("{name}.obj"));
        std::fs::write(&path, text).expect("write");
        agree(&path);
        if fast(text.as_bytes(), 16).is_some() {
            in_subset.push(*name);
        }
    }
    // The first eight are read by the parallel reader, the rest left to tobj.
    assert_eq!(
        in_subset,
        TRICKY[..8].iter().map(|c| c.0).collect::<Vec<_>>()
    );
}

#[test]
fn the_data_does_not_depend_on_chunks_or_threads() {
    let duck = std::fs::read("tests/data/course/models/devilduk.obj").expect("read");
    let sphere = std::fs::read("tests/data/course/models/sphere.obj").expect("read");
    for text in [&duck, &sphere] {
        let whole = fast(text, usize::MAX).expect("in the subset");
        for chunk in [1, 7, 100, 4096] {
            for threads in [1, 2, 3] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .expect("pool");
                let d = pool.install(|| fast(text, chunk));
                assert_eq!(d.as_ref(), Some(&whole), "chunk {chunk}, {threads} threads");
            }
        }
    }
}

const CUBE: &str = include_str!("data/course/models/cube.obj");
const PIECES: &str = r"(?s)[ \t\r\n/#\-.0-9eE+a-zA-Z]{0,12}";

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    /// Random edits of the cube (with a material library) load the same both ways.
    #[test]
    fn edited_cubes_load_the_same_both_ways(at in 0usize..700, len in 0usize..20, with in PIECES) {
        let dir = scratch("edits");
        std::fs::write(dir.join("m.mtl"), DUCK_MTL).expect("write");
        let path = dir.join("cube.obj");
        std::fs::write(&path, format!("mtllib m.mtl\nusemtl bill\n{}", splice(CUBE, at, len, &with)))
            .expect("write");
        agree(&path);
    }
}
