//! Domains: independent, deterministic dimensions for a path tracer, derived by key instead
//! of counted.
//!
//! A renderer that counts dimensions (`get_2d` for the lens, then one per bounce, one per
//! light) must keep the count consistent across code paths. A [`Domain`] is instead a
//! node of a tree: a pixel sample `(x, y, i)` and a seed give the root, and each child is
//! derived from its parent by a key ([`Domain::new_domain`]), by splitting the sample into
//! `n` sub-samples ([`Domain::split`]) or by moving to the next link of a chain
//! ([`Domain::chain`], e.g. the next bounce). Each domain holds one 2D dimension pair with
//! its own randomization; [`Domain::draw_2d`] returns it (and [`Domain::draw_1d`] its
//! first coordinate). Two domains with different derivations are independent; one domain
//! over the `spp` samples of a pixel is a scrambled net.
//!
//! ```
//! use qmckit::pixel::domain::{Domain, DomainBase};
//! let (spp, seed) = (16, 7);
//! for i in 0..spp {
//!     let root = Domain::root(DomainBase::OwenSobol, 3, 5, i, spp, seed)?;
//!     let lens = root.new_domain(1).draw_2d_f32();
//!     let mut bounce = root.new_domain(2);
//!     for _ in 0..3 {
//!         let [u, v] = bounce.new_domain(10).draw_2d_f32(); // BSDF
//!         let light = bounce.new_domain(11).draw_1d_f32(); // light choice
//!         assert!(u < 1.0 && v < 1.0 && light < 1.0 && lens[0] < 1.0);
//!         bounce = bounce.chain(); // next bounce
//!     }
//! }
//! # Ok::<(), qmckit::Error>(())
//! ```
//!
//! # The bits (stable)
//!
//! The values below are part of the API: a given `(base, x, y, i, spp, seed)` and
//! derivation give the same bits in every release. With
//!
//! ```text
//! mix(z)       = splitmix64's finalizer: z ^= z >> 30; z *= 0xbf58476d1ce4e5b9;
//!                z ^= z >> 27; z *= 0x94d049bb133111eb; z ^= z >> 31   (mod 2^64)
//! H(s, a, b)   = mix(mix(mix(s + W) ^ (a + 2W)) ^ (b + 3W)),  W = 0x9e3779b97f4a7c15
//!                (qmckit::hash::hash3; all sums mod 2^64)
//! rev(v)       = the 32 bits of v reversed
//! owen(v, k)   = rev(vegdahl(rev(v), k)), vegdahl as qmckit::hash::vegdahl:
//!                z = r ^ r*0x3d20adea; z += k; z *= (k >> 16) | 1;
//!                z ^= z*0x05526c56; z ^= z*0x53a22864   (mod 2^32; pbrt-v4's FastOwen)
//! sobol0(j)    = rev(j);   sobol1(j) = sum (XOR) over the set bits b of j of
//!                c_b, c_0 = 2^31, c_{b+1} = c_b ^ (c_b >> 1)   (Sobol' dimensions 0 and 1)
//! ```
//!
//! the domain's state `s` (never the pixel) follows the chain
//!
//! ```text
//! root(seed)          s = H(seed, 0, ROOT)       ROOT  = 0x524f4f54
//! new_domain(key)     s = H(s, key, NEW)         NEW   = 0x4e455744
//! chain()             s = H(s, 0, CHAIN)         CHAIN = 0x43484149
//! split(key, n, j)    s = H(s, key, SPLIT)       SPLIT = 0x53504c54,
//!                     index = index n + j, len = len n
//! ```
//!
//! (`index` starts as the sample index `i`, `len` as `spp`). A draw takes the pixel's key
//! `k` (64 bits) from the base,
//!
//! ```text
//! OwenSobol             k = H(s, y 2^32 + x, PIXEL)             PIXEL = 0x5049584c
//! OwenSobolTable(T)     k = T[(y + oy) mod S][(x + ox) mod S]   (S = the table's side,
//! LatticeTable(T, g)    (sx, sy) = T[same cell]                  ox = (s >> 32) mod S,
//!                       k = sx + 2^32 sy                         oy = (s >> 48) mod S)
//! ```
//!
//! then the sequence index `j = rev(vegdahl(rev(index), low32 H(s, k, SHUFFLE))) mod 2^m`,
//! `SHUFFLE = 0x53485546`, `m = ceil(log2 len)` (a nested permutation of `[0, 2^m)`: the
//! domain's `len` indices stay inside one block of `2^m`), and returns
//!
//! ```text
//! OwenSobol, OwenSobolTable   o = mix(k):  (owen(sobol0(j), low32 o), owen(sobol1(j), high32 o))
//! LatticeTable(T, g)          (rev(j) + sx, rev(j) g + sy)   (mod 2^32)
//! ```
//!
//! `draw_1d` is the first coordinate of `draw_2d`; the `_f32` forms round as
//! [`pbrt_f32`] (to nearest, at most `1 - 2^-24`).
//!
//! # Properties
//!
//! * **Nets.** The `len` samples of one pixel in one domain have the indices `j` of one
//!   aligned block of `2^m` Sobol' (or lattice) points; for `len = 2^m` they are that whole
//!   block: an Owen-scrambled `(0, m, 2)`-net, or a shifted rank-1 lattice of `2^m`
//!   points. A split by a power of two `n` keeps this for the `len n` sub-samples.
//! * **Independence.** Two domains have unrelated states; their scrambles and their
//!   index permutations differ, so their values are uncorrelated (tested: correlation of
//!   `2^16` draws below `4 / sqrt(2^16)`). With [`DomainBase::OwenSobol`] the pixel enters
//!   the key, so pixels are independent (white error in screen space). With the tables,
//!   every pixel of a domain reads the same offset into a toroidal table optimized so that
//!   neighbouring pixels' errors cancel (blue error; [`super::BlueNoiseSobol`]); two
//!   domains read the same cell with probability `1 / S^2`, and still permute their
//!   indices differently.
//!
//! Cost: a derivation is one `H` (3 `mix`); a draw 2 `H` (hashed base) or one `H` and a
//! table read, a nested permutation and 2 Owen scrambles (lattice: 2 multiply-adds).
//! No allocation, no `std`.

