//! Scene-level checks of the preparation stage, made once before anything is built: ids that
//! point into the material and texture tables, the camera, and the limits of `ir::limits` (a
//! hand-built IR or an API caller may break them; the front ends already keep to them).
//! Codes: `rtc::render::{material, texture, camera, limit}` (the names predate the preparation
//! stage; tests and users rely on them).

use crate::diag::{Diagnostic, Diagnostics, Severity};
use crate::ir::limits::{
    MAX_DEPTH, MAX_GLOSS_SAMPLES, MAX_IMAGE_BYTES, MAX_LIGHT_SAMPLES_PER_AXIS,
    MAX_PIXEL_SAMPLES_PER_AXIS, image_bytes,
};
use crate::ir::{Camera, LightKind, Object, Projection, RenderSettings, Sampling, Scene, Shape};

/// Whether a mix has at least one part and every part is one of the scene's `count` materials.
fn mix_parts_exist(mix: &crate::ir::Mix, count: usize) -> bool {
    let ids: Vec<crate::ir::MaterialId> = match mix {
        crate::ir::Mix::Map { stops, .. } => stops.iter().map(|(_, id)| *id).collect(),
        crate::ir::Mix::Layers(layers) => layers.clone(),
    };
    !ids.is_empty() && ids.iter().all(|id| (id.0 as usize) < count)
}

/// Every scene-level problem of `scene` but its objects' (see [`object`], which callers run on
/// each object first, in the pass that prepares it: a million objects make every pass cost),
/// in a fixed order.
pub(crate) fn scene(scene: &Scene, out: &mut Diagnostics) {
    for m in &scene.materials {
        let bad_texture = |t: Option<crate::ir::TextureId>| {
            t.is_some_and(|t| t.0 as usize >= scene.textures.len())
        };
        let mix_texture = match m.mix.as_deref() {
            Some(crate::ir::Mix::Map { texture, .. }) => Some(*texture),
            _ => None,
        };
        if bad_texture(m.texture)
            || bad_texture(m.bump.map(|b| b.texture))
            || bad_texture(mix_texture)
        {
            out.push(
                Diagnostic::error(
                    "rtc::render::texture",
                    m.span,
                    "this material names a texture that does not exist",
                )
                .with_label("this material"),
            );
        }
    }
    for m in &scene.materials {
        if let Some(mix) = &m.mix
            && !mix_parts_exist(mix, scene.materials.len())
        {
            out.push(
                Diagnostic::error(
                    "rtc::render::material",
                    m.span,
                    "this mixed material has no parts, or names a material that does not exist",
                )
                .with_label("this material"),
            );
        }
    }
    if let Err(d) = camera(&scene.camera) {
        out.push(d);
    }
    if let Err(d) = image_size(&scene.camera, &scene.settings.sampling) {
        out.push(d);
    }
    if let Err(d) = settings(&scene.settings) {
        out.push(d);
    }
    for l in &scene.lights {
        if let LightKind::Area { samples, .. } = l.kind
            && samples.iter().any(|n| *n > MAX_LIGHT_SAMPLES_PER_AXIS)
        {
            out.push(
                Diagnostic::error(
                    "rtc::render::limit",
                    l.span,
                    format!(
                        "more than {MAX_LIGHT_SAMPLES_PER_AXIS} samples along an edge of this area light"
                    ),
                )
                .with_label("this light")
                .with_help(format!(
                    "use at most {MAX_LIGHT_SAMPLES_PER_AXIS} samples per edge"
                )),
            );
        }
    }
}

/// The scene-level problems of the object `o` of `scene`: it (and its CSG operands) may only
/// name materials of the scene.
pub(crate) fn object(scene: &Scene, o: &Object, out: &mut Diagnostics) {
    if let Some(id) = o
        .material
        .filter(|id| id.0 as usize >= scene.materials.len())
    {
        out.push(
            Diagnostic::error(
                "rtc::render::material",
                o.span,
                format!("this object names material #{} which does not exist", id.0),
            )
            .with_label("this object"),
        );
    }
    if let Shape::Csg { children, .. } = &o.shape {
        for c in children {
            object(scene, c, out);
        }
    }
}

