//! Owen scrambling in base 2 (Owen 1995, "Randomly permuted (t,m,s)-nets and
//! (t,s)-sequences"): nested uniform scrambling, exact and hash-based.
//!
//! Nested uniform scrambling flips bit `k` of a 0.32 fraction (k = 1 the most significant)
//! with probability 1/2, independently for every value of the `k - 1` bits above it. The
//! result keeps nets as nets, makes each point uniform, and gives RQMC variance
//! `O(N^-3 (log N)^(s-1))` for smooth integrands.

use super::{Base2Digital, Randomizer, Randomizes, Scrambler, dimension_seed};
use crate::bits::{FromFraction, reverse_bits};
use crate::hash::{laine_karras, mix64, vegdahl};

/// Exact nested uniform scrambling (Owen 1995): one independent random flip per bit prefix,
/// each drawn from a 64-bit hash of `(seed, dimension, k, prefix)`; the tree of flips is
/// never stored. The structure of pbrt-v4's `OwenScrambler`. Cost: 32 [`mix64`] a value
/// (the dimension's key is hashed once, by [`ExactOwen::scrambler`]).
///
/// ```
/// use qmckit::randomize::ExactOwen;
/// let o = ExactOwen::new(3).scrambler(0);
/// // Nested: points sharing their top k bits still share them after scrambling.
/// let (a, b) = (0xABCD_0000u32, 0xABCD_FFFFu32);
/// assert_eq!(o.scramble(a) >> 16, o.scramble(b) >> 16);
/// // ... and differing in bit k, they still differ in bit k.
/// assert_ne!(o.scramble(0x8000_0000) >> 31, o.scramble(0) >> 31);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ExactOwen {
    seed: u64,
}

impl ExactOwen {
    /// The scramble for `seed`.
    pub const fn new(seed: u64) -> Self {
        ExactOwen { seed }
    }

    /// With the seed drawn from `rng`.
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R) -> Self {
        Self::new(rng.next_u64())
    }

    /// The scrambler of dimension `dim`: its 64-bit key,
    /// `mix64(seed ^ (dimension_seed(seed, dim) << 32))`. `const`; four hashes.
    pub const fn scrambler(&self, dim: usize) -> ExactOwenScrambler {
        ExactOwenScrambler {
            key: mix64(self.seed ^ ((dimension_seed(self.seed, dim) as u64) << 32)),
        }
    }

    /// The scrambled coordinate, `self.scrambler(dim).scramble(x)`. `const`.
    pub const fn scramble(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

/// [`ExactOwen`] prepared for one dimension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct ExactOwenScrambler {
    key: u64,
}

impl ExactOwenScrambler {
    /// Flips bit `31 - k` of `x` when `mix64(key ^ (2^k | top k bits of x)) >> 63` is 1, for
    /// `k = 0..32`: every `(k, prefix)` pair is a distinct node of the binary tree. `const`;
    /// 32 hashes.
    pub const fn scramble(&self, x: u32) -> u32 {
        let mut out = x;
        let mut k = 0u32;
        while k < 32 {
            let prefix = if k == 0 { 0 } else { x >> (32 - k) };
            let node = (1u64 << k) | prefix as u64;
            if mix64(self.key ^ node) >> 63 == 1 {
                out ^= 1 << (31 - k);
            }
            k += 1;
        }
        out
    }
}

impl Scrambler for ExactOwenScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        ExactOwenScrambler::scramble(self, x)
    }
}

impl Randomizer for ExactOwen {
    type Scrambler = ExactOwenScrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> ExactOwenScrambler {
        ExactOwen::scrambler(self, dim)
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.scramble(x, dim)
    }
}

impl<S: Base2Digital + ?Sized> Randomizes<S> for ExactOwen {
    super::base2_affine_fill!();
}

