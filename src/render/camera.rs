//! Primary rays: the course camera (COURSE.md §2.4) and a perspective camera with a field of view,
//! both optionally with a thin lens; an orthographic camera (optionally with a lens) and the
//! panoramas (`super::panorama`).

use crate::num::Norm;
use glam::DVec3;

use crate::geometry::Ray;
use crate::geometry::lanes::RayLanes;
use crate::ir::{self, Projection};
use crate::lanes::{self, Lanes, V3, WIDTH};

use super::panorama::Panorama;

/// A camera ready to generate rays for continuous image coordinates.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    eye: DVec3,
    /// Image-plane point at image coordinate (0, 0) (the bottom-left corner).
    origin: DVec3,
    /// Image-plane step per pixel to the right.
    right: DVec3,
    /// Image-plane step per pixel upwards.
    up: DVec3,
    /// Unit vectors spanning the lens, and the lens radius.
    lens_u: DVec3,
    lens_v: DVec3,
    aperture: f64,
    /// Unit view direction and the distance of the focal plane along it.
    forward: DVec3,
    focus_distance: f64,
    width: u32,
    height: u32,
    /// How pixels map to rays beyond the pinhole's plane image.
    kind: Kind,
}

/// The projections of a [`Camera`], as its ray function needs them.
#[derive(Clone, Copy, Debug)]
enum Kind {
    /// Rays from the eye through the plane image (course and perspective).
    Planar,
    /// Parallel rays from the plane image through the eye.
    Orthographic,
    /// A panorama: rays from the eye in directions `super::panorama` computes.
    Panorama(Panorama),
}

impl Camera {
    /// The ray generator of a camera the preparation stage validated (`opt::validate::camera`:
    /// an image, a view direction, an `up` across it, a field of view in (0, π)).
    pub fn new(c: &ir::Camera) -> Camera {
        let view = c.center - c.eye;
        let right_dir = view.cross(c.up);
        let (w, h) = (f64::from(c.width), f64::from(c.height));
        let forward = view.unit();
        let r_unit = right_dir.unit();
        let u_unit = r_unit.cross(view).unit();
        let mut kind = Kind::Planar;
        let (center, right, up) = match c.projection {
            Projection::Orthographic { height } => {
                // The plane through the eye, `height` world units tall (POV-Ray's orthographic).
                kind = Kind::Orthographic;
                let pixel = height / h;
                (c.eye, r_unit * pixel, u_unit * pixel)
            }
            Projection::Equirectangular
            | Projection::Fisheye { .. }
            | Projection::Cylindrical { .. } => {
                kind = Kind::Panorama(Panorama::new(c, forward, r_unit, u_unit));
                (c.center, r_unit, u_unit)
            }
            Projection::Course => {
                // |up| is the size of one pixel on the plane through `center` (COURSE.md §2.4).
                let size = c.up.norm();
                (c.center, r_unit * size, u_unit * size)
            }
            Projection::Perspective { fov_y } => {
                // The plane through `center`, sized so the image height spans `fov_y`.
                let pixel = 2.0 * view.norm() * libm::tan(0.5 * fov_y) / h;
                (c.center, r_unit * pixel, u_unit * pixel)
            }
        };
        let origin = center - 0.5 * w * right - 0.5 * h * up;
        let focus_distance = if c.focus_distance > 0.0 {
            c.focus_distance
        } else {
            view.norm()
        };
        Camera {
            eye: c.eye,
            origin,
            right,
            up,
            lens_u: r_unit,
            lens_v: u_unit,
            aperture: c.aperture.max(0.0),
            forward,
            focus_distance,
            width: c.width,
            height: c.height,
            kind,
        }
    }

    /// Whether some pixels have no ray (a fisheye's corners, [`super::panorama::BLIND`]).
    pub(crate) fn has_blind_pixels(&self) -> bool {
        matches!(self.kind, Kind::Panorama(p) if p.is_fisheye())
    }

    /// Whether every ray starts at the eye and passes through a plane image, so the pinhole
    /// packets and [`Camera::project`] apply.
    pub(crate) fn is_planar(&self) -> bool {
        matches!(self.kind, Kind::Planar)
    }

