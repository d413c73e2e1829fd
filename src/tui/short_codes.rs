//! A writer that shortens what the backend writes on its way to the terminal:
//!
//! - colours: the crossterm backend sets both colours at every change in
//!   the 256-colour form (`ESC[38;5;6;49m`, 11 bytes). This writer keeps
//!   track of the colours the terminal has, writes only the one that
//!   changes, and the 16 basic colours in their short codes (`ESC[36m`,
//!   5 bytes: index 0–7 is 30–37, 8–15 is 90–97, the same palette entries),
//!   and the underline colour's reset only when one is set;
//! - cursor moves: a CUP to the row the cursor is on becomes the shortest
//!   move along the row ([`super::cursor`]), and one to where it is, nothing.
//!
//! Every other sequence passes as it is; one it cannot read passes as it
//! is and forgets the colours and the cursor.

use std::io::{self, Write};

use super::cursor::Cursor;

/// Longest escape sequence held back (longer ones pass as they are).
const HOLD: usize = 64;

pub struct ShortCodes<W: Write> {
    out: W,
    /// An escape sequence being read.
    pending: Vec<u8>,
    /// The colours the terminal has (SGR codes), None when not known.
    fg: Option<Vec<u16>>,
    bg: Option<Vec<u16>>,
    /// The underline colour (the backend resets it after every frame).
    underline: Option<Vec<u16>>,
    cursor: Cursor,
}

impl<W: Write> ShortCodes<W> {
    pub fn new(out: W) -> ShortCodes<W> {
        ShortCodes {
            out,
            pending: Vec::new(),
            fg: None,
            bg: None,
            underline: None,
            cursor: Cursor::default(),
        }
    }

    /// Passes the held bytes as they are; a sequence that is not a private
    /// mode (`ESC[?…h`, `ESC[?…l`: the cursor shown, synchronized updates)
    /// may move the cursor.
    fn pass(&mut self) -> io::Result<()> {
        if !self.pending.starts_with(b"\x1b[?") {
            self.cursor.forget();
        }
        self.out.write_all(&self.pending)?;
        self.pending.clear();
        Ok(())
    }

    fn forget_colours(&mut self) {
        (self.fg, self.bg, self.underline) = (None, None, None);
    }

    /// Rewrites the held CUP `ESC [ row ; col H` as the shortest move there.
    fn rewrite_move(&mut self) -> io::Result<()> {
        let params = &self.pending[2..self.pending.len() - 1];
        let place = match parse(params).as_deref() {
            Some(&[r, c]) if r > 0 && c > 0 => Some((r - 1, c - 1)),
            _ => None,
        };
        let Some((row, col)) = place else {
            return self.pass();
        };
        self.pending.clear();
        let text = self.cursor.goto(row, col);
        self.out.write_all(text.as_bytes())
    }

    /// Rewrites the held SGR sequence `ESC [ params m`.
    fn rewrite(&mut self) -> io::Result<()> {
        let params = &self.pending[2..self.pending.len() - 1];
        let Some(codes) = parse(params) else {
            self.forget_colours();
            return self.pass();
        };
        let (mut fg, mut bg, mut underline) = (None, None, None);
        let mut keep: Vec<u16> = Vec::new();
        let mut i = 0;
        while i < codes.len() {
            let c = codes[i];
            let extended = |i: usize| match codes.get(i + 1) {
                Some(5) if i + 2 < codes.len() => Some(3),
                Some(2) if i + 4 < codes.len() => Some(5),
                _ => None,
            };
            match c {
                0 => {
                    keep.push(0);
                    self.fg = Some(vec![39]);
                    self.bg = Some(vec![49]);
                    self.underline = Some(vec![59]);
                    (fg, bg, underline) = (None, None, None);
                }
                30..=37 | 39 | 90..=97 => fg = Some(vec![c]),
                40..=47 | 49 | 100..=107 => bg = Some(vec![c]),
                59 => underline = Some(vec![c]),
                38 | 48 | 58 => {
                    let Some(n) = extended(i) else {
                        self.forget_colours();
                        return self.pass();
                    };
                    let code = short(&codes[i..i + n]);
                    match c {
                        38 => fg = Some(code),
                        48 => bg = Some(code),
                        _ => underline = Some(codes[i..i + n].to_vec()),
                    }
                    i += n;
                    continue;
                }
                _ => keep.push(c),
            }
            i += 1;
        }
        for (new, now) in [
            (fg, &mut self.fg),
            (bg, &mut self.bg),
            (underline, &mut self.underline),
        ] {
            if let Some(code) = new
                && now.as_ref() != Some(&code)
            {
                keep.extend_from_slice(&code);
                *now = Some(code);
            }
        }
        self.pending.clear();
        if keep.is_empty() {
            return Ok(());
        }
        let text: Vec<String> = keep.iter().map(u16::to_string).collect();
        write!(self.out, "\x1b[{}m", text.join(";"))
    }
}

