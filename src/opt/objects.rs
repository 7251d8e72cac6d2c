//! IR objects → prepared [`Primitive`]s: shape checks (by `geometry::shapes`), transforms,
//! materials, mesh loading through the asset service with instancing (one BVH per file and
//! smoothing, shared by every object placing it), MTL material ids, and diagnostics for
//! everything that cannot be drawn.

use crate::num::Norm;
use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use std::time::Duration;

use crate::assets::{self, ImageSource, MeshAsset};
use crate::diag::{Diagnostic, Diagnostics};
use crate::geometry::mesh::{Mesh, MeshParts};
use crate::geometry::shapes::{self, Leaf, isosurface::Watch};
use crate::geometry::world::balls::{Ball, is_origin};
use crate::geometry::world::primitive::{Geom, MeshRef, Primitive};
use crate::ir::limits::Memory;
use crate::ir::{
    ImageFilter, Mapping, Material, MaterialId, MeshSource, Object, Shape, Texture, TextureId,
    Transform,
};
use crate::source::Span;

/// What the meshes placed so far took.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct MeshStats {
    /// Distinct files (and smoothing) placed.
    pub(crate) meshes: usize,
    /// Their triangles, each file once.
    pub(crate) unique_triangles: usize,
    /// Time their BVHs took.
    pub(crate) bvh_build_time: Duration,
    /// Time reading the files and building their BVHs took.
    pub(crate) load_time: Duration,
    /// Approximate heap bytes of their triangles and BVHs.
    pub(crate) memory_bytes: usize,
}

/// Prepares objects, collecting every problem instead of stopping at the first.
pub(crate) struct Builder {
    /// Number of materials in the scene; MTL materials get ids from here on.
    base: u32,
    /// MTL materials added by meshes, in id order after the scene's.
    pub(crate) extra_materials: Vec<Material>,
    /// Textures the meshes' materials add (their base colour images), numbered after the
    /// scene's own from `texture_base`.
    pub(crate) extra_textures: Vec<MeshTexture>,
    texture_base: u32,
    /// Meshes this world placed already: a file placed N times is asked of the process-wide
    /// cache once, and its load warnings are reported once.
    cache: HashMap<(MeshKey, bool), (Arc<MeshAsset>, Arc<Mesh>)>,
    mtl_ids: HashMap<PathBuf, Vec<MaterialId>>,
    /// Findings so far.
    pub(crate) diagnostics: Diagnostics,
    /// The load's memory budget: each mesh placed is charged once (its file's data, then its
    /// triangles and BVH), and the textures after the objects.
    pub(crate) memory: Memory,
    /// Every isosurface prepared, by its object's span: what its searches see is reported
    /// after the render.
    pub(crate) isosurfaces: Vec<(Span, Watch)>,
}

impl Builder {
    /// A builder for a scene whose loading charged `memory` so far; MTL materials get ids
    /// from `first_extra` on.
    pub(crate) fn new(first_extra: u32, first_texture: u32, memory: Memory) -> Builder {
        Builder {
            base: first_extra,
            extra_materials: Vec::new(),
            extra_textures: Vec::new(),
            texture_base: first_texture,
            cache: HashMap::new(),
            mtl_ids: HashMap::new(),
            diagnostics: Diagnostics::default(),
            memory,
            isosurfaces: Vec::new(),
        }
    }

    /// What the meshes placed so far took.
    pub(crate) fn stats(&self) -> MeshStats {
        let mut s = MeshStats::default();
        for (asset, m) in self.cache.values() {
            s.meshes += 1;
            s.unique_triangles += m.triangle_count();
            s.bvh_build_time += m.build_time();
            s.load_time += asset.load_time + m.build_time();
            s.memory_bytes += m.memory();
        }
        s
    }

    fn error(&mut self, o: &Object, code: &'static str, msg: String, label: &str, help: &str) {
        let mut d = Diagnostic::error(code, o.span, msg).with_label(label);
        if !help.is_empty() {
            d = d.with_help(help);
        }
        self.diagnostics.push(d);
    }

    /// Prepares one object (and its CSG children); `None` after recording an error.
    pub(crate) fn object(&mut self, o: &Object, inherited: MaterialId) -> Option<Primitive> {
        let material = o.material.unwrap_or(inherited);
        if !self.invertible(o) {
            return None;
        }
        let geom = self.geom(o, material)?;
        let t = &o.transform.affine();
        Some(match o.motion.as_deref() {
            Some(m) => Primitive::moving(geom, *t, *m, material),
            None => Primitive::new(geom, *t, material),
        })
    }

