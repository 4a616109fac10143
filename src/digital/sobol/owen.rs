//! Owen-scrambled Sobol' for hot loops and per-pixel seeds (Burley 2020's use case).
//!
//! `reverse` distributes over XOR, so the bit-reversed Sobol' point is the GF(2) product of
//! the bit-reversed direction numbers with the index; the hash-based Owen scramble works on
//! reversed bits. A sample is therefore
//!
//! ```text
//! x_d(i) = reverse(hash(T0[i0] ^ T1[i1] ^ T2[i2] ^ T3[i3], key_d))
//! ```
//!
//! with `T_b` the byte tables of the reversed direction numbers (`i0..i3` the bytes of `i`)
//! and `key_d = dimension_seed(seed, d)`. The tables of dimensions 0..4 are one
//! seed-independent `static` (16 KiB, interleaved so that a point's four coordinates are
//! four 16-byte rows); the seed lives only in the four keys, so reseeding costs four
//! hashes (nine `mix64`, the seed's own hashed once: [`dimension_seeds`]). Dimensions from 4 on are evaluated from the direction numbers (32 AND/XOR steps).

use super::{SOBOL_DIRECTIONS, SOBOL_MAX_DIMS, Sobol, SobolDimension, byte_tables};
use crate::bits::{reverse_bits, to_f32, to_f32_lanes};
use crate::error::{Error, Result};
use crate::randomize::{FastOwen, FastOwenScrambler, OwenHash, Scrambled, dimension_seeds};
use crate::sampler::{FULL_RANGE, Sampler, check};

mod fill;

/// Dimensions served by the interleaved tables.
pub(super) const TABLE_DIMS: usize = 4;

/// `REVERSED4[b][v][lane]`: the XOR of `reverse(V_(8b + k + 1))` of dimension `lane` over the
/// set bits `k` of `v`. Built by the compiler from the direction numbers (4096 XORs).
static REVERSED4: [[[u32; TABLE_DIMS]; 256]; 4] = interleaved_tables();