/// The numbers of an SGR sequence (empty means 0); None if any is not one.
fn parse(params: &[u8]) -> Option<Vec<u16>> {
    let text = std::str::from_utf8(params).ok()?;
    if text.is_empty() {
        return Some(vec![0]);
    }
    text.split(';')
        .map(|p| {
            if p.is_empty() {
                Some(0)
            } else {
                p.parse().ok()
            }
        })
        .collect()
}

/// A 256-colour code (`38;5;n` or `48;5;n`) in its short form where the
/// index is one of the 16 basic colours; others as they are.
fn short(code: &[u16]) -> Vec<u16> {
    let base = if code[0] == 38 { 30 } else { 40 };
    match code {
        [_, 5, n] if *n < 8 => vec![base + n],
        [_, 5, n] if *n < 16 => vec![base + 60 + n - 8],
        _ => code.to_vec(),
    }
}

impl<W: Write> ShortCodes<W> {
    /// Plain text: it passes, and moves the cursor on.
    fn text(&mut self, text: &[u8]) -> io::Result<()> {
        self.cursor.printed(text);
        self.out.write_all(text)
    }
}

impl<W: Write> Write for ShortCodes<W> {
    fn write(&mut self, buf: &[u8]) -> io::Result<usize> {
        // Start of the plain text not yet written.
        let mut start = 0;
        for (k, &b) in buf.iter().enumerate() {
            if self.pending.is_empty() {
                if b == 0x1b {
                    self.text(&buf[start..k])?;
                    self.pending.push(b);
                    start = k + 1;
                }
                continue;
            }
            self.pending.push(b);
            start = k + 1;
            let n = self.pending.len();
            if n == 2 && b != b'[' {
                self.pass()?;
            } else if n > 2 && (0x40..=0x7e).contains(&b) {
                match b {
                    b'm' => self.rewrite()?,
                    b'H' => self.rewrite_move()?,
                    _ => self.pass()?,
                }
            } else if n > HOLD {
                self.forget_colours();
                self.pass()?;
            }
        }
        self.text(&buf[start..])?;
        Ok(buf.len())
    }

    fn flush(&mut self) -> io::Result<()> {
        self.out.flush()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const FRAME: &str = "\x1b[3;4H\x1b[38;5;6;49m⢶x\x1b[38;5;6;49my\x1b[38;5;3;49mz\
                         \x1b[39;49m \x1b[1m\x1b[38;2;1;2;3;49mw\x1b[0m\x1b[?25l";
    const SHORT: &str =
        "\x1b[3;4H\x1b[36;49m⢶xy\x1b[33mz\x1b[39m \x1b[1m\x1b[38;2;1;2;3mw\x1b[0m\x1b[?25l";

    fn through(chunks: &[&[u8]]) -> String {
        let mut w = ShortCodes::new(Vec::new());
        for c in chunks {
            w.write_all(c).unwrap();
        }
        String::from_utf8(w.out).unwrap()
    }

    #[test]
    fn colours_are_written_short_and_only_when_they_change() {
        assert_eq!(through(&[FRAME.as_bytes()]), SHORT);
    }

    #[test]
    fn moves_along_the_row_are_short_and_a_move_to_where_it_is_is_dropped() {
        let frame = "\x1b[3;4Hab\x1b[3;8Hc\x1b[3;2Hd\x1b[?25l\x1b[3;3He\x1b[5;1Hf\x1b7\x1b[5;3Hg";
        let short = "\x1b[3;4Hab\x1b[2Cc\x1b[2Gd\x1b[?25le\x1b[5;1Hf\x1b7\x1b[5;3Hg";
        assert_eq!(through(&[frame.as_bytes()]), short);
        let bytes: Vec<&[u8]> = frame.as_bytes().chunks(1).collect();
        assert_eq!(through(&bytes), short);
    }

    #[test]
    fn sequences_split_across_writes_are_read_whole() {
        let bytes: Vec<&[u8]> = FRAME.as_bytes().chunks(1).collect();
        assert_eq!(through(&bytes), SHORT);
        let bytes: Vec<&[u8]> = FRAME.as_bytes().chunks(5).collect();
        assert_eq!(through(&bytes), SHORT);
    }

    #[test]
    fn a_reset_is_kept_and_known_and_bright_colours_are_short() {
        let out = through(&[b"\x1b[0m\x1b[38;5;10;49ma\x1b[39;49mb\x1b[59m\x1b[0m"]);
        assert_eq!(out, "\x1b[0m\x1b[92ma\x1b[39mb\x1b[0m");
        // An underline colour set is reset.
        let out = through(&[b"\x1b[58;5;1ma\x1b[59m"]);
        assert_eq!(out, "\x1b[58;5;1ma\x1b[59m");
    }

    #[test]
    fn an_unreadable_sequence_passes_and_forgets_the_colours() {
        let out = through(&[b"\x1b[38;5;6;49ma\x1b[4:3mb\x1b[38;5;6;49mc"]);
        assert_eq!(out, "\x1b[36;49ma\x1b[4:3mb\x1b[36;49mc");
    }
}
