//! The same mesh in OBJ, PLY (ASCII, binary little- and big-endian) and STL (ASCII and binary)
//! renders the same image, byte for byte (vertex colours and images inside glTF files:
//! [`mesh_formats_colours`]). The other files are written here from the course
//! duck's OBJ text (positions as written, polygons as polygons, so the PLY reader's fan
//! triangulation is tested against the OBJ reader's): the OBJ reader is the reference.

use std::fmt::Write as _;

use rtc::assets::MeshAsset;
use std::path::{Path, PathBuf};

use rtc::eval::EvalOptions;
use rtc::render::{Image, RenderOptions, render_image};
use rtc::source::SourceMap;

/// Vertex colours and glTF images inside the file.
mod mesh_formats_colours;

/// The duck as written: position texts, texture coordinate texts, faces of (v, vt) corners.
struct Obj {
    positions: Vec<[String; 3]>,
    texcoords: Vec<[String; 2]>,
    faces: Vec<Vec<(usize, usize)>>,
}

fn duck() -> Obj {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models/devilduk.obj");
    let text = std::fs::read_to_string(path).expect("the course duck");
    let mut obj = Obj {
        positions: Vec::new(),
        texcoords: Vec::new(),
        faces: Vec::new(),
    };
    for line in text.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.first() {
            Some(&"v") => obj.positions.push([1, 2, 3].map(|i| w[i].to_owned())),
            Some(&"vt") => obj.texcoords.push([1, 2].map(|i| w[i].to_owned())),
            Some(&"f") => obj.faces.push(
                w[1..]
                    .iter()
                    .map(|c| {
                        let mut parts = c.split('/').map(|p| p.parse::<usize>().unwrap() - 1);
                        (parts.next().unwrap(), parts.next().unwrap())
                    })
                    .collect(),
            ),
            _ => {}
        }
    }
    assert!(obj.faces.len() > 2000 && obj.faces.iter().any(|f| f.len() == 4));
    obj
}

fn f32s<const N: usize>(texts: &[String; N]) -> [f32; N] {
    texts.each_ref().map(|t| t.parse::<f32>().unwrap())
}

/// PLY vertices are (position, uv) pairs: one per distinct pair the faces use.
fn ply_vertices(obj: &Obj) -> (Vec<(usize, usize)>, Vec<Vec<u32>>) {
    let mut ids = std::collections::HashMap::new();
    let mut verts = Vec::new();
    let faces = obj
        .faces
        .iter()
        .map(|f| {
            f.iter()
                .map(|&c| {
                    *ids.entry(c).or_insert_with(|| {
                        verts.push(c);
                        verts.len() as u32 - 1
                    })
                })
                .collect()
        })
        .collect();
    (verts, faces)
}

fn ply(obj: &Obj, format: &str) -> Vec<u8> {
    let (verts, faces) = ply_vertices(obj);
    let mut out = format!(
        "ply\nformat {format} 1.0\ncomment the course duck\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\nproperty float s\nproperty float t\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nelement face {}\nproperty list uchar int vertex_indices\nend_header\n",
        verts.len(),
        faces.len()
    )
    .into_bytes();
    let big = format == "binary_big_endian";
    // Values come big-endian; little-endian files get them reversed.
    let put = |out: &mut Vec<u8>, be: [u8; 4]| {
        if big {
            out.extend(be);
        } else {
            out.extend(be.iter().rev());
        }
    };
    for &(p, t) in &verts {
        let (p, t) = (&obj.positions[p], &obj.texcoords[t]);
        if format == "ascii" {
            let line = format!("{} {} {} {} {} 200 100 50", p[0], p[1], p[2], t[0], t[1]);
            out.extend(line.bytes().chain([b'\n']));
        } else {
            for v in f32s(p).into_iter().chain(f32s(t)) {
                put(&mut out, v.to_be_bytes());
            }
            out.extend([200, 100, 50]);
        }
    }
    for f in &faces {
        if format == "ascii" {
            let list: Vec<String> = f.iter().map(u32::to_string).collect();
            out.extend(format!("{} {}\n", f.len(), list.join(" ")).bytes());
        } else {
            out.push(f.len() as u8);
            for &i in f {
                put(&mut out, i.to_be_bytes());
            }
        }
    }
    out
}

