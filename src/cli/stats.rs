//! `rtc render --stats`: what a render took, in numbers a user can compare between scenes.

use std::time::Duration;

use rtc::opt::Stats;
use rtc::render::film::Film;

/// A few lines describing the world and the rays of a finished render: `load` is the time to
/// read and evaluate the scene, `elapsed` the preparation's and render's together.
pub fn describe(film: &Film, w: &Stats, load: Duration, elapsed: Duration) -> String {
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
    out
}
