//! A pixel grid over a plot's cells: Braille (2×4 dots a cell) or one dot
//! a cell, with the series that last drew through each cell. Shared by the
//! line charts and the drawing of a row of buildings.

use ratatui::layout::Rect;

/// Pixel grid of the plot: Braille (2×4 dots per cell) or one cell per dot.
pub struct Raster {
    pub cols: usize,
    pub rows: usize,
    /// Dots per cell across and down.
    pub dx: usize,
    pub dy: usize,
    pub bits: Vec<u8>,
    /// The last series drawn through each cell.
    pub owner: Vec<Option<usize>>,
    /// Every series drawn through each cell, a bit each (the first 64).
    pub through: Vec<u64>,
    pub x: [f64; 2],
    pub y: [f64; 2],
}

impl Raster {
    pub fn new(plot: Rect, braille: bool, x: [f64; 2], y: [f64; 2]) -> Raster {
        let (dx, dy) = if braille { (2, 4) } else { (1, 1) };
        let n = plot.width as usize * plot.height as usize;
        Raster {
            cols: plot.width as usize,
            rows: plot.height as usize,
            dx,
            dy,
            bits: vec![0; n],
            owner: vec![None; n],
            through: vec![0; n],
            x,
            y,
        }
    }

    pub fn px(&self, x: f64) -> f64 {
        (x - self.x[0]) / (self.x[1] - self.x[0]) * ((self.cols * self.dx) as f64 - 1.0)
    }

    pub fn py(&self, y: f64) -> f64 {
        (self.y[1] - y) / (self.y[1] - self.y[0]) * ((self.rows * self.dy) as f64 - 1.0)
    }

    /// The cell row of a value (for labels and the zero line).
    pub fn row(&self, y: f64) -> usize {
        ((self.py(y).round().max(0.0) as usize) / self.dy).min(self.rows.saturating_sub(1))
    }

    pub fn col(&self, x: f64) -> usize {
        ((self.px(x).round().max(0.0) as usize) / self.dx).min(self.cols.saturating_sub(1))
    }

    pub fn dot(&mut self, px: i64, py: i64, series: usize) {
        let (w, h) = ((self.cols * self.dx) as i64, (self.rows * self.dy) as i64);
        if px < 0 || py < 0 || px >= w || py >= h {
            return;
        }
        let (cx, cy) = (px as usize / self.dx, py as usize / self.dy);
        let i = cy * self.cols + cx;
        let bit = if self.dx == 2 {
            const DOTS: [[u8; 4]; 2] = [[0x01, 0x02, 0x04, 0x40], [0x08, 0x10, 0x20, 0x80]];
            DOTS[px as usize % 2][py as usize % 4]
        } else {
            1
        };
        self.bits[i] |= bit;
        self.owner[i] = Some(series);
        self.through[i] |= 1u64.checked_shl(series as u32).unwrap_or(0);
    }

    pub fn segment(&mut self, a: (f64, f64), b: (f64, f64), series: usize) {
        if !(a.0.is_finite() && a.1.is_finite() && b.0.is_finite() && b.1.is_finite()) {
            return;
        }
        let lim = |v: f64, n: usize| v.clamp(-(n as f64), 2.0 * n as f64);
        let (w, h) = (self.cols * self.dx, self.rows * self.dy);
        let (x0, y0) = (lim(self.px(a.0), w), lim(self.py(a.1), h));
        let (x1, y1) = (lim(self.px(b.0), w), lim(self.py(b.1), h));
        let n = (x1 - x0).abs().max((y1 - y0).abs()).ceil().max(1.0) as usize;
        for k in 0..=n {
            let t = k as f64 / n as f64;
            let x = (x0 + (x1 - x0) * t).round() as i64;
            let y = (y0 + (y1 - y0) * t).round() as i64;
            self.dot(x, y, series);
        }
    }
}
