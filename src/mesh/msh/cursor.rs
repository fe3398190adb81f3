//! A cursor over the bytes of an MSH file: ASCII tokens and lines, binary numbers, section
//! markers. Every read checks the bytes left, and every count read from the file is checked
//! against them before anything is allocated from it, so a forged count is an error, never a
//! huge allocation.

/// How the numbers of a file are stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Format {
    /// Text.
    Ascii,
    /// Binary, little-endian if `true`.
    Binary {
        /// Byte order of the numbers.
        little_endian: bool,
    },
}

impl Format {
    /// Smallest number of bytes an `int` takes: a digit and a separator in ASCII files.
    pub(crate) fn int_bytes(self) -> usize {
        match self {
            Format::Ascii => 2,
            Format::Binary { .. } => 4,
        }
    }

    /// Smallest number of bytes a `size_t` or a `double` takes (8-byte data size).
    pub(crate) fn wide_bytes(self) -> usize {
        match self {
            Format::Ascii => 2,
            Format::Binary { .. } => 8,
        }
    }
}

/// Reads numbers (ASCII tokens or binary values alike) from `bytes`, starting at `pos`.
pub(crate) struct Cursor<'a> {
    bytes: &'a [u8],
    /// Offset of the next byte to read.
    pub(crate) pos: usize,
    /// How the numbers are stored.
    pub(crate) format: Format,
}

impl<'a> Cursor<'a> {
    /// A cursor at `pos` in `bytes`.
    pub(crate) fn new(bytes: &'a [u8], pos: usize, format: Format) -> Self {
        Cursor { bytes, pos, format }
    }

    /// Bytes after the cursor.
    pub(crate) fn bytes_left(&self) -> usize {
        self.bytes.len().saturating_sub(self.pos)
    }

    /// Whether only whitespace is left.
    pub(crate) fn at_end(&self) -> bool {
        self.rest().iter().all(u8::is_ascii_whitespace)
    }

    fn rest(&self) -> &'a [u8] {
        &self.bytes[self.pos.min(self.bytes.len())..]
    }

    /// The next whitespace-separated token (ASCII text in any file: section markers and the
    /// `$PhysicalNames` section are text in binary files too).
    pub(crate) fn token(&mut self) -> Result<&'a [u8], String> {
        let rest = self.rest();
        let start = rest
            .iter()
            .position(|b| !b.is_ascii_whitespace())
            .ok_or("the file ends early")?;
        let len = rest[start..]
            .iter()
            .position(|b| b.is_ascii_whitespace())
            .unwrap_or(rest.len() - start);
        self.pos += start + len;
        Ok(&rest[start..start + len])
    }

    /// The next token as text (lossy), for numbers and messages.
    fn text_token(&mut self) -> Result<String, String> {
        self.token().map(shown)
    }

    /// The rest of the current line (without its line break) as text, and moves past it.
    pub(crate) fn line(&mut self) -> String {
        let rest = self.rest();
        let len = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        self.pos += (len + 1).min(rest.len());
        String::from_utf8_lossy(&rest[..len]).trim_end_matches('\r').to_string()
    }

    /// In ASCII files, checks that only whitespace is left on the current line and moves past
    /// its line break; `what` says what the line held. Nothing in binary files.
    pub(crate) fn end_line(&mut self, what: &str) -> Result<(), String> {
        if self.format != Format::Ascii {
            return Ok(());
        }
        let rest = self.rest();
        let len = rest.iter().position(|&b| b == b'\n').unwrap_or(rest.len());
        if let Some(extra) = rest[..len].split(u8::is_ascii_whitespace).find(|t| !t.is_empty()) {
            return Err(format!("{what} is followed by `{}` on its line", shown(extra)));
        }
        self.pos += (len + 1).min(rest.len());
        Ok(())
    }

    fn raw<const N: usize>(&mut self) -> Result<[u8; N], String> {
        let end = self.pos.checked_add(N).filter(|&e| e <= self.bytes.len());
        let end = end.ok_or("the file ends early")?;
        let mut out = [0; N];
        out.copy_from_slice(&self.bytes[self.pos..end]);
        self.pos = end;
        Ok(out)
    }

    /// One number: a token in ASCII files, `N` bytes in the file's byte order in binary ones;
    /// `kind` says what the token must be.
    fn number<T: std::str::FromStr, const N: usize>(
        &mut self,
        what: &str,
        kind: &str,
        from_le: fn([u8; N]) -> T,
        from_be: fn([u8; N]) -> T,
    ) -> Result<T, String> {
        match self.format {
            Format::Ascii => {
                let t = self.text_token().map_err(|e| format!("{what}: {e}"))?;
                t.parse().map_err(|_| format!("{what}: `{t}` is not {kind}"))
            }
            Format::Binary { little_endian } => {
                let b = self.raw::<N>().map_err(|e| format!("{what}: {e}"))?;
                Ok(if little_endian { from_le(b) } else { from_be(b) })
            }
        }
    }

    /// A `size_t` (8 bytes in binary files).
    pub(crate) fn size(&mut self, what: &str) -> Result<u64, String> {
        self.number(what, "a non-negative integer", u64::from_le_bytes, u64::from_be_bytes)
    }

    /// An `int` (4 bytes in binary files).
    pub(crate) fn int(&mut self, what: &str) -> Result<i32, String> {
        self.number(what, "an integer", i32::from_le_bytes, i32::from_be_bytes)
    }

    /// A `double`.
    pub(crate) fn double(&mut self, what: &str) -> Result<f64, String> {
        self.number(what, "a number", f64::from_le_bytes, f64::from_be_bytes)
    }

    /// An `int` read as ASCII text whatever the file's format (`$PhysicalNames`).
    pub(crate) fn text_int(&mut self, what: &str) -> Result<i32, String> {
        let t = self.text_token().map_err(|e| format!("{what}: {e}"))?;
        t.parse().map_err(|_| format!("{what}: `{t}` is not an integer"))
    }

    /// `n`, a count of items of at least `item_bytes` bytes each, refused if the rest of the
    /// file cannot hold that many.
    pub(crate) fn fits(&self, what: &str, n: u64, item_bytes: usize) -> Result<usize, String> {
        usize::try_from(n)
            .ok()
            .filter(|&n| n.saturating_mul(item_bytes) <= self.bytes_left())
            .ok_or_else(|| format!("{what} = {n}, more than the rest of the file can hold"))
    }

    /// A `size_t` count of items of at least `item_bytes` bytes each (see [`Cursor::fits`]).
    pub(crate) fn count(&mut self, what: &str, item_bytes: usize) -> Result<usize, String> {
        let n = self.size(what)?;
        self.fits(what, n, item_bytes)
    }

    /// Reads the section's end marker `$End<name>`.
    pub(crate) fn end_marker(&mut self, name: &str) -> Result<(), String> {
        let end = format!("$End{name}");
        match self.token() {
            Ok(t) if t == end.as_bytes() => Ok(()),
            Ok(t) => Err(format!("expected {end} after the section's data, found `{}`", shown(t))),
            Err(_) => Err(format!("the file ends before {end}")),
        }
    }

    /// Moves past the `$End<name>` line of a section that is not read, which must open a line.
    pub(crate) fn skip_section(&mut self, name: &str) -> Result<(), String> {
        let end = format!("$End{name}");
        let key = end.as_bytes();
        let rest = self.rest();
        let mut from = 0;
        while let Some(p) = find(&rest[from..], key) {
            let at = from + p;
            let opens_line = at == 0 || matches!(rest[at - 1], b'\n' | b'\r');
            let closes = rest.get(at + key.len()).is_none_or(u8::is_ascii_whitespace);
            if opens_line && closes {
                self.pos += at + key.len();
                return Ok(());
            }
            from = at + 1;
        }
        Err(format!("the file ends before {end}"))
    }
}

