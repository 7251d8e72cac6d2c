//! The STL and PLY readers never panic: random edits of small valid files (ASCII text spliced,
//! binary bytes overwritten, cut or extended), written to a temporary directory (meshes load by
//! path), come back as a mesh or a `MeshError`, and a loaded mesh answers rays. The
//! coverage-guided fuzzer in fuzz/ (`mesh_formats`) does this at scale; this is the short
//! version that runs in CI.

mod geometry_support;

use rtc::num::Norm;
use std::path::PathBuf;

use glam::DVec3;
use proptest::prelude::*;
use rtc::assets::MeshAsset;
use rtc::geometry::Ray;

mod fuzz_support;
use fuzz_support::splice;

/// A tetrahedron with normals, uvs and colours, one quad face fanned.
const PLY: &str = "ply\nformat ascii 1.0\ncomment t\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\nproperty float nx\nproperty float ny\nproperty float nz\nproperty float s\nproperty float t\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face 3\nproperty list uchar int vertex_indices\nelement edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n0 0 0 0 0 1 0 0 255 0 0\n1 0 0 0 0 1 1 0 0 255 0\n1 1 0 0 0 1 1 1 0 0 255\n0 1 0 0 0 1 0 1 9 9 9\n0 0 1 1 0 0 0.5 0.5 1 2 3\n4 0 1 2 3\n3 0 1 4\n3 1 2 4\n0 1\n";

const STL: &str = "solid t\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 1 0\n endloop\nendfacet\nfacet normal 0 0 1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n endloop\nendfacet\nendsolid t\n";

/// A directory of this test process's own.
fn scratch() -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-formats-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create a temporary directory");
    dir
}

/// Writes `bytes` as `name` and loads it; each test names its own file (they run in parallel).
fn load_and_trace(bytes: &[u8], name: &str, smooth: bool) {
    let path = scratch().join(name);
    std::fs::write(&path, bytes).expect("write");
    if let Ok(asset) = MeshAsset::load(&path, smooth) {
        let mesh = geometry_support::mesh_of(&asset);
        let b = mesh.bounds();
        let centre = 0.5 * (b.min + b.max);
        for dir in [DVec3::X, DVec3::NEG_Y, DVec3::new(0.3, 0.5, -0.8).unit()] {
            let ray = Ray::new(centre - 10.0 * dir, dir);
            if let Some(h) = mesh.intersect(&ray, 0.0, f64::INFINITY) {
                let finite = h.geometric.is_finite() && h.shading.is_finite();
                assert!(h.t >= 0.0 && finite, "{h:?}");
            }
        }
        let _ = asset.is_closed();
    }
}

/// The ASCII PLY as binary of either byte order (`big`), written from its own numbers.
fn binary_ply(big: bool) -> Vec<u8> {
    let (head, body) = PLY.split_once("end_header\n").unwrap();
    let order = if big { "big" } else { "little" };
    let head = head.replace("ascii", &format!("binary_{order}_endian"));
    let mut out = format!("{head}end_header\n").into_bytes();
    let lines: Vec<&str> = body.lines().collect();
    let put = |out: &mut Vec<u8>, mut b: Vec<u8>| {
        if big {
            b.reverse();
        }
        out.extend(b);
    };
    for l in &lines[..5] {
        let w: Vec<&str> = l.split(' ').collect();
        for x in &w[..8] {
            put(&mut out, x.parse::<f32>().unwrap().to_le_bytes().to_vec());
        }
        out.extend(w[8..].iter().map(|c| c.parse::<u8>().unwrap()));
    }
    for l in &lines[5..] {
        let w: Vec<i32> = l.split(' ').map(|c| c.parse().unwrap()).collect();
        if l.split(' ').count() == 2 {
            for v in w {
                put(&mut out, v.to_le_bytes().to_vec());
            }
        } else {
            out.push(w[0] as u8);
            for v in &w[1..] {
                put(&mut out, v.to_le_bytes().to_vec());
            }
        }
    }
    out
}

