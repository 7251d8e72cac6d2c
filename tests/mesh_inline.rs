//! Inline meshes (`mesh(vertices:, faces:, normals:, uv:)`) are the same mesh as the same data
//! in an OBJ file: the course duck written inline renders byte-identical to its OBJ, plain and
//! textured (the OBJ reader is the reference). And a rule any renderer keeps: a convex solid
//! lit by one point light casts no shadow on itself, so its image is the same with shadows on
//! and off (a mesh face inside CSG found itself again before its crossings were placed in
//! double precision).

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use rtc::eval::EvalOptions;
use rtc::render::{Image, RenderOptions, render_image};
use rtc::source::SourceMap;

fn scratch(test: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("rtc-mesh-inline-{}-{test}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("create a temporary directory");
    dir
}

/// The image of `scene` written to `dir/name.rtc`.
fn render(dir: &Path, name: &str, scene: &str) -> Image {
    let path = dir.join(format!("{name}.rtc"));
    std::fs::write(&path, scene).expect("write the scene");
    let mut sources = SourceMap::default();
    let loaded = rtc::loader::load(&path, &mut sources, &EvalOptions::default());
    assert!(
        !loaded.diagnostics.has_errors(),
        "{name}: {:?}",
        loaded.diagnostics.items
    );
    let options = RenderOptions {
        threads: 2,
        ..Default::default()
    };
    render_image(&loaded.scene.expect("a scene"), &options).expect("renders")
}

/// The course duck's OBJ text as inline lists: one vertex per distinct (position, uv) corner,
/// positions and uvs as the file writes them, faces as the file's polygons.
fn duck_inline() -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models/devilduk.obj");
    let text = std::fs::read_to_string(path).expect("the course duck");
    let (mut positions, mut uvs) = (Vec::new(), Vec::new());
    let mut faces = Vec::new();
    for line in text.lines() {
        let w: Vec<&str> = line.split_whitespace().collect();
        match w.first() {
            Some(&"v") => positions.push(format!("[{}, {}, {}]", w[1], w[2], w[3])),
            Some(&"vt") => uvs.push(format!("[{}, {}]", w[1], w[2])),
            Some(&"f") => faces.push(
                w[1..]
                    .iter()
                    .map(|c| {
                        let mut p = c.split('/').map(|p| p.parse::<usize>().unwrap() - 1);
                        (p.next().unwrap(), p.next().unwrap())
                    })
                    .collect::<Vec<_>>(),
            ),
            _ => {}
        }
    }
    assert!(faces.len() > 2000 && faces.iter().any(|f| f.len() == 4));
    let mut ids = std::collections::HashMap::new();
    let mut corners = Vec::new();
    let mut out = String::from("mesh(faces: [");
    for f in &faces {
        out.push('[');
        for (k, c) in f.iter().enumerate() {
            let next = ids.len();
            let id = *ids.entry(*c).or_insert_with(|| {
                corners.push(*c);
                next
            });
            write!(out, "{}{id}", if k > 0 { ", " } else { "" }).unwrap();
        }
        out.push_str("], ");
    }
    out.push_str("], vertices: [");
    for (p, _) in &corners {
        write!(out, "{}, ", positions[*p]).unwrap();
    }
    out.push_str("], uv: [");
    for (_, t) in &corners {
        write!(out, "{}, ", uvs[*t]).unwrap();
    }
    out.push_str("], smooth: true)");
    out
}

fn duck_scene(mesh: &str, material: &str) -> String {
    format!(
        "rtc 1.1\nimport std.layout {{ front_view }}\nlet duck = {mesh}.material({material})\nlet v = front_view(duck)\ncamera {{ eye: v.eye, center: v.center, up: Y, fov: v.fov, resolution: [96, 96] }}\npoint_light {{ position: v.light, color: rgb(1, 1, 1) }}\nduck\nrender {{ shadows: true }}\n"
    )
}

