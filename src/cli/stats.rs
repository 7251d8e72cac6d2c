//! `rtc render --stats`: what a render took, in numbers a user can compare between scenes.

use std::time::Duration;

use rtc::ir::{LightKind, LightSampling, Sampling};
use rtc::opt::Prepared;
use rtc::render::film::CUT_WEIGHT_UNIT;
use rtc::render::film::Film;

/// A few lines describing the world, the quality knobs and the rays of a finished render:
/// `load` is the time to read and evaluate the scene, `elapsed` the preparation's and render's
/// together.
pub(crate) fn describe(
    film: &Film,
    prepared: &Prepared,
    load: Duration,
    elapsed: Duration,
) -> String {
    let w = &prepared.stats();
    let s = &film.stats;
    let rays = s.camera_rays + s.secondary_rays + s.shadow_rays;
    let secs = elapsed.as_secs_f64().max(1e-9);
    let mut out = format!(
        "stats: {} objects ({} unbounded), {} meshes, {} triangles ({} with instances)\n\
         stats: scene read and evaluated in {:.3} s, world built in {:.3} s: first ray at {:.3} s\n",
        w.objects,
        w.unbounded,
        w.meshes,
        w.unique_triangles,
        w.instanced_triangles,
        load.as_secs_f64(),
        w.build_time.as_secs_f64(),
        (load + w.build_time).as_secs_f64(),
    );
    if w.meshes > 0 {
        out += &format!(
            "stats: mesh files loaded in {:.3} s (during either step above)\n",
            w.mesh_load_time.as_secs_f64()
        );
    }
    out += &format!(
        "stats: BVH build {:.3} s, geometry ~{:.1} MiB\n\
         stats: {rays} rays = {} camera + {} secondary + {} shadow; {} refined pixels\n\
         stats: render {:.3} s (world build included), {:.2} Mrays/s",
        w.bvh_build_time.as_secs_f64(),
        w.memory_bytes as f64 / (1 << 20) as f64,
        s.camera_rays,
        s.secondary_rays,
        s.shadow_rays,
        s.refined_pixels,
        secs,
        rays as f64 / secs / 1e6,
    );
    out += &format!("\n{}", quality_line(prepared));
    out += &format!("\n{}", cutoff_line(s, prepared.settings().cutoff));
    out
}

/// Every quality knob of the render with its value (docs/convergence.md lists them).
fn quality_line(p: &Prepared) -> String {
    let st = p.settings();
    let sampling = match st.sampling {
        Sampling::Grid { factor } => format!("supersampling {factor}×{factor}"),
        Sampling::Adaptive {
            min,
            max,
            threshold,
        } => format!(
            "supersampling adaptive {min}×{min} → {max}×{max} where neighbours differ > {threshold}"
        ),
    };
    let cells: Vec<String> = p
        .lights()
        .iter()
        .filter(|l| matches!(l.kind, LightKind::Area { .. }))
        .map(|l| l.samples.to_string())
        .collect();
    let lights = if cells.is_empty() {
        "no area lights".to_string()
    } else {
        let how = match st.light_samples {
            LightSampling::PerSample => "each per pixel sample",
            LightSampling::Spread => "spread over the pixel's samples",
        };
        format!("area-light cells {} ({how})", cells.join(", "))
    };
    let lens = if p.camera().aperture > 0.0 {
        "lens: one point per pixel sample"
    } else {
        "no lens"
    };
    format!(
        "stats: quality: {sampling}; {lights}; {lens}; max_depth {}; cutoff {:.3e}",
        st.max_depth, st.cutoff
    )
}

/// What the insignificance cut-off saved and what it may have cost. A cut ray saves itself,
/// its shadow rays (the render's mean per traced ray) and its own bounces (not counted, so the
/// saving is a lower bound). The energy is bounded by the cut rays' weights: what a cut ray
/// would have added to its pixel is its weight times the radiance it would have seen, ≤ 1 in a
/// scene lit at ≤ 1.
fn cutoff_line(s: &rtc::render::Stats, cutoff: f64) -> String {
    if cutoff == 0.0 {
        return "stats: cut-off 0: every secondary ray traced".to_string();
    }
    let traced = (s.camera_rays + s.secondary_rays).max(1);
    let shadow_per_ray = s.shadow_rays as f64 / traced as f64;
    let saved = s.cut_rays as f64 * (1.0 + shadow_per_ray);
    let dropped = s.cut_weight as f64 / CUT_WEIGHT_UNIT / s.camera_rays.max(1) as f64;
    format!(
        "stats: cut-off {cutoff:.3e}: {} secondary rays cut, ≥ {:.0} rays saved with their shadow \
         rays; energy dropped ≤ {dropped:.2e} per camera sample on average (linear, for radiance ≤ 1)",
        s.cut_rays, saved,
    )
}
