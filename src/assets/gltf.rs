//! glTF 2.0 meshes (`.gltf` with `.bin` files or embedded base64 buffers, and `.glb`): every
//! triangle primitive of the default scene (else the first), its node transforms flattened into
//! the positions, with normals, texture coordinates, vertex colours (`COLOR_0`) and the
//! material's base colour factor and texture (an image file beside it or inside it,
//! [`super::gltf_image`]).
//!
//! The `gltf` crate parses and validates the JSON (and the GLB container); its accessor reader
//! is not used: it subtracts 1 from an accessor's count and asserts on stride and size (panics
//! on files such as a zero-count accessor). Each accessor is checked ([`super::gltf_accessor`]:
//! type, component, stride, byte range within its view and buffer, with checked arithmetic)
//! before a value is read. Node trees are walked with a depth and a visit budget (a node may appear in several
//! trees; a file can make that grow exponentially) and the triangle budget is checked before
//! each primitive is read.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{DMat4, DVec3, Vec2, Vec3};
use gltf::mesh::Mode;

use super::embedded::{EmbeddedImage, ImageSource};
use super::gltf_accessor as accessor;
use super::gltf_accessor::malformed;
use super::gltf_image::buffer_file;
use super::mesh_data::{Indexed, too_many_triangles};
use super::obj_error::MeshError;
use crate::ir::Material;
use crate::ir::limits::MAX_MESH_FILE_BYTES;
use crate::num::Norm;

/// Deepest node nesting followed.
const MAX_DEPTH: usize = 256;

/// Most node visits in one scene (instances of nodes in several places included).
const MAX_VISITS: usize = 1 << 20;

/// A glTF file's mesh, materials and the other files it read (its `.bin` buffers).
#[derive(Debug)]
pub(super) struct GltfMesh {
    pub(super) mesh: Indexed,
    /// Per triangle, an index into `materials` (`u32::MAX`: none); empty when none has one.
    pub(super) material_of: Vec<u32>,
    pub(super) materials: Vec<Material>,
    /// Per material, its base colour texture's image (beside the glTF file or inside it).
    pub(super) images: Vec<Option<ImageSource>>,
    pub(super) buffers: Vec<PathBuf>,
    pub(super) warnings: Vec<String>,
}

impl GltfMesh {
    /// Adds the warning `w` once (a file may have it on every primitive).
    fn warn(&mut self, w: String) {
        if !self.warnings.contains(&w) {
            self.warnings.push(w);
        }
    }
}

/// The meshes of the glTF or GLB file `path` (its bytes `bytes`), at most `max_triangles`.
pub(super) fn parse(
    path: &Path,
    bytes: &[u8],
    max_triangles: usize,
) -> Result<GltfMesh, MeshError> {
    let gltf = validated(bytes)?;
    let mut paths = Vec::new();
    let buffers = gltf
        .document
        .buffers()
        .map(|b| buffer(path, &b, gltf.blob.as_deref(), &mut paths))
        .collect::<Result<Vec<_>, _>>()?;
    let scene = gltf
        .document
        .default_scene()
        .or_else(|| gltf.document.scenes().next())
        .ok_or_else(|| MeshError {
            fix: Some("export the file with a scene holding the model's nodes".to_owned()),
            ..MeshError::new("the glTF file has no scene", None)
        })?;
    let mut out = GltfMesh {
        mesh: Indexed::default(),
        material_of: Vec::new(),
        materials: Vec::new(),
        images: Vec::new(),
        buffers: paths,
        warnings: Vec::new(),
    };
    let mut walk = Walk {
        path,
        buffers: &buffers,
        out: &mut out,
        visits: 0,
        max_triangles,
        material_slots: vec![None; gltf.document.materials().len()],
        any_uv: false,
        embedded: HashMap::new(),
        colors: Vec::new(),
    };
    for node in scene.nodes() {
        walk.node(&node, DMat4::IDENTITY, 0)?;
    }
    let any_uv = walk.any_uv;
    let colors = std::mem::take(&mut walk.colors);
    if !any_uv {
        out.mesh.uvs.clear();
    }
    out.mesh.colors = vertex_colors(colors, out.mesh.vertices.len());
    if out.material_of.iter().all(|&m| m == u32::MAX) {
        out.material_of.clear();
    }
    Ok(out)
}