/// The ASCII STL as binary.
fn binary_stl() -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out.extend(2u32.to_le_bytes());
    let numbers: Vec<f32> = STL
        .split_whitespace()
        .filter_map(|w| w.parse::<f32>().ok())
        .collect();
    for facet in numbers.chunks(12) {
        out.extend(facet.iter().flat_map(|x| x.to_le_bytes()));
        out.extend([0, 0]);
    }
    out
}

/// `base` with `with` written over it at `at` (wrapping), then cut or extended to `len`.
fn mutate(mut base: Vec<u8>, at: usize, with: &[u8], len: Option<usize>) -> Vec<u8> {
    for (k, &b) in with.iter().enumerate() {
        let i = (at + k) % base.len();
        base[i] = b;
    }
    if let Some(len) = len {
        base.resize(len, 0xff);
    }
    base
}

const PIECES: &str = r"(?s)[ \t\r\n\-.0-9eE+a-z_]{0,12}";

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn ascii_ply_survives_edits(
        at in 0usize..800, len in 0usize..20, with in PIECES, smooth in any::<bool>()
    ) {
        load_and_trace(splice(PLY, at, len, &with).as_bytes(), "a.ply", smooth);
    }

    #[test]
    fn binary_ply_survives_edits(
        big in any::<bool>(), at in 0usize..1000, with in prop::collection::vec(any::<u8>(), 0..8),
        len in prop::option::of(0usize..800), smooth in any::<bool>()
    ) {
        load_and_trace(&mutate(binary_ply(big), at, &with, len), "b.ply", smooth);
    }

    #[test]
    fn ascii_stl_survives_edits(
        at in 0usize..300, len in 0usize..20, with in PIECES, smooth in any::<bool>()
    ) {
        load_and_trace(splice(STL, at, len, &with).as_bytes(), "a.stl", smooth);
    }

    #[test]
    fn binary_stl_survives_edits(
        at in 0usize..200, with in prop::collection::vec(any::<u8>(), 0..8),
        len in prop::option::of(0usize..300), smooth in any::<bool>()
    ) {
        load_and_trace(&mutate(binary_stl(), at, &with, len), "b.stl", smooth);
    }

    #[test]
    fn readers_never_panic_on_bytes(
        bytes in prop::collection::vec(any::<u8>(), 0..300), ply in any::<bool>()
    ) {
        let head: &[u8] = if ply { b"ply\nformat binary_little_endian 1.0\n" } else { b"" };
        let name = if ply { "r.ply" } else { "r.stl" };
        load_and_trace(&[head, &bytes].concat(), name, false);
    }
}

/// The seeds themselves load: the edits start from valid files.
#[test]
fn the_seeds_load() {
    let dir = scratch();
    for (name, bytes) in [
        ("s.ply", PLY.as_bytes().to_vec()),
        ("sle.ply", binary_ply(false)),
        ("sbe.ply", binary_ply(true)),
        ("s.stl", STL.as_bytes().to_vec()),
        ("sb.stl", binary_stl()),
    ] {
        std::fs::write(dir.join(name), &bytes).unwrap();
        let m = MeshAsset::load(&dir.join(name), true).unwrap_or_else(|e| panic!("{name}: {e:?}"));
        let want = if name.ends_with("ply") { 4 } else { 2 };
        assert_eq!(m.triangles.len(), want, "{name}");
        if name.ends_with("ply") {
            assert_eq!(m.uvs.len(), 4, "{name}");
            // The file's normals: (0, 0, 1) at the quad's corners.
            assert_eq!(m.normals[0], [glam::Vec3::Z; 3], "{name}");
        }
    }
}

