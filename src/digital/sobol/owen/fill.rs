//! The loops of [`OwenSobol::fill_f32`]: dimensions 0..4 of many points as `f32`, each
//! value `to_f32(reverse(hash(T0[i0] ^ T1[i1] ^ T2[i2] ^ T3[i3], key_d)))`, compiled once
//! per build of [`crate::dispatch`] (the portable one, AVX2, AVX-512 with GFNI).
//!
//! Sixteen values (four points) form one array of lanes, so the table XOR, the hash, the
//! reversal and the conversion are 16 lanes of identical work that the compiler maps onto
//! the build's vectors. The last step, `to_f32(reverse(h))`, is the build's cheapest form
//! of the same function ([`Finish`]): [`reversed_to_f32`] (five integer operations, no
//! leading-zero count) in the portable and AVX2 builds, and in the AVX-512 build the
//! reversal (two instructions with GFNI) and one conversion rounding toward zero, which is
//! [`crate::bits::to_f32`]'s truncation to 24 significant bits in one instruction.

use super::{OwenSobol, TABLE_DIMS};
#[cfg(target_pointer_width = "64")]
use super::{REVERSED4, reversed4, reversed4_high, reversed4_low};
use crate::bits::reversed_to_f32;
use crate::dispatch::{self, Kernel};
use crate::error::{Error, Result};
use crate::hash::{hash3_key, hash3_keyed, laine_karras, vegdahl_multiplier, vegdahl_prepared};
use crate::randomize::{FastOwen, OwenHash, dimension_seeds};

mod reseeded;
pub(super) use reseeded::reseeded;
#[cfg(all(test, feature = "std"))]
use reseeded::reseeded_at;

/// The third argument of the hash in [`crate::randomize::dimension_seed`].
const DIMENSION_SALT: u64 = 0x5EED;

/// `2^-32` as `f32` (exact).
#[cfg(all(feature = "std", target_arch = "x86_64"))]
const INV_2_POW_32: f32 = 1.0 / 4_294_967_296.0;

/// `out[k] = s.sample4_f32(indices[k])` in the widest build this CPU runs.
///
/// # Errors
/// [`Error::BufferLength`] unless the lengths agree (`out` untouched).
pub(super) fn dispatched(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) -> Result<()> {
    check_lengths(indices, out)?;
    // One pixel's run of 16 (the per-pixel call) through its own small kernel, so that the
    // call does not pay the general loop's set-up and register saves.
    #[cfg(target_pointer_width = "64")]
    if let (Ok(i16), Ok(o16)) = (
        <&[u32; 16]>::try_from(indices),
        <&mut [[f32; 4]; 16]>::try_from(&mut *out),
    ) && is_aligned_run(i16, Lanes)
    {
        let first = i16[0];
        dispatch::run_at(dispatch::level(), Run16 { s, first, out: o16 });
        return Ok(());
    }
    dispatched_general(s, indices, out);
    Ok(())
}

/// [`dispatched`] past its one-run case (lengths checked).
#[inline(never)]
fn dispatched_general(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    dispatch::run_at(dispatch::level(), Fill4 { s, indices, out });
}

/// Points `first .. first + 16` (`first` a multiple of 16): [`run16_f32`] compiled once
/// per build.
#[cfg(target_pointer_width = "64")]
struct Run16<'a> {
    s: &'a OwenSobol,
    first: u32,
    out: &'a mut [[f32; 4]; 16],
}

#[cfg(target_pointer_width = "64")]
impl Kernel for Run16<'_> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        run16_hashed(
            &self.s.keys,
            self.s.owen.hash(),
            self.first,
            self.out,
            Lanes,
        );
    }
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[inline(always)]
    fn run_avx512(self, cpu: dispatch::Avx512) {
        run16_hashed(&self.s.keys, self.s.owen.hash(), self.first, self.out, cpu);
    }
}

/// [`run16_f32`] of one seed's `keys` with the hash chosen at run time.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn run16_hashed<F: Finish>(
    keys: &[u32; TABLE_DIMS],
    hash: OwenHash,
    first: u32,
    out: &mut [[f32; 4]; 16],
    finish: F,
) {
    let high = spread(reversed4_high(first));
    match hash {
        OwenHash::Vegdahl => run16_f32(&Vegdahl16::prepare(keys), &high, first, out, finish),
        OwenHash::LaineKarras => {
            run16_f32(&LaineKarras16::prepare(keys), &high, first, out, finish);
        }
    }
}