use super::prepared::sobol1_reversed;
use super::{pbrt_f32, sobol0, sobol1};
use crate::bits::reverse_bits;
use crate::error::{Error, Result};
use crate::hash::{hash3, mix64, vegdahl};

/// The tag of [`Domain::root`]: `"ROOT"` as ASCII.
pub const TAG_ROOT: u64 = 0x524f_4f54;
/// The tag of [`Domain::new_domain`]: `"NEWD"`.
pub const TAG_NEW: u64 = 0x4e45_5744;
/// The tag of [`Domain::chain`]: `"CHAI"`.
pub const TAG_CHAIN: u64 = 0x4348_4149;
/// The tag of [`Domain::split`]: `"SPLT"`.
pub const TAG_SPLIT: u64 = 0x5350_4c54;
/// The tag of the hashed pixel key of [`DomainBase::OwenSobol`]: `"PIXL"`.
pub const TAG_PIXEL: u64 = 0x5049_584c;
/// The tag of the index permutation's key: `"SHUF"`.
pub const TAG_SHUFFLE: u64 = 0x5348_5546;

/// The largest table side, `2^12` (a `4096 x 4096` table).
pub const MAX_TABLE_LOG2_SIDE: u32 = 12;

/// A toroidal `S x S` table of per-pixel values (`S = 2^log2_side`), row-major: the cell of
/// pixel `(x, y)` at offset `(ox, oy)` is `((y + oy) mod S) S + (x + ox) mod S`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Table<'t, T> {
    log2_side: u32,
    cells: &'t [T],
}

/// Owen-scrambling keys, one a cell ([`DomainBase::OwenSobolTable`]).
pub type KeyTable<'t> = Table<'t, u32>;
/// Cranley–Patterson shifts `(sx, sy)`, 0.32 fractions, one a cell
/// ([`DomainBase::LatticeTable`]).
pub type ShiftTable<'t> = Table<'t, [u32; 2]>;

impl<'t, T: Copy> Table<'t, T> {
    /// The table of side `2^log2_side` over `cells` (`4^log2_side` of them).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a side past `2^`[`MAX_TABLE_LOG2_SIDE`] or a length
    /// other than `side^2`.
    pub const fn new(log2_side: u32, cells: &'t [T]) -> Result<Self> {
        if log2_side > MAX_TABLE_LOG2_SIDE || cells.len() != 1 << (2 * log2_side) {
            return Err(Error::InvalidParameter {
                what: "a domain table holds side^2 cells, side = 2^k with k <= 12",
            });
        }
        Ok(Table { log2_side, cells })
    }