/// The file parsed and validated. gltf-json 1.4.1's validation indexes the accessors by a
/// primitive's `POSITION` before checking that index (a panic, found by the mutation run in
/// tests/mesh_formats_fuzz.rs): every attribute's accessor is checked here first.
fn validated(bytes: &[u8]) -> Result<gltf::Gltf, MeshError> {
    let invalid = |e: gltf::Error| malformed(format!("not a valid glTF 2.0 file: {e}"));
    // The crate subtracts the 12-byte header from a GLB's declared length unchecked (an
    // overflow panic in builds with overflow checks: fuzz/found/mesh_formats-1-glb-short-length).
    if let Some(length) = bytes
        .strip_prefix(b"glTF")
        .and_then(|rest| rest.get(4..8))
        .map(|l| u32::from_le_bytes([l[0], l[1], l[2], l[3]]))
        && length < 12
    {
        return Err(malformed(format!(
            "the binary glTF header declares a length of {length} bytes, less than the 12 of the header itself"
        )));
    }
    let raw = gltf::Gltf::from_slice_without_validation(bytes).map_err(invalid)?;
    let blob = raw.blob;
    let root = raw.document.into_json();
    let accessors = root.accessors.len();
    for (m, mesh) in root.meshes.iter().enumerate() {
        for p in &mesh.primitives {
            if let Some(i) = p.attributes.values().find(|i| i.value() >= accessors) {
                return Err(malformed(format!(
                    "mesh {m} names accessor {}, but the file has {accessors}",
                    i.value()
                )));
            }
        }
    }
    // The crate's `Image::source` unwraps both (the specification requires them).
    for (i, image) in root.images.iter().enumerate() {
        if image.uri.is_none() && image.buffer_view.is_none() {
            return Err(malformed(format!(
                "image {i} has neither a `uri` nor a `bufferView`"
            )));
        }
        if image.buffer_view.is_some() && image.mime_type.is_none() {
            return Err(malformed(format!(
                "image {i} is in a buffer view but has no `mimeType`"
            )));
        }
    }
    let document = gltf::Document::from_json(root).map_err(invalid)?;
    Ok(gltf::Gltf { document, blob })
}

/// The files the buffers of the glTF file `path` (its bytes `bytes`) are read from.
pub(super) fn buffer_paths(path: &Path, bytes: &[u8]) -> Vec<PathBuf> {
    // Without validation (no index is followed: the buffers are listed as written).
    let Ok(gltf) = gltf::Gltf::from_slice_without_validation(bytes) else {
        return Vec::new();
    };
    gltf.document
        .buffers()
        .filter_map(|b| match b.source() {
            gltf::buffer::Source::Uri(uri) if !uri.starts_with("data:") => {
                Some(buffer_file(path, uri))
            }
            _ => None,
        })
        .collect()
}

/// The bytes of buffer `b`: the GLB's binary chunk, a `data:` URI, or a file next to `path`.
fn buffer(
    path: &Path,
    b: &gltf::Buffer<'_>,
    blob: Option<&[u8]>,
    paths: &mut Vec<PathBuf>,
) -> Result<Vec<u8>, MeshError> {
    let data = match b.source() {
        gltf::buffer::Source::Bin => blob
            .ok_or_else(|| malformed("a buffer refers to the GLB binary chunk, which is missing"))?
            .to_vec(),
        gltf::buffer::Source::Uri(uri) if uri.starts_with("data:") => {
            super::gltf_image::data_uri(uri)
                .map_err(|why| malformed(format!("buffer {} {why}", b.index())))?
                .1
        }
        gltf::buffer::Source::Uri(uri) => {
            let file = buffer_file(path, uri);
            paths.push(file.clone());
            crate::source::read_regular(&file, MAX_MESH_FILE_BYTES).map_err(|e| MeshError {
                fix: Some(format!(
                    "keep `{uri}` next to the glTF file, or export a `.glb` (one file)"
                )),
                ..MeshError::new(
                    format!("its buffer `{}` cannot be read: {e}", file.display()),
                    None,
                )
            })?
        }
    };
    if data.len() < b.length() {
        return Err(malformed(format!(
            "buffer {} has {} bytes, less than the {} it declares",
            b.index(),
            data.len(),
            b.length()
        )));
    }
    Ok(data)
}

