//! What both course front ends share: number sanity checks, the course camera, course materials,
//! oriented (textured) spheres, asset lookup, and the final assembly of a [`Scene`].

use crate::num::Norm;
use std::path::{Path, PathBuf};

use glam::{DAffine3, DQuat, DVec3};

use crate::diag::{Diagnostic, Diagnostics};
use crate::ir::{
    Camera, Color, Light, Material, Object, Projection, RenderSettings, Scene, Shape, TextureId,
};
use crate::source::Span;

/// Largest magnitude accepted for any number; beyond it f64 rendering math loses all precision.
const MAX_ABS: f64 = 1e12;

/// Reports NaN, infinities and absurd magnitudes; `text` is the number as written.
pub(crate) fn check_number(
    text: &str,
    value: f64,
    span: Span,
    what: &str,
    diags: &mut Diagnostics,
) -> Option<f64> {
    if !value.is_finite() {
        diags.push(
            Diagnostic::error(
                "rtc::compat::not_finite",
                span,
                format!("`{text}` is not a finite number"),
            )
            .with_label(format!("{what} must be a finite number"))
            .with_help("write an ordinary decimal number such as `1.5`"),
        );
        return None;
    }
    if value.abs() > MAX_ABS {
        diags.push(
            Diagnostic::error(
                "rtc::compat::out_of_range",
                span,
                format!("`{text}` is too large"),
            )
            .with_label(format!("{what} must be at most 1e12 in magnitude")),
        );
        return None;
    }
    Some(value)
}

/// Reports a value outside its meaningful range with the value shown.
pub(crate) fn out_of_range(span: Span, text: &str, what: &str, rule: &str) -> Diagnostic {
    Diagnostic::error(
        "rtc::compat::out_of_range",
        span,
        format!("{what} must be {rule}, found `{text}`"),
    )
    .with_label("out of range")
}

/// The course camera (COURSE.md §2.4): image plane through `center`, `|up|` = pixel size.
pub(crate) fn course_camera(
    eye: DVec3,
    center: DVec3,
    up: DVec3,
    size: [u32; 2],
    span: Span,
) -> Camera {
    Camera {
        eye,
        center,
        up,
        width: size[0],
        height: size[1],
        projection: Projection::Course,
        aperture: 0.0,
        focus_distance: (center - eye).norm(),
        shutter: None,
        motion: None,
        span,
    }
}

/// The course's default view for a scene that only gives `Eye`: 400×400 pixels of size 1 on the
/// plane z = 0 centred on (200, 200), looking down −z.
fn default_camera(eye: DVec3, span: Span) -> Camera {
    course_camera(
        eye,
        DVec3::new(200.0, 200.0, 0.0),
        DVec3::Y,
        [400, 400],
        span,
    )
}

/// A course material before it becomes IR: `reflect` is `None` unless the file says it, in which
/// case the course rule "ks doubles as the mirror weight" applies.
#[derive(Clone, Debug)]
pub(crate) struct CourseMaterial {
    /// Base colour.
    pub(crate) color: Color,
    /// Texture replacing the colour.
    pub(crate) texture: Option<TextureId>,
    /// Ambient coefficient.
    pub(crate) ka: f64,
    /// Diffuse coefficient.
    pub(crate) kd: f64,
    /// Specular coefficient.
    pub(crate) ks: f64,
    /// Phong exponent.
    pub(crate) n: f64,
    /// Explicit mirror weight (UOIT, rt2).
    pub(crate) reflect: Option<f64>,
    /// Transmission weight.
    pub(crate) refract: f64,
    /// Index of refraction.
    pub(crate) eta: f64,
    /// Where it was written.
    pub(crate) span: Span,
}

impl CourseMaterial {
    /// The IR material.
    pub(crate) fn to_ir(&self) -> Material {
        Material {
            color: self.color,
            texture: self.texture,
            bump: None,
            ka: self.ka,
            kd: self.kd,
            ks: self.ks,
            n: self.n,
            reflect: self.reflect.unwrap_or(self.ks),
            refract: self.refract,
            eta: self.eta,
            shading: None,
            span: self.span,
            ..Material::default()
        }
    }
}

/// Object-to-world transform of a textured course sphere centred at the origin: first spin by
/// `angle_deg` about +Y (the texture's north pole in object space, see `geometry::ray::equirectangular_uv`),
/// then rotate +Y onto `pole`, then move to `position`. The renderer helper may flip the spin's
/// sign here to match the reference renders; nothing else depends on it.
fn sphere_orientation(position: DVec3, pole: DVec3, angle_deg: f64) -> DAffine3 {
    let spin = DQuat::from_rotation_y(angle_deg.to_radians());
    let tilt = DQuat::from_rotation_arc(DVec3::Y, pole.unit_or(DVec3::Y));
    DAffine3::from_rotation_translation(tilt * spin, position)
}

/// A course sphere: a plain sphere, or (when it has a pole, angle or texture) a unit-placed sphere
/// with [`sphere_orientation`].
pub(crate) fn sphere_object(
    position: DVec3,
    radius: f64,
    orientation: Option<(DVec3, f64)>,
    material: Option<crate::ir::MaterialId>,
    span: Span,
) -> Object {
    match orientation {
        None => Object {
            motion: None,
            shape: Shape::Sphere {
                center: position,
                radius,
            },
            transform: crate::ir::Transform::IDENTITY,
            material,
            span,
            visibility: crate::ir::Visibility::ALL,
        },
        Some((pole, angle)) => Object {
            motion: None,
            shape: Shape::Sphere {
                center: DVec3::ZERO,
                radius,
            },
            transform: sphere_orientation(position, pole, angle).into(),
            material,
            span,
            visibility: crate::ir::Visibility::ALL,
        },
    }
}