    /// The side `S`.
    pub const fn side(&self) -> u32 {
        1 << self.log2_side
    }

    /// The cells, row-major.
    pub const fn cells(&self) -> &'t [T] {
        self.cells
    }

    /// The cell of pixel `(x, y)` under the offset of state `s` (see the module
    /// documentation). `O(1)`.
    #[inline]
    pub const fn cell(&self, x: u32, y: u32, s: u64) -> T {
        let mask = (1u32 << self.log2_side) - 1;
        let ox = (s >> 32) as u32 & mask;
        let oy = (s >> 48) as u32 & mask;
        let cx = x.wrapping_add(ox) & mask;
        let cy = y.wrapping_add(oy) & mask;
        self.cells[((cy as usize) << self.log2_side) | cx as usize]
    }
}

/// Where a domain's values come from (see the module documentation for the bits).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DomainBase<'t> {
    /// Owen-scrambled Sobol' (0, 1), the key hashed from the domain and the pixel: every
    /// pixel independent (white error in screen space).
    OwenSobol,
    /// Owen-scrambled Sobol' (0, 1), the key read from a toroidal table at the domain's
    /// offset (blue error when the table is optimized, as [`super::BlueNoiseSobol`]'s).
    OwenSobolTable(KeyTable<'t>),
    /// The rank-1 lattice `(rev(j), rev(j) g)` (`g` odd) in radical-inverse order,
    /// Cranley–Patterson shifted by the table's cell ([`super::BlueNoiseLattice`]).
    LatticeTable(ShiftTable<'t>, u32),
}

/// One 2D dimension pair of one pixel sample: made by [`Domain::root`], derived by
/// [`new_domain`](Domain::new_domain), [`split`](Domain::split) and
/// [`chain`](Domain::chain), drawn by [`draw_2d`](Domain::draw_2d). `Copy`, 64 bytes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Domain<'t> {
    base: DomainBase<'t>,
    x: u32,
    y: u32,
    index: u32,
    len: u64,
    state: u64,
}

impl<'t> Domain<'t> {
    /// The root domain of sample `index` of `spp` in pixel `(x, y)`: state `H(seed, 0,
    /// ROOT)`. The root itself is a domain; its children are independent of it.
    ///
    /// # Errors
    /// [`Error::ZeroPoints`] for `spp = 0`, [`Error::IndexOutOfRange`] for `index >= spp`.
    pub const fn root(
        base: DomainBase<'t>,
        x: u32,
        y: u32,
        index: u32,
        spp: u32,
        seed: u64,
    ) -> Result<Self> {
        if spp == 0 {
            return Err(Error::ZeroPoints);
        }
        if index >= spp {
            return Err(Error::IndexOutOfRange {
                index: index as u64,
                len: spp as u64,
            });
        }
        Ok(Domain {
            base,
            x,
            y,
            index,
            len: spp as u64,
            state: hash3(seed, 0, TAG_ROOT),
        })
    }

    /// A domain from its parts, unchecked (`index < len <= 2^32`): the pixel samplers'
    /// dimensions, whose sample was validated by their start.
    pub(crate) const fn from_parts(
        base: DomainBase<'t>,
        (x, y): (u32, u32),
        index: u32,
        len: u64,
        state: u64,
    ) -> Self {
        Domain {
            base,
            x,
            y,
            index,
            len,
            state,
        }
    }

    /// The child domain of `key`: state `H(s, key, NEW)`. Distinct keys give independent
    /// domains. `O(1)`.
    #[inline]
    #[must_use]
    pub const fn new_domain(&self, key: u64) -> Self {
        Domain {
            state: hash3(self.state, key, TAG_NEW),
            ..*self
        }
    }

    /// The next domain of a chain (the next bounce of a path): state `H(s, 0, CHAIN)`.
    /// `d.chain().chain()` is the third link. `O(1)`.
    #[inline]
    #[must_use]
    pub const fn chain(&self) -> Self {
        Domain {
            state: hash3(self.state, 0, TAG_CHAIN),
            ..*self
        }
    }