/// The four lanes of a point spread over the 16 lanes of four points.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn spread(x: [u32; TABLE_DIMS]) -> [u32; 16] {
    core::array::from_fn(|k| x[k % TABLE_DIMS])
}

/// The nested hash on 16 lanes (four points, lane `k` of dimension `k % 4`) with one seed's
/// four keys, whatever depends on the keys alone computed once, by [`prepare`](Self::prepare),
/// before the loops (the same bits as [`crate::hash::vegdahl`] or
/// [`crate::hash::laine_karras`] lane by lane).
trait Hash16: Copy {
    /// The keys spread over the lanes, and their parts of the hash.
    #[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
    fn prepare(keys: &[u32; TABLE_DIMS]) -> Self;
    /// `hash(x[k], keys[k % 4])` for every lane `k`.
    #[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
    fn hash16(&self, x: &[u32; 16]) -> [u32; 16];
}

/// Vegdahl's hash with the keys and their odd multipliers ([`vegdahl_multiplier`]) as lanes.
#[derive(Clone, Copy)]
struct Vegdahl16 {
    key: [u32; 16],
    multiplier: [u32; 16],
}

impl Hash16 for Vegdahl16 {
    #[inline(always)]
    fn prepare(keys: &[u32; TABLE_DIMS]) -> Self {
        let key: [u32; 16] = core::array::from_fn(|k| keys[k % TABLE_DIMS]);
        Vegdahl16 {
            key,
            multiplier: key.map(vegdahl_multiplier),
        }
    }
    #[inline(always)]
    fn hash16(&self, x: &[u32; 16]) -> [u32; 16] {
        let mut h = [0u32; 16];
        for k in 0..16 {
            h[k] = vegdahl_prepared(x[k], self.key[k], self.multiplier[k]);
        }
        h
    }
}

/// The Laine–Karras hash with the keys as lanes.
#[derive(Clone, Copy)]
struct LaineKarras16 {
    key: [u32; 16],
}

impl Hash16 for LaineKarras16 {
    #[inline(always)]
    fn prepare(keys: &[u32; TABLE_DIMS]) -> Self {
        LaineKarras16 {
            key: core::array::from_fn(|k| keys[k % TABLE_DIMS]),
        }
    }
    #[inline(always)]
    fn hash16(&self, x: &[u32; 16]) -> [u32; 16] {
        let mut h = [0u32; 16];
        for k in 0..16 {
            h[k] = laine_karras(x[k], self.key[k]);
        }
        h
    }
}

/// As [`dispatched`], always the portable build.
///
/// # Errors
/// As [`dispatched`].
pub(super) fn portable(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) -> Result<()> {
    check_lengths(indices, out)?;
    fill_blocks(s, indices, out, Lanes);
    Ok(())
}

/// The four-dimensional `f32` fill, compiled once per build ([`crate::dispatch::Kernel`]).
struct Fill4<'a> {
    s: &'a OwenSobol,
    indices: &'a [u32],
    out: &'a mut [[f32; 4]],
}

impl Kernel for Fill4<'_> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        fill_blocks(self.s, self.indices, self.out, Lanes);
    }
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[inline(always)]
    fn run_avx512(self, cpu: dispatch::Avx512) {
        fill_blocks(self.s, self.indices, self.out, cpu);
    }
}

/// [`OwenSobol::fill_f32`] (lengths already checked) with the widest build that is at most
/// `want` and that the CPU runs (for the test of every build).
#[cfg(all(test, feature = "std"))]
fn fill_f32_at(want: dispatch::Level, s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]]) {
    dispatch::run_at(want, Fill4 { s, indices, out });
}

/// `Ok` when `out` has one slot per index.
fn check_lengths(indices: &[u32], out: &[[f32; 4]]) -> Result<()> {
    if indices.len() == out.len() {
        Ok(())
    } else {
        Err(Error::BufferLength {
            expected: indices.len(),
            got: out.len(),
        })
    }
}