/// The duck as glTF: one node, one triangle primitive (POSITION, TEXCOORD_0, u32 indices), a
/// material with a base colour; `buffer` is the `buffers` entry's `uri` (absent for GLB).
fn gltf_json(obj: &Obj, uri: Option<&str>) -> (String, Vec<u8>) {
    let (verts, faces) = ply_vertices(obj);
    let mut bin = Vec::new();
    for &(p, _) in &verts {
        bin.extend(f32s(&obj.positions[p]).iter().flat_map(|c| c.to_le_bytes()));
    }
    let uv_at = bin.len();
    for &(_, t) in &verts {
        let [u, v] = f32s(&obj.texcoords[t]);
        bin.extend([u, 1.0 - v].iter().flat_map(|c| c.to_le_bytes()));
    }
    let idx_at = bin.len();
    let tris: Vec<u32> = faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).flat_map(move |k| [f[0], f[k], f[k + 1]]))
        .collect();
    bin.extend(tris.iter().flat_map(|i| i.to_le_bytes()));
    let n = verts.len();
    let uri = uri.map_or(String::new(), |u| format!(r#", "uri": "{u}""#));
    let json = format!(
        r#"{{"asset": {{"version": "2.0"}}, "scene": 0, "scenes": [{{"nodes": [0]}}],
"nodes": [{{"mesh": 0}}],
"meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0, "TEXCOORD_0": 1}}, "indices": 2, "material": 0}}]}}],
"materials": [{{"pbrMetallicRoughness": {{"baseColorFactor": [0.2, 0.4, 0.6, 1.0]}}}}],
"buffers": [{{"byteLength": {len}{uri}}}],
"bufferViews": [{{"buffer": 0, "byteOffset": 0, "byteLength": {uv_at}}}, {{"buffer": 0, "byteOffset": {uv_at}, "byteLength": {uvs}}}, {{"buffer": 0, "byteOffset": {idx_at}, "byteLength": {idx}}}],
"accessors": [{{"bufferView": 0, "componentType": 5126, "count": {n}, "type": "VEC3", "min": [-1e9, -1e9, -1e9], "max": [1e9, 1e9, 1e9]}},
  {{"bufferView": 1, "componentType": 5126, "count": {n}, "type": "VEC2"}},
  {{"bufferView": 2, "componentType": 5125, "count": {nt}, "type": "SCALAR"}}]}}"#,
        len = bin.len(),
        uvs = idx_at - uv_at,
        idx = bin.len() - idx_at,
        nt = tris.len(),
    );
    (json, bin)
}

/// The duck as one GLB file.
fn glb(obj: &Obj) -> Vec<u8> {
    let (json, bin) = gltf_json(obj, None);
    glb_of(&json, bin)
}

/// A GLB: header, JSON chunk, BIN chunk (each padded to 4 bytes).
fn glb_of(json: &str, mut bin: Vec<u8>) -> Vec<u8> {
    let mut json = json.as_bytes().to_vec();
    while !json.len().is_multiple_of(4) {
        json.push(b' ');
    }
    while !bin.len().is_multiple_of(4) {
        bin.push(0);
    }
    let total = 12 + 8 + json.len() + 8 + bin.len();
    let mut out = b"glTF".to_vec();
    out.extend(2u32.to_le_bytes());
    out.extend((total as u32).to_le_bytes());
    out.extend((json.len() as u32).to_le_bytes());
    out.extend(b"JSON");
    out.extend(json);
    out.extend((bin.len() as u32).to_le_bytes());
    out.extend(b"BIN\0");
    out.extend(bin);
    out
}

