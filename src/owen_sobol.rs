//! Owen-scrambled Sobol' fast paths for hot loops (Burley 2020's use case): byte tables of
//! the bit-reversed direction numbers, so that a sample is table reads, the Owen hash on the
//! reversed value, one bit reversal and a conversion. Same bits as the generic
//! `Scrambled<Sobol, FastOwen>` path (tested).
//!
//! * [`OwenSobolTable`]: one dimension, 4 KiB, random access.
//! * [`OwenSobol4`]: four dimensions interleaved (16 KiB), so the four coordinates of a point
//!   come from four 16-byte table rows and are hashed and converted as one 4-lane vector;
//!   [`OwenSobol4::fill_f32`] processes many indices and, on x86-64 hosts with `std`,
//!   dispatches at run time to an AVX2 build of the same code.

use crate::bits::{reverse_bits, to_f32_via_f64};
use crate::error::Result;
use crate::randomize::FastOwen;
use crate::sobol::{SobolDimension, byte_product, byte_tables};

/// One Sobol' dimension with hash-based Owen scrambling, for random access in hot loops:
/// byte tables of the *bit-reversed* direction numbers (`reverse` distributes over XOR), so
/// a sample is four table reads, the Owen hash on the reversed value, and one reversal:
/// `reverse(hash(T0[i0] ^ T1[i1] ^ T2[i2] ^ T3[i3], key))`. The same bits as
/// `FastOwen::scramble(SobolDimension::sample(i), dim)`. 4 KiB.
///
/// ```
/// use qmckit::randomize::FastOwen;
/// use qmckit::owen_sobol::OwenSobolTable;
/// use qmckit::sobol::SobolDimension;
/// let (d, owen) = (SobolDimension::new(2)?, FastOwen::new(99));
/// let t = OwenSobolTable::new(d, 2, owen);
/// assert_eq!(t.sample(123_456), owen.scramble(d.sample(123_456), 2));
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OwenSobolTable {
    t: [[u32; 256]; 4],
    owen: FastOwen,
    key: u32,
}

impl OwenSobolTable {
    /// Dimension `dim` (whose position `dim_index` keys the scramble) with `owen`. `const`.
    pub const fn new(dim: SobolDimension, dim_index: usize, owen: FastOwen) -> Self {
        let mut rev = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            rev[k] = dim.directions()[k].reverse_bits();
            k += 1;
        }
        let t = byte_tables(&rev);
        OwenSobolTable {
            t,
            owen,
            key: owen.dimension_key(dim_index),
        }
    }

    /// The scrambled point `index` as a 0.32 fraction.
    #[inline]
    pub const fn sample(&self, index: u32) -> u32 {
        let x_rev = byte_product(&self.t, index);
        self.owen.scramble_reversed(x_rev, self.key).reverse_bits()
    }

    /// The scrambled point `index` as an `f32` in `[0, 1)` ([`crate::bits::to_f32`]).
    #[inline]
    pub const fn sample_f32(&self, index: u32) -> f32 {
        crate::bits::to_f32(self.sample(index))
    }
}

/// Four Owen-scrambled Sobol' dimensions with interleaved byte tables: `sample_f32` returns
/// the four coordinates of a point, like `sobol_burley::sample_4d` but for every `u32` index
/// and exact to the bit of the scalar path. 16 KiB.
///
/// ```
/// use qmckit::owen_sobol::{OwenSobol4, OwenSobolTable};
/// use qmckit::randomize::FastOwen;
/// use qmckit::sobol::SobolDimension;
/// let owen = FastOwen::new(5);
/// let dims = [0, 1, 2, 3].map(|d| SobolDimension::new(d).unwrap());
/// let four = OwenSobol4::new(dims, [0, 1, 2, 3], owen);
/// let one = OwenSobolTable::new(dims[2], 2, owen);
/// assert_eq!(four.sample_f32(77)[2], one.sample_f32(77));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct OwenSobol4 {
    /// `t[b][v][lane]`: byte `b` of the index with value `v`, lane = dimension.
    t: [[[u32; 4]; 256]; 4],
    owen: FastOwen,
    keys: [u32; 4],
}