/// Which hash [`FastOwen`] uses. Word-sized (`repr(u32)`), so that a
/// [`FastOwenScrambler`] is two whole words and copies of scramblers laid over lanes are
/// single 8-byte moves (no store of a lone byte for a wider load to wait on).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
#[repr(u32)]
pub enum OwenHash {
    /// [`laine_karras`].
    LaineKarras,
    /// [`vegdahl`] (the default).
    #[default]
    Vegdahl,
}

/// Hash-based Owen scrambling: `reverse(hash(reverse(x), key_dim))` with `hash` one of
/// [`vegdahl`] (the default) or [`laine_karras`], `key_dim = dimension_seed(seed, dim)`
/// (Burley 2020, "Practical hash-based Owen scrambling"). Not every nested scramble is
/// reachable (the hash has 32 bits of key), but the result is a nested, bijective scramble
/// that keeps nets, at about a dozen integer operations a value once the dimension's key is
/// hashed ([`FastOwen::scrambler`]).
///
/// ```
/// use qmckit::randomize::{FastOwen, OwenHash};
/// let o = FastOwen::new(5);
/// assert_ne!(o.scramble(0, 0), o.scramble(0, 1)); // dimensions scramble independently
/// let lk = FastOwen::with_hash(5, OwenHash::LaineKarras).scrambler(2);
/// assert_eq!(lk.scramble(0xFFFF_0000) >> 16, lk.scramble(0xFFFF_1234) >> 16);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FastOwen {
    seed: u64,
    hash: OwenHash,
}

impl FastOwen {
    /// Vegdahl's hash with `seed`.
    pub const fn new(seed: u64) -> Self {
        Self::with_hash(seed, OwenHash::Vegdahl)
    }

    /// The given hash with `seed`.
    pub const fn with_hash(seed: u64, hash: OwenHash) -> Self {
        FastOwen { seed, hash }
    }

    /// With the seed drawn from `rng` (Vegdahl's hash).
    #[cfg(feature = "rand_core")]
    pub fn from_rng<R: rand_core::Rng + ?Sized>(rng: &mut R) -> Self {
        Self::new(rng.next_u64())
    }

    /// The seed.
    pub const fn seed(&self) -> u64 {
        self.seed
    }

    /// The hash.
    pub const fn hash(&self) -> OwenHash {
        self.hash
    }

    /// The 32-bit key of dimension `dim`, [`dimension_seed`]`(seed, dim)`.
    #[inline]
    pub const fn dimension_key(&self, dim: usize) -> u32 {
        dimension_seed(self.seed, dim)
    }

    /// The scrambler of dimension `dim` (one hash of the seed). `const`.
    #[inline]
    pub const fn scrambler(&self, dim: usize) -> FastOwenScrambler {
        FastOwenScrambler {
            key: self.dimension_key(dim),
            hash: self.hash,
        }
    }

    /// The scrambled coordinate, `self.scrambler(dim).scramble(x)`. `const`.
    #[inline]
    pub const fn scramble(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

/// [`FastOwen`] prepared for one dimension: the hash and the dimension's 32-bit key.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct FastOwenScrambler {
    key: u32,
    hash: OwenHash,
}

impl FastOwenScrambler {
    /// The scrambler with an explicit 32-bit key (what [`FastOwen::scrambler`] derives from
    /// the seed and the dimension).
    pub const fn from_key(key: u32, hash: OwenHash) -> Self {
        FastOwenScrambler { key, hash }
    }

    /// The key.
    pub const fn key(&self) -> u32 {
        self.key
    }

    /// The hash alone, on a bit-reversed coordinate: `hash(x_rev, key)` (for pipelines that
    /// already hold reversed bits, as the Owen-scrambled Sobol' tables do).
    #[inline]
    pub const fn scramble_reversed(&self, x_rev: u32) -> u32 {
        match self.hash {
            OwenHash::LaineKarras => laine_karras(x_rev, self.key),
            OwenHash::Vegdahl => vegdahl(x_rev, self.key),
        }
    }

