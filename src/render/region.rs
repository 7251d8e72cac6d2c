//! Regions: a sub-rectangle of the image rendered alone (`rtc accuracy --region`). Each pixel
//! keeps its full-image coordinates, so its camera ray and random numbers are the full
//! render's; the film holds only the rectangle.

use crate::diag::{Diagnostic, Severity};

/// A sub-rectangle of a `full_width × full_height` image, in pixels from the top left.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Region {
    /// The left column.
    pub x: u32,
    /// The top row.
    pub y: u32,
    /// Columns.
    pub width: u32,
    /// Rows.
    pub height: u32,
}

/// A region is written badly or does not fit the image.
pub const REGION: &str = "rtc::render::region";

impl Region {
    /// Parses `X,Y,W,H` (left column, top row, width, height; in pixels).
    pub fn parse(text: &str) -> Result<Region, Diagnostic> {
        let parts: Vec<Option<u32>> = text.split(',').map(|p| p.trim().parse().ok()).collect();
        match parts.as_slice() {
            [Some(x), Some(y), Some(width), Some(height)] => Ok(Region {
                x: *x,
                y: *y,
                width: *width,
                height: *height,
            }),
            _ => Err(Diagnostic::new(
                Severity::Error,
                REGION,
                None,
                format!("`{text}` is not a region"),
            )
            .with_help("write the region as X,Y,W,H in pixels (left, top, width, height), e.g. `--region 64,32,128,96`")),
        }
    }

    /// Checks that the region is not empty and lies inside a `width × height` image.
    pub(crate) fn check(&self, width: u32, height: u32) -> Result<(), Diagnostic> {
        let inside = |start: u32, len: u32, full: u32| {
            len > 0 && start.checked_add(len).is_some_and(|end| end <= full)
        };
        if inside(self.x, self.width, width) && inside(self.y, self.height, height) {
            return Ok(());
        }
        Err(Diagnostic::new(
            Severity::Error,
            REGION,
            None,
            format!(
                "the region {} does not fit the {width}×{height} image",
                self.text()
            ),
        )
        .with_help(format!(
            "give a non-empty X,Y,W,H with X+W ≤ {width} and Y+H ≤ {height}"
        )))
    }

    /// The region scaled with its image by `scale` per side: the corners are rounded, so
    /// neighbouring regions stay neighbours, and each side keeps at least one pixel within the
    /// scaled `width × height`.
    pub(crate) fn scaled(&self, scale: f64, width: u32, height: u32) -> Region {
        let at = |v: u32, full: u32| ((f64::from(v) * scale).round() as u32).min(full);
        let (x0, y0) = (
            at(self.x, width).min(width.saturating_sub(1)),
            at(self.y, height).min(height.saturating_sub(1)),
        );
        let x1 = at(self.x + self.width, width).max(x0 + 1);
        let y1 = at(self.y + self.height, height).max(y0 + 1);
        Region {
            x: x0,
            y: y0,
            width: x1 - x0,
            height: y1 - y0,
        }
    }

    /// `X,Y,W,H`, as it is written.
    pub fn text(&self) -> String {
        format!("{},{},{},{}", self.x, self.y, self.width, self.height)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_checks_and_scales() {
        let r = Region::parse("10, 20,30,40").unwrap();
        assert_eq!(
            r,
            Region {
                x: 10,
                y: 20,
                width: 30,
                height: 40
            }
        );
        assert_eq!(r.text(), "10,20,30,40");
        for bad in ["10,20,30", "a,b,c,d", "1,2,3,4,5", "-1,0,2,2"] {
            assert_eq!(Region::parse(bad).unwrap_err().code, REGION, "{bad}");
        }
        assert!(r.check(40, 60).is_ok());
        assert!(r.check(39, 60).is_err());
        assert!(r.check(40, 59).is_err());
        assert!(Region::parse("0,0,0,4").unwrap().check(8, 8).is_err());
        assert!(
            Region::parse("4294967295,0,1,1")
                .unwrap()
                .check(8, 8)
                .is_err()
        );
        assert_eq!(r.scaled(0.5, 20, 30), Region::parse("5,10,15,20").unwrap());
        // A one-pixel region keeps a pixel at any scale, inside the image.
        let corner = Region::parse("39,59,1,1").unwrap();
        assert_eq!(corner.scaled(0.1, 4, 6), Region::parse("3,5,1,1").unwrap());
    }
}
