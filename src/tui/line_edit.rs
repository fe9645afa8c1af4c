//! A one-line text field with a cursor, as the prompts use it: insert at the
//! cursor, ←/→/Home/End (and Ctrl-A/Ctrl-E) move, Backspace and Delete remove
//! a character, Ctrl-U deletes up to the cursor, Ctrl-W the word before it.

/// One editing action.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edit {
    Insert(char),
    /// The character before the cursor.
    Backspace,
    /// The character under the cursor.
    Delete,
    Left,
    Right,
    Home,
    End,
    /// Everything before the cursor (all of it with the cursor at the end).
    DeleteToStart,
    /// The word before the cursor: letters and digits, with the separators
    /// (`-`, `_`, `.`, spaces …) just before the cursor.
    DeleteWord,
}

/// The text and the cursor, a position between characters (0 ..= length).
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct LineEdit {
    chars: Vec<char>,
    cursor: usize,
    max: usize,
}

impl LineEdit {
    /// A field holding `text`, the cursor at its end, taking at most `max`
    /// characters.
    pub fn new(text: &str, max: usize) -> LineEdit {
        let chars: Vec<char> = text.chars().take(max).collect();
        LineEdit {
            cursor: chars.len(),
            chars,
            max,
        }
    }

    pub fn text(&self) -> String {
        self.chars.iter().collect()
    }

    /// The cursor, in characters from the start.
    pub fn cursor(&self) -> usize {
        self.cursor
    }

    /// The text before and from the cursor.
    pub fn split(&self) -> (String, String) {
        (
            self.chars[..self.cursor].iter().collect(),
            self.chars[self.cursor..].iter().collect(),
        )
    }

    pub fn apply(&mut self, edit: Edit) {
        let n = self.chars.len();
        match edit {
            Edit::Insert(c) => {
                if n < self.max && !c.is_control() {
                    self.chars.insert(self.cursor, c);
                    self.cursor += 1;
                }
            }
            Edit::Backspace => {
                if self.cursor > 0 {
                    self.cursor -= 1;
                    self.chars.remove(self.cursor);
                }
            }
            Edit::Delete => {
                if self.cursor < n {
                    self.chars.remove(self.cursor);
                }
            }
            Edit::Left => self.cursor = self.cursor.saturating_sub(1),
            Edit::Right => self.cursor = (self.cursor + 1).min(n),
            Edit::Home => self.cursor = 0,
            Edit::End => self.cursor = n,
            Edit::DeleteToStart => {
                self.chars.drain(..self.cursor);
                self.cursor = 0;
            }
            Edit::DeleteWord => {
                let mut start = self.cursor;
                while start > 0 && !self.chars[start - 1].is_alphanumeric() {
                    start -= 1;
                }
                while start > 0 && self.chars[start - 1].is_alphanumeric() {
                    start -= 1;
                }
                self.chars.drain(start..self.cursor);
                self.cursor = start;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn edited(text: &str, edits: &[Edit]) -> (String, usize) {
        let mut l = LineEdit::new(text, 20);
        for e in edits {
            l.apply(*e);
        }
        (l.text(), l.cursor())
    }

    #[test]
    fn moves_inserts_and_deletes_at_the_cursor() {
        use Edit::*;
        assert_eq!(edited("abc", &[Left, Insert('X')]), ("abXc".into(), 3));
        assert_eq!(edited("abc", &[Home, Delete]), ("bc".into(), 0));
        assert_eq!(edited("abc", &[Home, Backspace]), ("abc".into(), 0));
        assert_eq!(edited("abc", &[Home, Right, Backspace]), ("bc".into(), 0));
        assert_eq!(edited("abc", &[End, Delete, Right]), ("abc".into(), 3));
        assert_eq!(
            edited("abc", &[Left, Left, DeleteToStart]),
            ("bc".into(), 0)
        );
        assert_eq!(edited("abc", &[DeleteToStart]), ("".into(), 0));
        assert_eq!(
            edited("fig2-20261123-1530", &[DeleteWord]),
            ("fig2-20261123-".into(), 14)
        );
        assert_eq!(edited("fig2-20261123-", &[DeleteWord]), ("fig2-".into(), 5));
        assert_eq!(edited("µm ab", &[Home, DeleteWord]), ("µm ab".into(), 0));
        assert_eq!(
            edited("", &[Left, Right, Delete, DeleteWord]),
            ("".into(), 0)
        );
    }

    #[test]
    fn keeps_to_its_length_and_refuses_control_characters() {
        let mut l = LineEdit::new("0123456789abcdefghijXYZ", 20);
        assert_eq!(l.text(), "0123456789abcdefghij");
        l.apply(Edit::Insert('k'));
        l.apply(Edit::Backspace);
        l.apply(Edit::Insert('\u{1b}'));
        l.apply(Edit::Insert('k'));
        assert_eq!(l.text(), "0123456789abcdefghik");
        assert_eq!(l.split(), ("0123456789abcdefghik".into(), "".into()));
    }
}