    /// `reverse(hash(reverse(x), key))`. `const`.
    #[inline]
    pub const fn scramble(&self, x: u32) -> u32 {
        reverse_bits(self.scramble_reversed(reverse_bits(x)))
    }
}

impl Scrambler for FastOwenScrambler {
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        FastOwenScrambler::scramble(self, x)
    }

    /// The hash chosen once for all lanes (when they share it), then a loop of one hash
    /// over the lanes' keys, which vectorizes.
    #[inline(always)]
    fn scramble_lanes(lanes: &[Self], xs: &mut [u32]) {
        scramble_lanes_from::<false>(lanes, xs);
    }

    /// The hash works on reversed bits: reversed input saves one reversal a value.
    const TAKES_REVERSED: bool = true;

    /// `reverse(hash(x_rev, key))`: the scramble without its first reversal.
    #[inline(always)]
    fn scramble_lanes_reversed(lanes: &[Self], xs: &mut [u32]) {
        scramble_lanes_from::<true>(lanes, xs);
    }

    /// A pattern of 16 lanes sharing one hash (points of 1, 2, 4, 8 or 16 dimensions): the
    /// hash, the reversal, the mask and the conversion in one loop, a vector of 16 values
    /// an iteration. Other patterns: [`scramble_into_by_parts`](super::scramble_into_by_parts).
    #[inline(always)]
    fn scramble_lanes_into<T: FromFraction>(
        lanes: &[Self],
        xs: &mut [u32],
        out: &mut [T],
        reversed: bool,
        keep: u32,
    ) {
        if let (Some(first), Ok(l16)) = (lanes.first(), <&[Self; 16]>::try_from(lanes))
            && l16.iter().all(|l| l.hash == first.hash)
        {
            let keys: [u32; 16] = core::array::from_fn(|j| l16[j].key);
            match (first.hash, reversed) {
                (OwenHash::LaineKarras, true) => {
                    keyed_into::<true, T>(&keys, xs, out, keep, laine_karras);
                }
                (OwenHash::LaineKarras, false) => {
                    keyed_into::<false, T>(&keys, xs, out, keep, laine_karras);
                }
                (OwenHash::Vegdahl, true) => keyed_into::<true, T>(&keys, xs, out, keep, vegdahl),
                (OwenHash::Vegdahl, false) => {
                    keyed_into::<false, T>(&keys, xs, out, keep, vegdahl);
                }
            }
            return;
        }
        super::scramble_into_by_parts(lanes, xs, out, reversed, keep);
    }
}

/// `out[j] = T::from_fraction(reverse(hash(x_rev, keys[j % 16])) & keep)`, with
/// `x_rev = xs[j]` when `REVERSED`, else `reverse(xs[j])`, for `j` below the shorter
/// length: one vector of 16 values an iteration (from the first 64-byte boundary of
/// `out`), then the tail.
#[inline(always)]
fn keyed_into<const REVERSED: bool, T: FromFraction>(
    keys: &[u32; 16],
    xs: &[u32],
    out: &mut [T],
    keep: u32,
    hash: fn(u32, u32) -> u32,
) {
    let one = |x: u32, k: u32| {
        let x = if REVERSED { x } else { reverse_bits(x) };
        T::from_fraction(reverse_bits(hash(x, k)) & keep)
    };
    let n = xs.len().min(out.len());
    let (Some(xs), Some(out)) = (xs.get(..n), out.get_mut(..n)) else {
        return;
    };
    // The values before the first cache-line boundary of `out` one at a time, so that the
    // vector stores are aligned (a store across two lines costs two); the keys turned by
    // as many places to stay in phase.
    let head = out.as_ptr().align_offset(64).min(n);
    let (xs_head, xs) = xs.split_at(head);
    let (out_head, out) = out.split_at_mut(head);
    for ((o, &x), &k) in out_head.iter_mut().zip(xs_head).zip(keys) {
        *o = one(x, k);
    }
    let keys: [u32; 16] = core::array::from_fn(|j| keys[(j + head) % 16]);
    let (xs_full, xs_rest) = xs.as_chunks::<16>();
    let (out_full, out_rest) = out.as_chunks_mut::<16>();
    for (o, x) in out_full.iter_mut().zip(xs_full) {
        for j in 0..16 {
            o[j] = one(x[j], keys[j]);
        }
    }
    for ((o, &x), &k) in out_rest.iter_mut().zip(xs_rest).zip(&keys) {
        *o = one(x, k);
    }
}

