//! The pixel samplers (pbrt-v4's samplers as pure functions of pixel, index and
//! dimension) and their builder.

use super::{Entry, Param, alias, param};
use crate::pixel::Randomization;

/// A pixel sampler of [`PIXEL_SAMPLERS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum PixelKind {
    /// pbrt-v4's `ZSobolSampler`.
    Zsobol,
    /// pbrt-v4's `SobolSampler`.
    ImageSobol,
    /// pbrt-v4's `PaddedSobolSampler`.
    PaddedSobol,
    /// A seeded PMJ02 sequence per pixel and dimension.
    Pmj02,
    /// pbrt-v4's `PMJ02BNSampler` layout on a generated table.
    Pmj02bn,
    /// Independent hashed values.
    Independent,
    /// pbrt-v4's `HaltonSampler`.
    Halton,
    /// pbrt-v4's `StratifiedSampler`.
    Stratified,
    /// Owen-scrambled Sobol' with per-pixel keys from an optimized blue-noise table.
    BlueNoiseSobol,
    /// A rank-1 lattice with per-pixel shifts from an optimized blue-noise table.
    BlueNoiseLattice,
}

impl PixelKind {
    /// Whether it takes a randomizer at all (see [`accepts`](Self::accepts) for which): the
    /// three Sobol' samplers, halton and stratified. The others' randomness is their own.
    pub const fn takes_randomizer(self) -> bool {
        matches!(
            self,
            PixelKind::Zsobol
                | PixelKind::ImageSobol
                | PixelKind::PaddedSobol
                | PixelKind::Halton
                | PixelKind::Stratified
        )
    }

    /// Whether it takes the randomization `r`: the Sobol' samplers all four (`none`, `xor`,
    /// `fast-owen`, `owen`), halton all but `fast-owen` (pbrt refuses it), stratified only
    /// `none` (the strata's centres, pbrt's `jitter false`).
    pub const fn accepts(self, r: Randomization) -> bool {
        match self {
            PixelKind::Zsobol | PixelKind::ImageSobol | PixelKind::PaddedSobol => true,
            PixelKind::Halton => !matches!(r, Randomization::FastOwen),
            PixelKind::Stratified => matches!(r, Randomization::None),
            _ => false,
        }
    }

    /// The randomization without one given, pbrt's default: `PermuteDigits` for halton,
    /// `FastOwen` for the Sobol' samplers; stratified jitters (its own PCG32 stream).
    pub const fn default_randomization(self) -> Randomization {
        match self {
            PixelKind::Halton => Randomization::PermuteDigits,
            _ => Randomization::FastOwen,
        }
    }

    /// The samplers a randomizer that `self` refuses applies to, in words (for
    /// [`super::CatalogError::NotApplicable`]; the builder's, so `std`).
    #[cfg(feature = "std")]
    const fn rule(self) -> &'static str {
        match self {
            PixelKind::Halton => {
                "the Sobol' pixel samplers (halton takes none, xor and owen, as pbrt's)"
            }
            PixelKind::Stratified => {
                "the Sobol' and Halton pixel samplers (stratified takes none: the strata's \
                 centres; it jitters without one)"
            }
            _ => {
                "the Sobol' and Halton pixel samplers (zsobol, image-sobol, padded-sobol, \
                 halton, and none for stratified)"
            }
        }
    }

    /// Whether `spp` must be a power of two (zsobol).
    pub const fn needs_power_of_two(self) -> bool {
        matches!(self, PixelKind::Zsobol)
    }
}

/// An entry of [`PIXEL_SAMPLERS`].
pub type PixelEntry = Entry<PixelKind>;

const WIDTH: Param = param(
    "width",
    "image width in pixels",
    "none: needed",
    "1 to 2^30",
);
const HEIGHT: Param = param(
    "height",
    "image height in pixels",
    "none: needed",
    "1 to 2^30",
);
const SPP: Param = param("spp", "samples per pixel", "none: needed", "at least 1");
const SEED: Param = param(
    "seed",
    "the seed; below 2^32, pbrt's int seed as 32 bits",
    "0",
    "any u64",
);
const RANDOMIZER: Param = param(
    "randomizer",
    "pbrt's RandomizeStrategy",
    "fast-owen",
    "none, xor, fast-owen, owen",
);