    /// Sub-sample `j` of `n` (e.g. `n` light samples a camera sample): state `H(s, key,
    /// SPLIT)`, index `index n + j` of `len n`. For the pixel, the `len n` sub-samples of
    /// the child are one domain: with `n` and `spp` powers of two, one scrambled net of
    /// `spp n` points, not `spp` nets of `n`.
    ///
    /// # Errors
    /// [`Error::IndexOutOfRange`] for `j >= n` (and `n = 0`); [`Error::TooLarge`] when `len
    /// n` passes `2^32`.
    pub const fn split(&self, key: u64, n: u32, j: u32) -> Result<Self> {
        if j >= n {
            return Err(Error::IndexOutOfRange {
                index: j as u64,
                len: n as u64,
            });
        }
        let len = self.len * n as u64;
        if len > 1 << 32 {
            return Err(Error::TooLarge {
                what: "sub-samples of a pixel domain",
                requested: len,
                max: 1 << 32,
            });
        }
        Ok(Domain {
            state: hash3(self.state, key, TAG_SPLIT),
            index: (self.index as u64 * n as u64 + j as u64) as u32,
            len,
            ..*self
        })
    }

    /// The state `s` (the stable hash chain of the module documentation).
    pub const fn state(&self) -> u64 {
        self.state
    }

    /// The sample's index in the domain, `< len`.
    pub const fn index(&self) -> u32 {
        self.index
    }

    /// The samples of the pixel in the domain: `spp` times the splits' `n`.
    pub const fn len(&self) -> u64 {
        self.len
    }

    /// Never: a domain holds at least one sample (for clippy's `len` rule).
    pub const fn is_empty(&self) -> bool {
        false
    }

    /// The pixel.
    pub const fn pixel(&self) -> (u32, u32) {
        (self.x, self.y)
    }

    /// The base.
    pub const fn base(&self) -> DomainBase<'t> {
        self.base
    }

    /// The pixel's 64-bit key `k` (see the module documentation).
    #[inline]
    const fn key(&self) -> u64 {
        match self.base {
            DomainBase::OwenSobol => hash3(
                self.state,
                ((self.y as u64) << 32) | self.x as u64,
                TAG_PIXEL,
            ),
            DomainBase::OwenSobolTable(t) => t.cell(self.x, self.y, self.state) as u64,
            DomainBase::LatticeTable(t, _) => {
                let [sx, sy] = t.cell(self.x, self.y, self.state);
                sx as u64 | (sy as u64) << 32
            }
        }
    }

    /// The sequence index `j`: the nested permutation of `[0, 2^m)` keyed by `H(s, k,
    /// SHUFFLE)`.
    #[inline]
    const fn sequence_index(&self, k: u64) -> u32 {
        let mask = index_mask(self.len);
        let ks = hash3(self.state, k, TAG_SHUFFLE) as u32;
        reverse_bits(vegdahl(reverse_bits(self.index), ks)) & mask
    }

    /// The domain's 2D value, two 0.32 fractions (see the module documentation). `O(1)`.
    #[inline]
    pub const fn draw_2d(&self) -> [u32; 2] {
        let k = self.key();
        let j = self.sequence_index(k);
        match self.base {
            DomainBase::OwenSobol | DomainBase::OwenSobolTable(_) => {
                let o = mix64(k);
                [
                    owen(sobol0(j as u64), o as u32),
                    owen(sobol1(j as u64), (o >> 32) as u32),
                ]
            }
            DomainBase::LatticeTable(_, g) => {
                let r = reverse_bits(j);
                [
                    r.wrapping_add(k as u32),
                    r.wrapping_mul(g).wrapping_add((k >> 32) as u32),
                ]
            }
        }
    }

    /// The domain's 1D value: the first coordinate of [`draw_2d`](Self::draw_2d).
    #[inline]
    pub const fn draw_1d(&self) -> u32 {
        self.draw_2d()[0]
    }

    /// [`draw_2d`](Self::draw_2d) as `f32`s in `[0, 1)` ([`pbrt_f32`]).
    #[inline]
    pub const fn draw_2d_f32(&self) -> [f32; 2] {
        let [a, b] = self.draw_2d();
        [pbrt_f32(a), pbrt_f32(b)]
    }

    /// [`draw_1d`](Self::draw_1d) as an `f32` in `[0, 1)` ([`pbrt_f32`]).
    #[inline]
    pub const fn draw_1d_f32(&self) -> f32 {
        pbrt_f32(self.draw_1d())
    }
}