/// `to_f32(reverse(h))` on sixteen hashed lanes, in the form a build does best; every form
/// gives the bits of [`crate::bits::to_f32`] of the reversal.
trait Finish: Copy {
    /// The sixteen values (32-bit targets go point by point and do not call it).
    #[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
    fn f32x16(self, h: &[u32; 16]) -> [f32; 16];

    /// `a == b` for all 16 lanes.
    #[cfg_attr(not(target_pointer_width = "64"), allow(dead_code))]
    #[inline(always)]
    fn lanes_equal(self, a: &[u32; 16], b: &[u32; 16]) -> bool {
        let mut same = true;
        for (a, b) in a.iter().zip(b) {
            same &= a == b;
        }
        same
    }
}

/// [`reversed_to_f32`] lane by lane (the portable and AVX2 builds).
#[derive(Clone, Copy)]
struct Lanes;

impl Finish for Lanes {
    #[inline(always)]
    fn f32x16(self, h: &[u32; 16]) -> [f32; 16] {
        let mut y = [0f32; 16];
        for (y, &h) in y.iter_mut().zip(h) {
            *y = reversed_to_f32(h);
        }
        y
    }
}

/// The AVX-512 build: the reversal, then the conversion rounding toward zero (the 24
/// leading significant bits, as `to_f32` keeps) and the exact scaling by 2^-32.
#[cfg(all(feature = "std", target_arch = "x86_64"))]
impl Finish for dispatch::Avx512 {
    #[inline(always)]
    fn f32x16(self, h: &[u32; 16]) -> [f32; 16] {
        let mut r = [0u32; 16];
        for (r, &h) in r.iter_mut().zip(h) {
            *r = h.reverse_bits();
        }
        let mut y = self.u32_to_f32_toward_zero(r);
        for y in &mut y {
            *y *= INV_2_POW_32;
        }
        y
    }

    #[inline(always)]
    fn lanes_equal(self, a: &[u32; 16], b: &[u32; 16]) -> bool {
        dispatch::Avx512::lanes_equal(self, *a, *b)
    }
}

/// The loop of every [`OwenSobol::fill_f32`] build (the lengths are checked by the caller;
/// the shorter one bounds the loop), for the sampler's hash ([`fill_with`]).
#[inline(always)]
fn fill_blocks<F: Finish>(s: &OwenSobol, indices: &[u32], out: &mut [[f32; 4]], finish: F) {
    let n = indices.len().min(out.len());
    let (indices, out) = (
        indices.get(..n).unwrap_or(&[]),
        out.get_mut(..n).unwrap_or(&mut []),
    );
    // One pixel's run of 16 (the per-pixel call): straight to its loop, before the set-up
    // of the general one.
    #[cfg(target_pointer_width = "64")]
    if let (Ok(i16), Ok(o16)) = (
        <&[u32; 16]>::try_from(indices),
        <&mut [[f32; 4]; 16]>::try_from(&mut *out),
    ) && is_aligned_run(i16, finish)
    {
        run16_hashed(&s.keys, s.owen.hash(), i16[0], o16, finish);
        return;
    }
    match s.owen.hash() {
        OwenHash::Vegdahl => fill_with::<Vegdahl16, F>(s, indices, out, finish),
        OwenHash::LaineKarras => fill_with::<LaineKarras16, F>(s, indices, out, finish),
    }
}

/// [`fill_blocks`] with the hash `H` (equal lengths): on 64-bit targets runs of 16 points
/// and blocks of four ([`fill16`], [`block_f32`]), the keys' parts of the hash prepared once
/// for the whole call; the last `len % 4` points go one by one. 32-bit targets go point by
/// point (small code).
#[inline(always)]
fn fill_with<H: Hash16, F: Finish>(
    s: &OwenSobol,
    indices: &[u32],
    out: &mut [[f32; 4]],
    finish: F,
) {
    #[cfg(target_pointer_width = "64")]
    let (indices, out) = {
        let h = H::prepare(&s.keys);
        let (idx16, idx_rest) = indices.as_chunks::<16>();
        let (out16, out_rest) = out.as_chunks_mut::<16>();
        fill16(&h, idx16, out16, finish);
        let (idx4, idx_rest) = idx_rest.as_chunks::<4>();
        let (out4, out_rest) = out_rest.as_chunks_mut::<4>();
        for (o, i) in out4.iter_mut().zip(idx4) {
            *o = block_f32(&h, i, finish);
        }
        (idx_rest, out_rest)
    };
    #[cfg(not(target_pointer_width = "64"))]
    let _ = finish;
    for (o, &i) in out.iter_mut().zip(indices) {
        *o = s.sample4_f32(i);
    }
}

