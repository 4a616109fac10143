//! How each sampler feeds a pixel's dimensions: every study sampler is a catalog entry.
//!
//! A study renders every pixel with `spp` points of `[0, 1)^d`. A study sampler is either a
//! catalog sampler with a catalog randomizer ([`SceneSampler::Points`], the bits of `qmckit
//! points SAMPLER --scramble RANDOMIZER --seed K` with `K` the pixel's seed
//! `hash3(seed, pixel, salt)`, [`qmckit::hash::hash3`], so pixels and seeds are independent),
//! or a catalog pixel sampler ([`SceneSampler::Pixel`], the bits of `qmckit pixel NAME`:
//! seeded once per image, correlating pixels on purpose). Adding a sampler to a study is one
//! line of [`Study::samplers`](super::Study::samplers) naming catalog entries.
//!
//! The studies' samplers:
//!
//! | constant | catalog entries | point `i` of pixel `p` |
//! |---|---|---|
//! | [`INDEPENDENT`] | `independent` | independent uniform points, seeded per pixel |
//! | [`STRATIFIED`] | `stratified` | jittered `2^ceil(m/2) x 2^floor(m/2)` grid (`spp = 2^m`; 2D only) |
//! | [`HALTON`] | `halton` + `perm` | Halton points `0..spp` with random digit permutations |
//! | [`SOBOL_XOR`] | `sobol` + `xor` | Sobol' points `0..spp` with a random digital shift |
//! | [`SOBOL_OWEN`] | `sobol` + `fast-owen` | Sobol' points `0..spp`, hash-based Owen scrambling |
//! | [`ZSOBOL`] | pixel sampler `zsobol` + `fast-owen` | pbrt's blue-noise Sobol': dimensions in pairs, one `start_pixel_sample(x, y, i)`, then `get_2d` per pair |
//! | [`BN_SOBOL`] | pixel sampler `bn-sobol` | Owen-Sobol' per pixel, keys from the optimized blue-noise table; pairs as ZSobol's |
//! | [`BN_LATTICE`] | pixel sampler `bn-lattice` | a rank-1 lattice per pixel, shifts from the optimized blue-noise table; pairs as ZSobol's |
//!
//! Cost: building the catalog sampler once a pixel (O(d), Halton's permutations O(d b)),
//! then its batch fill, O(d) a point; a pixel sampler is built once an image row, then
//! O(log2(W spp)) a pair (ZSobol).

use qmckit::catalog::{self, Params, PixelParams};
use qmckit::hash::hash3;
use qmckit::pixel::PixelSampler;
use qmckit::{Error, Result, Sampler};

/// A sampler of a study: catalog names, checked when the sampler is prepared.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum SceneSampler {
    /// A catalog sampler and randomizer, built for each pixel with the pixel's seed.
    Points {
        /// The catalog sampler's name.
        sampler: &'static str,
        /// The catalog randomizer's name.
        randomizer: &'static str,
    },
    /// A catalog pixel sampler and randomizer, built once for the image and seed.
    Pixel {
        /// The catalog pixel sampler's name.
        sampler: &'static str,
        /// The catalog randomizer's name.
        randomizer: &'static str,
    },
}

/// Independent uniform points (white noise).
pub const INDEPENDENT: SceneSampler = SceneSampler::Points {
    sampler: "independent",
    randomizer: "none",
};
/// Jittered stratified points (2D integrands only).
pub const STRATIFIED: SceneSampler = SceneSampler::Points {
    sampler: "stratified",
    randomizer: "none",
};
/// Halton with random digit permutations.
pub const HALTON: SceneSampler = SceneSampler::Points {
    sampler: "halton",
    randomizer: "perm",
};
/// Sobol' with a random digital shift.
pub const SOBOL_XOR: SceneSampler = SceneSampler::Points {
    sampler: "sobol",
    randomizer: "xor",
};
/// Sobol' with hash-based Owen scrambling (the reference images' sampler).
pub const SOBOL_OWEN: SceneSampler = SceneSampler::Points {
    sampler: "sobol",
    randomizer: "fast-owen",
};
/// Ahmed & Wonka's blue-noise Sobol' (pbrt's ZSobolSampler).
pub const ZSOBOL: SceneSampler = SceneSampler::Pixel {
    sampler: "zsobol",
    randomizer: "fast-owen",
};

/// Blue-noise Owen-Sobol' (per-pixel keys from an optimized table).
pub const BN_SOBOL: SceneSampler = SceneSampler::Pixel {
    sampler: "bn-sobol",
    randomizer: "none",
};
/// Blue-noise rank-1 lattice (per-pixel shifts from an optimized table).
pub const BN_LATTICE: SceneSampler = SceneSampler::Pixel {
    sampler: "bn-lattice",
    randomizer: "none",
};

