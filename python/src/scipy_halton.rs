//! The Halton sequence in SciPy's floating-point arithmetic, so that the points equal
//! `scipy.stats.qmc.Halton`'s to the last bit (qmckit's own Halton is exact in 0.32 fixed
//! point, which differs from SciPy's doubles in the last bits).
//!
//! SciPy computes coordinate `x = sum_j p_j(d_j) b2r_j` from the most significant digit
//! down, one rounded addition a digit, where `d_j` is digit `j` of the index in base `b`,
//! `b2r_0 = 1 / b`, `b2r_(j+1) = b2r_j / b` (each division rounded), and `p_j` is the
//! identity (unscrambled; the sum stops at the last nonzero digit) or SciPy's random
//! permutation of position `j` (scrambled, `count = ceil(54 / log2 b) - 1` positions). Here
//! the weights `b2r_j` are computed once, the scrambled terms `p_j(r) * b2r_j` tabulated
//! once (the same products; unscrambled ones are `r * b2r_j` as they are used), the digits of
//! consecutive indices are counted like an odometer, and each coordinate's sum is taken in
//! the same order, so the bits are SciPy's. Adding the zero terms past the last nonzero
//! digit of an unscrambled index changes nothing (`s + 0.0 == s`).

/// One dimension: its base, the weights `b2r_j`, and for a scrambled sequence the table
/// `terms[j * base + r] = p_j(r) * b2r_j` (the size of SciPy's permutation array). The
/// unscrambled terms `r * b2r_j` are computed as they are used (the same product), so a
/// high base costs no table.
#[derive(Clone, Debug)]
pub struct Dimension {
    base: u64,
    positions: usize,
    weights: Vec<f64>,
    /// Empty for the unscrambled sequence.
    terms: Vec<f64>,
}

/// Digit positions of an index below 2^64 in base `base >= 2` (an upper bound).
fn index_digits(base: u64) -> usize {
    let mut n = 0;
    let mut p: u128 = 1;
    while p < (1u128 << 64) {
        p *= u128::from(base);
        n += 1;
    }
    n
}

impl Dimension {
    /// `perms`: `positions x base` digit images (SciPy's permutations), or `None` for the
    /// unscrambled sequence.
    pub fn new(base: u64, perms: Option<(&[i64], usize)>) -> Result<Self, String> {
        if base < 2 {
            return Err(format!("'base' must be at least 2 (got {base})"));
        }
        let b = base as usize;
        let positions = match perms {
            Some((p, rows)) => {
                if p.len() != rows * b {
                    return Err(format!(
                        "permutations of base {base} must have shape (positions, {base})"
                    ));
                }
                rows
            }
            None => index_digits(base),
        };
        let mut weights = Vec::with_capacity(positions);
        let mut b2r = 1.0 / base as f64;
        for _ in 0..positions {
            weights.push(b2r);
            b2r /= base as f64;
        }
        let mut terms = Vec::new();
        if let Some((p, _)) = perms {
            terms
                .try_reserve_exact(positions * b)
                .map_err(|_| format!("no memory for the digit tables of base {base}"))?;
            for (j, w) in weights.iter().enumerate() {
                for r in 0..b {
                    terms.push(p.get(j * b + r).copied().unwrap_or(0) as f64 * w);
                }
            }
        }
        Ok(Dimension {
            base,
            positions,
            weights,
            terms,
        })
    }

    /// Coordinates of indices `start, start + 1, ..` into `out[k * stride + offset]` for
    /// every `k < rows`.
    fn fill_column(&self, start: u64, rows: usize, out: &mut [f64], stride: usize, offset: usize) {
        const BLOCK: usize = 64;
        let b = self.base;
        let bu = b as usize;
        let positions = self.positions;
        // Digits of the current index, least significant first.
        let mut digits = vec![0u64; positions];
        let mut q = start;
        for d in digits.iter_mut() {
            *d = q % b;
            q /= b;
        }
        // The digit positions that can be nonzero in this range (unscrambled tables stop
        // adding there; the permuted tables add every position, as SciPy does).
        let last = start.saturating_add(rows as u64);
        let mut used = 0;
        let mut p = last;
        while p > 0 {
            used += 1;
            p /= b;
        }
        let used = used.min(positions);
        let mut block_digits = vec![0u32; BLOCK * positions];
        let mut sums = [0f64; BLOCK];
        let mut row = 0;
        while row < rows {
            let n = BLOCK.min(rows - row);
            for k in 0..n {
                for (j, d) in digits.iter().enumerate() {
                    if let Some(slot) = block_digits.get_mut(j * BLOCK + k) {
                        *slot = *d as u32;
                    }
                }
                // Next index: add one with carries.
                for d in digits.iter_mut() {
                    *d += 1;
                    if *d < b {
                        break;
                    }
                    *d = 0;
                }
            }
            sums[..n].fill(0.0);
            // Positions with digits beyond the range are zero: an unscrambled table adds
            // 0.0 there, so they are skipped; a permuted one adds p_j(0).
            if self.terms.is_empty() {
                for (j, &w) in self.weights.iter().enumerate().take(used) {
                    let ds = block_digits.get(j * BLOCK..j * BLOCK + n).unwrap_or(&[]);
                    for (s, &d) in sums.iter_mut().zip(ds) {
                        *s += d as f64 * w;
                    }
                }
            } else {
                for j in 0..positions {
                    let row_terms = self.terms.get(j * bu..(j + 1) * bu).unwrap_or(&[]);
                    let ds = block_digits.get(j * BLOCK..j * BLOCK + n).unwrap_or(&[]);
                    for (s, &d) in sums.iter_mut().zip(ds) {
                        *s += row_terms.get(d as usize).copied().unwrap_or(0.0);
                    }
                }
            }
            for (k, s) in sums.iter().take(n).enumerate() {
                if let Some(o) = out.get_mut((row + k) * stride + offset) {
                    *o = *s;
                }
            }
            row += n;
        }
    }
}

/// A Halton sequence in SciPy's arithmetic.
#[derive(Clone, Debug)]
pub struct ScipyHalton {
    dims: Vec<Dimension>,
}

impl ScipyHalton {
    pub fn new(dims: Vec<Dimension>) -> Self {
        ScipyHalton { dims }
    }

    pub fn dims(&self) -> usize {
        self.dims.len()
    }

    /// Rows `start ..` (row-major, `dims()` values a row), split over `workers` threads.
    pub fn fill(&self, start: u64, out: &mut [f64], workers: usize) {
        let d = self.dims.len();
        if d == 0 {
            return;
        }
        let _ = crate::fill::split_rows(out, d, workers, &|row, part: &mut [f64]| {
            let rows = part.len() / d;
            for (k, dim) in self.dims.iter().enumerate() {
                dim.fill_column(start + row as u64, rows, part, d, k);
            }
            Ok::<(), ()>(())
        });
    }
}