/// `2^m - 1`, `m = ceil(log2 len)` (all ones for `m >= 32`): the mask of the nested
/// permutation's block.
#[inline]
const fn index_mask(len: u64) -> u32 {
    let m = if len <= 1 {
        0
    } else {
        64 - (len - 1).leading_zeros()
    };
    if m >= 32 { u32::MAX } else { (1u32 << m) - 1 }
}

/// What a prepared fill computes once for a pixel and a state: the key `k`, the shuffle
/// key `low32 H(s, k, SHUFFLE)` and the reversed index mask `rev(2^m - 1)`.
#[inline(always)]
const fn prepare(base: DomainBase<'_>, pixel: (u32, u32), len: u64, state: u64) -> (u64, u32, u32) {
    let k = Domain::from_parts(base, pixel, 0, len, state).key();
    let ks = hash3(state, k, TAG_SHUFFLE) as u32;
    (k, ks, reverse_bits(index_mask(len)))
}

/// The prepared fill of one domain state over a pixel's samples: `out[i]` is the
/// [`Domain::draw_2d`] (converted by `conv`) of the domain with state `state` at sample
/// `i` of `len` in pixel `(x, y)`, for `i < out.len() <= len`. What depends on the pixel
/// and the state (the key `k`, the shuffle key, `mix(k)`) is computed once; per sample
/// the loop works in the bit-reversed domain: `rev(j) = vegdahl(rev(i), ks) & rev(mask)`,
/// Sobol' dimension 0 reversed is `j` and dimension 1 reversed its superset-XOR
/// transform, so an Owen-scrambled pair costs three scrambles and three reversals, and a
/// lattice pair one scramble and no reversal besides the index's; no branch, no division.
/// Bit-identical to the draws (tested).
#[inline(always)]
pub(crate) fn fill_pairs<T>(
    base: DomainBase<'_>,
    pixel: (u32, u32),
    len: u64,
    state: u64,
    out: &mut [[T; 2]],
    conv: impl Fn(u32) -> T,
) {
    let (k, ks, rmask) = prepare(base, pixel, len, state);
    match base {
        DomainBase::OwenSobol | DomainBase::OwenSobolTable(_) => {
            let o = mix64(k);
            let (ka, kb) = (o as u32, (o >> 32) as u32);
            for (i, v) in (0u32..).zip(out.iter_mut()) {
                let j = reverse_bits(vegdahl(reverse_bits(i), ks) & rmask);
                *v = [
                    conv(reverse_bits(vegdahl(j, ka))),
                    conv(reverse_bits(vegdahl(sobol1_reversed(j), kb))),
                ];
            }
        }
        DomainBase::LatticeTable(_, g) => {
            let (sx, sy) = (k as u32, (k >> 32) as u32);
            for (i, v) in (0u32..).zip(out.iter_mut()) {
                let r = vegdahl(reverse_bits(i), ks) & rmask;
                *v = [
                    conv(r.wrapping_add(sx)),
                    conv(r.wrapping_mul(g).wrapping_add(sy)),
                ];
            }
        }
    }
}

/// [`fill_pairs`]' first coordinates: `out[i]` is the [`Domain::draw_1d`] of sample `i`.
#[inline(always)]
pub(crate) fn fill_values<T>(
    base: DomainBase<'_>,
    pixel: (u32, u32),
    len: u64,
    state: u64,
    out: &mut [T],
    conv: impl Fn(u32) -> T,
) {
    let (k, ks, rmask) = prepare(base, pixel, len, state);
    match base {
        DomainBase::OwenSobol | DomainBase::OwenSobolTable(_) => {
            let ka = mix64(k) as u32;
            for (i, v) in (0u32..).zip(out.iter_mut()) {
                let j = reverse_bits(vegdahl(reverse_bits(i), ks) & rmask);
                *v = conv(reverse_bits(vegdahl(j, ka)));
            }
        }
        DomainBase::LatticeTable(..) => {
            let sx = k as u32;
            for (i, v) in (0u32..).zip(out.iter_mut()) {
                *v = conv((vegdahl(reverse_bits(i), ks) & rmask).wrapping_add(sx));
            }
        }
    }
}

/// Hash-based Owen scrambling of a 0.32 fraction: `rev(vegdahl(rev(v), key))`.
#[inline]
const fn owen(v: u32, key: u32) -> u32 {
    reverse_bits(vegdahl(reverse_bits(v), key))
}