const fn interleaved_tables() -> [[[u32; TABLE_DIMS]; 256]; 4] {
    let mut t = [[[0u32; TABLE_DIMS]; 256]; 4];
    let mut lane = 0;
    while lane < TABLE_DIMS {
        let mut rev = [0u32; 32];
        let mut k = 0;
        while k < 32 {
            rev[k] = SOBOL_DIRECTIONS[lane][k].reverse_bits();
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
        lane += 1;
    }
    t
}

/// The four unscrambled, bit-reversed coordinates (dimensions 0..4) of point `index`.
#[inline(always)]
const fn reversed4(index: u32) -> [u32; 4] {
    reversed4_low(index, reversed4_high(index))
}

/// The part of [`reversed4`] from the three upper bytes of `index` (three table reads),
/// shared by every index with the same `index >> 8`.
#[inline(always)]
const fn reversed4_high(index: u32) -> [u32; 4] {
    let r1 = &REVERSED4[1][((index >> 8) & 0xFF) as usize];
    let r2 = &REVERSED4[2][((index >> 16) & 0xFF) as usize];
    let r3 = &REVERSED4[3][(index >> 24) as usize];
    [
        r1[0] ^ r2[0] ^ r3[0],
        r1[1] ^ r2[1] ^ r3[1],
        r1[2] ^ r2[2] ^ r3[2],
        r1[3] ^ r2[3] ^ r3[3],
    ]
}

/// [`reversed4`] from its upper part `high` ([`reversed4_high`] of an index with the same
/// upper three bytes): one table read.
#[inline(always)]
const fn reversed4_low(index: u32, high: [u32; 4]) -> [u32; 4] {
    let r0 = &REVERSED4[0][(index & 0xFF) as usize];
    [
        r0[0] ^ high[0],
        r0[1] ^ high[1],
        r0[2] ^ high[2],
        r0[3] ^ high[3],
    ]
}

/// The reversed coordinates of the first `dims <= TABLE_DIMS` dimensions of points
/// `start, start + 1, ..` into the row-major `out` (whole rows; the caller checked the
/// range): four table reads a point ([`Sobol`]'s [`Base2Digital::fill_reversed`]).
///
/// [`Base2Digital::fill_reversed`]: crate::Base2Digital::fill_reversed
#[cfg(target_pointer_width = "64")]
#[inline]
pub(super) fn fill_reversed(dims: usize, start: u32, out: &mut [u32]) {
    if dims == TABLE_DIMS {
        // Four points (16 values) a store, then the rest point by point.
        let (blocks, rest) = out.as_chunks_mut::<16>();
        let mut i = start;
        for block in blocks.iter_mut() {
            // Consecutive indices: when the four share their upper three bytes, so do their
            // table reads.
            let last = i.wrapping_add(3);
            let r = if i >> 8 == last >> 8 {
                let high = reversed4_high(i);
                [
                    reversed4_low(i, high),
                    reversed4_low(i.wrapping_add(1), high),
                    reversed4_low(i.wrapping_add(2), high),
                    reversed4_low(last, high),
                ]
            } else {
                [
                    reversed4(i),
                    reversed4(i.wrapping_add(1)),
                    reversed4(i.wrapping_add(2)),
                    reversed4(last),
                ]
            };
            *block = core::array::from_fn(|j| r[j / 4][j % 4]);
            i = i.wrapping_add(4);
        }
        let (rows, _) = rest.as_chunks_mut::<TABLE_DIMS>();
        for (k, row) in rows.iter_mut().enumerate() {
            *row = reversed4(i.wrapping_add(k as u32));
        }
        return;
    }
    for (k, row) in out.chunks_exact_mut(dims.max(1)).enumerate() {
        for (o, r) in row.iter_mut().zip(reversed4(start.wrapping_add(k as u32))) {
            *o = r;
        }
    }
}

/// The Sobol' sequence with hash-based Owen scrambling ([`FastOwen`]): the same bits as
/// `Scrambled<Sobol, FastOwen>` with the same seed and hash, at random access cost of four
/// table reads, the hash and one bit reversal (dimensions 0..4), and with a reseed of four
/// hashes ([`with_seed`](Self::with_seed), [`reseed`](Self::reseed)) for a seed per pixel.
/// The value is 32 bytes; the tables are shared by every seed.
///
/// ```
/// use qmckit::digital::sobol::OwenSobol;
/// let s = OwenSobol::new(4, 7)?;
/// let mut px = [[0f32; 4]; 16];
/// for pixel in 0..4u64 {
///     let s = s.with_seed(pixel); // four hashes
///     s.fill_f32(&core::array::from_fn::<u32, 16, _>(|k| k as u32), &mut px)?;
///     assert!(px.iter().flatten().all(|x| (0.0..1.0).contains(x)));
///     assert_eq!(px[5][2], s.sample_f32(5, 2)?);
/// }
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct OwenSobol {
    dims: usize,
    owen: FastOwen,
    keys: [u32; TABLE_DIMS],
}

impl OwenSobol {
    /// `dims` dimensions (`1 <= dims <= SOBOL_MAX_DIMS`) scrambled with Vegdahl's hash and
    /// `seed`. `const`.
    ///
    /// # Errors
    /// [`Error::ZeroDimensions`], [`Error::DimensionOutOfRange`].
    pub const fn new(dims: usize, seed: u64) -> Result<Self> {
        Self::with_hash(dims, seed, OwenHash::Vegdahl)
    }

    /// The given hash. `const`.
    ///
    /// # Errors
    /// As [`new`](Self::new).
    pub const fn with_hash(dims: usize, seed: u64, hash: OwenHash) -> Result<Self> {
        if let Err(e) = Sobol::new(dims) {
            return Err(e);
        }
        Ok(Self::keyed(dims, FastOwen::with_hash(seed, hash)))
    }

    #[inline]
    const fn keyed(dims: usize, owen: FastOwen) -> Self {
        let seed = owen.seed();
        OwenSobol {
            dims,
            owen,
            keys: dimension_seeds(seed, 0),
        }
    }

    /// The same sequence with another seed: four hashes. `const`.
    #[inline]
    pub const fn with_seed(&self, seed: u64) -> Self {
        Self::keyed(self.dims, FastOwen::with_hash(seed, self.owen.hash()))
    }

    /// Sets the seed in place: four hashes.
    #[inline]
    pub fn reseed(&mut self, seed: u64) {
        *self = self.with_seed(seed);
    }

    /// The scramble ([`FastOwen`] with this seed and hash).
    pub const fn fast_owen(&self) -> FastOwen {
        self.owen
    }

    /// Coordinate `dim` of point `index` as a 0.32 fraction. `const`.
    ///
    /// # Errors
    /// [`Error::DimensionOutOfRange`] for `dim >= dims()`.
    #[inline]
    pub const fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        if let Err(e) = check(index, FULL_RANGE, dim, self.dims) {
            return Err(e);
        }
        if dim < TABLE_DIMS {
            let s = FastOwenScrambler::from_key(self.keys[dim], self.owen.hash());
            return Ok(reverse_bits(s.scramble_reversed(reversed4(index)[dim])));
        }
        match SobolDimension::new(dim) {
            Ok(d) => Ok(self.owen.scrambler(dim).scramble(d.sample(index))),
            Err(e) => Err(e),
        }
    }

    /// Coordinate `dim` of point `index` as an `f32` in `[0, 1)` ([`crate::bits::to_f32`]).
    /// `const`.
    ///
    /// # Errors
    /// As [`sample`](Self::sample).
    #[inline]
    pub const fn sample_f32(&self, index: u32, dim: usize) -> Result<f32> {
        match self.sample(index, dim) {
            Ok(x) => Ok(to_f32(x)),
            Err(e) => Err(e),
        }
    }

    /// Dimensions 0..4 of point `index` (whatever [`dims`](Sampler::dims) is), as 0.32
    /// fractions: four table rows, four hashes. `const`.
    #[inline(always)]
    pub const fn sample4(&self, index: u32) -> [u32; 4] {
        let rev = reversed4(index);
        let h = self.owen.hash();
        let mut out = [0u32; 4];
        let mut lane = 0;
        while lane < 4 {
            let s = FastOwenScrambler::from_key(self.keys[lane], h);
            out[lane] = reverse_bits(s.scramble_reversed(rev[lane]));
            lane += 1;
        }
        out
    }

    /// [`sample4`](Self::sample4) as `f32` in `[0, 1)`.
    #[inline(always)]
    pub fn sample4_f32(&self, index: u32) -> [f32; 4] {
        self.sample4(index).map(to_f32_lanes)
    }

    /// `out[k] = sample4_f32(indices[k])` for every `k`, four points (16 lanes) at a time.
    /// On x86-64 with `std` it runs the widest build of the same loop the CPU supports,
    /// detected at run time: AVX-512 with GFNI, else AVX2, else the portable one. The same
    /// bits on every build (tested against [`sample4_f32`](Self::sample4_f32)).
    ///
    /// # Errors
    /// [`Error::BufferLength`] (`expected: indices.len()`, `got: out.len()`) unless the two
    /// slices have the same length; `out` is then left untouched.
    pub fn fill_f32(&self, indices: &[u32], out: &mut [[f32; 4]]) -> Result<()> {
        fill::dispatched(self, indices, out)
    }

    /// A reseeded fill in one call: `indices` in `seeds.len()` equal blocks of `n` points,
    /// block `b` with seed `seeds[b]`, so `out[k] = self.with_seed(seeds[k / n])
    /// .sample4_f32(indices[k])` (the hash and the dimensions are `self`'s). The same values
    /// as [`reseed`](Self::reseed) then [`fill_f32`](Self::fill_f32) block by block; here
    /// the keys of eight seeds are hashed together, as eight lanes (one AVX-512 vector of
    /// `u64`), where a reseed hashes one seed's four keys alone. Runs the widest build
    /// this CPU supports, as [`fill_f32`](Self::fill_f32).
    ///
    /// ```
    /// use qmckit::digital::sobol::OwenSobol;
    /// let s = OwenSobol::new(4, 0)?;
    /// let seeds = [11u64, 12, 13];
    /// let indices: Vec<u32> = (0..3).flat_map(|_| 0..16u32).collect(); // 16 a pixel
    /// let mut px = vec![[0f32; 4]; 48];
    /// s.fill_f32_reseeded(&seeds, &indices, &mut px)?;
    /// assert_eq!(px[16 + 5], s.with_seed(12).sample4_f32(5));
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    ///
    /// # Errors
    /// [`Error::BufferLength`] unless `out` has one slot per index (`expected:
    /// indices.len()`, `got: out.len()`) and `indices.len()` is a multiple of
    /// `seeds.len()` (`expected`: the next multiple, 0 without seeds; `got:
    /// indices.len()`). `out` is then left untouched. No indices is `Ok` with any seeds.
    pub fn fill_f32_reseeded(
        &self,
        seeds: &[u64],
        indices: &[u32],
        out: &mut [[f32; 4]],
    ) -> Result<()> {
        fill::reseeded(self, seeds, indices, out)
    }

    /// The portable build of [`fill_f32`](Self::fill_f32) (what other targets use).
    ///
    /// # Errors
    /// As [`fill_f32`](Self::fill_f32).
    pub fn fill_f32_portable(&self, indices: &[u32], out: &mut [[f32; 4]]) -> Result<()> {
        fill::portable(self, indices, out)
    }
}

