//! [`super::phong::shade`] of a packet of surface points ([`crate::lanes`]): the
//! light directions, shadow rays, occlusion tests and sums of every point of the packet at
//! once, for point lights without glass shadows. Each lane gets `shade`'s operations in
//! `shade`'s order, so its colour is the same to the bit.
//!
//! Why: a pixel's 4×4 samples shaded one by one spent most of their instructions moving single
//! numbers in and out of `DVec3`s and waiting on one square root or division after another;
//! in lanes the compiler pairs them (`sqrtpd`, `divpd`) and the bookkeeping is shared.

use glam::DVec3;

use super::Surface;
use crate::geometry::lanes::cull::{Among, Bundle};
use crate::ir::{AmbientConvention, LightKind};
use crate::lanes::{self, Lanes, Mask, V3, WIDTH};
use crate::opt::Prepared;
use crate::render::context::Ctx;
use crate::render::offset::SpawnLanes;

/// The surface points of a packet: [`Surface`] lane by lane, with the Phong coefficients of
/// each point's material.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct SurfaceLanes {
    /// The lanes that hold a point.
    pub(crate) live: Mask,
    /// Hit points.
    pub(crate) p: V3,
    /// Where shadow rays leave.
    pub(crate) spawn: SpawnLanes,
    /// Unit normals facing the incoming rays (after any bump map).
    pub(crate) n: V3,
    /// Unit vectors towards the viewer.
    pub(crate) v: V3,
    /// Base colours.
    pub(crate) color: V3,
    /// Ambient coefficients.
    pub(crate) ka: Lanes,
    /// Diffuse coefficients.
    pub(crate) kd: Lanes,
    /// Specular coefficients.
    pub(crate) ks: Lanes,
    /// Phong exponents.
    pub(crate) shininess: Lanes,
    /// Shutter fractions of the rays that hit (shadow rays see moving objects then).
    pub(crate) time: Lanes,
}

impl SurfaceLanes {
    /// Sets lane `i` to `s` (and marks it live).
    #[inline(always)]
    pub(crate) fn set(&mut self, i: usize, s: &Surface<'_>) {
        self.live |= 1 << i;
        self.p.set(i, s.p);
        self.spawn.set(i, &s.spawn);
        self.n.set(i, s.n);
        self.v.set(i, s.v);
        self.color.set(i, s.color);
        self.set_material(i, s.mat);
        self.time[i] = s.time;
    }

    /// Sets lane `i`'s coefficients to `m`'s.
    #[inline(always)]
    fn set_material(&mut self, i: usize, m: &crate::ir::Material) {
        (self.ka[i], self.kd[i], self.ks[i], self.shininess[i]) = (m.ka, m.kd, m.ks, m.n);
    }
}

/// Whether [`shade`] can shade this scene's points: every light is a plain point light (no
/// cone, no fading, casting shadows).
pub(crate) fn applies(scene: &Prepared) -> bool {
    scene.lights().iter().all(|l| l.is_plain_point())
}

/// The Phong colours of the live lanes of `s` (other lanes are left zero), counted in
/// `ctx.stats`; only for scenes where [`applies`] holds, without glass shadows.
#[inline(always)]
pub(crate) fn shade(scene: &Prepared, s: &SurfaceLanes, ctx: &mut Ctx) -> V3 {
    let ambient = scene.settings().ambient;
    let shadows = scene.effects().shadows;
    // `Color::ZERO` plus each term, in `shade`'s order.
    let mut c = V3::ZERO;
    let ka_color = s.color.scale(&s.ka);
    if ambient == AmbientConvention::Once {
        c = c.add(&ka_color);
    }
    for light in scene.lights() {
        if ambient == AmbientConvention::PerLight {
            c = c.add(&ka_color.mul(&V3::splat(light.color)));
        }
        let LightKind::Point { position } = light.kind else {
            // `applies` holds: only point lights come here.
            continue;
        };
        let (_, count) = ctx.lights.cells(light.samples);
        // `light_sample` of a point light, the same for each of its cells.
        let lc = V3::splat(light.color / f64::from(count));
        for _ in 0..count {
            let d = s.p.from(position);
            let dist = d.norm();
            let l = V3::select(lanes::gt(&dist, 0.0), &d.div(&dist), &s.n);
            let n_dot_l = s.n.dot(&l);
            // Facing away: neither light nor shadow ray.
            let lit = s.live & lanes::gt(&n_dot_l, 0.0);
            let open = if shadows && lit != 0 {
                ctx.stats.shadow_rays += u64::from(lit.count_ones());
                lit & !blocked(scene, s, position, lit)
            } else {
                lit
            };
            if open == 0 {
                continue;
            }
            // `lit`: (kd·(N·L))·C·Lc + highlight·Lc, the light passing unfiltered (`pass` is
            // exactly one, and x·1 = x).
            let diffuse = s
                .color
                .scale(&lanes::map(|i| s.kd[i] * n_dot_l[i]))
                .mul(&lc);
            let h = highlight(s, &l, &n_dot_l, open);
            let specular = lc.scale(&h);
            c = V3::select(open, &c.add(&diffuse.add(&specular)), &c);
        }
    }
    c
}

/// The lanes of `lit` whose shadow ray towards `position` is blocked (`shade`'s `visible`).
#[inline(always)]
fn blocked(scene: &Prepared, s: &SurfaceLanes, position: DVec3, lit: Mask) -> Mask {
    let (rays, t_max, valid) = s.spawn.ray_to(position);
    // A lane without a ray (the light is its origin) sees the light.
    let cast = lit & valid;
    if cast == 0 {
        return 0;
    }
    let world = scene.world();
    let among = if world.has_loose_spheres() {
        world.among(&Bundle::of_packet(&rays, &t_max, cast))
    } else {
        Among::ALL
    };
    world.occluded_packet(&rays, &s.time, cast, 0.0, &t_max, among)
}

/// `super::highlight` of the lanes of `open` (others 0): `ks·max(0, R·V)^n` with
/// `R = (2·(N·L))·N − L`, libm's `pow` lane by lane.
#[inline(always)]
fn highlight(s: &SurfaceLanes, l: &V3, n_dot_l: &Lanes, open: Mask) -> Lanes {
    let r = s.n.scale(&lanes::map(|i| 2.0 * n_dot_l[i])).sub(l);
    let rv = r.dot(&s.v);
    let mut h = [0.0; WIDTH];
    for i in lanes::each(open) {
        if s.ks[i] != 0.0 && rv[i] > 0.0 {
            h[i] = s.ks[i] * libm::pow(rv[i], s.shininess[i]);
        }
    }
    h
}
