//! The effects set: which costly effects a scene calls for, so the renderer skips the rest.

use std::fmt;

use crate::ir::{
    Camera, Integrator, LightKind, Object, RenderMode, RenderSettings, Sampling, Scene,
    ShadingModel, Shape, Texture,
};

/// Which effects a scene uses. Each flag gates work in the renderer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Effects {
    /// Shadow rays are cast.
    pub(crate) shadows: bool,
    /// Some material reflects and `max_depth > 0`.
    pub(crate) reflection: bool,
    /// Some material transmits and `max_depth > 0`.
    pub(crate) refraction: bool,
    /// Some material has a colour texture.
    pub(crate) textures: bool,
    /// Some material has a bump map.
    pub(crate) bump: bool,
    /// Some light is an area light (soft shadows).
    pub(crate) soft_shadows: bool,
    /// Some light is a spot light (a cone per light sample).
    pub(crate) spot_lights: bool,
    /// Some light is a parallel light.
    pub(crate) parallel_lights: bool,
    /// Some light is a cylinder light.
    pub(crate) cylinder_lights: bool,
    /// Some light fades with distance.
    pub(crate) light_fading: bool,
    /// Some light casts no shadows (while the scene has shadows).
    pub(crate) shadowless_lights: bool,
    /// More than one sample per pixel.
    pub(crate) supersampling: bool,
    /// A thin-lens camera (depth of field).
    pub(crate) depth_of_field: bool,
    /// Gooch shading is used somewhere.
    pub(crate) gooch: bool,
    /// Hatching is used somewhere.
    pub(crate) hatching: bool,
    /// The scene has CSG nodes.
    pub(crate) csg: bool,
    /// The scene has meshes.
    pub(crate) meshes: bool,
    /// The shutter is open and something moves (an object or the camera): rays get times.
    pub motion_blur: bool,
    /// Some reflecting or refracting material is glossy (`gloss > 0`) and rays bounce.
    pub glossy: bool,
    /// Shadow rays pass through refractive objects (`render { glass_shadows: true }`).
    pub glass_shadows: bool,
    /// The lens flare post stage runs (`render { flare: ... }` and some light).
    pub flare: bool,
    /// Some object is hidden from some rays (`.no_shadow()`, `.no_image()`,
    /// `.no_reflection()`): hits on it are skipped, so rays are not traced in packets.
    pub(crate) visibility_flags: bool,
    /// Rays that meet nothing see a procedural sky (`render { sky: <pattern> }`).
    pub sky: bool,
    /// Rays that meet nothing see an image (`render { sky: image(..) }`).
    pub environment_map: bool,
    /// Constant fog along the rays.
    pub fog: bool,
    /// Ground fog along the rays.
    pub ground_fog: bool,
    /// The output has an alpha channel (`render { alpha: true }`).
    pub alpha: bool,
    /// Some reflecting material weighs its mirror by the Fresnel reflectance (`fresnel`).
    pub fresnel: bool,
    /// Some refracting material absorbs light inside it (`absorption`).
    pub absorption: bool,
    /// Some refracting material tints the light through it by its colour (`filter > 0`).
    pub filtered_transmission: bool,
    /// Some material's highlight takes its colour (`metallic > 0`).
    pub metallic: bool,
    /// Some material's diffuse falloff is not Lambert's (`brilliance ≠ 1`).
    pub brilliance: bool,
    /// Some material emits light (`emission`).
    pub emission: bool,
    /// Some reflecting and refracting material conserves energy (`conserve_energy`).
    pub conserve_energy: bool,
    /// Light bounces between surfaces: the path tracer (`render { integrator: path }`).
    pub global_illumination: bool,
}

/// What a scene holds that costs time to render, before its settings decide what is used.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(crate) struct Content {
    reflective: bool,
    refractive: bool,
    textured: bool,
    bumped: bool,
    area_lights: bool,
    /// Some light is a spot light.
    spot_lights: bool,
    /// Some light is a parallel light.
    parallel_lights: bool,
    /// Some light is a cylinder light.
    cylinder_lights: bool,
    /// Some object is hidden from some kind of ray.
    hidden_objects: bool,
    /// Some light fades with distance.
    fading_lights: bool,
    /// Some light casts no shadows.
    shadowless_lights: bool,
    lights: bool,
    gooch_material: bool,
    hatching_material: bool,
    csg: bool,
    meshes: bool,
    moving: bool,
    glossy: bool,
    /// The scene's sky is an image (an environment map), not a pattern.
    sky_image: bool,
    /// Materials using each finish term (before the settings decide what is used).
    finish: Finish,
}

