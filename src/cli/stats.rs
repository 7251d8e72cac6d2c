//! `rtc render --stats`: what a render took, in numbers a user can compare between scenes.

use std::time::Duration;

use rtc::render::film::Film;

/// A few lines describing the world and the rays of a finished render.
pub fn describe(film: &Film, elapsed: Duration) -> String {
    let s = &film.stats;
    let w = &film.world;
    let rays = s.camera_rays + s.secondary_rays + s.shadow_rays;
    let secs = elapsed.as_secs_f64().max(1e-9);
    format!(
        "stats: {} objects ({} unbounded), {} meshes, {} triangles ({} with instances)\n\
         stats: world build {:.3} s (BVH {:.3} s), ~{:.1} MiB\n\
         stats: {rays} rays = {} camera + {} secondary + {} shadow; {} refined pixels\n\
         stats: render {:.3} s (world build included), {:.2} Mrays/s",
        w.objects,
        w.unbounded,
        w.meshes,
        w.unique_triangles,
        w.instanced_triangles,
        w.build_time.as_secs_f64(),
        w.bvh_build_time.as_secs_f64(),
        w.memory_bytes as f64 / (1 << 20) as f64,
        s.camera_rays,
        s.secondary_rays,
        s.shadow_rays,
        s.refined_pixels,
        secs,
        rays as f64 / secs / 1e6,
    )
}
