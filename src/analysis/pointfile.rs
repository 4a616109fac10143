//! Reading point sets from text: the point-file format of `qmckit discrepancy`.
//!
//! # Format
//!
//! * One point a line: its coordinates as decimal numbers (anything [`f64`]'s `FromStr`
//!   accepts: `0.5`, `.5`, `5e-1`, `1`).
//! * Separators: one or more spaces or tabs, or a single comma with optional spaces or tabs
//!   around it; the two may be mixed on a line (`0.1, 0.2 0.3`). Two commas in a row, or a
//!   comma at the start or end of a line, is an error (an empty field).
//! * `#` starts a comment: the rest of the line is ignored. Blank lines (and lines holding
//!   only a comment) are ignored.
//! * A line holding only `#` (after trimming spaces and tabs) separates point sets.
//! * Every coordinate must be finite and in the closed interval `[0, 1]`; every point of a
//!   set must have as many coordinates as the set's first point (sets may differ).
//! * Every set must hold at least one point: empty input, a separator at the start or the
//!   end of the input, or two separators with no point between them is an error
//!   ("set K has no points"), reported at the separator that closes the empty set, or at
//!   the last line for the final set (line 1 for empty input).
//!
//! * Line ends: `\n`, `\r\n` or a lone `\r` (old Mac files). A UTF-8 byte-order mark at the
//!   start is skipped. Only ASCII spaces and tabs separate numbers: another white-space or
//!   control character (no-break space, vertical tab, form feed) inside a line is an error
//!   that names it, rather than a silently different split.
//! * A first line that is not numbers (a header such as `x,y`, as pandas writes) is an error
//!   with a hint: make it a comment with `#`.
//!
//! # Encodings
//!
//! Coordinates are read as real numbers ([`Encoding::Real`]) or as 0.32 numerators, the
//! integers `x * 2^32` that `qmckit points --format u32` writes ([`Encoding::U32`]: each an
//! integer in `0..=4294967295`, read exactly as `x / 2^32`). [`Encoding::Auto`], the default
//! of [`parse_point_sets`], reads a text as `u32` when every coordinate in it is written as
//! a whole number (digits only) and at least one of them exceeds 1, and as real numbers
//! otherwise: a real-valued file can only hold the whole numbers 0 and 1, so the rule never
//! misreads one; a `u32` file whose every value is 0 or 1 (at most the point at index 0 of
//! most constructions) is read as reals, and [`Encoding::U32`] forces the other reading.
//!
//! ```
//! use qmckit::analysis::pointfile::parse_point_sets;
//! let sets = parse_point_sets("0.25 0.5\n0.75,1  # a comment\n#\n0.5\n")?;
//! assert_eq!(sets.len(), 2);
//! assert_eq!((sets[0].dims, sets[0].data.clone()), (2, vec![0.25, 0.5, 0.75, 1.0]));
//! assert_eq!((sets[1].dims, sets[1].len()), (1, 1));
//! let err = parse_point_sets("0.5 0.5\n0.5 1.5\n").unwrap_err();
//! assert_eq!(err.to_string(), "line 2: \"1.5\" is outside [0, 1]");
//! // qmckit's u32 output reads back as the exact fractions.
//! let u = parse_point_sets("0 0\n2147483648 1431655765\n")?;
//! assert_eq!(u[0].data[2], 0.5);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;

use super::Points;

/// How a point file writes its coordinates (see [the module docs](self#encodings)).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Encoding {
    /// `U32` when every coordinate is a whole number and one exceeds 1, else `Real`.
    #[default]
    Auto,
    /// Real numbers in `[0, 1]`.
    Real,
    /// 0.32 numerators: integers in `0..=4294967295`, read as `x / 2^32`.
    U32,
}

/// One point set read from text: `len()` points of `dims` coordinates, row-major.
#[derive(Clone, Debug, PartialEq)]
pub struct PointSet {
    /// Coordinates per point (at least 1).
    pub dims: usize,
    /// The coordinates, row-major: point `i` is `data[i * dims..(i + 1) * dims]`.
    pub data: Vec<f64>,
}

impl PointSet {
    /// Number of points.
    pub fn len(&self) -> usize {
        self.data.len() / self.dims.max(1)
    }

