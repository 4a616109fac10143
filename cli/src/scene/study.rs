//! Studies: a reference image at a high sample count, renders per sampler, and the MSE over
//! seeds, with the low-frequency power of the error images.

use super::camera::Camera;
use super::geometry::Scene;
use super::integrands::{Integrand, standard_camera, standard_scene};
use super::samplers::{Prepared, SceneSampler};
use qmckit::analysis::screen_error::ScreenError;
use qmckit::work::Budget;
use qmckit::work::Limits;
use qmckit::work::Stop;
use qmckit::{Error, Jitter, OwenSobol, Result, Stratified};
use rayon::prelude::*;

use std::sync::atomic::{AtomicUsize, Ordering};

/// An image of linear values, row-major, row 0 at the top.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneImage {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// `width * height` values, `pixels[y * width + x]`.
    pub pixels: Vec<f64>,
}

impl SceneImage {
    /// The value of pixel `(x, y)` (`None` outside the image).
    pub fn get(&self, x: u32, y: u32) -> Option<f64> {
        if x < self.width && y < self.height {
            self.pixels
                .get(y as usize * self.width as usize + x as usize)
                .copied()
        } else {
            None
        }
    }

    /// The mean of `(self - other)^2` over the pixels (`None` for different sizes).
    pub fn mse(&self, other: &SceneImage) -> Option<f64> {
        if (self.width, self.height) != (other.width, other.height) {
            return None;
        }
        let n = self.pixels.len().max(1) as f64;
        Some(
            self.pixels
                .iter()
                .zip(&other.pixels)
                .map(|(a, b)| (a - b) * (a - b))
                .sum::<f64>()
                / n,
        )
    }
}

/// One sampler's result in a study.
#[derive(Clone, Debug, PartialEq)]
pub struct MseEntry {
    /// The sampler's name.
    pub sampler: String,
    /// Mean over seeds and pixels of `(render - reference)^2`.
    pub mse: f64,
    /// `mse` of the first entry (independent) divided by this `mse`: the lecture's "1/rx".
    pub relative: f64,
    /// Standard error of `mse` (the spread of the per-seed MSEs over `sqrt(seeds)`).
    pub mse_stderr: f64,
    /// Mean over seeds of the error image's normalized power `|DFT(E)|^2 / (W H var(E))`
    /// over the low band `1 <= |k| < min(W, H) / 8` (1 for white noise; smaller when the
    /// error is blue), as [`qmckit::analysis::screen_error`] defines it.
    pub low_band: f64,
    /// The same band of the unnormalized power `|DFT(E)|^2 / (W H)` (comparable between
    /// samplers whose MSE differs).
    pub low_band_absolute: f64,
}

/// A rendered study: see the [module documentation](super).
#[derive(Clone, Debug, PartialEq)]
pub struct SceneStudy {
    /// E.g. `"quad light, n = 16"`.
    pub name: String,
    /// Samples a pixel.
    pub spp: u32,
    /// Seeds the MSE is averaged over.
    pub seeds: u32,
    /// The reference image (Owen-scrambled Sobol' at `reference_spp`).
    pub reference: SceneImage,
    /// One render per sampler (seed 0), in the order of `mse`.
    pub renders: Vec<(String, SceneImage)>,
    /// `render - reference` per sampler (seed 0).
    pub errors: Vec<(String, SceneImage)>,
    /// One entry per sampler; the first is the independent sampler.
    pub mse: Vec<MseEntry>,
}

/// Image size, sample counts and seeds of a study.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct StudyOptions {
    /// Width in pixels, `>= 8`.
    pub width: u32,
    /// Height in pixels, `>= 8`.
    pub height: u32,
    /// Samples a pixel, a power of two.
    pub spp: u32,
    /// Seeds (independent renders) the MSE is averaged over, `>= 1`.
    pub seeds: u32,
    /// Samples a pixel of the reference, a power of two `>= spp`.
    pub reference_spp: u32,
}

impl StudyOptions {
    /// 64 x 64 pixels, 16 samples, 8 seeds, reference 1024: 2.9e7 samples, the five studies
    /// in about 12 s on a loaded two-core machine (release).
    pub const fn quick() -> Self {
        StudyOptions {
            width: 64,
            height: 64,
            spp: 16,
            seeds: 8,
            reference_spp: 1024,
        }
    }

    /// 128 x 128 pixels, 16 samples, 16 seeds, reference 2048: 2.3e8 samples, the five
    /// studies in about two minutes on a shared two-core machine (release).
    pub const fn full() -> Self {
        StudyOptions {
            width: 128,
            height: 128,
            spp: 16,
            seeds: 16,
            reference_spp: 2048,
        }
    }
}