    /// Image width in pixels.
    pub(crate) fn width(&self) -> u32 {
        self.width
    }

    /// Image height in pixels.
    pub(crate) fn height(&self) -> u32 {
        self.height
    }

    /// Where world point `p` appears on the image, in continuous pixel units (x from the left
    /// edge, y from the top edge; a pixel's centre is at +½), through the pinhole (or along the
    /// orthographic camera's rays); `None` when `p` is not in front of the eye, and for the
    /// panoramas.
    pub fn project(&self, p: DVec3) -> Option<(f64, f64)> {
        let d = p - self.eye;
        let along = d.dot(self.forward);
        if along <= 0.0 || matches!(self.kind, Kind::Panorama(_)) {
            return None;
        }
        let on_plane = match self.kind {
            Kind::Orthographic => p - along * self.forward,
            _ => self.eye + d * ((self.origin - self.eye).dot(self.forward) / along),
        };
        let rel = on_plane - self.origin;
        let px = rel.dot(self.right) / self.right.length_squared();
        let py = rel.dot(self.up) / self.up.length_squared();
        Some((px, f64::from(self.height) - py))
    }

    /// The eye point (the pinhole, the centre of a lens).
    pub(crate) fn eye(&self) -> DVec3 {
        self.eye
    }

    /// True when the camera has a lens (depth of field), so rays need lens samples.
    pub(crate) fn has_lens(&self) -> bool {
        self.aperture > 0.0
    }

    /// The ray through pixel column `x`, row `y` (0 = top) at sub-pixel offset `(sx, sy)` ∈ [0,1)²
    /// (`sy` upwards), with `lens` ∈ [0,1)² picking a point on the lens when there is one.
    /// Inlined: returned through memory, the ray was reloaded in wider pieces than it was
    /// stored in, which stalled on store forwarding (a third of `View::average`'s time).
    #[inline]
    pub fn ray(&self, x: u32, y: u32, sx: f64, sy: f64, lens: (f64, f64)) -> Ray {
        let px = f64::from(x) + sx;
        let py = f64::from(self.height - 1 - y) + sy;
        let target = self.origin + px * self.right + py * self.up;
        let (start, dir) = match self.kind {
            Kind::Planar => (self.eye, (target - self.eye).unit()),
            Kind::Orthographic => (target, self.forward),
            Kind::Panorama(p) => {
                let v = f64::from(self.height) - py;
                return Ray::new(self.eye, p.dir(px, v));
            }
        };
        if self.aperture <= 0.0 {
            return Ray::new(start, dir);
        }
        // Thin lens: aim every lens point at where the lens-less ray meets the focal plane.
        let focus = start + dir * (self.focus_distance / dir.dot(self.forward));
        let (a, b) = concentric_disk(lens.0, lens.1);
        let origin = start + self.aperture * (a * self.lens_u + b * self.lens_v);
        Ray::new(origin, (focus - origin).unit())
    }
}

/// The most rays [`Camera::pinhole_rays`] makes in one call.
pub(crate) const PINHOLE_BATCH: usize = 16;

impl Camera {
    /// [`Camera::ray`] of up to [`PINHOLE_BATCH`] samples of pixel (x, y) at sub-pixel
    /// `offsets`, into `out`, for a camera without a lens: bit for bit the same rays, their
    /// square roots and divisions in plain arrays the compiler pairs (`sqrtpd`, `divpd`: the
    /// same correctly rounded results), where one by one they queued on the divider.
    pub(crate) fn pinhole_rays(&self, x: u32, y: u32, offsets: &[(f64, f64)], out: &mut [Ray]) {
        self.pinhole_samples(y, |j| (x, offsets[j]), out);
    }

