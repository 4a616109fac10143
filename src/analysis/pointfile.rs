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
//! A UTF-8 byte-order mark at the start is skipped; `\r\n` line ends are accepted.
//!
//! ```
//! use qmckit::analysis::pointfile::parse_point_sets;
//! let sets = parse_point_sets("0.25 0.5\n0.75,1  # a comment\n#\n0.5\n")?;
//! assert_eq!(sets.len(), 2);
//! assert_eq!((sets[0].dims, sets[0].data.clone()), (2, vec![0.25, 0.5, 0.75, 1.0]));
//! assert_eq!((sets[1].dims, sets[1].len()), (1, 1));
//! let err = parse_point_sets("0.5 0.5\n0.5 1.5\n").unwrap_err();
//! assert_eq!(err.to_string(), "line 2: \"1.5\" is outside [0, 1]");
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::fmt;

use super::Points;

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

/// Parses one coordinate.
fn parse_value(token: &str) -> Result<f64, String> {
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

/// Appends the coordinates of one (comment-free, non-blank) line to `out`; returns how many.
fn parse_row(text: &str, out: &mut Vec<f64>) -> Result<usize, String> {
    let mut count = 0;
    for field in text.split(',') {
        let mut tokens = field.split_whitespace().peekable();
        if tokens.peek().is_none() {
            return Err(
                "empty field (two commas in a row, or a comma at the start or end \
                        of the line)"
                    .to_owned(),
            );
        }
        for token in tokens {
            out.push(parse_value(token)?);
            count += 1;
        }
    }
    Ok(count)
}

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

/// Parses point sets in the [format](self) above: one [`PointSet`] per `#`-separated block.
///
/// # Errors
/// A [`ParseError`] naming the first offending line: a token that is not a number, NaN or
/// infinity, a value outside `[0, 1]`, an empty comma-separated field, a point with a
/// different number of coordinates than its set's first point, or a set with no points.
/// Never panics.
pub fn parse_point_sets(text: &str) -> Result<Vec<PointSet>, ParseError> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut sets = Vec::new();
    let mut current = Current::new();
    let mut last_line = 0;
    for (index, raw) in text.lines().enumerate() {
        let line = index + 1;
        last_line = line;
        let trimmed = raw.trim();
        if trimmed == "#" {
            current.close(&mut sets, line)?;
            continue;
        }
        let content = raw.split('#').next().unwrap_or("");
        if content.trim().is_empty() {
            continue;
        }
        let error = |message| ParseError { line, message };
        let before = current.set.data.len();
        let count = parse_row(content, &mut current.set.data).map_err(error)?;
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
    fn never_panics_on_junk() {
        let alphabet = [
            "0", "1", "0.5", ".", "e", "-", "+", ",", " ", "\t", "#", "\n", "\r", "é", "NaN",
            "inf", "\u{feff}",
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