/// The most integrand samples one study may take (several minutes on two cores).
pub const MAX_STUDY_SAMPLES: u64 = 1 << 31;

/// The most pixels a study image may have.
pub const MAX_PIXELS: u64 = 1 << 22;

/// The seed of the reference images' Owen scrambling.
pub const REFERENCE_SEED: u64 = 0x5EED_4EF0_0000_0001;

/// The studies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Study {
    /// [`pixel_area_study`].
    PixelArea,
    /// [`soft_shadow_study`].
    SoftShadow,
    /// [`motion_defocus_study`].
    MotionDefocus,
    /// [`pixel_light_study`].
    PixelLight,
    /// [`ambient_occlusion_study`].
    AmbientOcclusion,
}

impl Study {
    /// Every study, in the lecture's order.
    pub const ALL: [Study; 5] = [
        Study::PixelArea,
        Study::SoftShadow,
        Study::MotionDefocus,
        Study::PixelLight,
        Study::AmbientOcclusion,
    ];

    /// The integrand.
    pub const fn integrand(self) -> Integrand {
        match self {
            Study::PixelArea => Integrand::PixelArea,
            Study::SoftShadow => Integrand::SoftShadow,
            Study::MotionDefocus => Integrand::MotionDefocus,
            Study::PixelLight => Integrand::PixelLight,
            Study::AmbientOcclusion => Integrand::AmbientOcclusion,
        }
    }

    /// The samplers compared, the first the independent baseline.
    pub const fn samplers(self) -> &'static [SceneSampler] {
        use super::samplers::{
            BN_LATTICE, BN_SOBOL, HALTON, INDEPENDENT, SOBOL_OWEN, SOBOL_XOR, STRATIFIED, ZSOBOL,
        };
        match self {
            Study::PixelArea | Study::SoftShadow => &[INDEPENDENT, STRATIFIED, SOBOL_OWEN],
            Study::MotionDefocus => &[INDEPENDENT, HALTON, SOBOL_OWEN],
            Study::PixelLight => &[
                INDEPENDENT,
                SOBOL_XOR,
                SOBOL_OWEN,
                ZSOBOL,
                BN_SOBOL,
                BN_LATTICE,
            ],
            Study::AmbientOcclusion => &[INDEPENDENT, SOBOL_OWEN, ZSOBOL, BN_SOBOL, BN_LATTICE],
        }
    }

    /// The title, for `spp` samples.
    pub fn title(self, spp: u32) -> String {
        let what = match self {
            Study::PixelArea => "pixel area",
            Study::SoftShadow => "quad light",
            Study::MotionDefocus => "motion blur + defocus",
            Study::PixelLight => "pixel x light",
            Study::AmbientOcclusion => "ambient occlusion",
        };
        format!("{what}, n = {spp}")
    }

    /// Integrand samples of the study: `W H (spp seeds samplers + reference_spp)`.
    pub fn cost(self, o: &StudyOptions) -> u64 {
        let per_pixel = (o.spp as u64)
            .saturating_mul(o.seeds as u64)
            .saturating_mul(self.samplers().len() as u64)
            .saturating_add(o.reference_spp as u64);
        (o.width as u64)
            .saturating_mul(o.height as u64)
            .saturating_mul(per_pixel)
    }

    /// Runs the study under the deadline of the budget of `limits` (started here if it was
    /// not; read once per image row of every render, [`Budget::UNLIMITED`] has none),
    /// reporting progress to the progress callback of `limits` in renders (one a sampler
    /// and seed, one for the reference).
    ///
    /// # Errors
    /// As [`check`]; [`Error::OutOfTime`] past the deadline.
    pub fn run<'a>(self, o: &StudyOptions, limits: impl Into<Limits<'a>>) -> Result<SceneStudy> {
        let limits = limits.into();
        let (budget, progress) = (limits.budget(), limits.progress());
        check(o)?;
        let stop = Stop::new(budget, "a scene study");
        let samples = self.cost(o);
        if samples > MAX_STUDY_SAMPLES {
            return Err(Error::TooLarge {
                what: "integrand samples of a scene study",
                requested: samples,
                max: MAX_STUDY_SAMPLES,
            });
        }
        let integrand = self.integrand();
        let scene = standard_scene();
        let camera = standard_camera(o.width, o.height, self == Study::MotionDefocus)?;
        let total = 1 + self.samplers().len() * o.seeds as usize;
        let done = AtomicUsize::new(0);
        let tick = || progress(done.fetch_add(1, Ordering::Relaxed) + 1, total);
        let reference = render_with(
            &scene,
            &camera,
            integrand,
            super::samplers::SOBOL_OWEN,
            o.reference_spp,
            REFERENCE_SEED,
            &stop,
        )?;
        tick();
        let (mut renders, mut errors, mut mse) = (Vec::new(), Vec::new(), Vec::new());
        for &kind in self.samplers() {
            let mut per_seed = Vec::with_capacity(o.seeds as usize);
            let (mut low, mut low_abs) = (0.0, 0.0);
            for s in 0..o.seeds {
                let img = render_with(&scene, &camera, integrand, kind, o.spp, s as u64, &stop)?;
                let err: Vec<f64> = img
                    .pixels
                    .iter()
                    .zip(&reference.pixels)
                    .map(|(a, b)| a - b)
                    .collect();
                per_seed.push(err.iter().map(|e| e * e).sum::<f64>() / err.len() as f64);
                let (l, la) = low_band(&err, o.width as usize, o.height as usize);
                low += l;
                low_abs += la;
                if s == 0 {
                    renders.push((kind.name(), img));
                    errors.push((
                        kind.name(),
                        SceneImage {
                            width: o.width,
                            height: o.height,
                            pixels: err,
                        },
                    ));
                }
                tick();
            }
            let k = o.seeds as f64;
            let mean = per_seed.iter().sum::<f64>() / k;
            let var = if o.seeds > 1 {
                per_seed
                    .iter()
                    .map(|m| (m - mean) * (m - mean))
                    .sum::<f64>()
                    / (k - 1.0)
            } else {
                0.0
            };
            mse.push(MseEntry {
                sampler: kind.name(),
                mse: mean,
                relative: 1.0,
                mse_stderr: (var / k).sqrt(),
                low_band: low / k,
                low_band_absolute: low_abs / k,
            });
        }
        let base = mse.first().map_or(0.0, |e| e.mse);
        for e in &mut mse {
            e.relative = if e.mse > 0.0 {
                base / e.mse
            } else if base > 0.0 {
                f64::INFINITY
            } else {
                1.0
            };
        }
        Ok(SceneStudy {
            name: self.title(o.spp),
            spp: o.spp,
            seeds: o.seeds,
            reference,
            renders,
            errors,
            mse,
        })
    }
}

