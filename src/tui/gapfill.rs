//! A backend wrapper that sends fewer bytes per frame. ratatui sends only
//! the cells that changed, and moves the cursor over every run of unchanged
//! cells between them (3–5 bytes along a row once [`super::short_codes`]
//! has shortened the move). A chart that shifts on a nudge changes every
//! other cell or so, so much of a frame is cursor moves. This wrapper
//! remembers what the screen shows and, where a short run of unchanged
//! cells lies between two changed ones in a row, sends those cells again
//! instead of the move, when that is no longer and needs no change of
//! colour or attribute. A blank cell (a space without
//! attributes) is sent in the foreground colour already set, since that
//! colour does not show on a blank: a blank after a coloured trace then
//! costs no colour change, and a blank that only changed its unseen
//! colour is not sent at all. The cursor, once hidden, is not hidden again
//! at every frame. The screen shows the same.

use ratatui::backend::{Backend, ClearType, WindowSize};
use ratatui::buffer::Cell;
use ratatui::layout::{Position, Size};
use ratatui::text::Span;

use super::cursor::move_cost;

pub struct GapFill<B: Backend> {
    inner: B,
    size: Size,
    /// What the screen shows, row-major; None where it is not known.
    shadow: Vec<Option<Cell>>,
    /// The cursor is hidden (ratatui hides it again at every frame).
    hidden: bool,
}

impl<B: Backend> GapFill<B> {
    pub fn new(inner: B) -> GapFill<B> {
        GapFill {
            inner,
            size: Size::default(),
            shadow: Vec::new(),
            hidden: false,
        }
    }

    pub fn inner_mut(&mut self) -> &mut B {
        &mut self.inner
    }

    /// Forgets the screen (after a resize or a partial clear).
    fn forget(&mut self, size: Size) {
        self.size = size;
        self.shadow = vec![None; size.width as usize * size.height as usize];
    }

    /// The screen is blank (after a clear of all of it).
    fn blanked(&mut self) {
        let size = self.inner.size().unwrap_or(self.size);
        self.size = size;
        self.shadow = vec![Some(Cell::default()); size.width as usize * size.height as usize];
    }

    fn known(&self, x: u16, y: u16) -> Option<&Cell> {
        if x >= self.size.width || y >= self.size.height {
            return None;
        }
        self.shadow[y as usize * self.size.width as usize + x as usize].as_ref()
    }

    /// The unchanged cells from `from` to `to` (exclusive) of row `y`, when
    /// sending them costs no more bytes than a cursor move and they share the
    /// style of `left`, the cell sent just before them.
    fn filler(&self, from: u16, to: u16, y: u16, left: &Cell) -> Option<Vec<(u16, u16, Cell)>> {
        // The writer below moves along a row in few bytes (CUF or CHA).
        let jump = move_cost((Some(y), Some(from)), (y, to));
        let same = |c: &Cell| {
            c.bg == left.bg && c.modifier == left.modifier && (c.fg == left.fg || blank(c))
        };
        let narrow = |c: &Cell| Span::raw(c.symbol()).width() == 1;
        if !narrow(left) {
            return None;
        }
        let mut bytes = 0;
        let mut cells = Vec::new();
        for x in from..to {
            let c = self.known(x, y)?;
            bytes += c.symbol().len();
            if bytes > jump || !same(c) || !narrow(c) {
                return None;
            }
            cells.push((x, y, c.clone()));
        }
        Some(cells)
    }
}

/// A space without attributes: its foreground colour does not show.
fn blank(c: &Cell) -> bool {
    c.symbol() == " " && c.modifier.is_empty()
}

/// Whether two cells show the same: symbol, background and attributes, and
/// the foreground unless both are blanks.
fn looks_same(a: &Cell, b: &Cell) -> bool {
    a.symbol() == b.symbol()
        && a.bg == b.bg
        && a.modifier == b.modifier
        && (a.fg == b.fg || blank(a) && blank(b))
}

impl<B: Backend> Backend for GapFill<B> {
    type Error = B::Error;