/// Which finish terms a scene's materials use.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Finish {
    fresnel: bool,
    absorption: bool,
    filtered: bool,
    metallic: bool,
    brilliance: bool,
    emission: bool,
    conserve_energy: bool,
}

impl Finish {
    /// The finish terms `mats` use; a term that cannot change a pixel of its material (Fresnel
    /// without a mirror, absorption or a filter without refraction) is not counted.
    fn of(mats: &[crate::ir::Material]) -> Finish {
        let any = |f: fn(&crate::ir::Material) -> bool| mats.iter().any(f);
        Finish {
            fresnel: any(|m| m.fresnel && m.reflect > 0.0),
            absorption: any(|m| m.refract > 0.0 && m.absorption != glam::DVec3::ZERO),
            // White glass passes `1·1 + 0`: exactly untinted.
            filtered: any(|m| {
                m.refract > 0.0
                    && m.filter > 0.0
                    && (m.color != glam::DVec3::ONE || m.texture.is_some() || m.mix.is_some())
            }),
            metallic: any(|m| m.metallic > 0.0 && m.ks > 0.0),
            brilliance: any(|m| m.brilliance != 1.0 && m.kd > 0.0),
            emission: any(|m| m.emission != glam::DVec3::ZERO),
            conserve_energy: any(|m| m.conserve_energy && m.reflect > 0.0 && m.refract > 0.0),
        }
    }
}

impl Content {
    /// What `scene` holds (its own materials; a mesh's MTL materials are not counted, so they
    /// reflect or refract only where a scene material does).
    fn of(scene: &Scene) -> Content {
        let mut c = Content::without_objects(scene);
        for o in &scene.objects {
            c.visit(o);
        }
        c
    }

    /// What `scene` holds apart from its objects, which [`Content::visit`] then adds one by one
    /// (so a caller that walks the objects anyway needs no pass of its own).
    pub(crate) fn without_objects(scene: &Scene) -> Content {
        let mats = &scene.materials;
        let material_model = |want: fn(&ShadingModel) -> bool| {
            mats.iter().any(|m| m.shading.as_ref().is_some_and(want))
        };
        Content {
            reflective: mats.iter().any(|m| m.reflect > 0.0),
            refractive: mats.iter().any(|m| m.refract > 0.0),
            textured: mats.iter().any(|m| m.texture.is_some() || m.mix.is_some()),
            bumped: mats.iter().any(|m| m.bump.is_some()),
            area_lights: scene
                .lights
                .iter()
                .any(|l| matches!(l.kind, LightKind::Area { .. })),
            spot_lights: scene.lights.iter().any(|l| l.spot.is_some()),
            parallel_lights: scene
                .lights
                .iter()
                .any(|l| matches!(l.kind, LightKind::Parallel { .. })),
            cylinder_lights: scene
                .lights
                .iter()
                .any(|l| matches!(l.kind, LightKind::Cylinder { .. })),
            fading_lights: scene.lights.iter().any(|l| l.fade.is_some()),
            shadowless_lights: scene.lights.iter().any(|l| !l.shadows),
            lights: !scene.lights.is_empty(),
            gooch_material: material_model(|m| matches!(m, ShadingModel::Gooch(_))),
            hatching_material: material_model(|m| matches!(m, ShadingModel::Hatching)),
            csg: false,
            meshes: false,
            hidden_objects: false,
            moving: scene.camera.motion.is_some(),
            glossy: mats
                .iter()
                .any(|m| m.gloss > 0.0 && (m.reflect > 0.0 || m.refract > 0.0)),
            sky_image: scene.settings.sky.is_some_and(|s| {
                matches!(
                    scene.textures.get(s.texture.0 as usize),
                    Some(Texture::Image { .. } | Texture::NormalMap { .. })
                )
            }),
            finish: Finish::of(mats),
        }
    }

    /// Records that meshes' own materials show images (found when the meshes load).
    pub(crate) fn add_mesh_textures(&mut self) {
        self.textured = true;
    }

    /// Adds what the object `o` (a top-level object or a CSG operand) holds.
    pub(crate) fn visit(&mut self, o: &Object) {
        self.moving |= o.motion.as_ref().is_some_and(|m| !m.is_still());
        self.hidden_objects |= !o.visibility.is_all();
        match &o.shape {
            Shape::Csg { children, .. } => {
                self.csg = true;
                children.iter().for_each(|c| self.visit(c));
            }
            Shape::Mesh { .. } => self.meshes = true,
            _ => {}
        }
    }
}

impl Effects {
    /// Computes the effects a scene calls for.
    pub fn of(scene: &Scene) -> Effects {
        Effects::new(&Content::of(scene), &scene.settings, &scene.camera)
    }

