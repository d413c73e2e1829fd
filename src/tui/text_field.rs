//! The one text field of the explorer: typed values, preset names and file
//! paths all use it. It opens with its whole text selected, so typing
//! replaces the old value; the usual line-editing keys work: ←/→, Home/End
//! (Ctrl-A/Ctrl-E), Backspace/Delete, Ctrl-U (to the start), Ctrl-K (to the
//! end), Ctrl-W (the word before the cursor). A text longer than `max`
//! characters is refused with a message, never cut silently.

use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

/// What a key did to the field.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FieldKey {
    /// The text or cursor changed (or nothing happened).
    Edited,
    /// Enter: take the text.
    Submit,
    /// Esc: leave the field without taking it.
    Cancel,
    /// A key the field does not use (Tab, ↑/↓): the dialog may.
    Other,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct TextField {
    /// The text, as characters (the cursor counts characters).
    chars: Vec<char>,
    /// Cursor position, 0..=len.
    cursor: usize,
    /// The whole text is selected: the next character typed replaces it.
    selected: bool,
    /// Most characters accepted.
    max: usize,
    /// Why the last input was refused, or the dialog's last complaint.
    pub error: Option<String>,
}

impl TextField {
    /// A field holding `text`, all of it selected, accepting `max` characters.
    pub fn new(text: &str, max: usize) -> TextField {
        let chars: Vec<char> = text.chars().collect();
        TextField {
            cursor: chars.len(),
            selected: !chars.is_empty(),
            chars,
            max,
            error: None,
        }
    }

    pub fn text(&self) -> String {
        self.chars.iter().collect()
    }

    pub fn cursor(&self) -> usize {
        self.cursor
    }

    pub fn is_selected(&self) -> bool {
        self.selected
    }

    /// Applies one key.
    pub fn on_key(&mut self, key: KeyEvent) -> FieldKey {
        let ctrl = key.modifiers.contains(KeyModifiers::CONTROL);
        let was_selected = std::mem::replace(&mut self.selected, false);
        match key.code {
            KeyCode::Enter => {
                self.selected = was_selected;
                return FieldKey::Submit;
            }
            KeyCode::Esc => return FieldKey::Cancel,
            KeyCode::Char('u') if ctrl => self.delete_to(0),
            KeyCode::Char('k') if ctrl => {
                self.chars.truncate(self.cursor);
            }
            KeyCode::Char('w') if ctrl => {
                let mut start = self.cursor;
                while start > 0 && self.chars[start - 1] == ' ' {
                    start -= 1;
                }
                while start > 0 && !matches!(self.chars[start - 1], ' ' | '/') {
                    start -= 1;
                }
                self.delete_to(start);
            }
            KeyCode::Char('a') if ctrl => self.cursor = 0,
            KeyCode::Char('e') if ctrl => self.cursor = self.chars.len(),
            KeyCode::Char(_) if ctrl => {}
            KeyCode::Char(c) => {
                if was_selected {
                    self.chars.clear();
                    self.cursor = 0;
                }
                if self.chars.len() >= self.max {
                    self.error = Some(format!("at most {} characters", self.max));
                    return FieldKey::Edited;
                }
                self.chars.insert(self.cursor, c);
                self.cursor += 1;
            }
            KeyCode::Backspace if was_selected => {
                self.chars.clear();
                self.cursor = 0;
            }
            KeyCode::Backspace if self.cursor > 0 => {
                self.cursor -= 1;
                self.chars.remove(self.cursor);
            }
            KeyCode::Delete if was_selected => {
                self.chars.clear();
                self.cursor = 0;
            }
            KeyCode::Delete if self.cursor < self.chars.len() => {
                self.chars.remove(self.cursor);
            }
            KeyCode::Left if was_selected => self.cursor = 0,
            KeyCode::Left => self.cursor = self.cursor.saturating_sub(1),
            KeyCode::Right => self.cursor = (self.cursor + 1).min(self.chars.len()),
            KeyCode::Home => self.cursor = 0,
            KeyCode::End => self.cursor = self.chars.len(),
            KeyCode::Backspace | KeyCode::Delete => {}
            _ => {
                self.selected = was_selected;
                return FieldKey::Other;
            }
        }
        self.error = None;
        FieldKey::Edited
    }