    /// [`Camera::ray`] of up to [`PINHOLE_BATCH`] samples of row `y`, sample `j` in column
    /// `at(j).0` at sub-pixel offset `at(j).1`, into `out`, for a camera without a lens: bit for
    /// bit the rays of [`Camera::pinhole_rays`] (samples of several pixels in one call).
    fn pinhole_samples(&self, y: u32, at: impl Fn(usize) -> (u32, (f64, f64)), out: &mut [Ray]) {
        debug_assert!(out.len() <= PINHOLE_BATCH);
        let p = self.pinhole_packet(y, at, out.len());
        for (j, r) in out.iter_mut().enumerate().take(PINHOLE_BATCH) {
            *r = Ray::new(self.eye, p.dir.get(j));
        }
    }

    /// [`Camera::pinhole_samples`] as a packet: lane `j < n` holds sample `j`'s ray, bit for
    /// bit (the lanes past `n` hold rays through the image plane's corner).
    #[inline(always)]
    pub(crate) fn pinhole_packet(
        &self,
        y: u32,
        at: impl Fn(usize) -> (u32, (f64, f64)),
        n: usize,
    ) -> RayLanes {
        let row = f64::from(self.height - 1 - y);
        let (mut px, mut py) = ([0.0; WIDTH], [0.0; WIDTH]);
        for j in 0..n.min(WIDTH) {
            let (x, (sx, sy)) = at(j);
            (px[j], py[j]) = (f64::from(x) + sx, row + sy);
        }
        self.pinhole_lanes(&px, &py)
    }

    /// The pinhole rays through the image-plane points `(px, py)` (pixel units): [`Camera::ray`]'s
    /// `(origin + px·right + py·up) − eye` and `Norm::unit`'s `v · (1 / √(v·v))`, lane by lane.
    #[inline(always)]
    fn pinhole_lanes(&self, px: &Lanes, py: &Lanes) -> RayLanes {
        debug_assert!(self.aperture <= 0.0);
        let along =
            |o: f64, r: f64, u: f64, e: f64| lanes::map(|j| ((o + px[j] * r) + py[j] * u) - e);
        let (o, r, u, e) = (self.origin, self.right, self.up, self.eye);
        let v = V3 {
            x: along(o.x, r.x, u.x, e.x),
            y: along(o.y, r.y, u.y, e.y),
            z: along(o.z, r.z, u.z, e.z),
        };
        let vv = v.dot(&v);
        let inv = lanes::map(|j| 1.0 / vv[j].sqrt());
        RayLanes {
            origin: V3::splat(self.eye),
            dir: v.scale(&inv),
        }
    }
}

// A pinhole batch is one packet.
const _: () = assert!(PINHOLE_BATCH == WIDTH);

/// A camera that moves while the shutter is open: its eye and the point it looks at move
/// linearly from their positions at shutter open to those at close.
#[derive(Clone, Debug)]
pub(crate) struct MovingCamera {
    base: ir::Camera,
    motion: ir::CameraMotion,
}

impl MovingCamera {
    /// The moving camera of `c`, `None` when it stands still.
    pub(crate) fn of(c: &ir::Camera) -> Option<MovingCamera> {
        c.motion.map(|motion| MovingCamera {
            base: c.clone(),
            motion,
        })
    }

    /// The camera at shutter fraction `time` (0 = open, 1 = close).
    pub(crate) fn at(&self, time: f64) -> Camera {
        let mut c = self.base.clone();
        c.eye = self.base.eye.lerp(self.motion.eye, time);
        c.center = self.base.center.lerp(self.motion.center, time);
        Camera::new(&c)
    }
}