impl SceneSampler {
    /// The name shown in the study's tables: the catalog names, `SAMPLER` or `SAMPLER +
    /// RANDOMIZER`.
    pub fn name(self) -> String {
        let (SceneSampler::Points {
            sampler,
            randomizer,
        }
        | SceneSampler::Pixel {
            sampler,
            randomizer,
        }) = self;
        if randomizer == "none" {
            sampler.to_string()
        } else {
            format!("{sampler} + {randomizer}")
        }
    }

    /// A salt that separates the samplers' per-pixel seeds (a hash of the names).
    fn salt(self) -> u64 {
        self.name().bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
            (h ^ b as u64).wrapping_mul(0x100_0000_01b3)
        })
    }
}

/// The catalog's refusal as the library's error: a construction's own error as it is; a
/// name or combination the catalog refuses (a study's fixed list, so a defect of the list)
/// as an invalid parameter.
fn catalog_error(e: catalog::CatalogError) -> Error {
    match e {
        catalog::CatalogError::Build(e) => e,
        _ => Error::InvalidParameter {
            what: "a scene study names a sampler or randomizer the catalog refuses",
        },
    }
}

/// A sampler prepared for one image and seed.
#[derive(Clone, Debug)]
pub(crate) struct Prepared {
    kind: SceneSampler,
    dims: usize,
    spp: u32,
    seed: u64,
    width: u32,
    height: u32,
    params: Params,
}

impl Prepared {
    /// `kind` for `dims`-dimensional points, `spp` (a power of two) a pixel, a `width x
    /// height` image and `seed`; builds the sampler once to check the names and sizes.
    ///
    /// # Errors
    /// [`Error::NotPowerOfTwo`]; [`Error::InvalidParameter`] for stratified points in more
    /// than two dimensions; the catalog's refusals.
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
        let mut params = Params::dims(dims);
        if let SceneSampler::Points { sampler, .. } = kind
            && catalog::sampler(sampler).map_err(catalog_error)?.name == "stratified"
        {
            if dims != 2 {
                return Err(Error::InvalidParameter {
                    what: "the stratified scene sampler is two-dimensional",
                });
            }
            let m = spp.trailing_zeros();
            params.strata = Some(vec![1 << m.div_ceil(2), 1 << (m / 2)]);
        }
        let p = Prepared {
            kind,
            dims,
            spp,
            seed,
            width,
            height,
            params,
        };
        match kind {
            SceneSampler::Points { .. } => drop(p.points(seed)?),
            SceneSampler::Pixel { .. } => drop(p.pixels()?),
        }
        Ok(p)
    }

    /// The catalog sampler of [`SceneSampler::Points`] with seed `seed`.
    fn points(&self, seed: u64) -> Result<Box<dyn Sampler>> {
        let SceneSampler::Points {
            sampler,
            randomizer,
        } = self.kind
        else {
            return Err(Error::InvalidParameter {
                what: "a pixel sampler is not a point sampler",
            });
        };
        catalog::build_named(sampler, randomizer, &self.params.clone().with_seed(seed))
            .map_err(catalog_error)
    }

    /// The catalog pixel sampler of [`SceneSampler::Pixel`] for the image (none for a
    /// point sampler, which is built per pixel).
    pub(crate) fn pixels(&self) -> Result<Option<Box<dyn PixelSampler>>> {
        let SceneSampler::Pixel {
            sampler,
            randomizer,
        } = self.kind
        else {
            return Ok(None);
        };
        let params = PixelParams {
            width: self.width,
            height: self.height,
            spp: self.spp,
            seed: self.seed,
        };
        let entry = catalog::pixel_sampler(sampler).map_err(catalog_error)?;
        // "none" for a sampler that takes no randomizer: its own randomness.
        let r = if entry.kind.takes_randomizer() {
            Some(catalog::randomizer(randomizer).map_err(catalog_error)?)
        } else {
            None
        };
        catalog::build_pixel(entry, r, &params)
            .map(Some)
            .map_err(catalog_error)
    }

    /// The `spp` points of pixel `(x, y)`, row-major into `out` (`spp * dims` values);
    /// `pixels` is [`Prepared::pixels`], built once for the caller's rows.
    ///
    /// # Errors
    /// Only the samplers' own (unreachable after [`Prepared::new`]).
    pub(crate) fn pixel(
        &self,
        pixels: Option<&dyn PixelSampler>,
        x: u32,
        y: u32,
        out: &mut [f64],
    ) -> Result<()> {
        let d = self.dims;
        let Some(ps) = pixels else {
            let pixel = y as u64 * self.width as u64 + x as u64;
            let s = self.points(hash3(self.seed, pixel, self.kind.salt()))?;
            return s.fill_as(0, out);
        };
        for (i, row) in out.chunks_exact_mut(d).enumerate().take(self.spp as usize) {
            let mut s = PixelSampler::start_pixel_sample(&ps, x, y, i as u32)?;
            let mut k = 0;
            while k < d {
                let [a, b] = s.get_2d(); // the pair at dimension k
                row[k] = qmckit::bits::to_f64(a);
                if k + 1 < d {
                    row[k + 1] = qmckit::bits::to_f64(b);
                }
                k += 2;
            }
        }
        Ok(())
    }
}
