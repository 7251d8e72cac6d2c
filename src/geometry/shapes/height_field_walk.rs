//! The cells of a height field's grid a ray's projection crosses, in order: a 2-D DDA
//! (Amanatides & Woo) over square blocks of cells, each with the lowest and highest height in
//! it, and inside a block whose height range the ray's meets, over its cells. A ray far above
//! the terrain crosses a 1024² grid in ~128 block steps instead of ~2 000 cell tests.

use glam::DVec2;

/// Cells per block side.
pub(super) const BLOCK: usize = 16;

/// The lowest and highest height of every block of [`BLOCK`]² cells, row by row.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Blocks {
    /// Blocks per row (along x).
    pub(super) cols: usize,
    /// Rows of blocks (along z).
    pub(super) rows: usize,
    /// `(min, max)` of the heights at the block's cells' corners.
    pub(super) range: Vec<(f32, f32)>,
}

impl Blocks {
    /// The blocks of a grid of `nx × nz` points (`h[j·nx + i]`).
    pub(super) fn new(nx: usize, nz: usize, h: &[f32]) -> Blocks {
        let (cells_x, cells_z) = (nx - 1, nz - 1);
        let cols = cells_x.div_ceil(BLOCK);
        let rows = cells_z.div_ceil(BLOCK);
        let mut range = vec![(f32::INFINITY, f32::NEG_INFINITY); cols * rows];
        for bj in 0..rows {
            for bi in 0..cols {
                let mut r = (f32::INFINITY, f32::NEG_INFINITY);
                // A block's cells reach one point past its last cell on each axis.
                for j in bj * BLOCK..=((bj + 1) * BLOCK).min(cells_z) {
                    for &v in &h[j * nx + bi * BLOCK..=j * nx + ((bi + 1) * BLOCK).min(cells_x)] {
                        r = (r.0.min(v), r.1.max(v));
                    }
                }
                range[bj * cols + bi] = r;
            }
        }
        Blocks { cols, rows, range }
    }
}

/// A ray projected on the grid: `p + t·d` in cell units (cell `(i, j)` covers `[i, i+1] ×
/// [j, j+1]`), with its height `y0 + t·dy`.
#[derive(Clone, Copy, Debug)]
pub(super) struct GridRay {
    /// Origin in cell units.
    pub(super) p: DVec2,
    /// Direction in cell units.
    pub(super) d: DVec2,
    /// Height at t = 0.
    pub(super) y0: f64,
    /// Height per unit t.
    pub(super) dy: f64,
}

impl GridRay {
    /// Whether the ray's heights over `[ta, tb]` may reach `[lo, hi]` (widened by rounding).
    #[inline]
    pub(super) fn meets(&self, ta: f64, tb: f64, lo: f64, hi: f64) -> bool {
        let (ya, yb) = (self.y0 + ta * self.dy, self.y0 + tb * self.dy);
        let (y_lo, y_hi) = (ya.min(yb), ya.max(yb));
        let slack = 1e-9 * (1.0 + y_lo.abs().max(y_hi.abs()));
        y_hi + slack >= lo && y_lo - slack <= hi
    }
}