impl Sampler for OwenSobol {
    fn dims(&self) -> usize {
        self.dims
    }

    fn len(&self) -> u64 {
        FULL_RANGE
    }

    #[inline]
    fn sample(&self, index: u32, dim: usize) -> Result<u32> {
        OwenSobol::sample(self, index, dim)
    }

    /// Sobol's sequential fill, then the scramble (as `Scrambled<Sobol, FastOwen>`).
    fn fill(&self, start: u32, out: &mut [u32]) -> Result<()> {
        match Sobol::new(self.dims) {
            Ok(sobol) => Scrambled::new(sobol, self.owen).fill(start, out),
            Err(e) => Err(e),
        }
    }
}

/// Coordinate `dim` of point `index` of the Owen-scrambled Sobol' sequence with `seed`
/// (Vegdahl's hash): the same bits as `OwenSobol::new(dim + 1, seed)?.sample(index, dim)`
/// and `Scrambled<Sobol, FastOwen>`. Hashes the seed on every call (three [`crate::hash::mix64`]);
/// for many samples of one seed, hold an [`OwenSobol`]. `const`.
///
/// # Errors
/// [`Error::DimensionOutOfRange`] past [`SOBOL_MAX_DIMS`].
///
/// ```
/// use qmckit::digital::sobol::{OwenSobol, owen_sobol};
/// assert_eq!(owen_sobol(9, 2, 42)?, OwenSobol::new(3, 42)?.sample(9, 2)?);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[inline]
pub const fn owen_sobol(index: u32, dim: usize, seed: u64) -> Result<u32> {
    if dim >= SOBOL_MAX_DIMS {
        return Err(Error::DimensionOutOfRange {
            dim,
            dims: SOBOL_MAX_DIMS,
        });
    }
    let s = FastOwen::new(seed).scrambler(dim);
    if dim < TABLE_DIMS {
        return Ok(reverse_bits(s.scramble_reversed(reversed4(index)[dim])));
    }
    match SobolDimension::new(dim) {
        Ok(d) => Ok(s.scramble(d.sample(index))),
        Err(e) => Err(e),
    }
}

