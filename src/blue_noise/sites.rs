//! The sites of the cell diagrams (the power diagrams of BNOT and CCVT in 2D, the exact
//! Voronoi cells of Lloyd in 3D): validation of a flat coordinate slice into fixed-size
//! points, the check that no two sites coincide, and a uniform bucket grid of the sites.
//!
//! Cost: validation `O(N)`, the distinctness check one sort (`O(N log N)`), the buckets two
//! passes over the sites (a counting sort into `g^D` buckets, about two sites a bucket).

use crate::{Error, Result};

/// `D`-dimensional sites from `sites` (row-major, `D` coordinates a site), each in
/// `[0, 1]` (on the torus reduced to `[0, 1)` by `x - floor(x)`).
///
/// # Errors
/// [`Error::ZeroPoints`], [`Error::RaggedPoints`], [`Error::TooManyPoints`] past `max`
/// sites, [`Error::CoordinateOutOfRange`]; an allocation past the size limit.
pub(crate) fn validate<const D: usize>(
    sites: &[f64],
    torus: bool,
    max: usize,
) -> Result<Vec<[f64; D]>> {
    if sites.is_empty() {
        return Err(Error::ZeroPoints);
    }
    if !sites.len().is_multiple_of(D) {
        return Err(Error::RaggedPoints {
            len: sites.len(),
            dims: D,
        });
    }
    let n = sites.len() / D;
    if n > max {
        return Err(Error::TooManyPoints {
            requested: n as u64,
            max: max as u64,
        });
    }
    if let Some(k) = sites.iter().position(|x| !(0.0..=1.0).contains(x)) {
        return Err(Error::CoordinateOutOfRange {
            point: k / D,
            dim: k % D,
        });
    }
    let mut pts = crate::size::vec_with_capacity(n)?;
    pts.extend(sites.chunks_exact(D).map(|p| {
        let mut v = [0.0; D];
        for (v, &x) in v.iter_mut().zip(p) {
            *v = if torus { x - x.floor() } else { x };
        }
        v
    }));
    Ok(pts)
}

/// [`Error::InvalidParameter`] (`what`) when two sites coincide.
///
/// # Errors
/// As above; an allocation past the size limit.
pub(crate) fn check_distinct<const D: usize>(pts: &[[f64; D]], what: &'static str) -> Result<()> {
    let mut order = crate::size::vec_with_capacity(pts.len())?;
    order.extend(pts.iter().copied());
    order.sort_unstable_by(|a, b| {
        a.iter()
            .zip(b)
            .map(|(x, y)| x.total_cmp(y))
            .find(|o| o.is_ne())
            .unwrap_or(core::cmp::Ordering::Equal)
    });
    if order.windows(2).any(|w| w[0] == w[1]) {
        return Err(Error::InvalidParameter { what });
    }
    Ok(())
}

/// The bucket of coordinate `x` in `[0, 1]` on an axis of `g` buckets.
pub(crate) fn bucket_of(x: f64, g: usize) -> usize {
    ((x * g as f64) as usize).min(g - 1)
}

/// The sites in a `g^D` grid of buckets over the unit cube, `g = floor((N / 2)^(1/D))` (at
/// least 1): about two sites a bucket, each bucket's sites in index order.
pub(crate) struct Buckets<const D: usize> {
    /// Buckets an axis.
    pub(crate) g: usize,
    start: Vec<usize>,
    items: Vec<u32>,
}

impl<const D: usize> Buckets<D> {
    /// The buckets along one axis (possibly past the grid, on the torus) that meet
    /// `[x - reach, x + reach]`: clamped to the grid in the cube.
    pub(crate) fn span(&self, x: f64, reach: f64, torus: bool) -> (i64, i64) {
        let g = self.g as i64;
        let (lo, hi) = (
            ((x - reach) * g as f64).floor() as i64,
            ((x + reach) * g as f64).floor() as i64,
        );
        if torus {
            (lo, hi)
        } else {
            (lo.max(0), hi.min(g - 1))
        }
    }

    /// A bucket index of the unrolled torus grid as its bucket in the grid and the period
    /// shift of its copy.
    pub(crate) fn unroll(&self, b: i64) -> (usize, f64) {
        let g = self.g as i64;
        (b.rem_euclid(g) as usize, b.div_euclid(g) as f64)
    }