/// The scene walk's state.
struct Walk<'a> {
    /// The glTF file (images are resolved beside it).
    path: &'a Path,
    buffers: &'a [Vec<u8>],
    out: &'a mut GltfMesh,
    visits: usize,
    max_triangles: usize,
    /// The rtc material of each glTF material used so far.
    material_slots: Vec<Option<u32>>,
    any_uv: bool,
    /// The images inside the file cut out so far, by image index.
    embedded: HashMap<usize, Arc<EmbeddedImage>>,
    /// Per primitive read: its vertices (first, count), the colour its vertices take
    /// without `COLOR_0` or multiply theirs by, and its `COLOR_0` if it has one.
    colors: Vec<PrimitiveColors>,
}

/// A primitive's vertex colours, see [`Walk::colors`].
struct PrimitiveColors {
    first: usize,
    count: usize,
    factor: Vec3,
    color0: Option<Vec<Vec3>>,
}

/// Per-vertex colours of `count` vertices (empty when no primitive has `COLOR_0`): glTF's
/// base colour is `COLOR_0` times the material's factor, white where a primitive has none.
fn vertex_colors(primitives: Vec<PrimitiveColors>, count: usize) -> Vec<Vec3> {
    if primitives.iter().all(|p| p.color0.is_none()) {
        return Vec::new();
    }
    let mut out = vec![Vec3::ONE; count];
    for p in primitives {
        let Some(span) = out.get_mut(p.first..p.first + p.count) else {
            continue;
        };
        match p.color0 {
            Some(c) => span.iter_mut().zip(c).for_each(|(o, c)| *o = c * p.factor),
            None => span.fill(p.factor),
        }
    }
    out
}