/// Every pixel sampler, in the order of the command's list.
pub static PIXEL_SAMPLERS: &[PixelEntry] = &[
    Entry {
        kind: PixelKind::Zsobol,
        name: "zsobol",
        aliases: &[alias(
            "blue-noise-sobol",
            "Ahmed & Wonka 2020's blue-noise Sobol'",
        )],
        summary: "pbrt-v4 ZSobolSampler: blue-noise Sobol', Morton-ordered pixels",
        math: "Sobol' index of (Morton(x, y), i) with hashed base-4 digit permutations (Ahmed & Wonka 2020)",
        params: &[
            WIDTH,
            HEIGHT,
            param("spp", "samples per pixel", "none: needed", "a power of two"),
            SEED,
            RANDOMIZER,
        ],
        item: "qmckit::pixel::ZSobol",
    },
    Entry {
        kind: PixelKind::ImageSobol,
        name: "image-sobol",
        aliases: &[
            alias("sobol", "pbrt-v4's SobolSampler name; qmckit pixel"),
            alias("global-sobol", "one Sobol' sequence over the image"),
        ],
        summary: "pbrt-v4 SobolSampler: one Sobol' sequence over the image plane",
        math: "the i-th Sobol' point in the pixel's elementary interval (Grünschloß, Raab & Keller 2012)",
        params: &[WIDTH, HEIGHT, SPP, SEED, RANDOMIZER],
        item: "qmckit::pixel::ImageSobol",
    },
    Entry {
        kind: PixelKind::PaddedSobol,
        name: "padded-sobol",
        aliases: &[alias("padded", "a short form")],
        summary: "pbrt-v4 PaddedSobolSampler: per pixel and dimension, a permuted, \
                  scrambled Sobol' (0, 1)",
        math: "Sobol'(0, 1) at a hashed permutation of i, scrambled per pixel and dimension (Pharr, Jakob & Humphreys 2023)",
        params: &[WIDTH, HEIGHT, SPP, SEED, RANDOMIZER],
        item: "qmckit::pixel::PaddedSobol",
    },
    Entry {
        kind: PixelKind::Halton,
        name: "halton",
        aliases: &[alias("halton-pixels", "qmckit::pixel::HaltonSampler")],
        summary: "pbrt-v4 HaltonSampler: one Halton sequence over the image plane",
        math: "the pixel's Halton indices o(p) + i 2^j 3^k (Chinese remainder of its base-2 and base-3 cells), radical inverses in the primes, digits permuted or Owen-scrambled (Pharr, Jakob & Humphreys 2023)",
        params: &[
            WIDTH,
            HEIGHT,
            SPP,
            SEED,
            param(
                "randomizer",
                "pbrt's RandomizeStrategy",
                "xor",
                "none, xor, owen",
            ),
        ],
        item: "qmckit::pixel::HaltonSampler",
    },
    Entry {
        kind: PixelKind::Stratified,
        name: "stratified",
        aliases: &[alias(
            "stratified-pixels",
            "qmckit::pixel::StratifiedSampler",
        )],
        summary: "pbrt-v4 StratifiedSampler: per pixel and dimension, the samples permuted \
                  over the strata, jittered",
        math: "stratum PermutationElement(i, n, Hash(p, d, seed)) plus a PCG32 jitter at 65536 i + d; spp split as pbrt does (xs = spp / div, ys = div)",
        params: &[
            WIDTH,
            HEIGHT,
            SPP,
            SEED,
            param(
                "randomizer",
                "none: the strata's centres (pbrt's jitter false)",
                "jittered",
                "none",
            ),
        ],
        item: "qmckit::pixel::StratifiedSampler",
    },
    Entry {
        kind: PixelKind::Pmj02,
        name: "pmj02",
        aliases: &[alias("pmj02-pixels", "qmckit::pixel::Pmj02Pixels")],
        summary: "one shared 65,536-point PMJ02 table, index-shuffled and Owen-scrambled per pixel and dimension",
        math: "PMJ02 (Christensen, Kensler & Kilpatrick 2018; stochastic generation, Helmer, Christensen & Kensler 2021), a nested scramble of the index (Burley 2020) and hash-based Owen scrambling (Owen 1995); every power-of-two prefix of a pixel's points a (0, m, 2)-net",
        params: &[WIDTH, HEIGHT, SPP, SEED],
        item: "qmckit::pixel::Pmj02Pixels",
    },
    Entry {
        kind: PixelKind::Pmj02bn,
        name: "pmj02bn",
        aliases: &[alias("pmj02bn-pixels", "qmckit::pixel::Pmj02BnPixels")],
        summary: "pbrt-v4 PMJ02BNSampler layout on a generated 65,536-point PMJ02BN table",
        math: "table points bucketed into a pixel tile, permuted blocks plus blue-noise shifts (Christensen et al. 2018; pbrt-v4)",
        params: &[
            WIDTH,
            HEIGHT,
            param("spp", "samples per pixel", "none: needed", "1 to 65536"),
            SEED,
        ],
        item: "qmckit::pixel::Pmj02BnPixels",
    },
    Entry {
        kind: PixelKind::BlueNoiseSobol,
        name: "bn-sobol",
        aliases: &[
            alias("blue-noise-owen-sobol", "qmckit::pixel::BlueNoiseSobol"),
            alias("bn-owen-sobol", "a short form"),
        ],
        summary: "blue-noise Owen-Sobol': per-pixel scrambling keys from an optimized 64x64 table",
        math: "Owen-scrambled Sobol' (0, 1) per pixel, keys permuted over a toroidal tile so the screen-space error is blue (Heitz & Belcour 2019; Belcour & Heitz 2021); dimension pairs are hashed domains",
        params: &[WIDTH, HEIGHT, SPP, SEED],
        item: "qmckit::pixel::BlueNoiseSobol",
    },
    Entry {
        kind: PixelKind::BlueNoiseLattice,
        name: "bn-lattice",
        aliases: &[alias(
            "blue-noise-lattice",
            "qmckit::pixel::BlueNoiseLattice",
        )],
        summary: "blue-noise rank-1 lattice: per-pixel Cranley-Patterson shifts from an optimized 64x64 table",
        math: "the lattice (rev(j), rev(j) g) per pixel, shifted by the pixel's cell of a toroidal table optimized for blue screen-space error (Belcour & Heitz 2021); dimension pairs are hashed domains",
        params: &[WIDTH, HEIGHT, SPP, SEED],
        item: "qmckit::pixel::BlueNoiseLattice",
    },
    Entry {
        kind: PixelKind::Independent,
        name: "independent",
        aliases: &[alias("random", "white noise")],
        summary: "independent uniform values per pixel (hashed; not pbrt's PCG stream)",
        math: "v = hash(seed, pixel, i, dim) 2^-32",
        params: &[
            WIDTH,
            HEIGHT,
            SPP,
            param("seed", "the seed", "0", "any u64"),
        ],
        item: "qmckit::pixel::IndependentPixels",
    },
];

