//! [`OwenSobol::fill_f32_reseeded`]: a seed a block of points, each block the points of
//! `s.with_seed(seed)`. The keys of eight seeds are hashed at a time as vector lanes
//! ([`keys8`]); a block that is one run of 16 from a multiple of 16 (a pixel's samples) goes
//! straight to the run kernel of [`super`], any other through its general loop. The values
//! are those of the one-seed fill with each seed's sampler (tested build by build).

use super::*;
/// `out[k] = s.with_seed(seeds[k / n]).sample4_f32(indices[k])` with `n = indices.len() /
/// seeds.len()` points a seed, in the widest build this CPU runs.
///
/// # Errors
/// [`Error::BufferLength`] unless `out` has one slot per index (`expected: indices.len()`)
/// and `indices` splits into `seeds.len()` equal blocks (`expected`: the next multiple of
/// `seeds.len()`, or 0 without seeds; `got: indices.len()`). `out` is then untouched.
pub(in super::super) fn reseeded(
    s: &OwenSobol,
    seeds: &[u64],
    indices: &[u32],
    out: &mut [[f32; 4]],
) -> Result<()> {
    check_lengths(indices, out)?;
    if indices.is_empty() {
        return Ok(());
    }
    let got = indices.len();
    if seeds.is_empty() || !got.is_multiple_of(seeds.len()) {
        return Err(Error::BufferLength {
            expected: got.next_multiple_of(seeds.len().max(1)) * seeds.len().min(1),
            got,
        });
    }
    let per_seed = got / seeds.len();
    dispatch::run_at(
        dispatch::level(),
        Reseeded {
            s,
            seeds,
            per_seed,
            indices,
            out,
        },
    );
    Ok(())
}

/// The reseeded fill ([`reseeded`]), compiled once per build.
struct Reseeded<'a> {
    s: &'a OwenSobol,
    seeds: &'a [u64],
    per_seed: usize,
    indices: &'a [u32],
    out: &'a mut [[f32; 4]],
}

impl Kernel for Reseeded<'_> {
    type Output = ();
    #[inline(always)]
    fn run(self) {
        reseeded_blocks(self, Lanes);
    }
    #[cfg(all(feature = "std", target_arch = "x86_64"))]
    #[inline(always)]
    fn run_avx512(self, cpu: dispatch::Avx512) {
        reseeded_blocks(self, cpu);
    }
}

/// The loop of every [`reseeded`] build, for the sampler's hash.
#[inline(always)]
fn reseeded_blocks<F: Finish>(k: Reseeded<'_>, finish: F) {
    match k.s.owen.hash() {
        OwenHash::Vegdahl => reseeded_with::<Vegdahl16, F>(k, finish),
        OwenHash::LaineKarras => reseeded_with::<LaineKarras16, F>(k, finish),
    }
}

/// The keys of eight seeds at a time as eight lanes ([`keys8`]), then each seed's block of
/// points: a block that is one run of 16 from a multiple of 16 (a pixel's samples) straight
/// as [`run16_f32`], any other as [`fill_blocks`] does it. Blocks of 16 points (a pixel's
/// samples) go through their own loop ([`reseeded16`]).
#[inline(always)]
fn reseeded_with<H: Hash16, F: Finish>(k: Reseeded<'_>, finish: F) {
    let Reseeded {
        s,
        seeds,
        per_seed,
        indices,
        out,
    } = k;
    #[cfg(target_pointer_width = "64")]
    if per_seed == 16 {
        let (idx16, _) = indices.as_chunks::<16>();
        let (out16, _) = out.as_chunks_mut::<16>();
        reseeded16::<H, F>(s, seeds, idx16, out16, finish);
        return;
    }
    let mut blocks = indices
        .chunks_exact(per_seed)
        .zip(out.chunks_exact_mut(per_seed));
    let (seeds8, rest) = seeds.as_chunks::<8>();
    for seeds in seeds8 {
        let keys = keys8(seeds);
        for (&seed, keys) in seeds.iter().zip(keys) {
            let Some((idx, out)) = blocks.next() else {
                return;
            };
            block::<H, F>(s, seed, keys, idx, out, finish);
        }
    }
    for (&seed, (idx, out)) in rest.iter().zip(blocks) {
        block::<H, F>(s, seed, dimension_seeds(seed, 0), idx, out, finish);
    }
}