/// [`FastOwenScrambler`]'s `scramble_lanes` (`REVERSED = false`) and
/// `scramble_lanes_reversed` (`REVERSED = true`, the input already bit-reversed).
#[inline(always)]
fn scramble_lanes_from<const REVERSED: bool>(lanes: &[FastOwenScrambler], xs: &mut [u32]) {
    let Some(first) = lanes.first() else {
        return;
    };
    let input = |x: u32| if REVERSED { x } else { reverse_bits(x) };
    // A pattern of 16 lanes (points of 1, 2, 4, 8 or 16 dimensions): the keys and the
    // check of the hashes are fixed-size (no loop, no 64-key buffer).
    if let Ok(l16) = <&[FastOwenScrambler; 16]>::try_from(lanes)
        && l16.iter().all(|l| l.hash == first.hash)
    {
        let keys: [u32; 16] = core::array::from_fn(|j| l16[j].key);
        match first.hash {
            OwenHash::LaineKarras => scramble_keyed::<REVERSED>(&keys, xs, laine_karras),
            OwenHash::Vegdahl => scramble_keyed::<REVERSED>(&keys, xs, vegdahl),
        }
        return;
    }
    let mut keys = [0u32; super::ROW_LANES];
    if lanes.len() > keys.len() || lanes.iter().any(|l| l.hash != first.hash) {
        for chunk in xs.chunks_mut(lanes.len()) {
            for (x, s) in chunk.iter_mut().zip(lanes) {
                *x = reverse_bits(s.scramble_reversed(input(*x)));
            }
        }
        return;
    }
    for (k, l) in keys.iter_mut().zip(lanes) {
        *k = l.key;
    }
    let keys = keys.get(..lanes.len()).unwrap_or(&[]);
    match first.hash {
        OwenHash::LaineKarras => scramble_keyed::<REVERSED>(keys, xs, laine_karras),
        OwenHash::Vegdahl => scramble_keyed::<REVERSED>(keys, xs, vegdahl),
    }
}

/// `xs[j] = reverse(hash(reverse(xs[j]), keys[j % keys.len()]))`, without the inner
/// reversal when `REVERSED`. A pattern of 16 lanes (points of 1, 2, 4, 8 or 16 dimensions
/// laid over rows) goes through fixed-size chunks, one vector of the widest build a chunk.
#[inline(always)]
fn scramble_keyed<const REVERSED: bool>(keys: &[u32], xs: &mut [u32], hash: fn(u32, u32) -> u32) {
    let one = |x: u32, k: u32| {
        let x = if REVERSED { x } else { reverse_bits(x) };
        reverse_bits(hash(x, k))
    };
    if let Ok(keys) = <&[u32; 16]>::try_from(keys) {
        let (full, rest) = xs.as_chunks_mut::<16>();
        for chunk in full {
            for (x, &k) in chunk.iter_mut().zip(keys) {
                *x = one(*x, k);
            }
        }
        for (x, &k) in rest.iter_mut().zip(keys) {
            *x = one(*x, k);
        }
        return;
    }
    for chunk in xs.chunks_mut(keys.len().max(1)) {
        for (x, &k) in chunk.iter_mut().zip(keys) {
            *x = one(*x, k);
        }
    }
}

