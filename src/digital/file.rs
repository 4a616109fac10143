//! Generator matrices read from a text file in the LDData `dnet` / `dnetup` formats
//! (L'Ecuyer, Nuyens et al., "Standard formats for low discrepancy data"; the files of
//! LatNet Builder, SSJ and the Magic Point Shop, e.g. Niederreiter–Xing nets).
//!
//! # The format
//!
//! The first line is a comment naming the format (`# dnet` or `# dnetup`). Then four
//! numbers, one per line, each optionally followed by a `#` comment: the base `b`, the
//! dimension `s`, the number of columns `k` (some files give the number of points `b^k`
//! instead; both are accepted and checked against the matrix lines), and the number of rows
//! `r`. Comment lines may sit anywhere in the header. Then `s` lines, one per dimension,
//! of `k` integers below `b^r`: column `c` of `C_j` written in base `b`, the digit of row 0
//! the most significant.
//!
//! Files labelled `dnetup` are read the same way. That is how QMCPy's `DigitalNetB2` reads
//! LDData's files (`msb=True`), and how the published `dnetup` files (the Magic Point
//! Shop's Niederreiter–Xing nets) are written: read bottom-up, as the label suggests, their
//! matrices would not form nets at all (the 4-dimensional one has t = m; read top-down,
//! t = 1, its published quality).
//!
//! Rows past the `K` output digits of [`super::DigitalNetB`] (`b^K >= 2^32`) are dropped:
//! they move a coordinate by less than `b^-K`, below the 0.32 resolution; fewer rows are
//! padded with zero rows. Cost: linear in the file size.

use super::{DigitalNetB, MAX_BASE, is_prime, output_digits};
use crate::error::{Error, Result};

fn bad(what: &'static str) -> Error {
    Error::InvalidParameter { what }
}

/// The generator matrices of a `dnet` or `dnetup` file (see the module docs for the
/// digit order), as a [`DigitalNetB`] with the file's base, dimension and columns.
///
/// ```
/// use qmckit::Sampler;
/// use qmckit::digital::parse_dnet;
/// // 2D, base 2, 3 columns, 3 rows: C_1 = identity (van der Corput), C_2 = reversed
/// // identity (i / 8): the 8-point Hammersley set.
/// let text = "# dnet\n2\n2\n3\n3\n4 2 1\n1 2 4\n";
/// let net = parse_dnet(text)?;
/// assert_eq!(net.len(), 8);
/// assert_eq!(net.sample(1, 0)?, 1 << 31); // 1/2
/// assert_eq!(net.sample(1, 1)?, 1 << 29); // 1/8
/// # Ok::<(), qmckit::Error>(())
/// ```
///
/// # Errors
/// [`Error::InvalidParameter`] naming what is wrong (no `# dnet`/`# dnetup` first line, a
/// missing or non-numeric header value, a base that is not a prime of at most 65521, a
/// matrix line with the wrong number of columns, an entry `>= b^r`, fewer matrix lines than
/// dimensions, or columns past `K`); [`Error::TooLarge`] past the allocation limit.
pub fn parse_dnet(text: &str) -> Result<DigitalNetB<Vec<u16>>> {
    let mut lines = text.lines();
    match lines.next().map(str::trim) {
        Some(l) if l.starts_with('#') && l.trim_start_matches('#').trim().starts_with("dnet") => {}
        _ => {
            return Err(bad(
                "a generator-matrix file must start with '# dnet' or '# dnetup'",
            ));
        }
    }
    let mut header = [0u64; 4];
    let mut got = 0;
    for line in lines.by_ref() {
        let content = line.split('#').next().unwrap_or("").trim();
        if content.is_empty() {
            continue;
        }
        let v = content
            .parse::<u64>()
            .map_err(|_| bad("a dnet header value (b, s, k, r) is not a whole number"))?;
        if let Some(slot) = header.get_mut(got) {
            *slot = v;
        }
        got += 1;
        if got == header.len() {
            break;
        }
    }
    if got < header.len() {
        return Err(bad("a dnet header needs four values: b, s, k, r"));
    }
    let [b, s, k_or_n, r] = header;
    if b < 2 || b > MAX_BASE as u64 || !is_prime(b as u32) {
        return Err(bad("a dnet base must be a prime of at most 65521"));
    }
    let b32 = b as u32;
    let (digits, _) = output_digits(b32)?;
    let s = usize::try_from(s).map_err(|_| bad("a dnet dimension does not fit"))?;
    if s == 0 {
        return Err(bad("a dnet file has fewer matrix lines than dimensions"));
    }
    // The matrix lines: comment lines between the header values and the matrices are
    // skipped too; lines past the s-th are not read.
    let body = lines
        .map(str::trim)
        .filter(|l| !l.is_empty() && !l.starts_with('#'))
        .take(s);
    if r == 0 || r > 64 {
        return Err(bad("a dnet row count r must be 1 to 64"));
    }
    let limit = (b as u128).checked_pow(r as u32).unwrap_or(u128::MAX);
    let mut k = None;
    let mut matrices = Vec::new();
    let mut lines_read = 0usize;
    for line in body {
        // At most K + 1 words are looked at: more columns are refused below.
        let mut cols = [""; super::MAX_DIGITS + 1];
        let mut len = 0;
        for (slot, word) in cols.iter_mut().zip(line.split_whitespace()) {
            *slot = word;
            len += 1;
        }
        let cols = cols.get(..len).unwrap_or(&[]);
        let kk = *k.get_or_insert(cols.len());
        if cols.len() != kk || kk == 0 {
            return Err(bad(
                "every dnet matrix line must hold the same k > 0 columns",
            ));
        }
        if kk > digits {
            return Err(bad(
                "a dnet file has more columns than the 0.32 output can index",
            ));
        }
        lines_read += 1;
        let start = matrices.len();
        // Grows with the file: checked against the allocation limit.
        crate::size::reserve(&mut matrices, digits * kk)?;
        matrices.resize(start + digits * kk, 0u16);
        for (c, word) in cols.iter().enumerate() {
            let mut v = word
                .parse::<u128>()
                .map_err(|_| bad("a dnet column is not a whole number"))?;
            if v >= limit {
                return Err(bad("a dnet column has more than r digits"));
            }
            // The r digits of the column, row 0 first.
            let mut col = [0u16; 64];
            for slot in col.iter_mut().take(r as usize) {
                *slot = (v % b as u128) as u16;
                v /= b as u128;
            }
            col[..r as usize].reverse(); // row 0 is the most significant digit
            for (row, &digit) in col.iter().take((r as usize).min(digits)).enumerate() {
                if let Some(e) = matrices.get_mut(start + row * kk + c) {
                    *e = digit;
                }
            }
        }
    }
    if lines_read < s {
        return Err(bad("a dnet file has fewer matrix lines than dimensions"));
    }
    let k = k.unwrap_or(0);
    let n_matches = (b as u128).checked_pow(k as u32) == Some(k_or_n as u128);
    if k_or_n != k as u64 && !n_matches {
        return Err(bad(
            "a dnet header's k (or b^k) does not match its matrix lines",
        ));
    }
    DigitalNetB::new(b32, s, k, matrices)
}