    fn draw<'a, I>(&mut self, content: I) -> Result<(), Self::Error>
    where
        I: Iterator<Item = (u16, u16, &'a Cell)>,
    {
        let size = self.inner.size()?;
        if size != self.size {
            self.forget(size);
        }
        let mut out: Vec<(u16, u16, Cell)> = Vec::new();
        for (x, y, cell) in content {
            // A cell that looks as the screen shows it already (a blank
            // whose unseen colour changed) is not sent.
            if self
                .known(x, y)
                .is_some_and(|shown| looks_same(shown, cell))
            {
                continue;
            }
            if let Some((px, py, left)) = out.last()
                && *py == y
                && x > px + 1
                && let Some(cells) = self.filler(px + 1, x, y, left)
            {
                out.extend(cells);
            }
            out.push((x, y, cell.clone()));
        }
        // Blanks keep the colour set before them (the backend keeps the
        // colour across cursor moves within a frame).
        for i in 1..out.len() {
            let (before, rest) = out.split_at_mut(i);
            let (left, cell) = (&before[i - 1].2, &mut rest[0].2);
            if blank(cell) && left.modifier.is_empty() {
                cell.fg = left.fg;
            }
        }
        let width = self.size.width as usize;
        for (x, y, cell) in &out {
            if *x < self.size.width && *y < self.size.height {
                self.shadow[*y as usize * width + *x as usize] = Some(cell.clone());
            }
        }
        self.inner.draw(out.iter().map(|(x, y, c)| (*x, *y, c)))
    }

    fn append_lines(&mut self, n: u16) -> Result<(), Self::Error> {
        self.forget(self.size);
        self.inner.append_lines(n)
    }

    fn hide_cursor(&mut self) -> Result<(), Self::Error> {
        if !self.hidden {
            self.inner.hide_cursor()?;
            self.hidden = true;
        }
        Ok(())
    }

    fn show_cursor(&mut self) -> Result<(), Self::Error> {
        self.hidden = false;
        self.inner.show_cursor()
    }

    fn get_cursor_position(&mut self) -> Result<Position, Self::Error> {
        self.inner.get_cursor_position()
    }

    fn set_cursor_position<P: Into<Position>>(&mut self, position: P) -> Result<(), Self::Error> {
        self.inner.set_cursor_position(position)
    }

    fn clear(&mut self) -> Result<(), Self::Error> {
        self.inner.clear()?;
        self.blanked();
        Ok(())
    }

    fn clear_region(&mut self, clear_type: ClearType) -> Result<(), Self::Error> {
        self.inner.clear_region(clear_type)?;
        if clear_type == ClearType::All {
            self.blanked();
        } else {
            self.forget(self.size);
        }
        Ok(())
    }

    fn size(&self) -> Result<Size, Self::Error> {
        self.inner.size()
    }

    fn window_size(&mut self) -> Result<WindowSize, Self::Error> {
        self.inner.window_size()
    }

    fn flush(&mut self) -> Result<(), Self::Error> {
        self.inner.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ratatui::Terminal;
    use ratatui::backend::{CrosstermBackend, TestBackend};
    use ratatui::style::{Color, Style};
    use std::cell::RefCell;
    use std::rc::Rc;

    /// Two frames: a row of Braille with every other cell changed.
    fn frames(t: &mut Terminal<impl Backend>) {
        for k in 0..2 {
            t.draw(|f| {
                let buf = f.buffer_mut();
                for x in 0..20 {
                    let s = if x % 2 == 0 && k == 1 { "⣿" } else { "⠁" };
                    buf[(x, 1)].set_symbol(s).set_fg(Color::Cyan);
                }
                buf[(30, 1)].set_symbol("x").set_style(Style::new());
                // A blank after the trace that changes with the frame.
                buf[(21 + k as u16, 1)].set_symbol(" ").set_fg(Color::Reset);
                buf[(20 + k as u16, 1)]
                    .set_symbol("⠁")
                    .set_fg(Color::Yellow);
            })
            .unwrap();
        }
    }

    #[test]
    fn the_screen_is_the_same_with_and_without_filling() {
        let mut plain = Terminal::new(TestBackend::new(40, 3)).unwrap();
        let mut filled = Terminal::new(GapFill::new(TestBackend::new(40, 3))).unwrap();
        frames(&mut plain);
        frames(&mut filled);
        // What shows: every symbol, and the colours of all but blanks.
        let shown = |b: &ratatui::buffer::Buffer| -> Vec<(String, Option<Color>, Color)> {
            b.content
                .iter()
                .map(|c| (c.symbol().to_string(), (!blank(c)).then_some(c.fg), c.bg))
                .collect()
        };
        assert_eq!(
            shown(plain.backend().buffer()),
            shown(filled.backend_mut().inner.buffer())
        );
    }

    #[derive(Clone, Default)]
    struct Sink(Rc<RefCell<Vec<u8>>>);
    impl std::io::Write for Sink {
        fn write(&mut self, b: &[u8]) -> std::io::Result<usize> {
            self.0.borrow_mut().extend_from_slice(b);
            Ok(b.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    /// Bytes of the second frame, and its cursor moves.
    fn second_frame(fill: bool) -> (usize, usize) {
        let sink = Sink::default();
        let backend = CrosstermBackend::new(sink.clone());
        let options = ratatui::TerminalOptions {
            viewport: ratatui::Viewport::Fixed(ratatui::layout::Rect::new(0, 0, 40, 3)),
        };
        if fill {
            frames(&mut Terminal::with_options(GapFill::new(backend), options).unwrap());
        } else {
            frames(&mut Terminal::with_options(backend, options).unwrap());
        }
        let all = sink.0.borrow();
        let text = String::from_utf8_lossy(&all);
        // The second frame starts after the first frame's final reset.
        let second = text.rsplit("\x1b[0m").nth(1).unwrap_or_default();
        (second.len(), second.matches('H').count())
    }

    #[test]
    fn a_one_cell_gap_is_sent_instead_of_a_cursor_move() {
        let (plain_bytes, plain_moves) = second_frame(false);
        let (fill_bytes, fill_moves) = second_frame(true);
        // Eleven changed cells, one unchanged between each: eleven moves
        // (one to the start, ten over the gaps) become one.
        assert_eq!(plain_moves, 11, "{plain_moves}");
        assert_eq!(fill_moves, 1, "{fill_moves}");
        assert!(fill_bytes < plain_bytes, "{fill_bytes} vs {plain_bytes}");
    }
}