/// Triangles fanned from each face's first corner, as the OBJ readers fan them.
fn triangles(obj: &Obj) -> Vec<[usize; 3]> {
    obj.faces
        .iter()
        .flat_map(|f| (1..f.len() - 1).map(move |k| [f[0].0, f[k].0, f[k + 1].0]))
        .collect()
}

fn stl_ascii(obj: &Obj) -> Vec<u8> {
    let mut out = String::from("solid duck\n");
    for t in triangles(obj) {
        out.push_str("  facet normal 0 0 0\n    outer loop\n");
        for v in t {
            let p = &obj.positions[v];
            writeln!(out, "      vertex {} {} {}", p[0], p[1], p[2]).unwrap();
        }
        out.push_str("    endloop\n  endfacet\n");
    }
    out.push_str("endsolid duck\n");
    out.into_bytes()
}

fn stl_binary(obj: &Obj) -> Vec<u8> {
    let tris = triangles(obj);
    // A header starting with `solid`, as some exporters write: the length decides.
    let mut out = b"solid but binary".to_vec();
    out.resize(80, b' ');
    out.extend((tris.len() as u32).to_le_bytes());
    for t in tris {
        out.extend([0u8; 12]);
        for v in t {
            for c in f32s(&obj.positions[v]) {
                out.extend(c.to_le_bytes());
            }
        }
        out.extend([0u8; 2]);
    }
    out
}

/// A directory of this test process's own.
fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-mesh-formats-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create a temporary directory");
    dir
}

/// The image of the mesh file `file` in `dir`, smooth, with `material`.
fn render(dir: &Path, file: &str, material: &str) -> Image {
    let scene = format!(
        "rtc 1\nimport std.layout {{ front_view }}\nlet duck = mesh(path: \"{file}\", smooth: true).material({material})\nlet v = front_view(duck)\ncamera {{ eye: v.eye, center: v.center, up: Y, fov: v.fov, resolution: [96, 96] }}\npoint_light {{ position: v.light, color: rgb(1, 1, 1) }}\nduck\nrender {{ shadows: true }}\n"
    );
    render_text(&dir.join(format!("{file}.rtc")), &scene)
}

/// The image of the scene `text`, written to `path` first (its assets resolve beside it); it
/// must load without errors.
fn render_text(path: &Path, text: &str) -> Image {
    std::fs::write(path, text).expect("write the scene");
    let mut sources = SourceMap::default();
    let loaded = rtc::loader::load(path, &mut sources, &EvalOptions::default());
    assert!(
        !loaded.diagnostics.has_errors(),
        "{}: {:?}",
        path.display(),
        loaded.diagnostics.items
    );
    let options = RenderOptions {
        threads: 2,
        ..Default::default()
    };
    render_image(&loaded.scene.expect("a scene"), &options).expect("renders")
}

