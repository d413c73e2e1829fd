//! How the screen may be drawn: Unicode or plain ASCII, colour or not; the
//! fixed colour of each quantity and model; the ASCII spelling of symbols.

use ratatui::buffer::Buffer;
use ratatui::style::Color;

/// How the screen may be drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Look {
    /// Plain ASCII characters only (`--ascii`, or a locale that is not UTF-8).
    pub ascii: bool,
    /// Colours allowed (off with NO_COLOR).
    pub color: bool,
}

impl Look {
    /// `s` as this terminal can show it: symbols spelled out in ASCII mode
    /// (ẋ → xdot, μ → mu, ξ → xi, Π → Pi, ω → w, τ → tau).
    pub fn text(&self, s: &str) -> String {
        if self.ascii {
            ascii_text(s)
        } else {
            s.to_string()
        }
    }
}

/// Fixed colours, one per quantity or model, the same in every scene.
pub mod palette {
    use ratatui::style::Color;
    /// The left structure: x1, ẋ1, f_s1.
    pub const LEFT: Color = Color::Cyan;
    /// The right structure: x2, ẋ2, f_s2.
    pub const RIGHT: Color = Color::Yellow;
    /// The contact line: the gap Π_d under x1 − x2.
    pub const CONTACT_LINE: Color = Color::Gray;
    /// The relative displacement x1 − x2.
    pub const RELATIVE: Color = Color::LightGreen;
    /// The pounding force f_p.
    pub const FORCE: Color = Color::Magenta;
    /// The improved Kelvin element.
    pub const IMPROVED: Color = Color::Green;
    /// The Kelvin element.
    pub const KELVIN: Color = Color::Red;
    /// Set 1 and set 2 on one chart.
    pub const SETS: [Color; 2] = [Color::LightBlue, Color::LightRed];
    /// The ground acceleration g(τ).
    pub const GROUND: Color = Color::Blue;
    /// A response without pounding.
    pub const FREE: Color = Color::Gray;
}

/// The colour of a contact model, fixed whatever the active set.
pub fn model_color(model: crate::model::ContactModel) -> Color {
    use crate::model::ContactModel;
    match model {
        ContactModel::Kelvin => palette::KELVIN,
        ContactModel::ImprovedKelvin => palette::IMPROVED,
        ContactModel::Hertz => Color::Yellow,
        ContactModel::HertzDamp => Color::Magenta,
        ContactModel::Jankowski => Color::Cyan,
        ContactModel::HuntCrossley => Color::LightYellow,
    }
}

/// The marker of a contact model where colours cannot tell the laws apart
/// (NO_COLOR, `--ascii`), fixed like its colour.
pub fn model_marker(model: crate::model::ContactModel) -> char {
    use crate::model::ContactModel;
    match model {
        ContactModel::ImprovedKelvin => '*',
        ContactModel::Kelvin => '+',
        ContactModel::Hertz => 'o',
        ContactModel::HertzDamp => '#',
        ContactModel::Jankowski => 'x',
        ContactModel::HuntCrossley => '%',
    }
}

/// Spells the explorer's symbols in ASCII, whole words where a letter would clash.
pub fn ascii_text(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 8);
    for c in s.chars() {
        match c {
            'ẋ' => out.push_str("xdot"),
            'μ' => out.push_str("mu"),
            'ξ' => out.push_str("xi"),
            'α' => out.push_str("alpha"),
            'Π' => out.push_str("Pi"),
            'ω' => out.push('w'),
            'τ' => out.push_str("tau"),
            'Δ' => out.push('d'),
            'δ' => out.push_str("delta"),
            'θ' => out.push_str("theta"),
            'β' => out.push_str("beta"),
            'π' => out.push_str("pi"),
            '²' => out.push_str("^2"),
            '₀' => out.push('0'),
            'ⁿ' => out.push('n'),
            '×' => out.push('x'),
            '·' => out.push('*'),
            '…' => out.push_str("..."),
            '←' => out.push_str("<-"),
            '→' => out.push_str("->"),
            '↑' => out.push('^'),
            '↓' => out.push('v'),
            '⇧' => out.push_str("Shift+"),
            '−' | '–' | '—' => out.push('-'),
            '\u{0304}' => {}
            c => out.push(c),
        }
    }
    out
}

/// Replaces every non-ASCII character of the frame with a plain one (box
/// lines, Braille, anything a view spelled in Unicode by mistake).
pub fn asciify(buf: &mut Buffer) {
    for cell in buf.content.iter_mut() {
        let s = cell.symbol();
        if s.is_ascii() {
            continue;
        }
        let out: String = s.chars().map(ascii_char).collect();
        cell.set_symbol(&out);
    }
}

fn ascii_char(c: char) -> char {
    match c {
        c if c.is_ascii() => c,
        '\u{2800}' => ' ',
        '\u{2801}'..='\u{28FF}' | '•' | '█' | '▀' | '▄' => '*',
        '─' | '━' | '═' | '−' | '–' | '—' | '┄' => '-',
        '│' | '┃' | '║' | '▏' => '|',
        '┌' | '┐' | '└' | '┘' | '├' | '┤' | '┬' | '┴' | '┼' | '╭' | '╮' | '╰' | '╯' => {
            '+'
        }
        'Π' => 'P',
        'ω' => 'w',
        'τ' => 't',
        '·' | '…' => '.',
        _ => '?',
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_law_has_its_own_colour_and_marker() {
        use crate::model::ContactModel;
        let all = ContactModel::ALL;
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert_ne!(model_color(*a), model_color(*b), "{a:?} {b:?}");
                assert_ne!(model_marker(*a), model_marker(*b), "{a:?} {b:?}");
            }
            assert!(model_marker(*a).is_ascii());
        }
    }

    #[test]
    fn ascii_names_do_not_clash_with_other_symbols() {
        assert_eq!(ascii_text("ẋ1"), "xdot1");
        assert_eq!(ascii_text("μ = Π_ω2/Π_ω1"), "mu = Pi_w2/Pi_w1");
        assert_eq!(ascii_text("Π_ξ"), "Pi_xi");
        assert_eq!(ascii_text("x [a_p/ω_p²]"), "x [a_p/w_p^2]");
    }
}