/// A one-primitive GLB: the PLY's five positions, u16 indices of its four triangles, a
/// material, under a node with a transform.
fn glb() -> Vec<u8> {
    let mut bin: Vec<u8> = Vec::new();
    for p in [
        [0f32, 0., 0.],
        [1., 0., 0.],
        [1., 1., 0.],
        [0., 1., 0.],
        [0., 0., 1.],
    ] {
        bin.extend(p.iter().flat_map(|c| c.to_le_bytes()));
    }
    for i in [0u16, 1, 2, 0, 2, 3, 0, 1, 4, 1, 2, 4] {
        bin.extend(i.to_le_bytes());
    }
    let json = r#"{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
"nodes": [{"children": [1], "rotation": [0, 0.7071068, 0, 0.7071068]}, {"mesh": 0, "scale": [2, 2, -2]}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
"materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1]}}],
"buffers": [{"byteLength": 84}],
"bufferViews": [{"buffer": 0, "byteLength": 60}, {"buffer": 0, "byteOffset": 60, "byteLength": 24}],
"accessors": [{"bufferView": 0, "componentType": 5126, "count": 5, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 1]},
  {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}]}"#;
    let mut json = json.as_bytes().to_vec();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend(((12 + 8 + json.len() + 8 + bin.len()) as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(json);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}

/// The GLB seed loads: its four triangles, transformed, with the material.
#[test]
fn the_glb_seed_loads() {
    let path = scratch().join("seed.glb");
    std::fs::write(&path, glb()).unwrap();
    let m = MeshAsset::load(&path, false).unwrap_or_else(|e| panic!("{e:?}"));
    assert_eq!(m.triangles.len(), 4);
    assert_eq!(m.materials.len(), 1);
    load_and_trace(&glb(), "g.glb", true);
}

/// Random mutations of every seed straight through the readers (no files): the binary
/// formats' counts, offsets and lengths, the text formats' words. `RTC_MUTATIONS` inputs
/// (default 10⁶); ignored in CI, run with `--ignored` (about a minute in release).
#[test]
#[ignore]
fn a_million_mutations() {
    use rtc::assets::indexed::{Format, triangles_in};
    let n: u64 = std::env::var("RTC_MUTATIONS")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(1_000_000);
    let seeds: Vec<(Format, Vec<u8>)> = vec![
        (Format::Ply, PLY.as_bytes().to_vec()),
        (Format::Ply, binary_ply(false)),
        (Format::Ply, binary_ply(true)),
        (Format::Stl, STL.as_bytes().to_vec()),
        (Format::Stl, binary_stl()),
        (Format::Gltf, glb()),
    ];
    let tokens: [&[u8]; 12] = [
        b"element",
        b"property",
        b"list",
        b"uchar",
        b"double",
        b"face",
        b"vertex",
        b"\n",
        b"4294967295",
        b"-1",
        b"facet",
        b"\"count\": 0",
    ];
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let mut next = move |m: usize| {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        (state % m.max(1) as u64) as usize
    };
    let (mut ok, mut refused) = (0u64, 0u64);
    for _ in 0..n {
        let (format, seed) = &seeds[next(seeds.len())];
        let mut b = seed.clone();
        for _ in 0..1 + next(4) {
            let at = next(b.len() + 1);
            match next(6) {
                0 if at < b.len() => b[at] ^= 1 << next(8),
                1 if at < b.len() => b[at] = next(256) as u8,
                2 => {
                    let t = tokens[next(tokens.len())];
                    b.splice(at..at, t.iter().copied());
                }
                3 => {
                    let end = (at + next(16)).min(b.len());
                    b.drain(at..end);
                }
                4 => b.truncate(at),
                _ if at + 4 <= b.len() => {
                    let v = [0u32, 1, 255, 65535, u32::MAX, next(1 << 20) as u32][next(6)];
                    b[at..at + 4].copy_from_slice(&v.to_le_bytes());
                }
                _ => {}
            }
        }
        match triangles_in(&b, *format) {
            Ok(_) => ok += 1,
            Err(_) => refused += 1,
        }
    }
    eprintln!("{n} mutated inputs: {ok} loaded, {refused} refused, no panic");
}