#[test]
fn the_duck_renders_the_same_from_every_format() {
    let obj = duck();
    let dir = scratch("duck");
    let source =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models/devilduk.obj");
    std::fs::copy(&source, dir.join("duck.obj")).expect("copy the duck");
    let (json, bin) = gltf_json(&obj, Some("duck.bin"));
    std::fs::write(dir.join("duck.bin"), bin).expect("write the buffer");
    let (_, bin) = gltf_json(&obj, None);
    use base64::Engine as _;
    let data = base64::engine::general_purpose::STANDARD.encode(&bin);
    let (embedded, _) = gltf_json(
        &obj,
        Some(&format!("data:application/octet-stream;base64,{data}")),
    );
    let files: [(&str, Vec<u8>); 8] = [
        ("duck.gltf", json.into_bytes()),
        ("duck_embedded.gltf", embedded.into_bytes()),
        ("duck.glb", glb(&obj)),
        ("duck_ascii.ply", ply(&obj, "ascii")),
        ("duck_le.ply", ply(&obj, "binary_little_endian")),
        ("duck_be.PLY", ply(&obj, "binary_big_endian")),
        ("duck_ascii.stl", stl_ascii(&obj)),
        ("duck_binary.stl", stl_binary(&obj)),
    ];
    for (name, bytes) in &files {
        std::fs::write(dir.join(name), bytes).expect("write a mesh file");
    }
    // Solid colour: every format. A uv-mapped image: the formats with texture coordinates.
    let plain = "material { color: rgb(0.9, 0.7, 0.15), ka: 0.15, kd: 0.75, ks: 0.25, n: 40 }";
    let earth =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/textures/earthmap1k.png");
    let textured = format!(
        "material {{ texture: image(path: \"{}\") }}",
        earth.display()
    );
    let reference = render(&dir, "duck.obj", plain);
    let reference_textured = render(&dir, "duck.obj", &textured);
    assert_ne!(reference, reference_textured, "the texture shows");
    for (name, _) in &files {
        assert!(
            render(&dir, name, plain) == reference,
            "{name} differs from the OBJ"
        );
        // glTF's v runs the other way: 1 − (1 − v) need not give v back, so not compared.
        if name.to_ascii_lowercase().ends_with(".ply") {
            let got = render(&dir, name, &textured);
            assert!(
                got == reference_textured,
                "{name} (textured) differs from the OBJ"
            );
        }
    }
    // Welded STL corners make the same surface as the OBJ's shared vertices.
    let load = |name: &str| MeshAsset::load(&dir.join(name), false).expect("loads");
    let reference = load("duck.obj");
    for (name, _) in &files {
        let a = load(name);
        assert_eq!(a.triangles.len(), reference.triangles.len(), "{name}");
        assert_eq!(a.is_closed(), reference.is_closed(), "{name}");
        assert_eq!((a.min, a.max), (reference.min, reference.max), "{name}");
        if name.contains("gl") {
            assert_eq!(a.materials.len(), 1, "{name}");
            assert_eq!(
                a.materials[0].color,
                glam::DVec3::new(0.2f32 as f64, 0.4f32 as f64, 0.6f32 as f64)
            );
            assert_eq!(a.material_of.len(), a.triangles.len(), "{name}");
            assert_eq!(a.uvs.len(), a.triangles.len(), "{name}");
        }
    }
    std::fs::remove_dir_all(&dir).ok();
}

/// A binary STL tetrahedron is closed once its corners are welded (CSG can use it); with one
/// face turned over it is not.
#[test]
fn a_welded_stl_tetrahedron_is_closed() {
    let p = [
        [1.0f32, 1.0, 1.0],
        [2.0, 1.0, 1.0],
        [1.0, 2.0, 1.0],
        [1.0, 1.0, 2.0],
    ];
    let stl = |faces: &[[usize; 3]]| {
        let mut out = vec![0u8; 80];
        out.extend((faces.len() as u32).to_le_bytes());
        for f in faces {
            out.extend([0u8; 12]);
            for &v in f {
                out.extend(p[v].iter().flat_map(|c| c.to_le_bytes()));
            }
            out.extend([0u8; 2]);
        }
        out
    };
    let dir = scratch("tetra");
    let path = dir.join("tetra.stl");
    let faces = [[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 2, 3]];
    std::fs::write(&path, stl(&faces)).unwrap();
    let m = MeshAsset::load(&path, true).expect("loads");
    assert_eq!(m.vertices.len(), 4, "welded");
    assert!(m.is_closed());
    let path = dir.join("flipped.stl");
    std::fs::write(&path, stl(&[[0, 2, 1], [0, 3, 2], [0, 1, 3], [1, 3, 2]])).unwrap();
    assert!(!MeshAsset::load(&path, true).expect("loads").is_closed());
    std::fs::remove_dir_all(&dir).ok();
}