impl OwenSobol4 {
    /// Sobol' dimensions `dims` (0-based), each scrambled as its own position by `owen`:
    /// the usual case of [`OwenSobol4::new`], validated. `const`, so firmware can bake the
    /// 16 KiB of tables into flash.
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`](crate::Error::DimensionOutOfRange) for a dimension past
    /// [`SOBOL_MAX_DIMS`](crate::SOBOL_MAX_DIMS).
    ///
    /// ```
    /// use qmckit::owen_sobol::OwenSobol4;
    /// use qmckit::randomize::FastOwen;
    /// static FOUR: OwenSobol4 = match OwenSobol4::from_dims([0, 1, 2, 3], FastOwen::new(7)) {
    ///     Ok(t) => t,
    ///     Err(_) => panic!(), // a build error, never a run-time panic
    /// };
    /// assert!(OwenSobol4::from_dims([0, 1, 2, 1 << 20], FastOwen::new(7)).is_err());
    /// # let _ = FOUR.sample(5);
    /// ```
    pub const fn from_dims(dims: [usize; 4], owen: FastOwen) -> Result<Self> {
        match (
            SobolDimension::new(dims[0]),
            SobolDimension::new(dims[1]),
            SobolDimension::new(dims[2]),
            SobolDimension::new(dims[3]),
        ) {
            (Ok(a), Ok(b), Ok(c), Ok(d)) => Ok(Self::new([a, b, c, d], dims, owen)),
            (Err(e), _, _, _) | (_, Err(e), _, _) | (_, _, Err(e), _) | (_, _, _, Err(e)) => Err(e),
        }
    }

    /// The dimensions `dims`, scrambled as positions `dim_indices` by `owen`. `const`.
    pub const fn new(dims: [SobolDimension; 4], dim_indices: [usize; 4], owen: FastOwen) -> Self {
        let mut t = [[[0u32; 4]; 256]; 4];
        let mut keys = [0u32; 4];
        let mut lane = 0;
        while lane < 4 {
            let mut rev = [0u32; 32];
            let mut k = 0;
            while k < 32 {
                rev[k] = dims[lane].directions()[k].reverse_bits();
                k += 1;
            }
            let tables = byte_tables(&rev);
            let mut b = 0;
            while b < 4 {
                let mut v = 0;
                while v < 256 {
                    t[b][v][lane] = tables[b][v];
                    v += 1;
                }
                b += 1;
            }
            keys[lane] = owen.dimension_key(dim_indices[lane]);
            lane += 1;
        }
        OwenSobol4 { t, owen, keys }
    }

    /// The four scrambled coordinates of point `index`, as 0.32 fractions.
    #[inline(always)]
    pub fn sample(&self, index: u32) -> [u32; 4] {
        let rows = [
            &self.t[0][(index & 0xFF) as usize],
            &self.t[1][((index >> 8) & 0xFF) as usize],
            &self.t[2][((index >> 16) & 0xFF) as usize],
            &self.t[3][(index >> 24) as usize],
        ];
        let mut x = [0u32; 4];
        for (lane, xl) in x.iter_mut().enumerate() {
            let rev = rows[0][lane] ^ rows[1][lane] ^ rows[2][lane] ^ rows[3][lane];
            *xl = reverse_bits(self.owen.scramble_reversed(rev, self.keys[lane]));
        }
        x
    }

    /// The four scrambled coordinates of point `index` as `f32` in `[0, 1)`.
    #[inline(always)]
    pub fn sample_f32(&self, index: u32) -> [f32; 4] {
        self.sample(index).map(to_f32_via_f64)
    }

    /// `out[k] = sample_f32(indices[k])` for every `k` (the shorter length wins). On x86-64
    /// with `std`, uses an AVX2 build of the same code when the CPU has AVX2.
    pub fn fill_f32(&self, indices: &[u32], out: &mut [[f32; 4]]) {
        #[cfg(all(feature = "std", target_arch = "x86_64"))]
        if std::arch::is_x86_feature_detected!("avx2") {
            // SAFETY: `fill_f32_avx2` only requires the CPU to support AVX2, which was
            // detected at run time on this very CPU just above.
            #[allow(unsafe_code)]
            unsafe {
                self.fill_f32_avx2(indices, out)
            };
            return;
        }
        self.fill_f32_portable(indices, out);
    }

    /// The portable build of [`fill_f32`](Self::fill_f32) (also what other targets use).
    pub fn fill_f32_portable(&self, indices: &[u32], out: &mut [[f32; 4]]) {
        for (o, &i) in out.iter_mut().zip(indices) {
            *o = self.sample_f32(i);
        }
    }

    /// The same loop compiled with AVX2 enabled (the code is identical; the compiler
    /// vectorizes the 32-bit multiplications and bit reversals with AVX2 instructions).
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[target_feature(enable = "avx2")]
    fn fill_f32_avx2(&self, indices: &[u32], out: &mut [[f32; 4]]) {
        for (o, &i) in out.iter_mut().zip(indices) {
            *o = self.sample_f32(i);
        }
    }
}