/// [`owen_sobol`] as an `f32` in `[0, 1)`. `const`.
///
/// # Errors
/// As [`owen_sobol`].
#[inline]
pub const fn owen_sobol_f32(index: u32, dim: usize, seed: u64) -> Result<f32> {
    match owen_sobol(index, dim, seed) {
        Ok(x) => Ok(to_f32(x)),
        Err(e) => Err(e),
    }
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// Sobol's reversed fill is its plain fill with every value bit-reversed (1 to 4
    /// dimensions, lengths with a partial block of four points, the last indices of the
    /// range), and `Scrambled<Sobol, FastOwen>`'s fills, which take it, equal sampling value
    /// by value. Past the range it is an error; Gray order and five dimensions are not
    /// served (`None`).
    #[test]
    fn reversed_fill_is_the_reversed_plain_fill() {
        use crate::Base2Digital;
        use crate::digital::sobol::Order;
        for dims in 1..=4usize {
            let sobol = Sobol::new(dims).unwrap();
            let cases = [
                (0u32, 0usize),
                (0, 1),
                (0, 16),
                (254, 9),
                (5, 7),
                (1000, 37),
                (u32::MAX - 6, 7),
            ];
            for (start, n) in cases {
                let mut plain = vec![0u32; n * dims];
                sobol.fill(start, &mut plain).unwrap();
                let mut rev = vec![0u32; n * dims];
                sobol.fill_reversed(start, &mut rev).unwrap().unwrap();
                let reversed: Vec<u32> = plain.iter().map(|x| x.reverse_bits()).collect();
                assert_eq!(rev, reversed, "dims {dims} start {start} n {n}");
                let sc = Scrambled::new(sobol, FastOwen::new(9));
                let mut f = vec![0u32; n * dims];
                sc.fill(start, &mut f).unwrap();
                let mut g = vec![0f32; n * dims];
                sc.fill_as(start, &mut g).unwrap();
                for (k, (&x, &y)) in f.iter().zip(&g).enumerate() {
                    let want = sc.sample(start + (k / dims) as u32, k % dims).unwrap();
                    assert_eq!(x, want, "dims {dims} start {start} k {k}");
                    assert_eq!(y.to_bits(), to_f32(want).to_bits());
                }
            }
            let mut four = vec![0u32; 4 * dims];
            assert!(
                sobol
                    .fill_reversed(u32::MAX - 2, &mut four)
                    .unwrap()
                    .is_err()
            );
        }
        // Gray order and wide points: the reversal folded into the direction numbers.
        for sobol in [
            Sobol::with_order(2, Order::Gray).unwrap(),
            Sobol::with_order(8, Order::Gray).unwrap(),
            Sobol::new(5).unwrap(),
            Sobol::new(21).unwrap(),
        ] {
            let dims = sobol.dims();
            for (start, n) in [(0u32, 1usize), (0, 16), (3, 300), (1 << 20, 33)] {
                let mut plain = vec![0u32; n * dims];
                sobol.fill(start, &mut plain).unwrap();
                let mut rev = vec![0u32; n * dims];
                sobol.fill_reversed(start, &mut rev).unwrap().unwrap();
                let reversed: Vec<u32> = plain.iter().map(|x| x.reverse_bits()).collect();
                assert_eq!(rev, reversed, "dims {dims} start {start} n {n}");
            }
        }
    }
}