    /// The compact ball [`Builder::object`]'s primitive for `o` would become in the world
    /// (`Ball::of`): a valid sphere with no motion and either no transform, or its centre at
    /// its origin and a (finite) translation, straight into the world's storage without the
    /// primitive. `None` for every other object (nothing recorded).
    ///
    /// Only what keeps every hit bit for bit is folded: a translated ball computes its hits as
    /// the primitive does (in object space), so a uniform scale, a translated sphere with its
    /// own centre elsewhere, or any motion stays a primitive (docs/language.md §12).
    pub(crate) fn ball(&self, o: &Object, inherited: MaterialId, object: u32) -> Option<Ball> {
        let Shape::Sphere { center, radius } = o.shape else {
            return None;
        };
        if o.motion.is_some() || shapes::check(&o.shape).is_err() {
            return None;
        }
        let material = o.material.unwrap_or(inherited);
        if o.transform.is_identity() {
            return Some(Ball::plain(center, radius, material, object));
        }
        match o.transform {
            // A non-finite offset is left to `object`, which reports it.
            Transform::Translation(offset) if offset.is_finite() && is_origin(center) => {
                Ball::translated(offset, radius, material, object)
            }
            _ => None,
        }
    }

    /// Records what [`Builder::object`] would about `o`, in the same order, but keeps nothing:
    /// a single shape is checked, not made into a primitive (its bounds, inverse transform)
    /// only to be dropped, as `rtc check` of a million spheres did.
    pub(crate) fn check(&mut self, o: &Object, inherited: MaterialId) {
        // An isosurface is prepared too: the note of an estimated gradient bound comes from it.
        if matches!(
            o.shape,
            Shape::Mesh { .. } | Shape::Csg { .. } | Shape::Isosurface { .. }
        ) {
            drop(self.object(o, inherited));
            return;
        }
        if !self.invertible(o) {
            return;
        }
        if let Err(flaw) = shapes::check(&o.shape) {
            self.diagnostics.push(flaw.diagnostic(o.span));
        }
    }

    /// Whether `o`'s transform can be inverted; if not, the error is recorded.
    fn invertible(&mut self, o: &Object) -> bool {
        // The identity (most objects of large scenes) passes the test below; skip its roots.
        if o.transform.is_identity() {
            return true;
        }
        let t = &o.transform.affine();
        let det = t.matrix3.determinant();
        let scale = t
            .matrix3
            .x_axis
            .norm()
            .max(t.matrix3.y_axis.norm())
            .max(t.matrix3.z_axis.norm());
        if !(det.is_finite() && t.translation.is_finite())
            || det.abs() <= 1e-12 * scale * scale * scale
        {
            self.error(
                o,
                "rtc::geometry::singular_transform",
                format!(
                    "the transform of this {} cannot be inverted",
                    o.shape.kind_name()
                ),
                "this object is flattened to zero thickness (or has a non-finite transform)",
                "give every scale factor a non-zero value",
            );
            return false;
        }
        true
    }

    fn geom(&mut self, o: &Object, material: MaterialId) -> Option<Geom> {
        let g = match &o.shape {
            Shape::Mesh {
                source,
                smooth,
                use_mtl,
            } => {
                let (asset, data) = self.mesh(o, source, *smooth)?;
                let mtl = (*use_mtl && !asset.materials.is_empty()).then(|| self.mtl(o, &asset));
                let colors = *use_mtl && data.has_colors();
                Geom::Mesh(MeshRef { data, mtl, colors })
            }
            Shape::Csg { op, children } => {
                let mut nodes = Vec::with_capacity(children.len());
                let mut ok = true;
                for c in children {
                    match self.object(c, material) {
                        Some(_) if !shapes::encloses_volume(&c.shape, &closed_mesh) => {
                            ok = false;
                            let what = match &c.shape {
                                Shape::Mesh { source, .. } => {
                                    format!("{} is not closed", source.describe())
                                }
                                Shape::Cylinder { .. }
                                | Shape::Cone { .. }
                                | Shape::Isosurface { .. } => {
                                    format!("this {} is open", c.shape.kind_name())
                                }
                                other => {
                                    format!("a {} is a surface, not a solid", other.kind_name())
                                }
                            };
                            self.diagnostics.push(
                                Diagnostic::error(
                                    "rtc::csg::open_operand",
                                    c.span,
                                    "CSG needs closed solids",
                                )
                                .with_label(what)
                                .with_secondary(o.span, "in this CSG operation")
                                .with_help(match &c.shape {
                                    Shape::Cylinder { .. } | Shape::Cone { .. } => "set `capped: true`",
                                    Shape::Isosurface { .. } => "leave out `open: true`: the container's walls close it",
                                    Shape::Mesh { .. } => "use a watertight mesh (every edge shared by two faces)",
                                    _ => "use a closed solid such as a box, sphere or capped cylinder",
                                }),
                            );
                        }
                        Some(n) => nodes.push(n),
                        None => ok = false,
                    }
                }
                if let Err(flaw) = shapes::check(&o.shape) {
                    self.diagnostics.push(flaw.diagnostic(o.span));
                    return None;
                }
                if !ok {
                    return None;
                }
                Geom::Csg {
                    op: *op,
                    children: nodes,
                }
            }
            leaf_shape => match shapes::leaf(leaf_shape) {
                Ok(l) => {
                    if let Leaf::Isosurface(iso) = &l {
                        let watch = iso.watch();
                        if let Some(note) = watch.note(o.span) {
                            self.diagnostics.push(note);
                        }
                        self.isosurfaces.push((o.span, watch));
                    }
                    Geom::Leaf(l)
                }
                Err(flaw) => {
                    self.diagnostics.push(flaw.diagnostic(o.span));
                    return None;
                }
            },
        };
        Some(g)
    }