/// [`reseeded_with`] with 16 points a seed: the keys of eight seeds at a time
/// ([`keys8`]), then each seed's run of 16 as [`run16_f32`] (checked against the previous
/// run plus 16 first, then against its own first index), any other block of 16 as
/// [`fill_with`]. The upper part of the table XOR is kept while the runs share it.
#[cfg(target_pointer_width = "64")]
#[inline(always)]
fn reseeded16<H: Hash16, F: Finish>(
    s: &OwenSobol,
    seeds: &[u64],
    indices: &[[u32; 16]],
    out: &mut [[[f32; 4]; 16]],
    finish: F,
) {
    let mut run = Runs {
        upper: u32::MAX,
        high: [0; 16],
        next: indices.first().map_or(0, |i| i[0]),
    };
    let mut blocks = indices.iter().zip(out.iter_mut());
    let (seeds8, rest) = seeds.as_chunks::<8>();
    // Software-pipelined: the keys of the next eight seeds are hashed before this eight's
    // points, so that their long chains of dependent multiplies (three `mix64` deep)
    // overlap the fills instead of stalling the next eight.
    let mut keys = seeds8.first().map(keys8);
    for (g, seeds) in seeds8.iter().enumerate() {
        let Some(now) = keys else {
            return;
        };
        keys = seeds8.get(g + 1).map(keys8);
        for (&seed, keys) in seeds.iter().zip(&now) {
            let Some((i, o)) = blocks.next() else {
                return;
            };
            run.pixel::<H, F>(s, seed, keys, i, o, finish);
        }
    }
    for (&seed, (i, o)) in rest.iter().zip(blocks) {
        run.pixel::<H, F>(s, seed, &dimension_seeds(seed, 0), i, o, finish);
    }
}

/// What [`reseeded16`] carries from one pixel to the next.
#[cfg(target_pointer_width = "64")]
struct Runs {
    /// `index >> 8` of the runs `high` belongs to (`u32::MAX`: none yet).
    upper: u32,
    /// [`reversed4_high`] of those runs, spread over 16 lanes.
    high: [u32; 16],
    /// The first index of the next run if the runs go on (a sequential fill).
    next: u32,
}

#[cfg(target_pointer_width = "64")]
impl Runs {
    /// One pixel: `s` with `seed` (whose keys are `keys`) on the 16 indices `i`.
    #[inline(always)]
    fn pixel<H: Hash16, F: Finish>(
        &mut self,
        s: &OwenSobol,
        seed: u64,
        keys: &[u32; TABLE_DIMS],
        i: &[u32; 16],
        o: &mut [[f32; 4]; 16],
        finish: F,
    ) {
        let first = if is_run_from(i, self.next, finish) {
            self.next
        } else if is_aligned_run(i, finish) {
            i[0]
        } else {
            let s = OwenSobol {
                dims: s.dims,
                owen: FastOwen::with_hash(seed, s.owen.hash()),
                keys: *keys,
            };
            fill_with::<H, F>(&s, i, o, finish);
            return;
        };
        self.next = first.wrapping_add(16);
        if first >> 8 != self.upper {
            self.upper = first >> 8;
            self.high = spread(reversed4_high(first));
        }
        run16_f32(&H::prepare(keys), &self.high, first, o, finish);
    }
}

/// One block of [`reseeded_with`]: `s` with `seed` (whose keys are `keys`) on `idx`.
#[inline(always)]
fn block<H: Hash16, F: Finish>(
    s: &OwenSobol,
    seed: u64,
    keys: [u32; TABLE_DIMS],
    idx: &[u32],
    out: &mut [[f32; 4]],
    finish: F,
) {
    #[cfg(target_pointer_width = "64")]
    if let (Ok(i16), Ok(o16)) = (
        <&[u32; 16]>::try_from(idx),
        <&mut [[f32; 4]; 16]>::try_from(&mut *out),
    ) && is_aligned_run(i16, finish)
    {
        let first = i16[0];
        let high = spread(reversed4_high(first));
        run16_f32(&H::prepare(&keys), &high, first, o16, finish);
        return;
    }
    let s = OwenSobol {
        dims: s.dims,
        owen: FastOwen::with_hash(seed, s.owen.hash()),
        keys,
    };
    fill_with::<H, F>(&s, idx, out, finish);
}

/// [`crate::randomize::dimension_seeds`]`(seed, 0)` of eight seeds, as lanes: the same
/// `1 + 2 x 4` [`crate::hash::mix64`] a seed, each step one loop over the eight seeds (a
/// vector of eight `u64` in the AVX-512 build, whose 64-bit multiply is one instruction),
/// so that eight reseeds cost about what one does point by point.
#[inline(always)]
fn keys8(seeds: &[u64; 8]) -> [[u32; TABLE_DIMS]; 8] {
    let mut base = [0u64; 8];
    for (b, &seed) in base.iter_mut().zip(seeds) {
        *b = hash3_key(seed);
    }
    let mut keys = [[0u32; TABLE_DIMS]; 8];
    for d in 0..TABLE_DIMS {
        let mut kd = [0u32; 8];
        for (k, &b) in kd.iter_mut().zip(&base) {
            *k = (hash3_keyed(b, d as u64, DIMENSION_SALT) >> 32) as u32;
        }
        for (keys, &k) in keys.iter_mut().zip(&kd) {
            keys[d] = k;
        }
    }
    keys
}

/// [`reseeded`] (lengths already checked, `per_seed >= 1`) with the widest build that is at
/// most `want` and that the CPU runs.
#[cfg(all(test, feature = "std"))]
pub(super) fn reseeded_at(
    want: dispatch::Level,
    s: &OwenSobol,
    seeds: &[u64],
    indices: &[u32],
    out: &mut [[f32; 4]],
) {
    let per_seed = indices.len() / seeds.len();
    dispatch::run_at(
        want,
        Reseeded {
            s,
            seeds,
            per_seed,
            indices,
            out,
        },
    );
}