    /// `true` when the set holds no points (never for a set [`parse_point_sets`] returns).
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// The validated view the measures take.
    ///
    /// # Errors
    /// Those of [`Points::new`]; never for a set [`parse_point_sets`] returns.
    pub fn points(&self) -> crate::Result<Points<'_>> {
        Points::new(&self.data, self.dims)
    }
}

/// Why a point file could not be read, and where.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ParseError {
    /// The offending line, 1-based.
    pub line: usize,
    /// What is wrong with it (one line, no trailing period).
    pub message: String,
}

impl fmt::Display for ParseError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.message)
    }
}

impl std::error::Error for ParseError {}

/// Longest excerpt of a bad token quoted in an error message, in characters.
const QUOTE_MAX: usize = 40;

/// A token for an error message: escaped (so the message stays on one line) and shortened.
fn quote(token: &str) -> String {
    if token.chars().count() <= QUOTE_MAX {
        format!("{token:?}")
    } else {
        let head: String = token.chars().take(QUOTE_MAX).collect();
        format!("{head:?}...")
    }
}

/// The lines of `text`: ends are `\n`, `\r\n` or a lone `\r`.
fn lines(text: &str) -> impl Iterator<Item = &str> {
    let mut rest = Some(text);
    std::iter::from_fn(move || {
        let t = rest?;
        match t.find(['\n', '\r']) {
            Some(i) => {
                let skip = if t[i..].starts_with("\r\n") { 2 } else { 1 };
                rest = Some(&t[i + skip..]);
                Some(&t[..i])
            }
            None => {
                rest = None;
                // A final line end leaves an empty tail: not a line.
                (!t.is_empty()).then_some(t)
            }
        }
    })
}

/// The separators between numbers (besides commas).
fn is_separator(c: char) -> bool {
    c == ' ' || c == '\t'
}

/// The message for an empty comma-separated field.
const EMPTY_FIELD: &str =
    "empty field (two commas in a row, or a comma at the start or end of the line)";

/// The tokens of one comment-free line, in order: `Err` for an empty comma-separated field.
/// Allocates nothing.
fn tokens(text: &str) -> impl Iterator<Item = Result<&str, String>> {
    text.split(',').flat_map(|field| {
        let mut toks = field
            .split(is_separator)
            .filter(|t| !t.is_empty())
            .peekable();
        let empty = toks.peek().is_none().then(|| Err(EMPTY_FIELD.to_owned()));
        empty.into_iter().chain(toks.map(Ok))
    })
}

/// `Some(name)` when `token` holds a white-space or control character that is not a
/// separator (it would otherwise be misread as part of a number).
fn stray_space(token: &str) -> Option<String> {
    token
        .chars()
        .find(|c| c.is_whitespace() || c.is_control())
        .map(|c| match c {
            '\u{a0}' => "U+00A0 (no-break space)".to_owned(),
            '\u{b}' => "U+000B (vertical tab)".to_owned(),
            '\u{c}' => "U+000C (form feed)".to_owned(),
            c => format!("U+{:04X}", c as u32),
        })
}

/// Parses one coordinate in `encoding` (`Real` or `U32`).
fn parse_value(token: &str, encoding: Encoding) -> Result<f64, String> {
    if let Some(c) = stray_space(token) {
        return Err(format!(
            "{} contains {c}, which does not separate numbers: use spaces, tabs or commas",
            quote(token)
        ));
    }
    if encoding == Encoding::U32 {
        return match token.parse::<u32>() {
            Ok(x) if is_whole(token) => Ok(crate::bits::to_f64(x)),
            _ => Err(format!(
                "{} is not a 0.32 numerator (an integer in 0..=4294967295)",
                quote(token)
            )),
        };
    }
    let x: f64 = token
        .parse()
        .map_err(|_| format!("{} is not a number", quote(token)))?;
    if !x.is_finite() {
        return Err(format!("{} is not a finite number", quote(token)));
    }
    if !(0.0..=1.0).contains(&x) {
        return Err(format!("{} is outside [0, 1]", quote(token)));
    }
    Ok(x)
}

/// `true` for a token of ASCII digits only.
fn is_whole(token: &str) -> bool {
    !token.is_empty() && token.bytes().all(|b| b.is_ascii_digit())
}