/// A camera that can make rays: an image, a view direction, an `up` across it, a field of view.
pub(crate) fn camera(c: &Camera) -> Result<(), Diagnostic> {
    let bad = |what: &str, help: &str| {
        Err(
            Diagnostic::error("rtc::render::camera", c.span, format!("the camera {what}"))
                .with_label("this camera")
                .with_help(help.to_string()),
        )
    };
    if c.width == 0 || c.height == 0 {
        return bad(
            "has an empty image",
            "give a width and height of at least 1 pixel",
        );
    }
    let view = c.center - c.eye;
    let right = view.cross(c.up);
    if !view.is_finite() || view.length_squared() == 0.0 {
        return bad(
            "looks at its own eye point",
            "move `center` away from `eye`",
        );
    }
    if !right.is_finite() || right.length_squared() == 0.0 {
        return bad(
            "has `up` parallel to the view direction",
            "choose an `up` that is not parallel to `center - eye`",
        );
    }
    if let Projection::Perspective { fov_y } = c.projection
        && !(fov_y > 0.0 && fov_y < std::f64::consts::PI)
    {
        return bad(
            "has a field of view outside (0°, 180°)",
            "use a field of view such as 45deg",
        );
    }
    if let Projection::Fisheye { fov } | Projection::Cylindrical { fov } = c.projection
        && !(fov > 0.0 && fov <= std::f64::consts::TAU)
    {
        return bad(
            "has a panorama's angle outside (0°, 360°]",
            "use an angle such as 180deg (a fisheye) or 360deg (a cylinder)",
        );
    }
    if let Projection::Orthographic { height } = c.projection
        && !(height > 0.0 && height.is_finite())
    {
        return bad(
            "has an orthographic view that is not > 0 units tall",
            "give the view a height such as 4 (world units)",
        );
    }
    if c.aperture > 0.0
        && !matches!(
            c.projection,
            Projection::Perspective { .. } | Projection::Course | Projection::Orthographic { .. }
        )
    {
        return bad(
            "has a lens (`aperture > 0`) on a panorama",
            "use `aperture: 0` with a panoramic projection",
        );
    }
    Ok(())
}

/// The image's film and bytes within [`MAX_IMAGE_BYTES`]; the help names the largest image of
/// the same shape that fits.
fn image_size(c: &Camera, sampling: &Sampling) -> Result<(), Diagnostic> {
    let adaptive = matches!(sampling, Sampling::Adaptive { .. });
    let bytes = image_bytes(c.width, c.height, adaptive);
    if bytes <= MAX_IMAGE_BYTES {
        return Ok(());
    }
    // Both sides scaled by the same factor, then the width trimmed to fit exactly.
    let max_pixels = MAX_IMAGE_BYTES / image_bytes(1, 1, adaptive);
    let scale = (max_pixels as f64 / (f64::from(c.width) * f64::from(c.height))).sqrt();
    let side = |n: u32| ((f64::from(n) * scale) as u64).clamp(1, max_pixels);
    let h = side(c.height);
    let w = side(c.width).min(max_pixels / h);
    let gib = |b: u64| b as f64 / f64::from(1u32 << 30);
    let sampling = if adaptive {
        ", with adaptive sampling,"
    } else {
        ""
    };
    Err(Diagnostic::error(
        "rtc::render::limit",
        c.span,
        format!(
            "a {}×{} image{sampling} needs {:.1} GiB, more than the {:.0} GiB rtc allows",
            c.width,
            c.height,
            gib(bytes),
            gib(MAX_IMAGE_BYTES)
        ),
    )
    .with_label("this camera's resolution")
    .with_help(format!(
        "render at most {w}×{h} (the same shape); each pixel takes {} bytes",
        image_bytes(1, 1, adaptive)
    )))
}

/// Checks an area light's samples per edge against `ir::limits` (each in 1..=256).
pub(crate) fn light_samples(samples: [u32; 2]) -> Result<(), Diagnostic> {
    if samples
        .iter()
        .all(|n| (1..=MAX_LIGHT_SAMPLES_PER_AXIS).contains(n))
    {
        return Ok(());
    }
    Err(Diagnostic::new(
        Severity::Error,
        "rtc::render::limit",
        None,
        format!(
            "{}×{} area-light samples: each edge takes 1 to {MAX_LIGHT_SAMPLES_PER_AXIS}",
            samples[0], samples[1]
        ),
    )
    .with_help(format!(
        "use 1 to {MAX_LIGHT_SAMPLES_PER_AXIS} samples per edge"
    )))
}