/// Visits the cells of a `cols × rows` grid of unit cells that `p + t·d` crosses for t in
/// `[t0, t1]` (the caller clips it to the grid), in order along the ray: `visit(i, j, ta, tb)`
/// with the cell's own t-interval; it returns `true` to stop.
pub(super) fn walk(
    p: DVec2,
    d: DVec2,
    cols: usize,
    rows: usize,
    t0: f64,
    t1: f64,
    mut visit: impl FnMut(usize, usize, f64, f64) -> bool,
) {
    let ordered = matches!(
        t0.partial_cmp(&t1),
        Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
    );
    if !ordered || cols == 0 || rows == 0 {
        return;
    }
    // The start cell from the point a little into the interval, so a start on a cell border
    // picks the cell the ray goes into. An unbounded interval is a line straight up or down
    // (the caller clips every other to the grid): any t gives its one point.
    let tm = match (t0.is_finite(), t1.is_finite()) {
        (true, true) => t0 + (t1 - t0) * 1e-9,
        (true, false) => t0,
        (false, true) => t1,
        (false, false) => 0.0,
    };
    let start = p + tm * d;
    let cell = |x: f64, n: usize| -> usize {
        if x.is_nan() || x <= 0.0 {
            0
        } else {
            (x.floor() as usize).min(n - 1)
        }
    };
    let (mut i, mut j) = (cell(start.x, cols), cell(start.y, rows));
    // Axis setup: the t of the next border and the t between borders.
    let axis = |k: usize, x: f64, dx: f64| -> (f64, f64) {
        if dx > 0.0 {
            ((k as f64 + 1.0 - x) / dx, 1.0 / dx)
        } else if dx < 0.0 {
            ((k as f64 - x) / dx, -1.0 / dx)
        } else {
            (f64::INFINITY, f64::INFINITY)
        }
    };
    let (mut next_x, step_x) = axis(i, p.x, d.x);
    let (mut next_z, step_z) = axis(j, p.y, d.y);
    let mut ta = t0;
    loop {
        let tb = next_x.min(next_z).min(t1);
        if visit(i, j, ta, tb.max(ta)) || tb >= t1 {
            return;
        }
        ta = tb.max(ta);
        if next_x <= next_z {
            if d.x > 0.0 {
                if i + 1 >= cols {
                    return;
                }
                i += 1;
            } else {
                if i == 0 {
                    return;
                }
                i -= 1;
            }
            next_x += step_x;
        } else {
            if d.y > 0.0 {
                if j + 1 >= rows {
                    return;
                }
                j += 1;
            } else {
                if j == 0 {
                    return;
                }
                j -= 1;
            }
            next_z += step_z;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The walk visits exactly the cells a fine sampling of the segment passes through (away
    /// from corners), in order, with contiguous t-intervals.
    #[test]
    fn the_walk_visits_the_cells_the_segment_crosses() {
        let cases = [
            (DVec2::new(0.3, 0.2), DVec2::new(1.0, 0.37)),
            (DVec2::new(7.9, 4.4), DVec2::new(-0.8, -0.3)),
            (DVec2::new(2.5, 0.1), DVec2::new(0.0, 1.0)),
            (DVec2::new(-1.0, 3.3), DVec2::new(1.0, 0.0)),
        ];
        for (p, d) in cases {
            let (cols, rows) = (8, 5);
            // Clip to the grid by sampling.
            let inside = |t: f64| {
                let q = p + t * d;
                q.x >= 0.0 && q.x <= cols as f64 && q.y >= 0.0 && q.y <= rows as f64
            };
            let ts: Vec<f64> = (-4000..4000)
                .map(|k| f64::from(k) * 0.005)
                .filter(|&t| inside(t))
                .collect();
            let (t0, t1) = (ts[0], *ts.last().unwrap());
            let mut want: Vec<(usize, usize)> = Vec::new();
            for &t in &ts {
                let q = p + t * d;
                let c = (
                    (q.x.floor() as usize).min(cols - 1),
                    (q.y.floor() as usize).min(rows - 1),
                );
                if want.last() != Some(&c) {
                    want.push(c);
                }
            }
            let mut got = Vec::new();
            let mut last_tb = t0;
            walk(p, d, cols, rows, t0, t1, |i, j, ta, tb| {
                assert!((ta - last_tb).abs() < 1e-12 && tb >= ta);
                last_tb = tb;
                got.push((i, j));
                false
            });
            assert_eq!(got, want, "{p} {d}");
        }
    }

    #[test]
    fn blocks_hold_their_cells_corner_heights() {
        let (nx, nz) = (20, 18);
        let h: Vec<f32> = (0..nx * nz).map(|k| ((k * 37) % 101) as f32).collect();
        let b = Blocks::new(nx, nz, &h);
        assert_eq!((b.cols, b.rows), (2, 2));
        let all = |i0: usize, i1: usize, j0: usize, j1: usize| {
            let mut r = (f32::INFINITY, f32::NEG_INFINITY);
            for j in j0..=j1 {
                for i in i0..=i1 {
                    r = (r.0.min(h[j * nx + i]), r.1.max(h[j * nx + i]));
                }
            }
            r
        };
        assert_eq!(b.range[0], all(0, 16, 0, 16));
        assert_eq!(b.range[1], all(16, 19, 0, 16));
        assert_eq!(b.range[3], all(16, 19, 16, 17));
    }
}