    /// The effects of a scene holding `content`, rendered with `settings` through `camera`.
    pub(crate) fn new(content: &Content, s: &RenderSettings, camera: &Camera) -> Effects {
        let shaded = s.mode == RenderMode::Shaded;
        let path = match s.integrator {
            Integrator::Path(p) if shaded => Some(p),
            _ => None,
        };
        // The path tracer's bounces take the place of Whitted's `max_depth`.
        let bounces = shaded && path.map_or(s.max_depth > 0, |p| p.bounces > 0);
        let model_used = |want: fn(&ShadingModel) -> bool, in_material: bool| {
            shaded && (want(&s.shading) || in_material)
        };
        let shadows = shaded && s.shadows && content.lights;
        Effects {
            shadows,
            reflection: bounces && content.reflective,
            refraction: bounces && content.refractive,
            textures: shaded && content.textured,
            bump: shaded && content.bumped,
            soft_shadows: shadows && content.area_lights,
            spot_lights: shaded && content.spot_lights,
            parallel_lights: shaded && content.parallel_lights,
            cylinder_lights: shaded && content.cylinder_lights,
            light_fading: shaded && content.fading_lights,
            shadowless_lights: shadows && content.shadowless_lights,
            supersampling: match s.sampling {
                Sampling::Grid { factor } => factor > 1,
                Sampling::Adaptive { max, .. } => max > 1,
            },
            depth_of_field: camera.aperture > 0.0,
            gooch: model_used(
                |m| matches!(m, ShadingModel::Gooch(_)),
                content.gooch_material,
            ),
            hatching: model_used(
                |m| matches!(m, ShadingModel::Hatching),
                content.hatching_material,
            ),
            csg: content.csg,
            meshes: content.meshes,
            motion_blur: content.moving && camera.shutter.is_some_and(|s| s.is_open()),
            glossy: bounces && content.glossy,
            glass_shadows: shadows && s.glass_shadows && content.refractive,
            flare: shaded && s.flare.is_some() && content.lights,
            visibility_flags: content.hidden_objects,
            sky: shaded && s.sky.is_some() && !content.sky_image,
            environment_map: shaded && s.sky.is_some() && content.sky_image,
            fog: shaded && s.fog.is_some_and(|f| f.ground.is_none()),
            ground_fog: shaded && s.fog.is_some_and(|f| f.ground.is_some()),
            alpha: shaded && s.alpha,
            fresnel: bounces && content.reflective && content.finish.fresnel,
            absorption: bounces && content.refractive && content.finish.absorption,
            filtered_transmission: bounces && content.refractive && content.finish.filtered,
            metallic: shaded && content.lights && content.finish.metallic,
            brilliance: shaded && content.lights && content.finish.brilliance,
            emission: shaded && content.finish.emission,
            conserve_energy: bounces && content.finish.conserve_energy,
            global_illumination: path.is_some(),
        }
    }

    /// The names of the effects in use, in a fixed order.
    pub(crate) fn names(&self) -> Vec<&'static str> {
        let all = [
            (self.shadows, "shadows"),
            (self.soft_shadows, "soft shadows"),
            (self.spot_lights, "spot lights"),
            (self.parallel_lights, "parallel lights"),
            (self.cylinder_lights, "cylinder lights"),
            (self.light_fading, "light fading"),
            (self.shadowless_lights, "shadowless lights"),
            (self.reflection, "reflection"),
            (self.refraction, "refraction"),
            (self.textures, "textures"),
            (self.bump, "bump maps"),
            (self.supersampling, "supersampling"),
            (self.depth_of_field, "depth of field"),
            (self.motion_blur, "motion blur"),
            (self.gooch, "gooch"),
            (self.hatching, "hatching"),
            (self.csg, "csg"),
            (self.meshes, "meshes"),
            (self.glossy, "glossy"),
            (self.glass_shadows, "light through glass"),
            (self.flare, "lens flare"),
            (self.visibility_flags, "visibility flags"),
            (self.sky, "sky"),
            (self.environment_map, "environment map"),
            (self.fog, "fog"),
            (self.ground_fog, "ground fog"),
            (self.alpha, "alpha"),
            (self.fresnel, "fresnel"),
            (self.absorption, "absorption"),
            (self.filtered_transmission, "filtered transmission"),
            (self.metallic, "metallic"),
            (self.brilliance, "brilliance"),
            (self.emission, "emission"),
            (self.conserve_energy, "conserve energy"),
            (self.global_illumination, "global illumination"),
        ];
        all.iter().filter(|(on, _)| *on).map(|(_, n)| *n).collect()
    }
}

impl fmt::Display for Effects {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let names = self.names();
        if names.is_empty() {
            f.write_str("none")
        } else {
            f.write_str(&names.join(", "))
        }
    }
}