/// Finds an asset named in a course file at `scene` (the asset service's one search order), or
/// reports it missing: a `kind` file ("mesh", "texture") named at `span`.
pub(crate) fn find_asset(
    scene: &Path,
    name: &str,
    span: Span,
    kind: &str,
    diags: &mut Diagnostics,
) -> Option<PathBuf> {
    let dir = scene.parent().unwrap_or(Path::new(""));
    match crate::assets::search::find(dir, name) {
        Ok(path) => Some(path),
        Err(missing) => {
            diags.push(missing.diagnostic(span, kind, scene));
            None
        }
    }
}

/// Everything a course file defines, collected before the checks that need the whole file.
#[derive(Debug, Default)]
pub(crate) struct Draft {
    /// `Eye` (YAML) or the `Eye` record (`.in`).
    pub(crate) eye: Option<(DVec3, Span)>,
    /// A full `Camera` block.
    pub(crate) camera: Option<Camera>,
    /// An eye or camera was written (even if it had errors), so "no eye" would be noise.
    pub(crate) camera_written: bool,
    /// Lights in order.
    pub(crate) lights: Vec<Light>,
    /// The scene under construction (materials, textures, objects, settings).
    pub(crate) scene: SceneParts,
}

/// The parts of a [`Scene`] other than the camera and lights.
#[derive(Debug)]
pub(crate) struct SceneParts {
    /// Materials, one per object.
    pub(crate) materials: Vec<Material>,
    /// Textures.
    textures: Vec<crate::ir::Texture>,
    /// Objects.
    pub(crate) objects: Vec<Object>,
    /// Settings.
    pub(crate) settings: RenderSettings,
}

impl Default for SceneParts {
    fn default() -> SceneParts {
        SceneParts {
            materials: Vec::new(),
            textures: Vec::new(),
            objects: Vec::new(),
            settings: RenderSettings::course_defaults(),
        }
    }
}

impl SceneParts {
    /// Adds a material and returns its id.
    pub(crate) fn add_material(&mut self, m: Material) -> crate::ir::MaterialId {
        self.materials.push(m);
        crate::ir::MaterialId((self.materials.len() - 1) as u32)
    }

    /// Adds a texture and returns its id.
    pub(crate) fn add_texture(&mut self, t: crate::ir::Texture) -> TextureId {
        self.textures.push(t);
        TextureId((self.textures.len() - 1) as u32)
    }
}

impl Draft {
    /// Picks the camera (Camera beats Eye, with a warning; neither is an error) and returns the
    /// scene unless an error was reported. `whole` is the span used when no camera exists.
    pub(crate) fn finish(
        self,
        whole: Span,
        missing_help: &str,
        diags: &mut Diagnostics,
    ) -> Option<Scene> {
        let camera = match (self.camera, self.eye) {
            (Some(camera), Some((_, eye_span))) => {
                diags.push(
                    Diagnostic::warning(
                        "rtc::compat::camera_override",
                        eye_span,
                        "`Eye` is ignored because a `Camera` is given",
                    )
                    .with_label("ignored")
                    .with_secondary(camera.span, "this camera is used"),
                );
                Some(camera)
            }
            (Some(camera), None) => Some(camera),
            (None, Some((eye, span))) => Some(default_camera(eye, span)),
            (None, None) if self.camera_written => None,
            (None, None) => {
                diags.push(
                    Diagnostic::error("rtc::compat::no_camera", whole, "the scene has no eye")
                        .with_label("no `Eye` or `Camera` in this file")
                        .with_help(missing_help.to_string()),
                );
                None
            }
        };
        if diags.has_errors() {
            return None;
        }
        let parts = self.scene;
        Some(Scene {
            camera: camera?,
            lights: self.lights,
            materials: parts.materials,
            textures: parts.textures,
            objects: parts.objects,
            settings: parts.settings,
            memory: crate::ir::limits::Memory::default(),
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orientation_maps_the_pole_and_places_the_centre() {
        let pole = DVec3::new(0.0, 1.0, 0.7);
        let t = sphere_orientation(DVec3::new(1.0, 2.0, 3.0), pole, 90.0);
        let north = t.transform_vector3(DVec3::Y);
        assert!((north - pole.unit()).norm() < 1e-12);
        assert!((t.transform_point3(DVec3::ZERO) - DVec3::new(1.0, 2.0, 3.0)).norm() < 1e-12);
    }

    #[test]
    fn spin_turns_about_the_pole_first() {
        // With the pole at +Y, a 90° spin takes object +X to world −Z (right-handed about +Y).
        let t = sphere_orientation(DVec3::ZERO, DVec3::Y, 90.0);
        let x = t.transform_vector3(DVec3::X);
        assert!((x - DVec3::new(0.0, 0.0, -1.0)).norm() < 1e-12);
    }

    #[test]
    fn reflect_defaults_to_ks() {
        let m = CourseMaterial {
            color: DVec3::ONE,
            texture: None,
            ka: 0.2,
            kd: 0.7,
            ks: 0.5,
            n: 64.0,
            reflect: None,
            refract: 0.0,
            eta: 1.0,
            span: Span::default(),
        };
        assert_eq!(m.to_ir().reflect, 0.5);
        let explicit = CourseMaterial {
            reflect: Some(0.9),
            ..m
        };
        assert_eq!(explicit.to_ir().reflect, 0.9);
    }
}