/// Position of `key` in `hay`.
fn find(hay: &[u8], key: &[u8]) -> Option<usize> {
    hay.windows(key.len()).position(|w| w == key)
}

/// Up to 40 characters of `t`, lossily decoded, for messages.
pub(crate) fn shown(t: &[u8]) -> String {
    let text = String::from_utf8_lossy(t);
    match text.char_indices().nth(40) {
        Some((cut, _)) => format!("{}…", &text[..cut]),
        None => text.into_owned(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_beyond_the_bytes_left_are_refused_before_allocating() {
        let bytes = b"18446744073709551615 3 1.5";
        let mut r = Cursor::new(bytes, 0, Format::Ascii);
        let err = r.count("number of nodes", 8).unwrap_err();
        assert!(err.contains("more than the rest of the file can hold"), "{err}");
        assert_eq!(r.count("n", 1).unwrap(), 3);
        assert_eq!(r.double("x").unwrap(), 1.5);
        assert!(r.int("y").unwrap_err().contains("ends early"));
    }

    #[test]
    fn binary_numbers_follow_the_byte_order() {
        let mut bytes = 7u64.to_be_bytes().to_vec();
        bytes.extend((-2i32).to_le_bytes());
        let mut r = Cursor::new(&bytes, 0, Format::Binary { little_endian: false });
        assert_eq!(r.size("n").unwrap(), 7);
        r.format = Format::Binary { little_endian: true };
        assert_eq!(r.int("i").unwrap(), -2);
    }

    #[test]
    fn skipped_sections_end_at_their_end_marker_opening_a_line() {
        let bytes = b"$Comments\nsee $EndComments inside\n$EndCommentsX\n$EndComments\n$Nodes";
        let mut r = Cursor::new(bytes, 10, Format::Ascii);
        r.skip_section("Comments").unwrap();
        assert_eq!(r.token().unwrap(), b"$Nodes");
        let mut r = Cursor::new(b"$Foo\n1 2\n", 5, Format::Ascii);
        assert!(r.skip_section("Foo").unwrap_err().contains("$EndFoo"));
    }

    #[test]
    fn ascii_lines_must_not_hold_more_than_was_read() {
        let mut r = Cursor::new(b"1 2 3 \n4 5", 0, Format::Ascii);
        r.size("a").unwrap();
        r.size("b").unwrap();
        let err = r.end_line("element 1").unwrap_err();
        assert!(err.contains("`3`"), "{err}");
        r.size("c").unwrap();
        r.end_line("element 1").unwrap();
        assert_eq!(r.size("d").unwrap(), 4);
    }
}