#[test]
fn the_duck_written_inline_renders_as_its_obj() {
    let dir = scratch("duck");
    let obj = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/models/devilduk.obj");
    let file = format!("mesh(path: \"{}\", smooth: true)", obj.display());
    let inline = duck_inline();
    let earth =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/textures/earthmap1k.png");
    let plain = "material { color: rgb(0.9, 0.7, 0.15), ka: 0.15, kd: 0.75, ks: 0.25, n: 40 }";
    let textured = format!(
        "material {{ texture: image(path: \"{}\") }}",
        earth.display()
    );
    for (k, material) in [plain, textured.as_str()].iter().enumerate() {
        let reference = render(&dir, &format!("obj{k}"), &duck_scene(&file, material));
        let got = render(&dir, &format!("inline{k}"), &duck_scene(&inline, material));
        assert!(
            got == reference,
            "material {k}: the inline duck differs from the OBJ"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

const TETRA: &str = "mesh(vertices: [[1, 1, 1], [-1, -1, 1], [-1, 1, -1], [1, -1, -1]], faces: [[0, 1, 3], [0, 2, 1], [0, 3, 2], [1, 2, 3]])";

fn convex_scene(object: &str, shadows: bool) -> String {
    format!(
        "rtc 1.1\ncamera {{ eye: [0.5, 1, 5], center: [0, 0, 0], up: Y, fov: 40deg, resolution: [120, 90] }}\npoint_light {{ position: [5, 5, 5] }}\npoint_light {{ position: [-4, 3, 6], color: rgb(0.4, 0.5, 0.6) }}\n({object}).material(material {{ color: rgb(1, 0.5, 0.2), ks: 0.3 }})\nrender {{ shadows: {shadows} }}\n"
    )
}

#[test]
fn a_convex_mesh_solid_does_not_shadow_itself() {
    let dir = scratch("convex");
    let cases = [
        ("tetra", TETRA.to_owned()),
        ("tetra_and_ball", format!("{TETRA} & sphere(radius: 1.2)")),
        (
            "tetra_and_ball_turned",
            format!("({TETRA}.scale(1e3) & sphere(radius: 1.2e3)).rotate(y: 20deg).scale(1e-3)"),
        ),
    ];
    for (name, object) in &cases {
        let lit = render(&dir, &format!("{name}_on"), &convex_scene(object, true));
        let unlit = render(&dir, &format!("{name}_off"), &convex_scene(object, false));
        let differing = lit
            .as_raw()
            .chunks(3)
            .zip(unlit.as_raw().chunks(3))
            .filter(|(a, b)| a != b)
            .count();
        assert_eq!(
            differing, 0,
            "{name}: {differing} pixels shadowed by the solid itself"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn an_inline_mesh_has_bounds_and_is_a_closed_solid() {
    let dir = scratch("bounds");
    let scene = format!(
        "rtc 1.1\ncamera {{ eye: [0, 0, 5] }}\npoint_light {{ position: [5, 5, 5] }}\nlet t = {TETRA}\nassert(t.bounds.min == [-1, -1, -1])\nassert(t.scale(2).bounds.max == [2, 2, 2])\nt - sphere(radius: 0.5)\n"
    );
    let image = render(&dir, "bounds", &scene);
    assert!(image.as_raw().iter().any(|&b| b > 0), "the solid shows");
    std::fs::remove_dir_all(&dir).ok();
}

/// A quad with texture coordinates in OBJ (its MTL material's `map_Kd` names `image`) and in
/// glTF (its base colour texture's URI), both beside the image.
fn textured_quad_files(dir: &Path, image: &str) {
    std::fs::write(
        dir.join("quad.obj"),
        "mtllib quad.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl skin\nf 1/1 2/2 3/3 4/4\n",
    )
    .unwrap();
    std::fs::write(
        dir.join("quad.mtl"),
        format!("newmtl skin\nKa 0.1 0.1 0.1\nKd 1 1 1\nKs 0 0 0\nmap_Kd -s 1 1 1 {image}\n"),
    )
    .unwrap();
    // Positions (4 × vec3), texture coordinates (4 × vec2), indices (6 × u16).
    let mut bin = Vec::new();
    for p in [
        [-1f32, -1.0, 0.0],
        [1.0, -1.0, 0.0],
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
    ] {
        p.iter().for_each(|x| bin.extend(x.to_le_bytes()));
    }
    for t in [[0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]] {
        t.iter().for_each(|x| bin.extend(x.to_le_bytes()));
    }
    for i in [0u16, 1, 2, 0, 2, 3] {
        bin.extend(i.to_le_bytes());
    }
    std::fs::write(dir.join("quad.bin"), &bin).unwrap();
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1}},"indices":2,"material":0}}]}}],
"materials":[{{"pbrMetallicRoughness":{{"baseColorTexture":{{"index":0}}}}}}],
"textures":[{{"source":0}}],"images":[{{"uri":"{image}"}}],
"buffers":[{{"uri":"quad.bin","byteLength":{}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":32}},{{"buffer":0,"byteOffset":80,"byteLength":12}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]}},
{{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"}},{{"bufferView":2,"componentType":5123,"count":6,"type":"SCALAR"}}]}}"#,
        bin.len()
    );
    std::fs::write(dir.join("quad.gltf"), json).unwrap();
}

fn quad_scene(mesh: &str) -> String {
    format!(
        "rtc 1.1\ncamera {{ eye: [0, 0, 3], center: [0, 0, 0], up: Y, fov: 50deg, resolution: [64, 64] }}\npoint_light {{ position: [1, 2, 6] }}\n{mesh}\n"
    )
}

/// A mesh material's base colour image (MTL `map_Kd`, glTF `baseColorTexture`) shows as the
/// same image given by hand does: bilinear, on the mesh's texture coordinates.
#[test]
fn mesh_materials_show_their_base_colour_images() {
    let dir = scratch("images");
    let earth =
        Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/course/textures/earthmap1k.png");
    std::fs::copy(&earth, dir.join("earth.png")).unwrap();
    textured_quad_files(&dir, "earth.png");
    let by_hand = |file: &str, extra: &str| {
        quad_scene(&format!(
            "mesh(path: \"{file}\").material(material {{ texture: image(path: \"earth.png\", filter: \"bilinear\"){extra} }})"
        ))
    };
    for (file, extra) in [
        ("quad.obj", ", ka: 0.1, kd: 1, ks: 0"),
        ("quad.gltf", ", kd: 1"),
    ] {
        let own = render(
            &dir,
            &format!("{file}_own"),
            &quad_scene(&format!("mesh(path: \"{file}\", use_mtl: true)")),
        );
        let given = render(&dir, &format!("{file}_given"), &by_hand(file, extra));
        let plain = render(
            &dir,
            &format!("{file}_plain"),
            &quad_scene(&format!("mesh(path: \"{file}\")")),
        );
        assert!(
            own == given,
            "{file}: the material's own image differs from the same image given"
        );
        assert!(own != plain, "{file}: the image shows");
    }
    // A missing image is a warning, and the material's colour is drawn.
    textured_quad_files(&dir, "no_such.png");
    let path = dir.join("missing.rtc");
    std::fs::write(&path, quad_scene("mesh(path: \"quad.obj\", use_mtl: true)")).unwrap();
    let mut sources = SourceMap::default();
    let loaded = rtc::loader::load(&path, &mut sources, &EvalOptions::default());
    let prepared = rtc::opt::prepare(&loaded.scene.expect("a scene"));
    let warnings = match &prepared {
        Ok(p) => p.warnings().to_vec(),
        Err(d) => panic!("prepares with a warning: {:?}", d.items),
    };
    assert!(
        warnings
            .iter()
            .any(|d| d.code == "rtc::mesh::missing_image"),
        "{warnings:?}"
    );
    std::fs::remove_dir_all(&dir).ok();
}