#[cfg(feature = "std")]
pub use built::{PixelParams, build_pixel};

#[cfg(feature = "std")]
mod built {
    use super::super::{CatalogError, RandomizerEntry};
    use super::{PixelEntry, PixelKind as P};
    use crate::pixel::{
        BlueNoiseLattice, BlueNoiseSobol, HaltonSampler, ImageSobol, IndependentPixels,
        PaddedSobol, PixelGrid, PixelPoint, PixelSampler, Pmj02BnTables, Pmj02Pixels,
        PreparedHalton, StratifiedSampler, ZSobol,
    };
    use std::boxed::Box;

    /// The dimensions the boxed Halton pixel sampler tabulates ([`PreparedHalton`]):
    /// `2 .. 64`, a quarter MiB built in about 10 ms (all 1000 would take 25 MiB and half a
    /// second, as pbrt's constructor); the dimensions above are computed
    /// digit by digit, with the same values.
    const HALTON_TABLE_DIMS: usize = 64;

    /// The image, the samples per pixel and the seed of a pixel sampler.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct PixelParams {
        /// Image width in pixels.
        pub width: u32,
        /// Image height in pixels.
        pub height: u32,
        /// Samples per pixel.
        pub spp: u32,
        /// The seed (below `2^32`, pbrt's `int` seed as 32 bits).
        pub seed: u64,
    }

    /// The pixel sampler `entry` names for `params`, randomized by `randomizer` (see
    /// [`PixelKind::accepts`](super::PixelKind::accepts): the Sobol' samplers `none`, `xor`, `fast-owen`, `owen`, halton
    /// all but `fast-owen`, stratified `none` for the strata's centres; `None` is pbrt's
    /// default, [`PixelKind::default_randomization`](super::PixelKind::default_randomization), and stratified jittered; the others
    /// take none). The same values as `qmckit pixel`.
    ///
    /// ```
    /// use qmckit::catalog::{self, PixelParams};
    /// use qmckit::pixel::PixelSampler;
    /// let p = PixelParams { width: 16, height: 9, spp: 1, seed: 0 };
    /// let z = catalog::build_pixel(catalog::pixel_sampler("zsobol")?, None, &p)?;
    /// // A boxed sampler starts its pixel samples through the trait's path.
    /// let mut first = PixelSampler::start_pixel_sample(&z, 1, 0, 0)?;
    /// assert_eq!(first.get_1d_f32(), 0.570228934);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// [`CatalogError::NotApplicable`] for a randomizer the sampler does not take; the
    /// samplers' own errors (an empty image, zsobol's `spp` not a power of two, ...).
    pub fn build_pixel(
        entry: &PixelEntry,
        randomizer: Option<&RandomizerEntry>,
        params: &PixelParams,
    ) -> core::result::Result<Box<dyn PixelSampler>, CatalogError> {
        let PixelParams {
            width: w,
            height: h,
            spp,
            seed,
        } = *params;
        let kind = entry.kind;
        let r = match randomizer {
            None => kind.default_randomization(),
            Some(r) => match r.kind.pixel() {
                Some(p) if kind.accepts(p) => p,
                Some(_) => {
                    return Err(CatalogError::NotApplicable {
                        randomizer: r.name,
                        sampler: entry.name,
                        base: None,
                        rule: kind.rule(),
                    });
                }
                None => {
                    return Err(CatalogError::NotApplicable {
                        randomizer: r.name,
                        sampler: entry.name,
                        base: None,
                        rule: "sampler sequences (the pixel samplers take none, xor, fast-owen \
                               and owen)",
                    });
                }
            },
        };
        Ok(match entry.kind {
            P::Zsobol => Box::new(ZSobol::new(w, h, spp, r, seed)?),
            P::ImageSobol => Box::new(ImageSobol::new(w, h, spp, r, seed)?),
            P::PaddedSobol => Box::new(PaddedSobol::new(w, h, spp, r, seed)?),
            P::Pmj02 => Box::new(Pmj02Pixels::new(w, h, spp, seed)?),
            P::Independent => Box::new(IndependentPixels::new(w, h, spp, seed)?),
            P::BlueNoiseSobol => Box::new(BlueNoiseSobol::new(w, h, spp, seed)?),
            P::BlueNoiseLattice => Box::new(BlueNoiseLattice::new(w, h, spp, seed)?),
            P::Halton => Box::new(PreparedHalton::new(
                HaltonSampler::new(w, h, spp, r, seed)?,
                HALTON_TABLE_DIMS,
            )?),
            // Jittered unless `none` was asked for.
            P::Stratified => Box::new(StratifiedSampler::with_spp(
                w,
                h,
                spp,
                randomizer.is_none(),
                seed,
            )?),
            P::Pmj02bn => {
                // Validates the image before the table is built.
                PixelGrid::new(w, h, spp, false)?;
                let tables = Pmj02BnTables::new(spp, seed)?;
                let grid = tables.sampler(w, h, seed)?.grid();
                Box::new(OwnedPmj02Bn { tables, grid, seed })
            }
        })
    }

    /// A [`crate::pixel::Pmj02BnPixels`] with its tables owned (the boxed form).
    struct OwnedPmj02Bn {
        tables: Pmj02BnTables,
        grid: PixelGrid,
        seed: u64,
    }

    impl OwnedPmj02Bn {
        /// The borrowing sampler (validated when built: no checks).
        fn on(&self) -> crate::pixel::Pmj02BnPixels<'_> {
            self.tables.sampler_of(self.grid, self.seed)
        }
    }

    impl PixelSampler for OwnedPmj02Bn {
        fn grid(&self) -> PixelGrid {
            self.grid
        }

        fn pixel_key(&self, x: u32, y: u32, index: u32) -> u64 {
            self.on().pixel_key(x, y, index)
        }

        fn sample_index(&self, at: &PixelPoint, dim: usize) -> Option<u64> {
            self.on().sample_index(at, dim)
        }

        fn counter_dimension(&self, dim: usize, width: usize) -> usize {
            self.on().counter_dimension(dim, width)
        }

        fn value_1d(&self, at: &PixelPoint, dim: usize) -> u32 {
            self.on().value_1d(at, dim)
        }

        fn value_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
            self.on().value_2d(at, dim)
        }

        fn value_pixel_2d(&self, at: &PixelPoint, dim: usize) -> [u32; 2] {
            self.on().value_pixel_2d(at, dim)
        }

        fn pixel_2d_moves_counter(&self) -> bool {
            self.on().pixel_2d_moves_counter()
        }

        // The prepared per-pixel fills of the borrowing sampler (the defaults would go
        // value by value).
        fn fill_2d(
            &self,
            x: u32,
            y: u32,
            dim: usize,
            out: &mut [[u32; 2]],
        ) -> crate::error::Result<()> {
            self.on().fill_2d(x, y, dim, out)
        }

        fn fill_2d_f32(
            &self,
            x: u32,
            y: u32,
            dim: usize,
            out: &mut [[f32; 2]],
        ) -> crate::error::Result<()> {
            self.on().fill_2d_f32(x, y, dim, out)
        }

        fn fill_1d(&self, x: u32, y: u32, dim: usize, out: &mut [u32]) -> crate::error::Result<()> {
            self.on().fill_1d(x, y, dim, out)
        }

        fn fill_1d_f32(
            &self,
            x: u32,
            y: u32,
            dim: usize,
            out: &mut [f32],
        ) -> crate::error::Result<()> {
            self.on().fill_1d_f32(x, y, dim, out)
        }
    }
}