/// Shirley–Chiu mapping of the unit square onto the unit disk (keeps stratification).
fn concentric_disk(u: f64, v: f64) -> (f64, f64) {
    let (a, b) = (2.0 * u - 1.0, 2.0 * v - 1.0);
    if a == 0.0 && b == 0.0 {
        return (0.0, 0.0);
    }
    let q = std::f64::consts::FRAC_PI_4;
    let (r, phi) = if a.abs() > b.abs() {
        (a, q * (b / a))
    } else {
        (b, 2.0 * q - q * (a / b))
    };
    (r * libm::cos(phi), r * libm::sin(phi))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::Span;

    fn course(eye: DVec3, up: DVec3, w: u32, h: u32) -> ir::Camera {
        ir::Camera {
            eye,
            center: DVec3::new(200.0, 200.0, 0.0),
            up,
            width: w,
            height: h,
            projection: Projection::Course,
            aperture: 0.0,
            focus_distance: 0.0,
            shutter: None,
            motion: None,
            span: Span::default(),
        }
    }

    #[test]
    fn course_default_maps_pixel_centres_to_the_plane() {
        let eye = DVec3::new(200.0, 200.0, 1000.0);
        let cam = Camera::new(&course(eye, DVec3::Y, 400, 400));
        for (x, y) in [(0, 0), (399, 0), (17, 250), (399, 399)] {
            let r = cam.ray(x, y, 0.5, 0.5, (0.5, 0.5));
            let want = DVec3::new(f64::from(x) + 0.5, 399.0 - f64::from(y) + 0.5, 0.0);
            let t = -r.origin.z / r.dir.z;
            assert!((r.at(t) - want).norm() < 1e-9, "{x},{y}: {:?}", r.at(t));
        }
    }

    /// The pinhole packets and batches give [`Camera::ray`]'s rays bit for bit, for samples of
    /// several pixels of a row and for partial packets.
    #[test]
    fn pinhole_packets_are_the_rays_one_by_one() {
        let mut rnd = crate::geometry::testing::test_uniform(41);
        for round in 0..40 {
            let eye = DVec3::new(rnd(), rnd(), rnd()) * 50.0 - 25.0;
            let c = ir::Camera {
                center: DVec3::new(rnd(), rnd(), rnd()) * 10.0,
                projection: Projection::Perspective {
                    fov_y: 0.2 + 2.0 * rnd(),
                },
                ..course(eye, DVec3::new(rnd() - 0.5, 1.0, rnd() - 0.5), 37, 23)
            };
            let cam = Camera::new(&c);
            let y = round % 23;
            let at = |j: usize| ((j as u32 * 5) % 37, ((j as f64 + 0.5) / 16.0, 0.25));
            let n = [WIDTH, 7, 1][round as usize % 3];
            let packet = cam.pinhole_packet(y, at, n);
            let mut batch = [Ray::new(DVec3::ZERO, DVec3::ZERO); PINHOLE_BATCH];
            cam.pinhole_samples(y, at, &mut batch[..n]);
            for (j, b) in batch.iter().enumerate().take(n) {
                let (x, (sx, sy)) = at(j);
                let want = cam.ray(x, y, sx, sy, (0.5, 0.5));
                let bits = |d: DVec3| d.to_array().map(f64::to_bits);
                assert_eq!(bits(packet.dir.get(j)), bits(want.dir), "lane {j}");
                assert_eq!(bits(packet.origin.get(j)), bits(want.origin));
                assert_eq!(bits(b.dir), bits(want.dir));
            }
        }
    }

    #[test]
    fn project_inverts_the_pixel_ray() {
        let eye = DVec3::new(3.0, 2.0, 9.0);
        let c = ir::Camera {
            center: DVec3::new(0.5, 0.0, 0.0),
            projection: Projection::Perspective { fov_y: 0.7 },
            ..course(eye, DVec3::Y, 64, 48)
        };
        let cam = Camera::new(&c);
        for (x, y, sx, sy) in [(0, 0, 0.5, 0.5), (63, 47, 0.1, 0.9), (20, 30, 0.25, 0.75)] {
            let r = cam.ray(x, y, sx, sy, (0.5, 0.5));
            let (px, py) = cam.project(r.at(7.0)).unwrap();
            assert!((px - (f64::from(x) + sx)).abs() < 1e-9, "{px}");
            assert!((py - (f64::from(y) + 1.0 - sy)).abs() < 1e-9, "{py}");
        }
        assert!(cam.project(eye + (eye - c.center)).is_none());
    }

    #[test]
    fn up_length_is_the_pixel_size() {
        let eye = DVec3::new(200.0, 200.0, 1000.0);
        let cam = Camera::new(&course(eye, DVec3::new(0.0, 0.75, 0.0), 800, 400));
        let r = cam.ray(0, 399, 0.0, 0.0, (0.5, 0.5));
        let t = -r.origin.z / r.dir.z;
        let p = r.at(t);
        assert!((p.x - (200.0 - 400.0 * 0.75)).abs() < 1e-9);
        assert!((p.y - (200.0 - 200.0 * 0.75)).abs() < 1e-9);
    }

    #[test]
    fn perspective_spans_the_field_of_view() {
        let mut c = course(DVec3::new(200.0, 200.0, 1000.0), DVec3::Y, 100, 100);
        c.projection = Projection::Perspective {
            fov_y: 90f64.to_radians(),
        };
        let cam = Camera::new(&c);
        let top = cam.ray(50, 0, 0.0, 1.0, (0.5, 0.5));
        assert!((top.dir.angle_between(DVec3::NEG_Z) - 45f64.to_radians()).abs() < 1e-9);
    }

    #[test]
    fn lens_rays_meet_at_the_focal_plane() {
        let mut c = course(DVec3::new(200.0, 200.0, 1000.0), DVec3::Y, 10, 10);
        c.aperture = 20.0;
        c.focus_distance = 500.0;
        let cam = Camera::new(&c);
        let a = cam.ray(3, 4, 0.5, 0.5, (0.1, 0.9));
        let b = cam.ray(3, 4, 0.5, 0.5, (0.8, 0.2));
        assert!(a.origin != b.origin);
        let pa = a.at((500.0 - a.origin.z) / a.dir.z);
        let pb = b.at((500.0 - b.origin.z) / b.dir.z);
        assert!((pa - pb).norm() < 1e-9);
    }

    #[test]
    fn orthographic_rays_are_parallel_and_start_on_the_eye_plane() {
        // Looking down −z from (1, 2, 10): 4 units tall, 80 × 40 pixels of 0.05 units.
        let c = ir::Camera {
            center: DVec3::new(1.0, 2.0, 0.0),
            projection: Projection::Orthographic { height: 2.0 },
            ..course(DVec3::new(1.0, 2.0, 10.0), DVec3::Y, 80, 40)
        };
        let cam = Camera::new(&c);
        for (i, j) in [(0, 0), (79, 39), (13, 27), (40, 20)] {
            let r = cam.ray(i, j, 0.5, 0.5, (0.5, 0.5));
            assert_eq!(r.dir, DVec3::NEG_Z, "({i}, {j})");
            // eye + (i + ½ − w/2)·p·right + (h/2 − j − ½)·p·up, p = height / h.
            let p = 2.0 / 40.0;
            let want = DVec3::new(
                1.0 + (f64::from(i) + 0.5 - 40.0) * p,
                2.0 + (20.0 - f64::from(j) - 0.5) * p,
                10.0,
            );
            assert!(
                (r.origin - want).norm() < 1e-12,
                "({i}, {j}): {:?}",
                r.origin
            );
            let (px, py) = cam.project(r.at(3.0)).unwrap();
            assert!((px - (f64::from(i) + 0.5)).abs() < 1e-9);
            assert!((py - (f64::from(j) + 0.5)).abs() < 1e-9);
        }
        assert!(!cam.is_planar());
    }

    #[test]
    fn orthographic_lens_rays_meet_at_the_focal_plane() {
        let mut c = course(DVec3::new(0.0, 0.0, 10.0), DVec3::Y, 10, 10);
        c.center = DVec3::ZERO;
        c.projection = Projection::Orthographic { height: 3.0 };
        c.aperture = 0.5;
        c.focus_distance = 4.0;
        let cam = Camera::new(&c);
        let a = cam.ray(3, 4, 0.5, 0.5, (0.1, 0.9));
        let b = cam.ray(3, 4, 0.5, 0.5, (0.8, 0.2));
        let pinhole = Camera::new(&ir::Camera {
            aperture: 0.0,
            ..c.clone()
        })
        .ray(3, 4, 0.5, 0.5, (0.5, 0.5));
        let on_plane = |r: Ray| r.at((6.0 - r.origin.z) / r.dir.z);
        assert!(a.origin != b.origin);
        assert!((on_plane(a) - pinhole.at(4.0)).norm() < 1e-9);
        assert!((on_plane(b) - pinhole.at(4.0)).norm() < 1e-9);
    }
}