impl Randomizer for FastOwen {
    type Scrambler = FastOwenScrambler;
    #[inline]
    fn scrambler(&self, dim: usize) -> FastOwenScrambler {
        FastOwen::scrambler(self, dim)
    }
    #[inline]
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.scramble(x, dim)
    }
}

impl<S: Base2Digital + ?Sized> Randomizes<S> for FastOwen {
    super::base2_affine_fill!();
}

/// [`ExactOwenScrambler`] with the flips of its top `levels` tree levels tabled: for a
/// batch of values, the flips of level `k` depend only on the top `k` bits of a value, so
/// the top levels are `2^levels - 1` distinct hashes, computed once (a tree walk) rather
/// than once a value. The lower levels are hashed a value at a time, a block of
/// 16 values per level (so the hashes vectorize). Same bits as
/// [`ExactOwenScrambler::scramble`]. `std` only (the table is allocated: `2^levels` `u32`).
#[cfg(feature = "std")]
#[derive(Clone, Debug)]
pub struct ExactOwenTable {
    key: u64,
    levels: u32,
    /// The flips of levels `0 .. levels` for every `levels`-bit prefix.
    flips: std::vec::Vec<u32>,
}

/// Values a block of [`ExactOwenTable::scramble_top_strided`].
#[cfg(feature = "std")]
const OWEN_LANES: usize = 16;

#[cfg(feature = "std")]
impl ExactOwenScrambler {
    /// The table of this scrambler's top `levels` levels (clamped to `1 ..= 24`): `2^levels
    /// - 1` hashes, `2^levels` `u32` of memory. Pays for itself on batches of about
    /// `2^levels` values or more.
    pub fn table(&self, levels: u32) -> ExactOwenTable {
        let levels = levels.clamp(1, 24);
        let mut flips = std::vec![0u32; 1usize << levels];
        // After step k, flips[p] (p < 2^(k+1)) holds the flips of levels 0..=k for the
        // (k+1)-bit prefix p; the parent p >> 1 is read before its slot is overwritten.
        for k in 0..levels {
            for p in (0..1usize << k).rev() {
                let node = (1u64 << k) | p as u64;
                let flip = ((mix64(self.key ^ node) >> 63) as u32) << (31 - k);
                let v = flips.get(p).copied().unwrap_or(0) | flip;
                if let Some(pair) = flips.get_mut(2 * p..2 * p + 2) {
                    pair.fill(v);
                }
            }
        }
        ExactOwenTable {
            key: self.key,
            levels,
            flips,
        }
    }
}

#[cfg(feature = "std")]
impl ExactOwenTable {
    /// The levels tabled.
    pub fn levels(&self) -> u32 {
        self.levels
    }

    /// `scramble(x) & mask` with `mask` the top `bits` bits (`bits` clamped to `1 ..= 32`):
    /// the levels at and below `bits` are not hashed.
    #[inline]
    pub fn scramble_top(&self, x: u32, bits: u32) -> u32 {
        let bits = bits.clamp(1, 32);
        let mut out = x ^ self.top(x);
        for k in self.levels..bits {
            out ^= self.flip(x, k);
        }
        out & (u32::MAX << (32 - bits))
    }

    /// The flips of the tabled levels for `x`.
    #[inline(always)]
    fn top(&self, x: u32) -> u32 {
        // levels in 1..=24: the shift is in range (wrapping only drops the check).
        self.flips
            .get(x.wrapping_shr(32u32.wrapping_sub(self.levels)) as usize)
            .copied()
            .unwrap_or(0)
    }

    /// The flip of level `k` (`1 <= k < 32`) for `x`, in place.
    #[inline(always)]
    fn flip(&self, x: u32, k: u32) -> u32 {
        // 1 <= k < 32: every shift is in range; the wrapping forms only drop the overflow
        // checks (which would keep the lanes from vectorizing).
        let node = 1u64.wrapping_shl(k) | u64::from(x.wrapping_shr(32u32.wrapping_sub(k)));
        ((mix64(self.key ^ node) >> 63) as u32).wrapping_shl(31u32.wrapping_sub(k))
    }