/// Appends the coordinates of one (comment-free, non-blank) line to `out`; returns how many.
fn parse_row(text: &str, encoding: Encoding, out: &mut Vec<f64>) -> Result<usize, String> {
    let mut count = 0;
    for token in tokens(text) {
        let token = token?;
        if out.len() == out.capacity() {
            // Doubling growth through the checked helper: the 1 GiB rule holds for the
            // parsed values, and a refused allocation is an error, not an abort.
            crate::size::reserve(out, out.len().max(1024)).map_err(|e| e.to_string())?;
        }
        out.push(parse_value(token, encoding)?);
        count += 1;
    }
    Ok(count)
}

/// The part of a line before its comment.
fn content(raw: &str) -> &str {
    raw.split('#').next().unwrap_or("")
}

/// `true` for a line that separates point sets: only `#`, between spaces or tabs.
fn is_set_separator(raw: &str) -> bool {
    raw.trim_matches(is_separator) == "#"
}

/// The encoding [`Encoding::Auto`] picks for `text` (see [the module docs](self#encodings)).
pub fn detect_encoding(text: &str) -> Encoding {
    let mut above_one = false;
    for raw in lines(text) {
        for token in tokens(content(raw)).flatten() {
            if !is_whole(token) {
                return Encoding::Real;
            }
            above_one |= token.trim_start_matches('0').len() > 1
                || token
                    .trim_start_matches('0')
                    .parse::<u8>()
                    .is_ok_and(|v| v > 1);
        }
    }
    if above_one {
        Encoding::U32
    } else {
        Encoding::Real
    }
}

/// The most coordinates read from one text, over all its sets: the parsed `f64` values stay
/// within [`crate::size::MAX_ALLOC_BYTES`], whatever the text's size.
pub const MAX_VALUES: usize = (crate::size::MAX_ALLOC_BYTES / 8) as usize;

/// The set being read: its points and where its first point was.
struct Current {
    set: PointSet,
    /// Line of the first point (0 while empty).
    first_line: usize,
}

impl Current {
    fn new() -> Self {
        Current {
            set: PointSet {
                dims: 0,
                data: Vec::new(),
            },
            first_line: 0,
        }
    }

    /// Moves the finished set into `sets`; an empty one is an error reported at `line`.
    fn close(&mut self, sets: &mut Vec<PointSet>, line: usize) -> Result<(), ParseError> {
        if self.set.is_empty() {
            return Err(ParseError {
                line: line.max(1),
                message: format!("set {} has no points", sets.len() + 1),
            });
        }
        sets.push(std::mem::replace(self, Current::new()).set);
        Ok(())
    }
}

/// Parses point sets in the [format](self) above, in the encoding [`Encoding::Auto`]
/// detects: one [`PointSet`] per `#`-separated block.
///
/// # Errors
/// A [`ParseError`] naming the first offending line: a token that is not a number, NaN or
/// infinity, a value outside `[0, 1]`, an empty comma-separated field, a stray white-space
/// character, a point with a different number of coordinates than its set's first point,
/// or a set with no points. Never panics. Cost: linear in the text.
pub fn parse_point_sets(text: &str) -> Result<Vec<PointSet>, ParseError> {
    parse_point_sets_as(text, Encoding::Auto)
}