impl Walk<'_> {
    fn node(
        &mut self,
        node: &gltf::Node<'_>,
        parent: DMat4,
        depth: usize,
    ) -> Result<(), MeshError> {
        self.visits += 1;
        if depth > MAX_DEPTH || self.visits > MAX_VISITS {
            return Err(malformed(format!(
                "the scene's node tree is deeper than {MAX_DEPTH} or has more than {MAX_VISITS} node instances"
            )));
        }
        let local = DMat4::from_cols_array_2d(&node.transform().matrix().map(|c| c.map(f64::from)));
        let m = parent * local;
        if let Some(mesh) = node.mesh() {
            for p in mesh.primitives() {
                self.primitive(&p, m)?;
            }
        }
        for child in node.children() {
            self.node(&child, m, depth + 1)?;
        }
        Ok(())
    }

    fn primitive(&mut self, p: &gltf::Primitive<'_>, m: DMat4) -> Result<(), MeshError> {
        if p.mode() != Mode::Triangles {
            self.out.warn(format!(
                "a primitive of mode {:?} is skipped (only triangles are read)",
                p.mode()
            ));
            return Ok(());
        }
        let position = p
            .get(&gltf::Semantic::Positions)
            .ok_or_else(|| malformed("a triangle primitive has no POSITION attribute"))?;
        let positions: Vec<Vec3> = accessor::floats::<3>(self.buffers, &position, "POSITION")?
            .into_iter()
            .map(Vec3::from)
            .collect();
        let indices: Vec<u32> = match p.indices() {
            Some(a) => accessor::indices(self.buffers, &a)?,
            None => (0..positions.len() as u32).collect(),
        };
        if let Some(bad) = indices.iter().find(|&&i| i as usize >= positions.len()) {
            return Err(malformed(format!(
                "a primitive's index {bad} is beyond its {} vertices",
                positions.len()
            )));
        }
        let count = self.out.mesh.triangles.len() + indices.len() / 3;
        if count > self.max_triangles {
            return Err(too_many_triangles(count as u64, self.max_triangles));
        }
        let normals = match p.get(&gltf::Semantic::Normals) {
            Some(a) => Some(accessor::floats::<3>(self.buffers, &a, "NORMAL")?),
            None => None,
        };
        let uvs = match p.get(&gltf::Semantic::TexCoords(0)) {
            Some(a) => Some(accessor::floats::<2>(self.buffers, &a, "TEXCOORD_0")?),
            None => None,
        };
        let color0 = match p.get(&gltf::Semantic::Colors(0)) {
            Some(a) => Some(accessor::colors(self.buffers, &a)?),
            None => None,
        };
        for (name, len) in [
            ("NORMAL", normals.as_ref().map(Vec::len)),
            ("TEXCOORD_0", uvs.as_ref().map(Vec::len)),
            ("COLOR_0", color0.as_ref().map(Vec::len)),
        ] {
            if len.is_some_and(|n| n != positions.len()) {
                return Err(malformed(format!(
                    "a primitive's {name} count differs from its POSITION count"
                )));
            }
        }
        let slot = self.material(p.material());
        let base = self.out.mesh.vertices.len() as u32;
        // The factor multiplies COLOR_0 unless a texture shows (then it is not applied, as
        // without vertex colours); no material is glTF's default, white.
        let factor = match slot as usize {
            s if self.out.images.get(s).is_some_and(Option::is_none) => {
                self.out.materials[s].color.as_vec3()
            }
            _ => Vec3::ONE,
        };
        self.colors.push(PrimitiveColors {
            first: base as usize,
            count: positions.len(),
            factor,
            color0,
        });
        let normal_matrix = m.inverse().transpose();
        let mesh = &mut self.out.mesh;
        mesh.vertices.extend(
            positions
                .iter()
                .map(|p| m.transform_point3(p.as_dvec3()).as_vec3()),
        );
        // Per-vertex attributes for every vertex once any primitive has them.
        match normals {
            Some(n) => {
                mesh.normals.resize(base as usize, Vec3::ZERO);
                mesh.normals.extend(n.iter().map(|v| {
                    let t = normal_matrix.transform_vector3(DVec3::from(v.map(f64::from)));
                    t.unit_or(DVec3::ZERO).as_vec3()
                }));
            }
            None if !mesh.normals.is_empty() => {
                mesh.normals.resize(mesh.vertices.len(), Vec3::ZERO)
            }
            None => {}
        }
        // rtc's texture coordinates put v = 0 at the bottom (OBJ's); glTF's at the top.
        match uvs {
            Some(t) => {
                self.any_uv = true;
                mesh.uvs.resize(base as usize, Vec2::ZERO);
                mesh.uvs
                    .extend(t.iter().map(|[u, v]| Vec2::new(*u, 1.0 - *v)));
            }
            None => mesh.uvs.resize(mesh.vertices.len(), Vec2::ZERO),
        }
        // A mirroring transform turns the winding over: keep the front face outside.
        let flip = m.determinant() < 0.0;
        for t in indices.chunks_exact(3) {
            let (a, b, c) = (t[0] + base, t[1] + base, t[2] + base);
            mesh.triangles
                .push(if flip { [a, c, b] } else { [a, b, c] });
            self.out.material_of.push(slot);
        }
        Ok(())
    }

    /// The rtc material slot of a glTF material (its base colour factor; `u32::MAX` for none).
    fn material(&mut self, m: gltf::Material<'_>) -> u32 {
        let Some(i) = m.index() else { return u32::MAX };
        if let Some(Some(slot)) = self.material_slots.get(i) {
            return *slot;
        }
        let [r, g, b, a] = m.pbr_metallic_roughness().base_color_factor();
        let mut out = Material {
            color: DVec3::new(r.into(), g.into(), b.into()),
            kd: 1.0,
            ..Material::default()
        };
        if a < 1.0 {
            out.refract = (1.0 - f64::from(a)).clamp(0.0, 1.0);
        }
        let image = self.base_color_image(&m);
        if image.is_some() && [r, g, b] != [1.0; 3] {
            self.out.warn(
                "a material's base colour factor is not applied over its texture: the texture is shown as it is"
                    .to_owned(),
            );
        }
        self.out.materials.push(out);
        self.out.images.push(image);
        let slot = self.out.materials.len() as u32 - 1;
        if let Some(s) = self.material_slots.get_mut(i) {
            *s = Some(slot);
        }
        slot
    }

    /// The image of material `m`'s base colour texture, beside the file or inside it, read
    /// through `TEXCOORD_0` (others, and images that cannot be found, are warned of).
    fn base_color_image(&mut self, m: &gltf::Material<'_>) -> Option<ImageSource> {
        let info = m.pbr_metallic_roughness().base_color_texture()?;
        if info.tex_coord() != 0 {
            self.out.warn(format!(
                "a base colour texture on TEXCOORD_{} is not read (only TEXCOORD_0): its base colour factor is used",
                info.tex_coord()
            ));
            return None;
        }
        let image = info.texture().source();
        match super::gltf_image::source(self.path, self.buffers, &image, &mut self.embedded) {
            Ok(source) => Some(source),
            Err(why) => {
                self.out.warn(format!(
                    "a base colour texture (image {}) {why}: its base colour factor is used",
                    image.index()
                ));
                None
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use base64::Engine as _;

    /// A one-triangle glTF: positions (0,0,0), (1,0,0), (0,1,0) as a data URI; `count` is the
    /// position accessor's, `nodes` the JSON node list (node 0 is the scene's root).
    fn file(count: usize, nodes: &str) -> Vec<u8> {
        let bin: Vec<u8> = [0f32, 0., 0., 1., 0., 0., 0., 1., 0.]
            .iter()
            .flat_map(|c| c.to_le_bytes())
            .collect();
        let data = base64::engine::general_purpose::STANDARD.encode(&bin);
        format!(
            r#"{{"asset": {{"version": "2.0"}}, "scenes": [{{"nodes": [0]}}], "nodes": {nodes},
"meshes": [{{"primitives": [{{"attributes": {{"POSITION": 0}}}}]}}],
"buffers": [{{"byteLength": 36, "uri": "data:application/octet-stream;base64,{data}"}}],
"bufferViews": [{{"buffer": 0, "byteLength": 36}}],
"accessors": [{{"bufferView": 0, "componentType": 5126, "count": {count}, "type": "VEC3", "min": [0, 0, 0], "max": [1, 1, 0]}}]}}"#
        )
        .into_bytes()
    }

    #[test]
    fn node_transforms_are_flattened_and_mirrors_keep_the_winding() {
        let nodes =
            r#"[{"children": [1], "translation": [1, 2, 3]}, {"mesh": 0, "scale": [-1, 1, 1]}]"#;
        let g = parse(Path::new("t.gltf"), &file(3, nodes), 10).unwrap();
        let v = &g.mesh.vertices;
        assert_eq!(
            v[..],
            [
                Vec3::new(1., 2., 3.),
                Vec3::new(0., 2., 3.),
                Vec3::new(1., 3., 3.)
            ]
        );
        // Mirrored by the scale: corners 1 and 2 swapped, so the normal still points along +z.
        assert_eq!(g.mesh.triangles, vec![[0, 2, 1]]);
        assert!(g.material_of.is_empty() && g.materials.is_empty());
    }

    #[test]
    fn bad_accessors_and_trees_are_errors_not_panics() {
        let one = r#"[{"mesh": 0}]"#;
        // A zero count (the crate's reader computes count − 1), one beyond the view.
        for count in [0, 4] {
            let e = parse(Path::new("t.gltf"), &file(count, one), 10).expect_err("refused");
            assert!(
                e.message.contains("accessor 0") || e.message.contains("glTF"),
                "{e:?}"
            );
        }
        // A node that is its own child: refused by validation or by the walk's budget.
        assert!(
            parse(
                Path::new("t.gltf"),
                &file(3, r#"[{"mesh": 0, "children": [0]}]"#),
                10
            )
            .is_err()
        );
        // Over the triangle budget.
        assert!(
            parse(Path::new("t.gltf"), &file(3, one), 0)
                .unwrap_err()
                .too_large
        );
        assert!(parse(Path::new("t.gltf"), b"{not json", 10).is_err());
        // A GLB header declaring fewer bytes than the header (the crate's unchecked
        // subtraction; fuzz/found/mesh_formats-1-glb-short-length).
        for length in [0u32, 11] {
            let mut glb = b"glTF".to_vec();
            glb.extend(2u32.to_le_bytes());
            glb.extend(length.to_le_bytes());
            glb.extend(b"\0\0\0\0JSON{}");
            let e = parse(Path::new("t.glb"), &glb, 10).expect_err("refused");
            assert!(e.message.contains("less than the 12"), "{e:?}");
        }
        // A POSITION naming an accessor the file lacks (gltf-json's validation indexed it).
        let text = String::from_utf8(file(3, one)).unwrap();
        let e = parse(
            Path::new("t.gltf"),
            text.replace(r#""POSITION": 0"#, r#""POSITION": 5"#)
                .as_bytes(),
            10,
        )
        .expect_err("refused");
        assert!(e.message.contains("accessor 5"), "{e:?}");
    }
}