    /// [`scramble_top`](Self::scramble_top) of `xs[0]`, `xs[stride]`, ... in place, with
    /// the widest vector build the CPU runs.
    pub fn scramble_top_strided(&self, xs: &mut [u32], stride: usize, bits: u32) {
        let stride = stride.max(1);
        let bits = bits.clamp(1, 32);
        crate::dispatch::run_at(
            crate::dispatch::level(),
            OwenTopKernel {
                t: self,
                xs,
                stride,
                bits,
            },
        );
    }

    /// Blocks of [`OWEN_LANES`] values, level by level (the hashes of a level are
    /// independent, so the compiler vectorizes them), then the rest one by one.
    #[inline(always)]
    fn scramble_blocks(&self, xs: &mut [u32], stride: usize, bits: u32) {
        let mask = u32::MAX << (32 - bits);
        let count = xs.len().div_ceil(stride);
        let full = count / OWEN_LANES;
        for b in 0..full {
            let base = b * OWEN_LANES * stride;
            let mut x = [0u32; OWEN_LANES];
            for (l, v) in x.iter_mut().enumerate() {
                *v = xs.get(base + l * stride).copied().unwrap_or(0);
            }
            let mut out = [0u32; OWEN_LANES];
            for (o, &v) in out.iter_mut().zip(&x) {
                *o = v ^ self.top(v);
            }
            for k in self.levels..bits {
                for (o, &v) in out.iter_mut().zip(&x) {
                    *o ^= self.flip(v, k);
                }
            }
            for (l, &o) in out.iter().enumerate() {
                if let Some(slot) = xs.get_mut(base + l * stride) {
                    *slot = o & mask;
                }
            }
        }
        for slot in xs.iter_mut().step_by(stride).skip(full * OWEN_LANES) {
            *slot = self.scramble_top(*slot, bits);
        }
    }
}

/// [`ExactOwenTable::scramble_top_strided`] as a dispatched kernel.
#[cfg(feature = "std")]
struct OwenTopKernel<'a> {
    t: &'a ExactOwenTable,
    xs: &'a mut [u32],
    stride: usize,
    bits: u32,
}

#[cfg(feature = "std")]
impl crate::dispatch::Kernel for OwenTopKernel<'_> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        self.t.scramble_blocks(self.xs, self.stride, self.bits);
    }
}

#[cfg(all(test, feature = "std"))]
mod table_tests {
    use super::*;

    /// The tabled scramble against the definition: every level count, masks of 1 to 32
    /// bits, strides, and lengths that leave a partial block.
    #[test]
    fn table_matches_scramble() {
        let xs: std::vec::Vec<u32> = (0..333u64)
            .map(|i| (mix64(i.wrapping_mul(0x9E37_79B9)) >> 7) as u32)
            .chain([0, u32::MAX, 0x8000_0000, 1])
            .collect();
        for seed in [0u64, 5, u64::MAX] {
            for dim in [0usize, 3] {
                let s = ExactOwen::new(seed).scrambler(dim);
                for levels in [1u32, 2, 7, 16, 24] {
                    let t = s.table(levels);
                    for bits in [1u32, 13, 30, 31, 32] {
                        let mask = u32::MAX << (32 - bits);
                        for stride in [1usize, 3] {
                            let mut got = xs.clone();
                            t.scramble_top_strided(&mut got, stride, bits);
                            for (i, (&g, &x)) in got.iter().zip(&xs).enumerate() {
                                let want = if i % stride == 0 {
                                    s.scramble(x) & mask
                                } else {
                                    x
                                };
                                assert_eq!(g, want, "seed {seed} levels {levels} bits {bits}");
                                if i % stride == 0 {
                                    assert_eq!(t.scramble_top(x, bits), want);
                                }
                            }
                        }
                    }
                }
            }
        }
    }
}