/// Sixteen points at a time: a run of 16 consecutive indices from a multiple of 16 (a
/// pixel's samples, a sequential fill) as whole rows of the low-byte table
/// ([`run16_f32`]), other indices as four blocks of four ([`block_f32`]). The upper part
/// of the table XOR ([`reversed4_high`]) is kept from one run to the next while the runs
/// share their upper three bytes (16 runs in a row in a sequential fill).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn fill16<H: Hash16, F: Finish>(
    h: &H,
    indices: &[[u32; 16]],
    out: &mut [[[f32; 4]; 16]],
    finish: F,
) {
    // `index >> 8` of the runs `high` belongs to: none yet (`index >> 8 < 2^24`).
    let mut upper = u32::MAX;
    let mut high = [0u32; 16];
    // The first index of the next run if the runs go on (a sequential fill).
    let mut next = indices.first().map_or(0, |i| i[0]);
    for (o, i) in out.iter_mut().zip(indices) {
        let first = if is_run_from(i, next, finish) {
            Some(next)
        } else if is_aligned_run(i, finish) {
            Some(i[0])
        } else {
            None
        };
        if let Some(first) = first {
            next = first.wrapping_add(16);
            if first >> 8 != upper {
                upper = first >> 8;
                high = spread(reversed4_high(first));
            }
            run16_f32(h, &high, first, o, finish);
        } else {
            let (o4, _) = o.as_chunks_mut::<4>();
            let (i4, _) = i.as_chunks::<4>();
            for (o, i) in o4.iter_mut().zip(i4) {
                *o = block_f32(h, i, finish);
            }
        }
    }
}

/// `true` when `idx` is `i, i + 1, .., i + 15` with `i` a multiple of 16 (so the 16 share
/// their upper three bytes and their low bytes are one run of table rows).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn is_aligned_run(idx: &[u32; 16], finish: impl Finish) -> bool {
    is_run_from(idx, idx[0] & !15, finish)
}

/// `true` when `idx` is `first, first + 1, .., first + 15` and `first` is a multiple of 16:
/// `idx[k] ^ k == first` for every lane (then `first ^ k = first + k`; with the low bits of
/// `first` set, lane 0 differs). With `first` a predicted value (the previous run's plus
/// 16) rather than a read of `idx[0]`, this is one vector XOR and compare.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn is_run_from(idx: &[u32; 16], first: u32, finish: impl Finish) -> bool {
    let run: [u32; 16] = core::array::from_fn(|k| first ^ k as u32);
    first.is_multiple_of(16) && finish.lanes_equal(idx, &run)
}

/// Sixteen points `first .. first + 16` (`first` a multiple of 16) into `out` as 64
/// lanes: the low-byte table's 16 consecutive rows XORed with the shared upper part, then
/// the hash and [`Finish`] on four arrays of 16 lanes (four AVX-512 vectors).
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn run16_f32<H: Hash16, F: Finish>(
    h: &H,
    high: &[u32; 16],
    first: u32,
    out: &mut [[f32; 4]; 16],
    finish: F,
) {
    let low = (first & 0xF0) as usize;
    let Some(Ok(rows)) = REVERSED4[0]
        .as_flattened()
        .get(4 * low..4 * low + 64)
        .map(<&[u32; 64]>::try_from)
    else {
        return; // unreachable: low + 16 <= 256
    };
    // Computed in a local array and stored in one copy: the loop then reads and writes
    // only its own arrays, so it compiles to straight vector code (no run-time overlap
    // check against `out`), and the key-only parts of the hash are computed once.
    let mut y = [0f32; 64];
    let (ys, _) = y.as_chunks_mut::<16>();
    let (rows, _) = rows.as_chunks::<16>();
    for (o, r) in ys.iter_mut().zip(rows) {
        let mut x = [0u32; 16];
        for k in 0..16 {
            x[k] = r[k] ^ high[k];
        }
        *o = finish.f32x16(&h.hash16(&x));
    }
    out.as_flattened_mut().copy_from_slice(&y);
}