    fn mesh(
        &mut self,
        o: &Object,
        source: &MeshSource,
        smooth: bool,
    ) -> Option<(Arc<MeshAsset>, Arc<Mesh>)> {
        let key = (MeshKey::of(source), smooth);
        if let Some(m) = self.cache.get(&key) {
            return Some(m.clone());
        }
        match assets::mesh_of(source, smooth) {
            Ok(asset) => {
                // The file's data, charged before its triangles are laid out and its BVH
                // built; the prepared mesh is charged once built.
                if let Err(over) = self.memory.charge(asset_bytes(&asset)) {
                    let what = source.describe();
                    self.diagnostics.push(over.diagnostic(o.span, &what));
                    return None;
                }
                // An OBJ file's warnings are about its material library; a glTF file's about
                // parts rtc does not read (a base colour texture, points and lines).
                let format = source.path().map(assets::indexed::Format::of);
                let (code, label) = match format {
                    Some(assets::indexed::Format::Gltf) => {
                        ("rtc::mesh::partial", "drawn without what is not read")
                    }
                    _ => ("rtc::mesh::missing_mtl", "drawn with the object's material"),
                };
                for w in &asset.warnings {
                    self.diagnostics.push(
                        Diagnostic::warning(
                            code,
                            o.span,
                            format!("{} loads, but {w}", source.describe()),
                        )
                        .with_label(label),
                    );
                }
                let mesh = Arc::new(Mesh::build(MeshParts {
                    vertices: &asset.vertices,
                    triangles: &asset.triangles,
                    normals: &asset.normals,
                    uvs: &asset.uvs,
                    colors: &asset.colors,
                    material_of: &asset.material_of,
                }));
                if let Err(over) = self.memory.charge(mesh.memory() as u64) {
                    let what = format!("the triangles and BVH of {}", source.describe());
                    self.diagnostics.push(over.diagnostic(o.span, &what));
                    return None;
                }
                self.cache.insert(key, (asset.clone(), mesh.clone()));
                Some((asset, mesh))
            }
            Err(e) => {
                self.diagnostics.push(e.diagnostic_of(o.span, source));
                None
            }
        }
    }

    fn mtl(&mut self, o: &Object, data: &MeshAsset) -> Vec<MaterialId> {
        if let Some(ids) = self.mtl_ids.get(&data.path) {
            return ids.clone();
        }
        let mut ids = Vec::with_capacity(data.materials.len());
        for (k, m) in data.materials.iter().enumerate() {
            let mut m = m.clone();
            if let Some(Some(image)) = data.images.get(k) {
                m.texture = self.base_color_image(o, image);
            }
            self.extra_materials.push(m);
            ids.push(MaterialId(
                self.base + self.extra_materials.len() as u32 - 1,
            ));
        }
        self.mtl_ids.insert(data.path.clone(), ids.clone());
        ids
    }
}