/// Checks a glossy lobe's rays against `ir::limits` (1..=[`MAX_GLOSS_SAMPLES`]).
pub(crate) fn gloss_samples(n: u32) -> Result<(), Diagnostic> {
    if (1..=MAX_GLOSS_SAMPLES).contains(&n) {
        return Ok(());
    }
    Err(Diagnostic::new(
        Severity::Error,
        "rtc::render::limit",
        None,
        format!("{n} rays per glossy lobe: a lobe takes 1 to {MAX_GLOSS_SAMPLES}"),
    )
    .with_help(format!("use gloss_samples from 1 to {MAX_GLOSS_SAMPLES}")))
}

/// Settings within `ir::limits`: bounces and samples per pixel; a cut-off in [0, 1].
pub(crate) fn settings(s: &RenderSettings) -> Result<(), Diagnostic> {
    let too_big = |what: String, help: String| {
        Err(Diagnostic::new(Severity::Error, "rtc::render::limit", None, what).with_help(help))
    };
    if s.max_depth > MAX_DEPTH {
        return too_big(
            format!(
                "a recursion depth of {} is more than {MAX_DEPTH}",
                s.max_depth
            ),
            format!("use a max_depth of at most {MAX_DEPTH}"),
        );
    }
    let factor = match s.sampling {
        Sampling::Grid { factor } => factor,
        Sampling::Adaptive { min, max, .. } => min.max(max),
    };
    if factor > MAX_PIXEL_SAMPLES_PER_AXIS {
        return too_big(
            format!("{factor} samples per axis is more than {MAX_PIXEL_SAMPLES_PER_AXIS}"),
            format!("use at most {MAX_PIXEL_SAMPLES_PER_AXIS} samples per axis"),
        );
    }
    if let crate::ir::Integrator::Path(p) = s.integrator {
        use crate::ir::limits::{MAX_BOUNCES, MAX_PATH_SAMPLES, MAX_PIXEL_PATHS};
        let paths = p.paths_per_pixel(factor * factor);
        if p.samples == 0 || p.samples > MAX_PATH_SAMPLES || p.bounces > MAX_BOUNCES {
            return too_big(
                format!(
                    "a path tracer of {} paths per camera ray and {} bounces",
                    p.samples, p.bounces
                ),
                format!(
                    "use 1..={MAX_PATH_SAMPLES} paths per camera ray and at most {MAX_BOUNCES} bounces"
                ),
            );
        }
        if paths > u64::from(MAX_PIXEL_PATHS) {
            return too_big(
                format!("{paths} paths per pixel is more than {MAX_PIXEL_PATHS}"),
                "lower the path tracer's samples or the supersampling".to_string(),
            );
        }
    }
    if !(0.0..=1.0).contains(&s.cutoff) {
        return too_big(
            format!(
                "an insignificance cut-off of {} is outside [0, 1]",
                s.cutoff
            ),
            "use a cutoff in [0, 1]; 0 traces every ray".to_string(),
        );
    }
    if let Some(f) = &s.flare {
        let values = [
            f64::from(f.ghosts),
            f.dispersal,
            f.halo,
            f64::from(f.streaks),
            f.threshold,
            f.intensity,
        ];
        for ((name, lo, hi), v) in crate::ir::Flare::RANGES.into_iter().zip(values) {
            if !(lo..=hi).contains(&v) {
                return too_big(
                    format!("the flare's {name} of {v} is outside {lo}..={hi}"),
                    format!("give the flare a {name} in {lo}..={hi}"),
                );
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ir::{Integrator, PathTracing};

    #[test]
    fn the_path_tracer_settings_keep_their_budgets() {
        let path = |samples, bounces, factor| RenderSettings {
            integrator: Integrator::Path(PathTracing {
                samples,
                bounces,
                roulette: 3,
            }),
            sampling: Sampling::Grid { factor },
            ..RenderSettings::language_defaults()
        };
        assert!(settings(&path(16, 16, 4)).is_ok());
        assert!(settings(&path(256, 256, 16)).is_ok());
        for bad in [
            path(0, 16, 1),
            path(5000, 16, 1),
            path(16, 300, 1),
            path(257, 16, 16),
        ] {
            assert_eq!(settings(&bad).unwrap_err().code, "rtc::render::limit");
        }
    }
}