/// Validates study options.
///
/// # Errors
/// [`Error::InvalidParameter`] for an image smaller than 8 x 8 (no low frequency band) or
/// a reference with fewer samples than the renders; [`Error::TooLarge`] past
/// [`MAX_PIXELS`]; [`Error::ZeroPoints`] for no samples or no seeds;
/// [`Error::NotPowerOfTwo`] for `spp` or `reference_spp`.
pub fn check(o: &StudyOptions) -> Result<()> {
    if o.spp == 0 || o.seeds == 0 || o.reference_spp == 0 {
        return Err(Error::ZeroPoints);
    }
    if o.width < 8 || o.height < 8 {
        return Err(Error::InvalidParameter {
            what: "a scene study needs an image of at least 8 x 8 pixels",
        });
    }
    let pixels = o.width as u64 * o.height as u64;
    if pixels > MAX_PIXELS {
        return Err(Error::TooLarge {
            what: "pixels of a scene study",
            requested: pixels,
            max: MAX_PIXELS,
        });
    }
    for n in [o.spp, o.reference_spp] {
        if !n.is_power_of_two() {
            return Err(Error::NotPowerOfTwo { n: n as u64 });
        }
    }
    if o.reference_spp < o.spp {
        return Err(Error::InvalidParameter {
            what: "the reference needs at least as many samples as the renders",
        });
    }
    Ok(())
}

/// Estimated work of all five studies with options `o`, in integrand samples (each a camera
/// ray and at most one secondary ray; a few million a second on two cores). A caller compares
/// it with its budget; each study also refuses past [`MAX_STUDY_SAMPLES`] by itself.
///
/// ```
/// use qmckit_cli::scene::{StudyOptions, cost};
/// assert!(cost(&StudyOptions::quick()) < cost(&StudyOptions::full()));
/// ```
pub fn cost(opts: &StudyOptions) -> u64 {
    Study::ALL
        .iter()
        .fold(0u64, |a, s| a.saturating_add(s.cost(opts)))
}