impl Builder {
    /// The texture showing a mesh material's base colour image on the mesh's texture
    /// coordinates (bilinear, as glTF viewers read it), or `None` with a warning when the
    /// image cannot be read (a file that is not there, an image inside a glTF file that does
    /// not decode): the material's colour is used.
    fn base_color_image(&mut self, o: &Object, image: &ImageSource) -> Option<TextureId> {
        let texture = match image {
            ImageSource::File(path) => {
                if !path.is_file() {
                    self.missing_image(
                        o,
                        format!(
                            "the mesh's material names the image `{}`, which cannot be read",
                            path.display()
                        ),
                        "put the image beside the mesh file, or fix its name in the material",
                    );
                    return None;
                }
                MeshTexture::File(Texture::Image {
                    path: path.to_path_buf(),
                    mapping: Mapping::Uv,
                    filter: ImageFilter::Bilinear,
                    span: o.span,
                })
            }
            ImageSource::Embedded(e) => {
                // Charged from the header's size before it is decoded, as an image file is.
                if let Err(over) = self.memory.charge(e.decoded_bytes()) {
                    self.diagnostics
                        .push(over.diagnostic(o.span, &format!("the texture {}", e.name)));
                    return None;
                }
                match e.picture() {
                    Ok(p) => MeshTexture::Decoded(p),
                    Err(err) => {
                        self.missing_image(
                            o,
                            format!(
                                "the mesh's material shows {}, which cannot be decoded: {}",
                                e.name, err.message
                            ),
                            "export the file again with its textures as PNG or JPEG images",
                        );
                        return None;
                    }
                }
            }
        };
        self.extra_textures.push(texture);
        Some(TextureId(
            self.texture_base + self.extra_textures.len() as u32 - 1,
        ))
    }

    fn missing_image(&mut self, o: &Object, message: String, help: &str) {
        self.diagnostics.push(
            Diagnostic::warning("rtc::mesh::missing_image", o.span, message)
                .with_label("drawn with the material's colour")
                .with_help(help),
        );
    }
}

/// A texture a mesh's own material adds: an image file, or an image from inside the mesh
/// file, decoded already (through [`assets::EmbeddedImage`]).
#[derive(Clone, Debug)]
pub(crate) enum MeshTexture {
    /// An image file, loaded as the scene's own textures are.
    File(Texture),
    /// A decoded image, shown on the mesh's texture coordinates, read bilinearly.
    Decoded(Arc<assets::Picture>),
}

/// Which loaded mesh an object uses: its file, or the inline value (by address: the scene
/// holds every inline mesh while it is prepared, so an address names one value).
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
enum MeshKey {
    File(PathBuf),
    Inline(usize),
}

impl MeshKey {
    fn of(source: &MeshSource) -> MeshKey {
        match source {
            MeshSource::File(path) => MeshKey::File(path.clone()),
            MeshSource::Inline(m) => MeshKey::Inline(Arc::as_ptr(m) as usize),
        }
    }
}

/// Whether the mesh is a closed surface (through the asset cache).
fn closed_mesh(source: &MeshSource, smooth: bool) -> bool {
    mesh_bounds(source, smooth).is_some_and(|(_, closed)| closed)
}

/// The bounds of a mesh in its own coordinates and whether it is a closed surface (a
/// solid to the enclosure lints); `None` when it does not load.
pub(crate) fn mesh_bounds(
    source: &MeshSource,
    smooth: bool,
) -> Option<(crate::geometry::aabb::Aabb, bool)> {
    let m = assets::mesh_of(source, smooth).ok()?;
    Some((
        crate::geometry::aabb::Aabb::new(m.min, m.max),
        m.is_closed(),
    ))
}

/// Whether point `p` (in the file's coordinates) is inside the closed mesh file; false when it
/// does not load or is not closed.
pub(crate) fn inside_mesh(source: &MeshSource, smooth: bool, p: glam::DVec3) -> bool {
    assets::mesh_of(source, smooth).is_ok_and(|m| m.is_closed() && m.contains(p))
}

/// Heap bytes of a mesh file's data as loaded.
fn asset_bytes(a: &MeshAsset) -> u64 {
    (std::mem::size_of_val(a.vertices.as_slice())
        + std::mem::size_of_val(a.triangles.as_slice())
        + std::mem::size_of_val(a.normals.as_slice())
        + std::mem::size_of_val(a.uvs.as_slice())
        + std::mem::size_of_val(a.colors.as_slice())
        + std::mem::size_of_val(a.material_of.as_slice())
        + a.images
            .iter()
            .map(|i| match i {
                Some(ImageSource::Embedded(e)) => e.encoded_len(),
                _ => 0,
            })
            .sum::<usize>()) as u64
}

#[cfg(test)]
mod tests;