    /// The buckets of `sites` (coordinates in `[0, 1]`).
    ///
    /// # Errors
    /// An allocation past the size limit.
    pub(crate) fn new(sites: &[[f64; D]]) -> Result<Self> {
        let half = sites.len() as f64 / 2.0;
        let root = match D {
            2 => half.sqrt(),
            3 => half.cbrt(),
            _ => half.powf(1.0 / D as f64),
        };
        let g = (root.floor() as usize).max(1);
        let cells = g.pow(D as u32);
        let cell = |p: &[f64; D]| p.iter().rev().fold(0, |k, &x| k * g + bucket_of(x, g));
        let mut start = crate::size::vec_zeroed::<usize>(cells + 1)?;
        for p in sites {
            start[cell(p) + 1] += 1;
        }
        for k in 0..cells {
            start[k + 1] += start[k];
        }
        let mut fill = start.clone();
        let mut items = crate::size::vec_zeroed::<u32>(sites.len())?;
        for (i, p) in sites.iter().enumerate() {
            let c = cell(p);
            items[fill[c]] = i as u32;
            fill[c] += 1;
        }
        Ok(Buckets { g, start, items })
    }

    /// The sites of bucket `c` (each component below `g`), in index order.
    pub(crate) fn get(&self, c: [usize; D]) -> &[u32] {
        let k = c.iter().rev().fold(0, |k, &x| k * self.g + x);
        self.items
            .get(self.start[k]..self.start[k + 1])
            .unwrap_or(&[])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every site is listed once, in the bucket its coordinates fall in (`floor(x g)`,
    /// `g - 1` for `x = 1`), buckets in index order, in 2D and 3D.
    #[test]
    fn buckets_hold_each_site_where_it_lies() {
        fn check<const D: usize>(n: usize) {
            let mut s = 0x2545_F491_4F6C_DD1Du64;
            let mut pts = vec![[0.0; D]; n];
            for p in &mut pts {
                for x in p.iter_mut() {
                    s ^= s << 13;
                    s ^= s >> 7;
                    s ^= s << 17;
                    *x = (s >> 11) as f64 / (1u64 << 53) as f64;
                }
            }
            pts[0] = [1.0; D];
            let b = Buckets::new(&pts).unwrap();
            let g = b.g;
            let mut seen = vec![0u32; n];
            let mut c = [0usize; D];
            for k in 0..g.pow(D as u32) {
                let mut r = k;
                for x in c.iter_mut() {
                    *x = r % g;
                    r /= g;
                }
                let items = b.get(c);
                assert!(items.windows(2).all(|w| w[0] < w[1]));
                for &i in items {
                    seen[i as usize] += 1;
                    for (x, &cx) in pts[i as usize].iter().zip(&c) {
                        let want = ((x * g as f64).floor() as usize).min(g - 1);
                        assert_eq!(want, cx);
                    }
                }
            }
            assert!(seen.iter().all(|&k| k == 1));
        }
        check::<2>(500);
        check::<3>(700);
    }

    #[test]
    fn validation_and_distinctness() {
        assert!(matches!(
            validate::<3>(&[], false, 10),
            Err(Error::ZeroPoints)
        ));
        assert!(matches!(
            validate::<3>(&[0.1; 4], false, 10),
            Err(Error::RaggedPoints { len: 4, dims: 3 })
        ));
        assert!(matches!(
            validate::<2>(&[0.1; 8], false, 3),
            Err(Error::TooManyPoints { .. })
        ));
        assert!(matches!(
            validate::<2>(&[0.1, 0.2, 0.3, f64::NAN], false, 10),
            Err(Error::CoordinateOutOfRange { point: 1, dim: 1 })
        ));
        assert_eq!(validate::<2>(&[1.0, 0.5], true, 10).unwrap(), [[0.0, 0.5]]);
        assert!(check_distinct(&[[0.5, 0.5, 0.1], [0.5, 0.5, 0.2]], "x").is_ok());
        assert!(check_distinct(&[[0.5, 0.5, 0.1], [0.2, 0.0, 0.0], [0.5, 0.5, 0.1]], "x").is_err());
    }
}