    /// Replaces the text (a dialog's suggestion), all of it selected.
    pub fn set_text(&mut self, text: &str) {
        *self = TextField::new(text, self.max);
    }

    fn delete_to(&mut self, start: usize) {
        self.chars.drain(start..self.cursor);
        self.cursor = start;
    }

    /// The text as shown in `width` columns with the cursor as `_` (or the
    /// selection in brackets), its end kept in view.
    pub fn shown(&self, width: usize) -> String {
        let text = self.text();
        let full = if self.selected {
            format!("[{text}]")
        } else {
            let before: String = self.chars[..self.cursor].iter().collect();
            let after: String = self.chars[self.cursor..].iter().collect();
            format!("{before}_{after}")
        };
        let n = full.chars().count();
        if n <= width || width < 2 {
            return full;
        }
        // Keep the cursor in view: show the last `width - 1` characters up to it.
        let anchor = if self.selected {
            n
        } else {
            (self.cursor + 1).max(width - 1).min(n)
        };
        let start = anchor.saturating_sub(width - 1);
        format!(
            "…{}",
            full.chars()
                .skip(start + 1)
                .take(width - 1)
                .collect::<String>()
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn press(f: &mut TextField, code: KeyCode, ctrl: bool) -> FieldKey {
        let m = if ctrl {
            KeyModifiers::CONTROL
        } else {
            KeyModifiers::NONE
        };
        f.on_key(KeyEvent::new(code, m))
    }

    fn typed(f: &mut TextField, s: &str) {
        for c in s.chars() {
            press(f, KeyCode::Char(c), false);
        }
    }

    #[test]
    fn typing_replaces_the_selected_value() {
        let mut f = TextField::new("0.5", 32);
        typed(&mut f, "abc");
        assert_eq!(f.text(), "abc");
    }

    #[test]
    fn cursor_keys_move_and_insert_in_place() {
        let mut f = TextField::new("0.5", 32);
        press(&mut f, KeyCode::End, false);
        press(&mut f, KeyCode::Left, false);
        typed(&mut f, "2");
        assert_eq!(f.text(), "0.25");
        press(&mut f, KeyCode::Home, false);
        typed(&mut f, "-");
        assert_eq!(f.text(), "-0.25");
        assert_eq!(f.cursor(), 1);
    }

    #[test]
    fn ctrl_u_and_ctrl_w_delete_instead_of_typing() {
        let mut f = TextField::new("", 64);
        typed(&mut f, "/tmp/out/run one");
        press(&mut f, KeyCode::Char('w'), true);
        assert_eq!(f.text(), "/tmp/out/run ");
        press(&mut f, KeyCode::Char('w'), true);
        assert_eq!(f.text(), "/tmp/out/");
        press(&mut f, KeyCode::Char('u'), true);
        assert_eq!(f.text(), "");
        press(&mut f, KeyCode::Char('q'), true);
        assert_eq!(f.text(), "");
    }

    #[test]
    fn overlong_text_is_refused_with_a_message() {
        let mut f = TextField::new("", 4);
        typed(&mut f, "abcdef");
        assert_eq!(f.text(), "abcd");
        assert_eq!(f.error.as_deref(), Some("at most 4 characters"));
    }

    #[test]
    fn enter_and_esc_end_the_field() {
        let mut f = TextField::new("x", 4);
        assert_eq!(press(&mut f, KeyCode::Enter, false), FieldKey::Submit);
        assert_eq!(press(&mut f, KeyCode::Esc, false), FieldKey::Cancel);
        assert_eq!(press(&mut f, KeyCode::Tab, false), FieldKey::Other);
    }
}