/// Four points as 16 lanes: point `p`'s table rows XORed into lanes `4p .. 4p + 4`, then the
/// hash over all 16 with the keys spread to 16 lanes, and [`Finish`].
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn block_f32<H: Hash16, F: Finish>(h: &H, idx: &[u32; 4], finish: F) -> [[f32; 4]; 4] {
    let mut x = [0u32; 16];
    // Four indices with the same upper three bytes (consecutive ones, 63 blocks in 64)
    // share those bytes' table reads: 7 reads for the block instead of 16.
    let shared = idx[0] >> 8;
    if idx.iter().all(|&i| i >> 8 == shared) {
        let high = reversed4_high(idx[0]);
        for (p, &index) in idx.iter().enumerate() {
            let rev = reversed4_low(index, high);
            for lane in 0..4 {
                x[(4 * p + lane) % 16] = rev[lane];
            }
        }
    } else {
        for (p, &index) in idx.iter().enumerate() {
            let rev = reversed4(index);
            for lane in 0..4 {
                x[(4 * p + lane) % 16] = rev[lane];
            }
        }
    }
    let y = finish.f32x16(&h.hash16(&x));
    core::array::from_fn(|p| core::array::from_fn(|lane| y[(4 * p + lane) % 16]))
}

#[cfg(all(test, feature = "std"))]
mod tests {
    use super::*;

    /// Every build the CPU runs, on lengths leaving 0 to 3 points past the blocks of four
    /// and on unequal lengths, for both hashes, against the scalar `sample4_f32`.
    #[test]
    fn every_build_matches_the_scalar_path() {
        // Consecutive runs (blocks sharing their upper bytes, and blocks across a 256
        // boundary), then scattered indices.
        let indices: Vec<u32> = (0..40u32)
            .chain(250..262)
            .chain((0..4099u32).map(|k| k.wrapping_mul(2_654_435_761) ^ (k >> 3)))
            .chain([0, 1, 255, 256, u32::MAX])
            .chain(4096..4160)
            .chain(0xFFFF_FFF0..=u32::MAX)
            .chain(4000..4040)
            .collect();
        for hash in [OwenHash::Vegdahl, OwenHash::LaineKarras] {
            let s = OwenSobol::with_hash(4, 77, hash).unwrap();
            for len in [
                0,
                1,
                2,
                3,
                4,
                5,
                6,
                7,
                16,
                17,
                33,
                4101,
                4103,
                indices.len(),
            ] {
                for lv in dispatch::levels() {
                    let mut out = vec![[-1f32; 4]; len];
                    fill_f32_at(lv, &s, &indices[..len], &mut out);
                    for (k, o) in out.iter().enumerate() {
                        let want = s.sample4_f32(indices[k]).map(f32::to_bits);
                        assert_eq!(o.map(f32::to_bits), want, "{lv:?} {hash:?} len {len} k {k}");
                    }
                }
            }
        }
    }

