//! The effects set: which costly effects a scene calls for, so the render plan skips the rest.

use std::fmt;

use crate::ir::{LightKind, Object, RenderMode, Sampling, Scene, ShadingModel, Shape};

/// Which effects a scene uses. Each flag gates work in the renderer.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Effects {
    /// Shadow rays are cast.
    pub shadows: bool,
    /// Some material reflects and `max_depth > 0`.
    pub reflection: bool,
    /// Some material transmits and `max_depth > 0`.
    pub refraction: bool,
    /// Some material has a colour texture.
    pub textures: bool,
    /// Some material has a bump map.
    pub bump: bool,
    /// Some light is an area light (soft shadows).
    pub soft_shadows: bool,
    /// More than one sample per pixel.
    pub supersampling: bool,
    /// A thin-lens camera (depth of field).
    pub depth_of_field: bool,
    /// Gooch shading is used somewhere.
    pub gooch: bool,
    /// Hatching is used somewhere.
    pub hatching: bool,
    /// The scene has CSG nodes.
    pub csg: bool,
    /// The scene has meshes.
    pub meshes: bool,
}

impl Effects {
    /// Computes the effects a scene calls for.
    pub fn of(scene: &Scene) -> Effects {
        let s = &scene.settings;
        let shaded = s.mode == RenderMode::Shaded;
        let bounces = shaded && s.max_depth > 0;
        let mats = &scene.materials;
        let model_used = |want: fn(&ShadingModel) -> bool| {
            shaded
                && (want(&s.shading) || mats.iter().any(|m| m.shading.as_ref().is_some_and(want)))
        };
        let mut e = Effects {
            shadows: shaded && s.shadows && !scene.lights.is_empty(),
            reflection: bounces && mats.iter().any(|m| m.reflect > 0.0),
            refraction: bounces && mats.iter().any(|m| m.refract > 0.0),
            textures: shaded && mats.iter().any(|m| m.texture.is_some()),
            bump: shaded && mats.iter().any(|m| m.bump.is_some()),
            soft_shadows: false,
            supersampling: match s.sampling {
                Sampling::Grid { factor } => factor > 1,
                Sampling::Adaptive { max, .. } => max > 1,
            },
            depth_of_field: scene.camera.aperture > 0.0,
            gooch: model_used(|m| matches!(m, ShadingModel::Gooch(_))),
            hatching: model_used(|m| matches!(m, ShadingModel::Hatching)),
            csg: false,
            meshes: false,
        };
        e.soft_shadows = e.shadows
            && scene
                .lights
                .iter()
                .any(|l| matches!(l.kind, LightKind::Area { .. }));
        for o in &scene.objects {
            e.visit(o);
        }
        e
    }

    fn visit(&mut self, o: &Object) {
        match &o.shape {
            Shape::Csg { children, .. } => {
                self.csg = true;
                children.iter().for_each(|c| self.visit(c));
            }
            Shape::Mesh { .. } => self.meshes = true,
            _ => {}
        }
    }

    /// The names of the effects in use, in a fixed order.
    pub fn names(&self) -> Vec<&'static str> {
        let all = [
            (self.shadows, "shadows"),
            (self.soft_shadows, "soft shadows"),
            (self.reflection, "reflection"),
            (self.refraction, "refraction"),
            (self.textures, "textures"),
            (self.bump, "bump maps"),
            (self.supersampling, "supersampling"),
            (self.depth_of_field, "depth of field"),
            (self.gooch, "gooch"),
            (self.hatching, "hatching"),
            (self.csg, "csg"),
            (self.meshes, "meshes"),
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
