//! Where the terminal's cursor is, from the bytes written to it, and the
//! shortest way to move it. The crossterm backend moves the cursor with
//! `ESC[row;colH` (CUP, up to 8 bytes at 80×24) before every run of changed
//! cells. On the row the cursor is already on, `ESC[colG` (CHA, absolute
//! column, 4–5 bytes) or `ESC[nC` (CUF, n columns on, 3–4 bytes) does the
//! same in fewer bytes.
//!
//! The row is known after a CUP: text never leaves it (the explorer writes
//! no control characters and nothing past the right margin). The column is
//! followed only through characters one column wide everywhere (printable
//! ASCII and Braille); after any other, CHA is used, which needs no column.

/// The cursor as far as the bytes written tell (0-based).
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Cursor {
    row: Option<u16>,
    col: Option<u16>,
    /// The first byte of a three-byte UTF-8 character in `U+2xxx`, waiting
    /// for the second to tell whether it is Braille.
    lead_e2: bool,
}

/// Bytes of a decimal number.
fn digits(n: u16) -> usize {
    n.to_string().len()
}

/// Bytes of the shortest move from `from` (row and column, when known) to
/// `(row, col)`, 0-based; 0 when the cursor is there already.
pub fn move_cost(from: (Option<u16>, Option<u16>), (row, col): (u16, u16)) -> usize {
    shortest(from, (row, col)).len()
}

/// The shortest sequence moving the cursor from `from` to `(row, col)`.
fn shortest(from: (Option<u16>, Option<u16>), (row, col): (u16, u16)) -> String {
    let cup = format!("\x1b[{};{}H", row + 1, col + 1);
    if from.0 != Some(row) {
        return cup;
    }
    match from.1 {
        Some(c) if c == col => String::new(),
        Some(c) if c < col && digits(col - c) <= digits(col + 1) => {
            if col - c == 1 {
                "\x1b[C".into()
            } else {
                format!("\x1b[{}C", col - c)
            }
        }
        _ if col == 0 => "\x1b[G".into(),
        _ => format!("\x1b[{}G", col + 1),
    }
}

impl Cursor {
    /// Nothing known (an unreadable sequence, a control character).
    pub fn forget(&mut self) {
        *self = Cursor::default();
    }

    /// The text just written moves the cursor on.
    pub fn printed(&mut self, text: &[u8]) {
        for &b in text {
            if self.lead_e2 {
                self.lead_e2 = false;
                // U+2800..U+28FF is E2 A0..A3 xx.
                let braille = (0xa0..=0xa3).contains(&b);
                self.col = self.col.filter(|_| braille).map(|c| c + 1);
                continue;
            }
            match b {
                0x20..=0x7e => self.col = self.col.map(|c| c + 1),
                0x80..=0xbf => {}
                0xe2 => self.lead_e2 = true,
                0xc0..=0xff => self.col = None,
                _ => self.forget(),
            }
        }
    }

    /// The sequence for a CUP to `(row, col)` (0-based), and the cursor there.
    pub fn goto(&mut self, row: u16, col: u16) -> String {
        let out = shortest((self.row, self.col), (row, col));
        self.row = Some(row);
        self.col = Some(col);
        self.lead_e2 = false;
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shortest_move_along_a_row_and_a_cup_elsewhere() {
        let mut c = Cursor::default();
        assert_eq!(c.goto(9, 44), "\x1b[10;45H");
        c.printed("ab⣿".as_bytes());
        // Three columns on: at 47; 50 is three more.
        assert_eq!(c.goto(9, 50), "\x1b[3C");
        assert_eq!(c.goto(9, 51), "\x1b[C");
        assert_eq!(c.goto(9, 51), "");
        // Backwards: the absolute column.
        assert_eq!(c.goto(9, 40), "\x1b[41G");
        // Another row: a CUP.
        assert_eq!(c.goto(10, 40), "\x1b[11;41H");
        // After a character whose width is not certain, the column is not known.
        c.printed("…".as_bytes());
        assert_eq!(c.goto(10, 45), "\x1b[46G");
        c.forget();
        assert_eq!(c.goto(10, 45), "\x1b[11;46H");
        assert_eq!(move_cost((Some(3), Some(10)), (3, 14)), 4);
        assert_eq!(move_cost((Some(3), None), (3, 0)), 3);
    }

    #[test]
    fn a_character_split_across_writes_is_counted_once() {
        let mut c = Cursor::default();
        c.goto(0, 0);
        let braille = "⣿".as_bytes();
        c.printed(&braille[..1]);
        c.printed(&braille[1..]);
        assert_eq!(c.goto(0, 3), "\x1b[2C");
    }
}
