//! The pixel samplers (pbrt-v4's samplers as pure functions of pixel, index and
//! dimension) and their builder.

use super::{Entry, Param, alias, param};

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
}

impl PixelKind {
    /// Whether it takes a randomizer (`none`, `xor`, `fast-owen`, `owen`; default
    /// `fast-owen`): the three Sobol' samplers. The others' randomness is their own.
    pub const fn takes_randomizer(self) -> bool {
        matches!(
            self,
            PixelKind::Zsobol | PixelKind::ImageSobol | PixelKind::PaddedSobol
        )
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
        kind: PixelKind::Pmj02,
        name: "pmj02",
        aliases: &[alias("pmj02-pixels", "qmckit::pixel::Pmj02Pixels")],
        summary: "a seeded PMJ02 sequence per pixel and dimension, index permuted per pixel",
        math: "PMJ02 (Christensen, Kensler & Kilpatrick 2018) in pbrt-v4's per-pixel layout",
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
        ImageSobol, IndependentPixels, PaddedSobol, PixelGrid, PixelPoint, PixelSampler,
        Pmj02BnTables, Pmj02Pixels, Randomization, ZSobol,
    };
    use std::boxed::Box;

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

    /// The pixel sampler `entry` names for `params`, randomized by `randomizer` (the
    /// Sobol' samplers: `none`, `xor`, `fast-owen`, `owen`; `None` is `fast-owen`, pbrt's
    /// default; the others take none). The same values as `qmckit pixel`.
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
        let r = match (randomizer, entry.kind.takes_randomizer()) {
            (None, _) => Randomization::FastOwen,
            (Some(r), true) => r.kind.pixel().ok_or(CatalogError::NotApplicable {
                randomizer: r.name,
                sampler: entry.name,
                base: None,
                rule: "sampler sequences (the pixel samplers take none, xor, fast-owen \
                       and owen)",
            })?,
            (Some(r), false) => {
                return Err(CatalogError::NotApplicable {
                    randomizer: r.name,
                    sampler: entry.name,
                    base: None,
                    rule: "the Sobol' pixel samplers (zsobol, image-sobol, padded-sobol)",
                });
            }
        };
        Ok(match entry.kind {
            P::Zsobol => Box::new(ZSobol::new(w, h, spp, r, seed)?),
            P::ImageSobol => Box::new(ImageSobol::new(w, h, spp, r, seed)?),
            P::PaddedSobol => Box::new(PaddedSobol::new(w, h, spp, r, seed)?),
            P::Pmj02 => Box::new(Pmj02Pixels::new(w, h, spp, seed)?),
            P::Independent => Box::new(IndependentPixels::new(w, h, spp, seed)?),
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
    }
}
