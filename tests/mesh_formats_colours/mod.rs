//! Vertex colours (PLY, glTF `COLOR_0`) and glTF base colour images inside the file: a PLY
//! quad's colours against the analytic rule (barycentric blend of its corners), every
//! encoding of the same colours byte-identical, glTF's `COLOR_0` as the PLY's, and an image in
//! a `.glb` buffer view or a `data:` URI as the same image beside the file.

use std::fmt::Write as _;

use super::*;

/// The quad of the colour tests: corners (±1, ±1, 0) counter-clockwise from (−1, −1), as
/// bytes of sRGB-agnostic channels (read as image texels are: byte/255).
const QUAD: [[f32; 3]; 4] = [
    [-1.0, -1.0, 0.0],
    [1.0, -1.0, 0.0],
    [1.0, 1.0, 0.0],
    [-1.0, 1.0, 0.0],
];
const QUAD_COLOURS: [[u8; 3]; 4] = [[255, 0, 0], [0, 255, 40], [20, 60, 255], [250, 250, 250]];

/// The quad as PLY: `uchar` colours (`red green blue`), or float ones (`diffuse_red` ...,
/// each the f32 byte/255 the reader computes), or none; `format` is `ascii` or
/// `binary_little_endian`.
fn colour_ply(format: &str, colours: Option<&str>) -> Vec<u8> {
    let mut out = format!(
        "ply\nformat {format} 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
    );
    match colours {
        Some("uchar") => out.push_str("property uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"),
        Some(_) => out.push_str("property float diffuse_red\nproperty float diffuse_green\nproperty float diffuse_blue\n"),
        None => {}
    }
    out.push_str("element face 1\nproperty list uchar int vertex_indices\nend_header\n");
    let mut out = out.into_bytes();
    let float = |b: u8| f32::from(b) / 255.0;
    for (p, c) in QUAD.iter().zip(QUAD_COLOURS) {
        if format == "ascii" {
            let mut line = format!("{} {} {}", p[0], p[1], p[2]);
            match colours {
                Some("uchar") => write!(line, " {} {} {} 255", c[0], c[1], c[2]).unwrap(),
                Some(_) => {
                    write!(line, " {} {} {}", float(c[0]), float(c[1]), float(c[2])).unwrap()
                }
                None => {}
            }
            out.extend(line.bytes().chain([b'\n']));
        } else {
            p.iter().for_each(|x| out.extend(x.to_le_bytes()));
            match colours {
                Some("uchar") => out.extend(c.iter().chain(&[255])),
                Some(_) => c.iter().for_each(|&b| out.extend(float(b).to_le_bytes())),
                None => {}
            }
        }
    }
    if format == "ascii" {
        out.extend(b"4 0 1 2 3\n");
    } else {
        out.push(4);
        [0i32, 1, 2, 3]
            .iter()
            .for_each(|i| out.extend(i.to_le_bytes()));
    }
    out
}

/// The quad seen straight on, filling a 32×32 orthographic view; the object's material only
/// emits (white), so a pixel is its surface colour, written `trunc(255·c)` (`encoding:
/// linear`); the light is for a file's own materials.
fn quad_render(dir: &Path, file: &str, use_mtl: bool) -> Image {
    let scene = format!(
        "rtc 1.1\ncamera {{ eye: [0, 0, 3], center: [0, 0, 0], up: Y, projection: \"orthographic\", height: 2, resolution: [32, 32] }}\npoint_light {{ position: [0.5, 1, 4] }}\nmesh(path: \"{file}\", use_mtl: {use_mtl}).material(material {{ color: rgb(0.3), ka: 0, kd: 0, ks: 0, emission: rgb(1, 1, 1) }})\nrender {{ encoding: linear }}\n"
    );
    super::render_text(&dir.join(format!("{file}-{use_mtl}.rtc")), &scene)
}