/// Renders `integrand` with `kind` at `spp` samples a pixel and `seed`, in parallel over rows.
fn render_with(
    scene: &Scene,
    camera: &Camera,
    integrand: Integrand,
    kind: SceneSampler,
    spp: u32,
    seed: u64,
    stop: &Stop,
) -> Result<SceneImage> {
    let (w, h) = (camera.width(), camera.height());
    let d = integrand.dims();
    let sampler = Prepared::new(kind, d, spp, w, h, seed)?;
    let rows: Vec<Result<Vec<f64>>> = (0..h)
        .into_par_iter()
        .map(|y| {
            stop.budget_check()?;
            let pixels = sampler.pixels()?;
            let mut buf = vec![0.0; spp as usize * d];
            let mut row = Vec::with_capacity(w as usize);
            for x in 0..w {
                sampler.pixel(pixels.as_deref(), x, y, &mut buf)?;
                let sum: f64 = buf
                    .chunks_exact(d)
                    .map(|u| integrand.eval(scene, camera, x, y, u))
                    .sum();
                row.push(sum / spp as f64);
            }
            Ok(row)
        })
        .collect();
    let mut pixels = Vec::with_capacity(w as usize * h as usize);
    for r in rows {
        pixels.extend(r?);
    }
    Ok(SceneImage {
        width: w,
        height: h,
        pixels,
    })
}

/// The image of `study`'s integrand rendered with Owen-scrambled Sobol' at `spp` samples a
/// pixel and scramble seed `seed` (the reference is `spp = reference_spp`,
/// `seed = REFERENCE_SEED`). Cost `W H spp` samples.
///
/// # Errors
/// As [`check`] (with `spp` as the reference count), and past [`MAX_STUDY_SAMPLES`].
pub fn reference_image(study: Study, o: &StudyOptions, spp: u32, seed: u64) -> Result<SceneImage> {
    check(&StudyOptions {
        reference_spp: spp,
        spp: spp.min(o.spp),
        ..*o
    })?;
    let samples = o.width as u64 * o.height as u64 * spp as u64;
    if samples > MAX_STUDY_SAMPLES {
        return Err(Error::TooLarge {
            what: "integrand samples of a scene study",
            requested: samples,
            max: MAX_STUDY_SAMPLES,
        });
    }
    let camera = standard_camera(o.width, o.height, study == Study::MotionDefocus)?;
    render_with(
        &standard_scene(),
        &camera,
        study.integrand(),
        super::samplers::SOBOL_OWEN,
        spp,
        seed,
        &Stop::never("a scene reference"),
    )
}

/// The normalized and absolute low-band power of an error image (see [`MseEntry`]): the
/// `low_band` and `low_band_absolute` of [`ScreenError::from_error`] (the same bands as the
/// screen-space error of the pixel samplers), `(0, 0)` for a constant image.
/// O(W H (W + H)).
pub fn low_band(err: &[f64], w: usize, h: usize) -> (f64, f64) {
    match ScreenError::from_error(err.to_vec(), w, h) {
        Ok(e) => (e.low_band, e.low_band_absolute),
        Err(_) => (0.0, 0.0),
    }
}

/// Lecture table 1 at `n = spp`: the pixel-area integrand ([`Integrand::PixelArea`], 2D:
/// the film position; unshadowed analytic light) with independent, jittered stratified and
/// Owen-scrambled Sobol' points. Cost: [`Study::cost`] with 3 samplers.
///
/// # Errors
/// As [`check`]; past [`MAX_STUDY_SAMPLES`].
pub fn pixel_area_study(o: &StudyOptions) -> Result<SceneStudy> {
    Study::PixelArea.run(o, &Budget::UNLIMITED)
}

/// Lecture table 2 at `n = spp`: soft shadows of the quad light ([`Integrand::SoftShadow`],
/// 2D: the light sample, by area) at the pixel center's hit, independent / stratified /
/// Sobol' fast-owen. Cost: 3 samplers.
///
/// # Errors
/// As [`pixel_area_study`].
pub fn soft_shadow_study(o: &StudyOptions) -> Result<SceneStudy> {
    Study::SoftShadow.run(o, &Budget::UNLIMITED)
}

/// Motion blur and defocus ([`Integrand::MotionDefocus`], 5D: film 2, lens 2, time 1):
/// independent / Halton (random digit permutations) / Sobol' fast-owen. Cost: 3 samplers.
///
/// # Errors
/// As [`pixel_area_study`].
pub fn motion_defocus_study(o: &StudyOptions) -> Result<SceneStudy> {
    Study::MotionDefocus.run(o, &Budget::UNLIMITED)
}

/// Pixel x light ([`Integrand::PixelLight`], 4D: film 2, light 2): independent, Sobol' 4D
/// (digital shift), Sobol' fast-owen 4D, ZSobol (blue-noise Sobol', pairs of dimensions) and
/// the table-driven blue-noise Owen-Sobol' and lattice (pairs of dimensions as domains).
/// Cost: 6 samplers.
///
/// # Errors
/// As [`pixel_area_study`].
pub fn pixel_light_study(o: &StudyOptions) -> Result<SceneStudy> {
    Study::PixelLight.run(o, &Budget::UNLIMITED)
}

