//! How each sampler feeds a pixel's dimensions.
//!
//! A study renders every pixel with `spp` points of `[0, 1)^d`. The randomized samplers are
//! made independent between pixels and seeds by a per-pixel seed,
//! `hash3(seed, pixel, salt)` ([`qmckit::hash::hash3`]); the pixel samplers ([`ZSobol`])
//! take the study's seed and correlate pixels on purpose.
//!
//! | sampler | point `i` of pixel `p` |
//! |---|---|
//! | [`SceneSampler::Independent`] | [`Independent`] with the pixel's seed |
//! | [`SceneSampler::Stratified`] | jittered [`Stratified`] `2^ceil(m/2) x 2^floor(m/2)` grid (`spp = 2^m`; 2D only) |
//! | [`SceneSampler::Halton`] | [`Halton`] points `0..spp` with random digit permutations keyed by the pixel's seed |
//! | [`SceneSampler::SobolShift`] | Sobol' points `0..spp` with a random digital shift (XOR) per pixel |
//! | [`SceneSampler::OwenSobol`] | Sobol' with the catalog's `fast-owen` randomizer (hash-based Owen scrambling, [`OwenSobol`], the bits of `qmckit points sobol --scramble fast-owen --seed K`) points `0..spp`, seeded per pixel |
//! | [`SceneSampler::ZSobol`] | pbrt's blue-noise Sobol' ([`ZSobol`], FastOwen): dimensions in pairs, one `start_pixel_sample(x, y, i)`, then `get_2d` per pair |
//!
//! Cost: O(d) integer work a point (Halton's permutations O(d log spp)); ZSobol O(log2(W spp))
//! a pair.

use qmckit::bits::to_f64;
use qmckit::hash::hash3;
use qmckit::pixel::{PixelSampler, Randomization, ZSobol};
use qmckit::randomize::digits::DigitScramble;
use qmckit::randomize::{DigitalShift, Scrambled};
use qmckit::{Error, Halton, Independent, Jitter, OwenSobol, Result, Sampler, Sobol, Stratified};

/// A sampler of a study.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SceneSampler {
    /// Independent uniform points (white noise).
    Independent,
    /// Jittered stratified points (2D integrands only).
    Stratified,
    /// Halton with random digit permutations.
    Halton,
    /// Sobol' with a random digital shift.
    SobolShift,
    /// Sobol' with the catalog's `fast-owen` randomizer (hash-based Owen scrambling).
    OwenSobol,
    /// Ahmed & Wonka's blue-noise Sobol' (pbrt's ZSobolSampler).
    ZSobol,
}

impl SceneSampler {
    /// The name shown in the study's tables.
    pub const fn name(self) -> &'static str {
        match self {
            SceneSampler::Independent => "independent",
            SceneSampler::Stratified => "stratified",
            SceneSampler::Halton => "Halton",
            SceneSampler::SobolShift => "Sobol'",
            SceneSampler::OwenSobol => "Sobol' fast-owen",
            SceneSampler::ZSobol => "ZSobol",
        }
    }
}

/// A sampler prepared for one image and seed.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Prepared {
    kind: SceneSampler,
    dims: usize,
    spp: u32,
    seed: u64,
    width: u32,
    zsobol: Option<ZSobol>,
    strata: [u32; 2],
}

impl Prepared {
    /// `kind` for `dims`-dimensional points, `spp` (a power of two) a pixel, a `width x
    /// height` image and `seed`.
    ///
    /// # Errors
    /// [`Error::NotPowerOfTwo`]; [`Error::InvalidParameter`] for stratified points in more
    /// than two dimensions; the samplers' own errors.
    pub(crate) fn new(
        kind: SceneSampler,
        dims: usize,
        spp: u32,
        width: u32,
        height: u32,
        seed: u64,
    ) -> Result<Self> {
        if !spp.is_power_of_two() {
            return Err(Error::NotPowerOfTwo { n: spp as u64 });
        }
        if kind == SceneSampler::Stratified && dims != 2 {
            return Err(Error::InvalidParameter {
                what: "the stratified scene sampler is two-dimensional",
            });
        }
        let m = spp.trailing_zeros();
        let zsobol = if kind == SceneSampler::ZSobol {
            Some(ZSobol::new(
                width,
                height,
                spp,
                Randomization::FastOwen,
                seed,
            )?)
        } else {
            None
        };
        // Validate the dimension count once.
        Sobol::new(dims)?;
        Halton::new(dims)?;
        Ok(Prepared {
            kind,
            dims,
            spp,
            seed,
            width,
            zsobol,
            strata: [1 << m.div_ceil(2), 1 << (m / 2)],
        })
    }

    /// The `spp` points of pixel `(x, y)`, row-major into `out` (`spp * dims` values).
    ///
    /// # Errors
    /// Only the samplers' own (unreachable after [`Prepared::new`]).
    pub(crate) fn pixel(&self, x: u32, y: u32, out: &mut [f64]) -> Result<()> {
        let d = self.dims;
        let pixel = y as u64 * self.width as u64 + x as u64;
        let ps = hash3(self.seed, pixel, self.kind as u64);
        let fill = |s: &dyn Fn(u32, usize) -> Result<u32>, out: &mut [f64]| -> Result<()> {
            for (i, row) in out.chunks_exact_mut(d).enumerate() {
                for (k, v) in row.iter_mut().enumerate() {
                    *v = to_f64(s(i as u32, k)?);
                }
            }
            Ok(())
        };
        match self.kind {
            SceneSampler::Independent => {
                let s = Independent::new(d, ps)?;
                fill(&|i, k| s.sample(i, k), out)
            }
            SceneSampler::Stratified => {
                let s = Stratified::new(&self.strata, Jitter::Random(ps))?;
                fill(&|i, k| s.sample(i, k), out)
            }
            SceneSampler::Halton => {
                let s = Halton::with_scramble(d, DigitScramble::Permutations(ps))?;
                fill(&|i, k| s.sample(i, k), out)
            }
            SceneSampler::SobolShift => {
                let s = Scrambled::new(Sobol::new(d)?, DigitalShift::new(ps));
                fill(&|i, k| s.sample(i, k), out)
            }
            SceneSampler::OwenSobol => {
                let s = OwenSobol::new(d, ps)?;
                fill(&|i, k| s.sample(i, k), out)
            }
            SceneSampler::ZSobol => {
                let Some(z) = &self.zsobol else {
                    return Err(Error::InvalidParameter {
                        what: "ZSobol sampler not prepared",
                    });
                };
                for (i, row) in out.chunks_exact_mut(d).enumerate().take(self.spp as usize) {
                    let mut s = z.start_pixel_sample(x, y, i as u32)?;
                    let mut k = 0;
                    while k < d {
                        let [a, b] = s.get_2d(); // the pair at dimension k
                        row[k] = to_f64(a);
                        if k + 1 < d {
                            row[k + 1] = to_f64(b);
                        }
                        k += 2;
                    }
                }
                Ok(())
            }
        }
    }
}