/// The colour the analytic rule gives at quad point (s, t) ∈ [0, 1]²: barycentric
/// interpolation of the corners' colours over the triangle (0, 1, 2) or (0, 2, 3) it lies in
/// (the quad is fanned from corner 0), as bytes `trunc(255·c)`.
fn quad_colour_at(s: f64, t: f64) -> [f64; 3] {
    let c = |k: usize, ch: usize| f64::from(QUAD_COLOURS[k][ch]) / 255.0;
    std::array::from_fn(|ch| {
        let v = if t <= s {
            (1.0 - s) * c(0, ch) + (s - t) * c(1, ch) + t * c(2, ch)
        } else {
            (1.0 - t) * c(0, ch) + s * c(2, ch) + (t - s) * c(3, ch)
        };
        255.0 * v
    })
}

/// A PLY file's vertex colours shade the mesh (with `use_mtl: true`): every pixel is the
/// barycentric blend of the corners' colours at its centre, so the corners' pixels are near
/// their colours and the centre is the mean of the diagonal's two corners; ASCII, binary,
/// `uchar` and float colours give the same image, byte for byte; without `use_mtl`, or
/// without colours, the object's material shades, as before.
#[test]
fn ply_vertex_colours_shade_the_mesh() {
    let dir = scratch("colours");
    let files = [
        ("ascii.ply", colour_ply("ascii", Some("uchar"))),
        (
            "binary.ply",
            colour_ply("binary_little_endian", Some("uchar")),
        ),
        ("float_ascii.ply", colour_ply("ascii", Some("float"))),
        (
            "float_binary.ply",
            colour_ply("binary_little_endian", Some("float")),
        ),
        ("plain.ply", colour_ply("binary_little_endian", None)),
    ];
    for (name, bytes) in &files {
        std::fs::write(dir.join(name), bytes).expect("write a mesh file");
    }
    let coloured = quad_render(&dir, "ascii.ply", true);
    let (w, h) = coloured.dimensions();
    let mut worst = 0f64;
    for y in 0..h {
        for x in 0..w {
            let s = (f64::from(x) + 0.5) / f64::from(w);
            let t = 1.0 - (f64::from(y) + 0.5) / f64::from(h);
            let want = quad_colour_at(s, t);
            let got = coloured.get_pixel(x, y).0;
            for ch in 0..3 {
                // trunc(255·c) of a colour within rounding of the rule's.
                let d = f64::from(got[ch]) - want[ch];
                worst = worst.max(d.abs());
                assert!(
                    (-1.0..=0.001).contains(&d),
                    "pixel ({x}, {y}) channel {ch}: {} for {:.3}",
                    got[ch],
                    want[ch]
                );
            }
        }
    }
    // The centre (on the diagonal 0–2, between four pixels) and a corner, spelled out.
    let centre = quad_colour_at(0.5, 0.5);
    for ch in 0..3 {
        let mean = (f64::from(QUAD_COLOURS[0][ch]) + f64::from(QUAD_COLOURS[2][ch])) / 2.0;
        assert!((centre[ch] - mean).abs() < 1e-9);
        let corner = f64::from(coloured.get_pixel(0, h - 1).0[ch]);
        assert!((corner - f64::from(QUAD_COLOURS[0][ch])).abs() <= 255.0 * 2.0 / 32.0);
    }
    for (name, _) in &files[1..4] {
        assert!(
            quad_render(&dir, name, true) == coloured,
            "{name} differs from ascii.ply"
        );
    }
    // The object's material: an emitted grey of 0.3 everywhere.
    let plain = quad_render(&dir, "plain.ply", false);
    assert!(
        plain.pixels().all(|p| p.0 == [76, 76, 76]),
        "{:?}",
        plain.get_pixel(3, 3)
    );
    assert!(
        quad_render(&dir, "ascii.ply", false) == plain,
        "colours without use_mtl"
    );
    assert!(
        quad_render(&dir, "plain.ply", true) == plain,
        "use_mtl without colours"
    );
    let asset = MeshAsset::load(&dir.join("binary.ply"), false).expect("loads");
    assert_eq!(asset.colors.len(), asset.triangles.len());
    assert!(
        MeshAsset::load(&dir.join("plain.ply"), false)
            .unwrap()
            .colors
            .is_empty()
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// The quad as glTF: positions, texture coordinates, `COLOR_0` (normalised bytes) and u16
/// indices in one buffer, `extra` bytes after them (an image); `material` and `images` are
/// the JSON of the material list and the image list, `more_views` extra buffer views.
fn quad_gltf(
    buffer_uri: Option<&str>,
    extra: &[u8],
    material: &str,
    images: &str,
) -> (String, Vec<u8>) {
    let mut bin = Vec::new();
    QUAD.iter()
        .flatten()
        .for_each(|x| bin.extend(x.to_le_bytes()));
    for t in [[0f32, 1.0], [1.0, 1.0], [1.0, 0.0], [0.0, 0.0]] {
        t.iter().for_each(|x| bin.extend(x.to_le_bytes()));
    }
    QUAD_COLOURS
        .iter()
        .for_each(|c| bin.extend(c.iter().chain(&[0])));
    for i in [0u16, 1, 2, 0, 2, 3] {
        bin.extend(i.to_le_bytes());
    }
    let image_at = bin.len();
    bin.extend(extra);
    let uri = buffer_uri.map_or(String::new(), |u| format!(r#","uri":"{u}""#));
    let json = format!(
        r#"{{"asset":{{"version":"2.0"}},"scene":0,"scenes":[{{"nodes":[0]}}],"nodes":[{{"mesh":0}}],
"meshes":[{{"primitives":[{{"attributes":{{"POSITION":0,"TEXCOORD_0":1{colour}}},"indices":3{material_ref}}}]}}],
{material}{images}
"buffers":[{{"byteLength":{len}{uri}}}],
"bufferViews":[{{"buffer":0,"byteOffset":0,"byteLength":48}},{{"buffer":0,"byteOffset":48,"byteLength":32}},{{"buffer":0,"byteOffset":80,"byteLength":16}},{{"buffer":0,"byteOffset":96,"byteLength":12}},{{"buffer":0,"byteOffset":{image_at},"byteLength":{image_len}}}],
"accessors":[{{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3","min":[-1,-1,0],"max":[1,1,0]}},
{{"bufferView":1,"componentType":5126,"count":4,"type":"VEC2"}},{{"bufferView":2,"componentType":5121,"normalized":true,"count":4,"type":"VEC4"}},{{"bufferView":3,"componentType":5123,"count":6,"type":"SCALAR"}}]}}"#,
        colour = if material.is_empty() {
            r#","COLOR_0":2"#
        } else {
            ""
        },
        material_ref = if material.is_empty() {
            ""
        } else {
            r#","material":0"#
        },
        len = bin.len(),
        image_len = extra.len().max(1),
    );
    (json, bin)
}

/// A glTF quad's `COLOR_0` (normalised bytes, no material: glTF's white) shades it as the
/// same bytes in a PLY file do, byte for byte.
#[test]
fn gltf_vertex_colours_match_the_ply_ones() {
    let dir = scratch("gltf-colours");
    std::fs::write(dir.join("q.ply"), colour_ply("ascii", Some("uchar"))).unwrap();
    let (json, bin) = quad_gltf(None, &[0], "", "");
    std::fs::write(dir.join("q.glb"), glb_of(&json, bin)).unwrap();
    let ply = quad_render(&dir, "q.ply", true);
    assert!(
        quad_render(&dir, "q.glb", true) == ply,
        "COLOR_0 differs from the PLY colours"
    );
    std::fs::remove_dir_all(&dir).ok();
}

/// A small PNG: a 4×4 gradient.
fn png() -> Vec<u8> {
    let img = image::RgbImage::from_fn(4, 4, |x, y| image::Rgb([60 * x as u8, 60 * y as u8, 200]));
    let mut out = std::io::Cursor::new(Vec::new());
    img.write_to(&mut out, image::ImageFormat::Png).unwrap();
    out.into_inner()
}

/// A glTF material's base colour texture inside the file (a `.glb` buffer view, a base64
/// `data:` URI) shows as the same image beside the file does, byte for byte; a broken image
/// inside the file is the warning `rtc::mesh::missing_image` and the factor is drawn.
#[test]
fn gltf_images_inside_the_file_show_as_files_beside_it() {
    use base64::Engine as _;
    let dir = scratch("gltf-images");
    let png = png();
    std::fs::write(dir.join("tex.png"), &png).unwrap();
    let material = r#""materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0}}}],"textures":[{"source":0}],"#;
    let (json, bin) = quad_gltf(
        Some("q.bin"),
        &[],
        material,
        r#""images":[{"uri":"tex.png"}],"#,
    );
    std::fs::write(dir.join("q.bin"), bin).unwrap();
    std::fs::write(dir.join("file.gltf"), json).unwrap();
    let data = base64::engine::general_purpose::STANDARD.encode(&png);
    let (json, bin) = quad_gltf(
        Some("q.bin"),
        &[],
        material,
        &format!(r#""images":[{{"uri":"data:image/png;base64,{data}"}}],"#),
    );
    std::fs::write(dir.join("q.bin"), bin).unwrap();
    std::fs::write(dir.join("uri.gltf"), json).unwrap();
    let view = r#""images":[{"bufferView":4,"mimeType":"image/png"}],"#;
    let (json, bin) = quad_gltf(None, &png, material, view);
    std::fs::write(dir.join("view.glb"), glb_of(&json, bin)).unwrap();
    let reference = quad_render(&dir, "file.gltf", true);
    assert!(
        reference != quad_render(&dir, "file.gltf", false),
        "the image shows"
    );
    for name in ["uri.gltf", "view.glb"] {
        assert!(
            quad_render(&dir, name, true) == reference,
            "{name} differs from file.gltf"
        );
    }
    // Broken: cut short, not an image, an unknown type, a view beyond its buffer.
    let warnings = |name: &str| {
        let path = dir.join(format!("{name}.rtc"));
        std::fs::write(
            &path,
            format!(
                "rtc 1.1\ncamera {{ eye: [0, 0, 3] }}\nmesh(path: \"{name}\", use_mtl: true)\n"
            ),
        )
        .unwrap();
        let mut sources = SourceMap::default();
        let loaded = rtc::loader::load(&path, &mut sources, &EvalOptions::default());
        match rtc::opt::prepare(&loaded.scene.expect("a scene")) {
            Ok(p) => p.warnings().iter().map(|d| d.code).collect::<Vec<_>>(),
            Err(d) => panic!("{name}: prepares with a warning: {:?}", d.items),
        }
    };
    let cases: [(&str, &[u8], &str, &str); 4] = [
        (
            "short.glb",
            &png[..png.len() / 2],
            view,
            "rtc::mesh::missing_image",
        ),
        (
            "text.glb",
            b"not an image",
            view,
            "rtc::mesh::missing_image",
        ),
        (
            "webp.glb",
            &png,
            r#""images":[{"bufferView":4,"mimeType":"image/webp"}],"#,
            "rtc::mesh::partial",
        ),
        (
            "beyond.glb",
            &png,
            r#""images":[{"bufferView":4,"mimeType":"image/png"}],"#,
            "rtc::mesh::partial",
        ),
    ];
    for (name, bytes, images, code) in cases {
        let (mut json, bin) = quad_gltf(None, bytes, material, images);
        if name == "beyond.glb" {
            json = json.replace(
                &format!(r#""byteLength":{}}}]"#, png.len()),
                r#""byteLength":99999}]"#,
            );
        }
        std::fs::write(dir.join(name), glb_of(&json, bin)).unwrap();
        let got = warnings(name);
        assert!(got.contains(&code), "{name}: {got:?}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
