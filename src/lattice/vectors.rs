//! Generating vectors: the LDData `lattice` text format and Korobov vectors.

use crate::error::{Error, Result};

/// What a lattice file's header says, and how many components were read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct LatticeFile {
    /// Dimensions the file declares (`s`); `None` for Kuo's two-column format.
    pub declared_dims: Option<usize>,
    /// The modulus `n` the vector was built for; `None` for Kuo's two-column format.
    pub modulus: Option<u64>,
    /// Components stored into the output slice.
    pub read: usize,
}

/// The integer of one token, or an error naming the format.
fn number(token: &str) -> Result<u64> {
    token.parse::<u64>().map_err(|_| Error::InvalidParameter {
        what: "lattice file: a line is not a non-negative integer",
    })
}

/// Reads a generating vector from `text` into `out` (as many components as fit, or as the
/// file has) and returns the header. Two formats:
///
/// * LDData `lattice`: a first line `# lattice` (a comment naming the format), then the
///   dimension `s` and the modulus `n` (each on its own line, anything after `#` ignored,
///   `#` lines skipped), then `s` lines with `z_1, .., z_s`; comments are allowed only in
///   the header (before the first component);
/// * Kuo's two-column files: lines `j z_j` for `j = 1, 2, ..` (no header).
///
/// No allocation (`no_std`); `O(len(text))`.
///
/// ```
/// let text = "# lattice\n# a comment\n3 # dims\n16 # n\n1\n5\n7\n";
/// let mut z = [0u32; 3];
/// let info = qmckit::lattice::parse_lattice(text, &mut z)?;
/// assert_eq!((info.modulus, info.read, z), (Some(16), 3, [1, 5, 7]));
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] for a malformed file: a non-integer line, a header
/// without `s` and `n`, fewer components than `s` (when `out` asks for more), a component
/// of `2^32` or more, a modulus of 0 or above `2^32`, or Kuo rows out of sequence.
pub fn parse_lattice(text: &str, out: &mut [u32]) -> Result<LatticeFile> {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let first = lines.clone().next().ok_or(Error::InvalidParameter {
        what: "lattice file: empty",
    })?;
    if !first.starts_with('#') {
        return parse_two_column(lines, out);
    }
    if !first.contains("lattice") {
        return Err(Error::InvalidParameter {
            what: "lattice file: the first line must be the comment '# lattice'",
        });
    }
    let mut header = [0u64; 2];
    let mut got = 0;
    for line in lines.by_ref() {
        let body = line.split('#').next().unwrap_or("").trim();
        if body.is_empty() {
            continue;
        }
        if let Some(slot) = header.get_mut(got) {
            *slot = number(body)?;
        }
        got += 1;
        if got == 2 {
            break;
        }
    }
    if got < 2 {
        return Err(Error::InvalidParameter {
            what: "lattice file: the header needs the dimension and the modulus",
        });
    }
    let [dims, modulus] = header;
    if modulus == 0 || modulus > 1 << 32 {
        return Err(Error::InvalidParameter {
            what: "lattice file: the modulus must be between 1 and 2^32",
        });
    }
    let dims = usize::try_from(dims).unwrap_or(usize::MAX);
    let want = out.len().min(dims);
    let mut read = 0;
    // Full comment lines may still follow the header's two numbers, before the components.
    let components = lines.skip_while(|l| l.starts_with('#'));
    for (slot, line) in out.iter_mut().take(want).zip(components) {
        *slot = component(line)?;
        read += 1;
    }
    if read < want {
        return Err(Error::InvalidParameter {
            what: "lattice file: fewer components than its header declares",
        });
    }
    Ok(LatticeFile {
        declared_dims: Some(dims),
        modulus: Some(modulus),
        read,
    })
}

/// One component line: an integer below `2^32`.
fn component(line: &str) -> Result<u32> {
    u32::try_from(number(line)?).map_err(|_| Error::InvalidParameter {
        what: "lattice file: a component of 2^32 or more",
    })
}

/// Kuo's `j z_j` rows.
fn parse_two_column<'a>(
    lines: impl Iterator<Item = &'a str>,
    out: &mut [u32],
) -> Result<LatticeFile> {
    let mut read = 0;
    for (k, line) in lines.enumerate() {
        let mut tokens = line.split_whitespace();
        let (Some(j), Some(z), None) = (tokens.next(), tokens.next(), tokens.next()) else {
            return Err(Error::InvalidParameter {
                what: "lattice file: a row is not 'j z_j'",
            });
        };
        if number(j)? != k as u64 + 1 {
            return Err(Error::InvalidParameter {
                what: "lattice file: rows 'j z_j' must number j = 1, 2, ...",
            });
        }
        let z = component(z)?;
        match out.get_mut(k) {
            Some(slot) => *slot = z,
            None => break,
        }
        read += 1;
    }
    Ok(LatticeFile {
        declared_dims: None,
        modulus: None,
        read,
    })
}

/// The Korobov vector `z_j = a^(j-1) mod n` into `out` (Korobov 1959): one parameter
/// instead of `s`, good for well-chosen `a` (e.g. tables in Sloan & Joe 1994). `O(s)`.
///
/// ```
/// let mut z = [0u32; 4];
/// qmckit::lattice::korobov(3, 16, &mut z)?;
/// assert_eq!(z, [1, 3, 9, 11]); // 27 mod 16 = 11
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::ZeroPoints`] for `n = 0`, [`Error::TooManyPoints`] past `2^32`.
pub fn korobov(a: u64, n: u64, out: &mut [u32]) -> Result<()> {
    crate::sampler::check_set(n, 1)?;
    let a = a % n;
    let mut z = 1 % n;
    for slot in out.iter_mut() {
        // z < n <= 2^32, so it fits a u32 (n = 2^32 keeps z below it).
        *slot = z as u32;
        z = ((z as u128 * a as u128) % n as u128) as u64;
    }
    Ok(())
}