/// Ambient occlusion ([`Integrand::AmbientOcclusion`], 2D: a cosine-weighted direction at
/// the pixel center's hit): white noise (independent per pixel; Sobol' fast-owen with a seed per
/// pixel) against blue noise (ZSobol, and the table-driven blue-noise Owen-Sobol' and
/// lattice). [`MseEntry::low_band`] holds the error images' low-frequency power. Cost: 5
/// samplers.
///
/// # Errors
/// As [`pixel_area_study`].
pub fn ambient_occlusion_study(o: &StudyOptions) -> Result<SceneStudy> {
    Study::AmbientOcclusion.run(o, &Budget::UNLIMITED)
}

/// Two 2D patterns of the quad-light figure: `(stratified, Sobol')`.
pub type PatternPair = (Vec<[f64; 2]>, Vec<[f64; 2]>);

/// The `spp`-point patterns of the "warping samples to a quad light" figure, in the quad's
/// `(u, v)` in `[0, 1)^2`: a jittered `2^ceil(m/2) x 2^floor(m/2)` grid (4 x 4 for 16) and
/// the first `spp` Owen-scrambled Sobol' points, both from `seed`. O(spp).
///
/// # Errors
/// [`Error::ZeroPoints`]; [`Error::NotPowerOfTwo`]; [`Error::TooLarge`] past 2^16 points.
pub fn quad_light_uv(spp: u32, seed: u64) -> Result<PatternPair> {
    if spp == 0 {
        return Err(Error::ZeroPoints);
    }
    if !spp.is_power_of_two() {
        return Err(Error::NotPowerOfTwo { n: spp as u64 });
    }
    if spp > 1 << 16 {
        return Err(Error::TooLarge {
            what: "points of the quad-light figure",
            requested: spp as u64,
            max: 1 << 16,
        });
    }
    let m = spp.trailing_zeros();
    let st = Stratified::new(&[1 << m.div_ceil(2), 1 << (m / 2)], Jitter::Random(seed))?;
    let so = OwenSobol::new(2, seed)?;
    let to = qmckit::bits::to_f64;
    let mut a = Vec::with_capacity(spp as usize);
    let mut b = Vec::with_capacity(spp as usize);
    for i in 0..spp {
        a.push([to(st.sample(i, 0)?), to(st.sample(i, 1)?)]);
        b.push([to(so.sample(i, 0)?), to(so.sample(i, 1)?)]);
    }
    Ok((a, b))
}

/// The same patterns as [`quad_light_uv`] warped onto the studies' quad light by the area
/// map `y = p_0 + u e_x + v e_y` (uniform density `1 / A`), as they land: the world `(x, z)`
/// of each point (the light is horizontal, at height 2.6, spanning `x` in `[-0.5, 1]`, `z`
/// in `[-0.5, 0.5]`; [`quad_light_extent`]). `.0` is the stratified pattern, `.1` Sobol'.
///
/// # Errors
/// As [`quad_light_uv`].
///
/// ```
/// let (st, so) = qmckit_cli::scene::quad_light_points(16, 1)?;
/// assert_eq!((st.len(), so.len()), (16, 16));
/// assert!(st.iter().chain(&so).all(|p| (-0.5..=1.0).contains(&p[0]) && (-0.5..=0.5).contains(&p[1])));
/// # Ok::<(), qmckit::Error>(())
/// ```
pub fn quad_light_points(o_spp: u32, seed: u64) -> Result<PatternPair> {
    let (a, b) = quad_light_uv(o_spp, seed)?;
    let q = standard_scene().light;
    let land = |v: Vec<[f64; 2]>| -> Vec<[f64; 2]> {
        v.into_iter()
            .map(|[u, w]| {
                let p = q.point(u, w);
                [p.x, p.z]
            })
            .collect()
    };
    Ok((land(a), land(b)))
}

/// The world `(x, z)` ranges of the studies' quad light: `([x_min, x_max], [z_min, z_max])`.
pub fn quad_light_extent() -> ([f64; 2], [f64; 2]) {
    let c = standard_scene().light.corners();
    let (mut x, mut z) = (
        [f64::INFINITY, f64::NEG_INFINITY],
        [f64::INFINITY, f64::NEG_INFINITY],
    );
    for p in c {
        x = [x[0].min(p.x), x[1].max(p.x)];
        z = [z[0].min(p.z), z[1].max(p.z)];
    }
    (x, z)
}