/// [`parse_point_sets`] in a chosen [`Encoding`].
///
/// # Errors
/// As [`parse_point_sets`]; in [`Encoding::U32`] a token that is not an integer in
/// `0..=4294967295`.
pub fn parse_point_sets_as(text: &str, encoding: Encoding) -> Result<Vec<PointSet>, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let encoding = match encoding {
        Encoding::Auto => detect_encoding(text),
        chosen => chosen,
    };
    let mut sets = Vec::new();
    let mut current = Current::new();
    let mut last_line = 0;
    let mut total = 0usize;
    for (index, raw) in lines(text).enumerate() {
        let line = index + 1;
        last_line = line;
        if is_set_separator(raw) {
            current.close(&mut sets, line)?;
            continue;
        }
        let content = content(raw);
        if content.trim_matches(is_separator).is_empty() {
            continue;
        }
        let first_of_input = sets.is_empty() && current.first_line == 0;
        // A header names columns: its first token starts with a letter.
        let header = first_of_input
            && content
                .trim_start_matches(is_separator)
                .starts_with(|c: char| c.is_alphabetic() || c == '"' || c == '_');
        let error = |mut message: String| {
            if header && message.ends_with("is not a number") {
                message.push_str(" (a header line? Start it with '#' to make it a comment)");
            }
            ParseError { line, message }
        };
        let before = current.set.data.len();
        let count = parse_row(content, encoding, &mut current.set.data).map_err(error)?;
        total = total.saturating_add(count);
        if total > MAX_VALUES {
            return Err(error(format!(
                "more than {MAX_VALUES} coordinates in all: the parsed values would pass the \
                 {} byte limit; split the input",
                crate::size::MAX_ALLOC_BYTES
            )));
        }
        if current.first_line == 0 {
            current.set.dims = count;
            current.first_line = line;
        } else if count != current.set.dims {
            current.set.data.truncate(before);
            return Err(error(format!(
                "{count} coordinate(s), but the first point of this set (line {}) has {}",
                current.first_line, current.set.dims
            )));
        }
    }
    current.close(&mut sets, last_line)?;
    Ok(sets)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> ParseError {
        parse_point_sets(text).unwrap_err()
    }

    #[test]
    fn separators_and_comments() {
        let sets = parse_point_sets(
            "# header\n\n0.1\t0.2   0.3\n0.4, 0.5 ,0.6\n 0.7 ,\t0.8 0.9 # tail\r\n",
        )
        .unwrap();
        assert_eq!(sets.len(), 1);
        assert_eq!(sets[0].dims, 3);
        assert_eq!(sets[0].data, [0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]);
        assert_eq!(sets[0].points().unwrap().len(), 3);
    }

    #[test]
    fn several_sets_may_differ_in_dimension() {
        let sets = parse_point_sets("0.5 0.5\n  #  \n0.25\n0.75\n#\n1,0,1\n").unwrap();
        let shapes: Vec<_> = sets.iter().map(|s| (s.len(), s.dims)).collect();
        assert_eq!(shapes, [(1, 2), (2, 1), (1, 3)]);
    }

    #[test]
    fn comment_lines_do_not_separate() {
        let sets = parse_point_sets("0.5\n# not a separator\n##\n0.25\n").unwrap();
        assert_eq!(sets.len(), 1);
        assert_eq!(sets[0].len(), 2);
    }

    #[test]
    fn bad_values_name_the_line() {
        assert_eq!(
            err("0.5\n0.5 x\n").to_string(),
            "line 2: \"x\" is not a number"
        );
        assert_eq!(err("0.5\n\nNaN\n").line, 3);
        assert!(err("inf\n").message.contains("not a finite number"));
        assert!(err("-0.5\n").message.contains("outside [0, 1]"));
        assert!(err("0.5\n1.0000001\n").message.contains("outside [0, 1]"));
        assert!(err("0.5,,0.5\n").message.contains("empty field"));
        assert!(err("0.5,\n").message.contains("empty field"));
        assert!(err(",0.5\n").message.contains("empty field"));
    }

    #[test]
    fn ragged_rows() {
        let e = err("0.1 0.2\n0.3 0.4\n\n0.5\n");
        assert_eq!(e.line, 4);
        assert_eq!(
            e.message,
            "1 coordinate(s), but the first point of this set (line 1) has 2"
        );
    }

    #[test]
    fn empty_sets() {
        assert_eq!(err("").to_string(), "line 1: set 1 has no points");
        assert_eq!(
            err("# only a comment\n\n").to_string(),
            "line 2: set 1 has no points"
        );
        assert_eq!(err("#\n0.5\n").to_string(), "line 1: set 1 has no points");
        assert_eq!(
            err("0.5\n#\n#\n0.5\n").to_string(),
            "line 3: set 2 has no points"
        );
        assert_eq!(err("0.5\n#\n").to_string(), "line 2: set 2 has no points");
    }

    #[test]
    fn long_and_odd_tokens_stay_on_one_line() {
        let long = "9".repeat(500) + "x";
        let e = err(&long);
        assert!(e.message.len() < 100 && e.message.contains("..."), "{e}");
        let e = err("0.5\u{1b}[31m\n");
        assert!(!e.to_string().contains('\u{1b}'));
        assert_eq!(parse_point_sets("\u{feff}0.5\n").unwrap()[0].data, [0.5]);
        // Multi-byte characters are cut on character boundaries.
        assert!(err(&"é".repeat(100)).message.contains("é\"... is not"));
    }

    #[test]
    fn line_ends_of_every_kind() {
        for text in [
            "0.1 0.2\r0.3 0.4\r",
            "0.1 0.2\r\n0.3 0.4",
            "0.1 0.2\n0.3 0.4\n",
        ] {
            let sets = parse_point_sets(text).unwrap();
            assert_eq!((sets[0].len(), sets[0].dims), (2, 2), "{text:?}");
        }
        // A blank line between CR line ends is one blank line, not a separator.
        let sets = parse_point_sets("0.5\r\r0.25\r#\r0.75").unwrap();
        assert_eq!(sets.len(), 2);
        assert_eq!(sets[0].data, [0.5, 0.25]);
    }

    #[test]
    fn only_spaces_tabs_and_commas_separate() {
        for (text, name) in [
            ("0.1\u{a0}0.2\n", "U+00A0"),
            ("0.1\u{b}0.2\n", "U+000B"),
            ("0.1\u{c}0.2\n", "U+000C"),
            ("0.1\u{2003}0.2\n", "U+2003"),
        ] {
            let e = err(text);
            assert!(e.message.contains(name), "{e}");
            assert!(e.message.contains("does not separate"), "{e}");
        }
    }

    #[test]
    fn a_header_gets_a_hint() {
        let e = err("x,y\n0.1,0.2\n");
        assert_eq!(e.line, 1);
        assert!(e.message.contains("header"), "{e}");
        // Not on later lines: there it is a bad value.
        assert!(!err("0.1,0.2\nx,y\n").message.contains("header"));
        assert_eq!(parse_point_sets("# x,y\n0.1,0.2\n").unwrap()[0].len(), 1);
    }

    #[test]
    fn u32_numerators_are_detected_and_exact() {
        let sets = parse_point_sets("0 0\n2147483648 1431655765\n4294967295 1\n").unwrap();
        assert_eq!(
            sets[0].data,
            [
                0.0,
                0.0,
                0.5,
                1431655765.0 / 4294967296.0,
                4294967295.0 / 4294967296.0,
                1.0 / 4294967296.0
            ]
        );
        // Only 0 and 1: real numbers.
        assert_eq!(detect_encoding("0 1\n1 0\n"), Encoding::Real);
        assert_eq!(detect_encoding("0 1\n2 0\n"), Encoding::U32);
        assert_eq!(detect_encoding("0.5 2\n"), Encoding::Real);
        assert_eq!(detect_encoding("00000002\n"), Encoding::U32);
        assert_eq!(detect_encoding("0001\n"), Encoding::Real);
        // Forced readings.
        let one = parse_point_sets_as("1 0\n", Encoding::U32).unwrap();
        assert_eq!(one[0].data, [1.0 / 4294967296.0, 0.0]);
        assert!(
            err("4294967296 0\n")
                .message
                .contains("not a 0.32 numerator")
        );
        assert!(parse_point_sets_as("0.5\n", Encoding::U32).is_err());
        assert!(parse_point_sets_as("2\n", Encoding::Real).is_err());
    }

    #[test]
    fn never_panics_on_junk() {
        let alphabet = [
            "0",
            "1",
            "0.5",
            ".",
            "e",
            "-",
            "+",
            ",",
            " ",
            "\t",
            "#",
            "\n",
            "\r",
            "é",
            "NaN",
            "inf",
            "\u{feff}",
            "\u{a0}",
            "4294967296",
            "7",
        ];
        // A small deterministic enumeration of short strings over the alphabet.
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..20_000 {
            let mut s = String::new();
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let mut x = state;
            for _ in 0..(x % 12) {
                x /= 12;
                s.push_str(alphabet[(x % alphabet.len() as u64) as usize]);
                x = x.rotate_left(7) ^ state;
            }
            if let Ok(sets) = parse_point_sets(&s) {
                for set in sets {
                    let p = set.points().unwrap();
                    assert_eq!(p.len() * p.dims(), set.data.len());
                }
            }
        }
    }
}