    /// Every build of the reseeded fill against a reseed and the scalar `sample4_f32`
    /// point by point (whose keys come from `dimension_seeds`, not from the eight-lane
    /// `keys8`): 1 to 19 seeds (whole groups of eight and the rest), blocks that are aligned
    /// runs of 16 (one after another, across a 256-point boundary, and all the same run),
    /// runs of 16 not starting at a multiple of 16, and blocks of 1, 5 and 33 scattered
    /// indices; both hashes.
    #[test]
    fn every_build_of_the_reseeded_fill_matches_reseeding() {
        let scattered: Vec<u32> = (0..19 * 33u32)
            .map(|k| k.wrapping_mul(2_654_435_761) ^ (k >> 2))
            .collect();
        for hash in [OwenHash::Vegdahl, OwenHash::LaineKarras] {
            let s = OwenSobol::with_hash(4, 5, hash).unwrap();
            for n_seeds in [1usize, 7, 8, 9, 16, 19] {
                let seeds: Vec<u64> = (0..n_seeds as u64)
                    .map(|p| crate::hash::mix64(p ^ 0xABCD) ^ (p << 60))
                    .collect();
                let aligned: Vec<u32> = (0..16 * n_seeds as u32).map(|k| k + 4096).collect();
                let shifted: Vec<u32> = (0..16 * n_seeds as u32).map(|k| k + 8).collect();
                // Every pixel on the same run (a renderer's samples 0..16 of each pixel):
                // not the run after the previous one.
                let repeated: Vec<u32> = (0..16 * n_seeds as u32).map(|k| k % 16 + 32).collect();
                let cases = [
                    aligned,
                    shifted,
                    repeated,
                    scattered[..n_seeds].to_vec(),
                    scattered[..5 * n_seeds].to_vec(),
                    scattered[..33 * n_seeds].to_vec(),
                ];
                for indices in &cases {
                    let per_seed = indices.len() / n_seeds;
                    for lv in dispatch::levels() {
                        let mut out = vec![[-1f32; 4]; indices.len()];
                        reseeded_at(lv, &s, &seeds, indices, &mut out);
                        for (k, o) in out.iter().enumerate() {
                            let t = s.with_seed(seeds[k / per_seed]);
                            let want = t.sample4_f32(indices[k]).map(f32::to_bits);
                            assert_eq!(
                                o.map(f32::to_bits),
                                want,
                                "{lv:?} {hash:?} {n_seeds} seeds, {per_seed} a seed, k {k}"
                            );
                        }
                    }
                }
            }
        }
    }

    /// The one-run kernel of a 16-point call, in every build and through `fill_f32`, against
    /// the scalar `sample4_f32`: runs at 0, in the middle, across no byte boundary and at
    /// the top of the index range; both hashes.
    #[test]
    fn every_build_of_the_one_run_call_matches_the_scalar_path() {
        for hash in [OwenHash::Vegdahl, OwenHash::LaineKarras] {
            let s = OwenSobol::with_hash(4, 3, hash).unwrap();
            for first in [0u32, 16, 240, 4096, 0x00AB_CDE0, 0xFFFF_FFF0] {
                let idx: [u32; 16] = core::array::from_fn(|k| first + k as u32);
                let want: Vec<[u32; 4]> = idx
                    .iter()
                    .map(|&i| s.sample4_f32(i).map(f32::to_bits))
                    .collect();
                for lv in dispatch::levels() {
                    let mut out = [[-1f32; 4]; 16];
                    dispatch::run_at(
                        lv,
                        Run16 {
                            s: &s,
                            first,
                            out: &mut out,
                        },
                    );
                    let got: Vec<[u32; 4]> = out.iter().map(|o| o.map(f32::to_bits)).collect();
                    assert_eq!(got, want, "{lv:?} {hash:?} {first}");
                }
                let mut out = [[-1f32; 4]; 16];
                s.fill_f32(&idx, &mut out).unwrap();
                let got: Vec<[u32; 4]> = out.iter().map(|o| o.map(f32::to_bits)).collect();
                assert_eq!(got, want, "fill_f32 {hash:?} {first}");
            }
        }
    }

    /// The reseeded fill's errors leave `out` untouched; no indices is `Ok`.
    #[test]
    fn the_reseeded_fill_checks_its_lengths() {
        let s = OwenSobol::new(4, 1).unwrap();
        let idx: Vec<u32> = (0..32).collect();
        let mut out = vec![[-1f32; 4]; 32];
        let err = |expected, got| Err(Error::BufferLength { expected, got });
        assert_eq!(s.fill_f32_reseeded(&[1, 2, 3], &idx, &mut out), err(33, 32));
        assert_eq!(s.fill_f32_reseeded(&[], &idx, &mut out), err(0, 32));
        assert_eq!(s.fill_f32_reseeded(&[1], &idx, &mut out[..31]), err(32, 31));
        assert!(out.iter().all(|o| *o == [-1.0; 4]));
        assert_eq!(s.fill_f32_reseeded(&[], &[], &mut []), Ok(()));
        assert_eq!(s.fill_f32_reseeded(&[1, 2], &[], &mut []), Ok(()));
        assert_eq!(s.fill_f32_reseeded(&[1, 2], &idx, &mut out), Ok(()));
        assert_eq!(out[16], s.with_seed(2).sample4_f32(16));
    }
}
