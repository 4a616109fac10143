//! Byte tables of a GF(2) matrix-vector product (the "method of four Russians"): random
//! access to one Sobol' dimension by four table reads.

use super::SobolDimension;

/// The four byte tables of the GF(2) product with columns `cols`: `T_b[v]` is the XOR of
/// `cols[8b + k]` over the set bits `k` of `v`, built as `T[v] = T[v & (v - 1)] ^ col`
/// (1024 XORs).
pub(crate) const fn byte_tables(cols: &[u32; 32]) -> [[u32; 256]; 4] {
    let mut t = [[0u32; 256]; 4];
    let mut b = 0;
    while b < 4 {
        let mut v = 1usize;
        while v < 256 {
            let low = v.trailing_zeros() as usize;
            t[b][v] = t[b][v & (v - 1)] ^ cols[8 * b + low];
            v += 1;
        }
        b += 1;
    }
    t
}

/// Four byte-table reads XORed: the product [`byte_tables`] encodes, at `index`.
#[inline]
pub(crate) const fn byte_product(t: &[[u32; 256]; 4], index: u32) -> u32 {
    t[0][(index & 0xFF) as usize]
        ^ t[1][((index >> 8) & 0xFF) as usize]
        ^ t[2][((index >> 16) & 0xFF) as usize]
        ^ t[3][(index >> 24) as usize]
}

/// One Sobol' dimension's generator matrix unrolled into four byte tables (4 KiB): random
/// access by four table reads and three XORs, `x(i) = T0[i0] ^ T1[i1] ^ T2[i2] ^ T3[i3]` for
/// the bytes `i0..i3` of `i` (the "method of four Russians" for GF(2) matrix-vector
/// products). For hosts, or firmware with RAM or flash to spare; [`SobolDimension::sample`]
/// needs no table.
///
/// ```
/// use qmckit::digital::sobol::{SobolDimension, SobolTable};
/// let d = SobolDimension::new(3)?;
/// let t = SobolTable::new(d);
/// assert_eq!(t.sample(0xDEAD_BEEF), d.sample(0xDEAD_BEEF));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct SobolTable {
    t: [[u32; 256]; 4],
}

impl SobolTable {
    /// The tables of one dimension: 1024 XORs. `const`.
    pub const fn new(dim: SobolDimension) -> Self {
        SobolTable {
            t: byte_tables(dim.directions()),
        }
    }

    /// Natural-order point `index`, the same bits as [`SobolDimension::sample`].
    #[inline]
    pub const fn sample(&self, index: u32) -> u32 {
        byte_product(&self.t, index)
    }
}
