//! The point generators behind the Python engines: each builder validates its parameters
//! with qmckit and returns a [`NativeSampler`], which fills caller-owned NumPy arrays.
//!
//! Every generator is a boxed `qmckit::Sampler` (random access by index, so a fill can
//! start anywhere and be split over threads), except the SciPy-arithmetic Halton sequence
//! ([`crate::scipy_halton`]). This is the one module to change when the samplers come from
//! qmckit's catalog.

use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyReadwriteArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use qmckit::digital::DigitalNetB;
use qmckit::digital::sobol::Order;
use qmckit::lattice::Rank1Lattice;
use qmckit::randomize::digits::DigitScramble;
use qmckit::randomize::{
    Affine, CranleyPatterson, DigitalShift, FastOwen, Randomizer, Randomizes, Scrambled, Scrambler,
};
use qmckit::{Base2Digital, Halton, LatinHypercube, Sampler, Sobol};

use crate::error::{to_py, value_error};
use crate::fill::{self, SharedSampler};
use crate::scipy_halton::{Dimension, ScipyHalton};
use crate::sobol_owen::SobolOwen;
use crate::truncate::Truncated;

/// Fills of at least this many values run with the GIL released.
const DETACH_VALUES: usize = 1 << 14;

enum Inner {
    Points(Box<SharedSampler>),
    ScipyHalton(ScipyHalton),
}

/// A point generator: `fill(start, out, workers)` writes points `start, start + 1, ..` into
/// a preallocated C-contiguous `(n, dims)` array of `float64` (coordinates in `[0, 1)`) or
/// `uint32` (0.32 fixed-point fractions, `x / 2^32`), in place.
#[pyclass(frozen, module = "qmckit._qmckit")]
pub struct NativeSampler {
    inner: Inner,
    /// Kept bits of every 0.32 coordinate (Sobol's `bits`).
    mask: u32,
    name: String,
}

impl NativeSampler {
    fn points(s: Box<SharedSampler>, mask: u32, name: impl Into<String>) -> Self {
        NativeSampler {
            inner: Inner::Points(s),
            mask,
            name: name.into(),
        }
    }

    fn dims_(&self) -> usize {
        match &self.inner {
            Inner::Points(s) => s.dims(),
            Inner::ScipyHalton(h) => h.dims(),
        }
    }

    fn len_(&self) -> u64 {
        match &self.inner {
            Inner::Points(s) => s.len(),
            Inner::ScipyHalton(_) => qmckit::sampler::FULL_RANGE,
        }
    }

    /// Validates a fill of `rows` rows from `start`; returns `start` as a qmckit index.
    fn check_range(&self, start: u64, rows: usize) -> PyResult<u32> {
        let len = self.len_();
        let end = start.saturating_add(rows as u64);
        if end > len {
            let why = if len == qmckit::sampler::FULL_RANGE {
                "qmckit indices are 32-bit: at most 2^32 points".to_string()
            } else {
                format!("this {} has {len} points", self.name)
            };
            return Err(value_error(format!(
                "points {start}..{end} requested, but {why}"
            )));
        }
        // end <= len <= 2^32, so start < 2^32 when rows > 0.
        Ok(u32::try_from(start).unwrap_or(u32::MAX))
    }
}

#[pymethods]
impl NativeSampler {
    /// Number of coordinates of a point.
    #[getter]
    fn dims(&self) -> usize {
        self.dims_()
    }

    /// Number of valid point indices (2^32 for a sequence).
    #[getter]
    fn len(&self) -> u64 {
        self.len_()
    }

    /// What generates the points.
    #[getter]
    fn name(&self) -> &str {
        &self.name
    }

    fn __repr__(&self) -> String {
        format!("NativeSampler({}, dims={})", self.name, self.dims_())
    }

    /// Points `start .. start + n` into `out`, an `(n, dims)` C-contiguous `float64` or
    /// `uint32` array, in place (no copy). `workers` threads share the rows; the values do
    /// not depend on it. The GIL is released during long fills.
    #[pyo3(signature = (start, out, workers = 1))]
    fn fill(
        &self,
        py: Python<'_>,
        start: u64,
        out: &Bound<'_, PyAny>,
        workers: usize,
    ) -> PyResult<()> {
        let workers = workers.max(1);
        if let Ok(mut a) = out.extract::<PyReadwriteArray2<'_, f64>>() {
            let rows = self.check_shape(a.shape(), a.is_c_contiguous())?;
            let start = self.check_range(start, rows)?;
            let slice = a
                .as_slice_mut()
                .map_err(|e| value_error(format!("out: {e}")))?;
            return self.run(py, slice.len(), || self.fill_f64(start, slice, workers));
        }
        if let Ok(mut a) = out.extract::<PyReadwriteArray2<'_, u32>>() {
            let rows = self.check_shape(a.shape(), a.is_c_contiguous())?;
            let start = self.check_range(start, rows)?;
            let slice = a
                .as_slice_mut()
                .map_err(|e| value_error(format!("out: {e}")))?;
            return self.run(py, slice.len(), || self.fill_u32(start, slice, workers));
        }
        Err(PyTypeError::new_err(
            "out must be a writeable 2-D numpy array of float64 or uint32",
        ))
    }
}

impl NativeSampler {
    fn check_shape(&self, shape: &[usize], c_contiguous: bool) -> PyResult<usize> {
        let dims = self.dims_();
        if shape.len() != 2 || shape.get(1).copied() != Some(dims) {
            return Err(value_error(format!(
                "out must have shape (n, {dims}), got {shape:?}"
            )));
        }
        if !c_contiguous {
            return Err(value_error("out must be C-contiguous"));
        }
        Ok(shape.first().copied().unwrap_or(0))
    }

    fn run<F>(&self, py: Python<'_>, values: usize, f: F) -> PyResult<()>
    where
        F: FnOnce() -> Result<(), qmckit::Error> + Send,
    {
        let r = if values >= DETACH_VALUES {
            py.detach(f)
        } else {
            f()
        };
        r.map_err(to_py)
    }

    fn fill_f64(&self, start: u32, out: &mut [f64], workers: usize) -> qmckit::Result<()> {
        if out.is_empty() {
            return Ok(());
        }
        match &self.inner {
            Inner::Points(s) => fill::fill_f64(s.as_ref(), start, out, self.mask, workers),
            Inner::ScipyHalton(h) => {
                h.fill(u64::from(start), out, workers);
                Ok(())
            }
        }
    }

    fn fill_u32(&self, start: u32, out: &mut [u32], workers: usize) -> qmckit::Result<()> {
        if out.is_empty() {
            return Ok(());
        }
        match &self.inner {
            Inner::Points(s) => fill::fill_u32(s.as_ref(), start, out, self.mask, workers),
            Inner::ScipyHalton(h) => {
                // floor(x 2^32) of SciPy's doubles (x < 1; clamped should x round to 1).
                let mut tmp = vec![0f64; out.len()];
                h.fill(u64::from(start), &mut tmp, workers);
                for (o, x) in out.iter_mut().zip(tmp) {
                    *o = (x * 4_294_967_296.0).min(u32::MAX as f64) as u32;
                }
                Ok(())
            }
        }
    }
}

// ---------------------------------------------------------------------------------------
// Randomizers given by their affine maps (SciPy's LMS + digital shift, drawn in Python).

/// One affine map a dimension, `x -> M x ^ c` (the identity past the table).
#[derive(Clone, Debug)]
struct AffineTable(Vec<Affine>);

#[derive(Clone, Copy, Debug)]
struct AffineScrambler(Affine);

impl Scrambler for AffineScrambler {
    const AFFINE: bool = true;
    #[inline]
    fn scramble(&self, x: u32) -> u32 {
        self.0.apply(x)
    }
    #[inline]
    fn affine(&self) -> Option<Affine> {
        Some(self.0)
    }
}

impl Randomizer for AffineTable {
    type Scrambler = AffineScrambler;
    fn scrambler(&self, dim: usize) -> AffineScrambler {
        AffineScrambler(self.0.get(dim).copied().unwrap_or(Affine::IDENTITY))
    }
    fn apply(&self, x: u32, dim: usize) -> u32 {
        self.scrambler(dim).scramble(x)
    }
}

/// Folded into Sobol's direction numbers by the sampler's affine fill (no per-value
/// map application).
impl<S: Base2Digital + ?Sized> Randomizes<S> for AffineTable {
    #[inline]
    fn affine_fill(
        sampler: &S,
        start: u32,
        out: &mut [u32],
        maps: &dyn Fn(usize) -> Option<Affine>,
    ) -> Option<qmckit::Result<()>> {
        sampler.fill_affine(start, out, maps)
    }
}

fn affine_table(
    images: &PyReadonlyArray2<'_, u32>,
    shifts: &PyReadonlyArray1<'_, u32>,
    d: usize,
) -> PyResult<AffineTable> {
    let im = images.as_array();
    let sh = shifts.as_array();
    if im.shape() != [d, 32] || sh.len() != d {
        return Err(value_error(format!(
            "images must have shape ({d}, 32) and shifts ({d},)"
        )));
    }
    let mut maps = Vec::with_capacity(d);
    for j in 0..d {
        let mut a = Affine::IDENTITY;
        for (k, slot) in a.images.iter_mut().enumerate() {
            *slot = im.get([j, k]).copied().unwrap_or(1 << k);
        }
        a.shift = sh.get(j).copied().unwrap_or(0);
        maps.push(a);
    }
    Ok(AffineTable(maps))
}

fn mask_of(bits: u32) -> PyResult<u32> {
    match bits {
        1..=32 => Ok(u32::MAX << (32 - bits)),
        _ => Err(value_error(format!(
            "bits must be between 1 and 32 (qmckit's coordinates and indices are 32-bit), got {bits}"
        ))),
    }
}

fn boxed<S: Sampler + Send + Sync + 'static>(s: S) -> Box<SharedSampler> {
    Box::new(s)
}

/// Sobol' points in Gray-code order (SciPy's), `bits`-bit coordinates. `randomizer`:
/// `None`, `"owen"` (exact nested uniform), `"fast-owen"` (hash-based), `"xor"` (digital
/// shift), `"affine"` (the maps `images`, `shifts`: SciPy's LMS + shift).
#[pyfunction]
#[pyo3(signature = (d, bits = 30, randomizer = None, seed = 0, images = None, shifts = None))]
pub fn sobol(
    d: usize,
    bits: u32,
    randomizer: Option<&str>,
    seed: u64,
    images: Option<PyReadonlyArray2<'_, u32>>,
    shifts: Option<PyReadonlyArray1<'_, u32>>,
) -> PyResult<NativeSampler> {
    let mask = mask_of(bits)?;
    let s = Sobol::with_order(d, Order::Gray).map_err(to_py)?;
    let (b, name): (Box<SharedSampler>, &str) = match randomizer {
        None => (boxed(s), "Sobol'"),
        // Masks its own values (and skips the levels below `bits`): no mask on top.
        Some("owen") => {
            let b = boxed(SobolOwen::new(s, seed, bits));
            return Ok(NativeSampler::points(b, u32::MAX, "Sobol' + Owen"));
        }
        // Masks its own values inside the scramble loop (so a `float64` fill is one fused
        // pass): no mask on top.
        Some("fast-owen") => {
            let b = boxed(Scrambled::new(s, Truncated::new(FastOwen::new(seed), mask)));
            return Ok(NativeSampler::points(b, u32::MAX, "Sobol' + fast Owen"));
        }
        Some("xor") => (
            boxed(Scrambled::new(s, DigitalShift::new(seed))),
            "Sobol' + digital shift",
        ),
        Some("affine") => match (images, shifts) {
            (Some(im), Some(sh)) => (
                boxed(Scrambled::new(s, affine_table(&im, &sh, d)?)),
                "Sobol' + LMS + shift",
            ),
            _ => return Err(value_error("the affine randomizer needs images and shifts")),
        },
        Some(other) => return Err(value_error(format!("unknown Sobol' randomizer {other:?}"))),
    };
    Ok(NativeSampler::points(b, mask, name))
}

/// qmckit's Halton sequence (0.32 fixed point): `randomizer` `None`, `"owen"` (nested
/// scrambling in base b), `"perm-hash"` (hashed random digit permutations), `"faure"`.
#[pyfunction]
#[pyo3(signature = (d, randomizer = None, seed = 0))]
pub fn halton(d: usize, randomizer: Option<&str>, seed: u64) -> PyResult<NativeSampler> {
    let scramble = digit_scramble(randomizer, seed)?;
    let h = Halton::with_scramble(d, scramble).map_err(to_py)?;
    Ok(NativeSampler::points(boxed(h), u32::MAX, "Halton"))
}

fn digit_scramble(randomizer: Option<&str>, seed: u64) -> PyResult<DigitScramble> {
    Ok(match randomizer {
        None => DigitScramble::None,
        Some("owen") => DigitScramble::Owen(seed),
        Some("perm-hash") => DigitScramble::Permutations(seed),
        Some("faure") => DigitScramble::Faure,
        Some(other) => return Err(value_error(format!("unknown digit randomizer {other:?}"))),
    })
}

/// The Halton sequence in SciPy's arithmetic (the same doubles as `scipy.stats.qmc.Halton`):
/// `bases`, and optionally SciPy's digit permutations (one `(positions, base)` int64 array
/// a dimension).
#[pyfunction]
#[pyo3(signature = (bases, permutations = None))]
pub fn halton_scipy(
    bases: Vec<u64>,
    permutations: Option<Vec<PyReadonlyArray2<'_, i64>>>,
) -> PyResult<NativeSampler> {
    let mut dims = Vec::with_capacity(bases.len());
    let scrambled = permutations.is_some();
    for (k, &b) in bases.iter().enumerate() {
        let dim = match &permutations {
            Some(p) => {
                let a = p
                    .get(k)
                    .ok_or_else(|| value_error("one permutation table a base is needed"))?;
                let shape = a.shape();
                let rows = shape.first().copied().unwrap_or(0);
                let table = a
                    .as_slice()
                    .map_err(|_| value_error("permutations must be C-contiguous"))?;
                Dimension::new(b, Some((table, rows)))
            }
            None => Dimension::new(b, None),
        }
        .map_err(value_error)?;
        dims.push(dim);
    }
    Ok(NativeSampler {
        inner: Inner::ScipyHalton(ScipyHalton::new(dims)),
        mask: u32::MAX,
        name: if scrambled {
            "Halton (SciPy, scrambled)"
        } else {
            "Halton (SciPy)"
        }
        .into(),
    })
}

/// Kuo's extensible rank-1 lattice (radical-inverse order, 2^20 points), randomly shifted
/// (Cranley-Patterson) when `shift`.
#[pyfunction]
#[pyo3(signature = (d, shift = false, seed = 0))]
pub fn lattice(d: usize, shift: bool, seed: u64) -> PyResult<NativeSampler> {
    let l = Rank1Lattice::kuo(d).map_err(to_py)?;
    Ok(if shift {
        NativeSampler::points(
            boxed(Scrambled::new(l, CranleyPatterson::new(seed))),
            u32::MAX,
            "lattice",
        )
    } else {
        NativeSampler::points(boxed(l), u32::MAX, "lattice")
    })
}

/// The R_d Kronecker sequence, randomly shifted when `shift`.
#[pyfunction]
#[pyo3(signature = (d, shift = false, seed = 0))]
pub fn kronecker(d: usize, shift: bool, seed: u64) -> PyResult<NativeSampler> {
    let k = qmckit::lattice::kronecker::Kronecker::r_d(d).map_err(to_py)?;
    Ok(if shift {
        NativeSampler::points(
            boxed(Scrambled::new(k, CranleyPatterson::new(seed))),
            u32::MAX,
            "Kronecker",
        )
    } else {
        NativeSampler::points(boxed(k), u32::MAX, "Kronecker")
    })
}

/// Faure's (0, d)-sequence in the least prime base `b >= d`, digit-scrambled as
/// [`halton`]'s `randomizer`.
#[pyfunction]
#[pyo3(signature = (d, randomizer = None, seed = 0))]
pub fn faure(d: usize, randomizer: Option<&str>, seed: u64) -> PyResult<NativeSampler> {
    let mut base = (d as u32).max(2);
    while !qmckit::digital::is_prime(base) {
        base += 1;
    }
    let net = DigitalNetB::faure(base, d)
        .map_err(to_py)?
        .with_scramble(digit_scramble(randomizer, seed)?);
    Ok(NativeSampler::points(
        boxed(net),
        u32::MAX,
        format!("Faure (base {base})"),
    ))
}

/// `n` Latin hypercube points (one in every `1/n` slab of every axis).
#[pyfunction]
pub fn latin_hypercube(n: u64, d: usize, seed: u64) -> PyResult<NativeSampler> {
    let l = LatinHypercube::new(n, d, seed).map_err(to_py)?;
    Ok(NativeSampler::points(boxed(l), u32::MAX, "Latin hypercube"))
}

/// The stochastic PMJ02 sequence in 2D.
#[pyfunction]
pub fn pmj02(seed: u64) -> PyResult<NativeSampler> {
    Ok(NativeSampler::points(
        boxed(qmckit::pmj::Pmj02::new(seed)),
        u32::MAX,
        "PMJ02",
    ))
}

/// The first `n` points of the PMJ02BN sequence of `seed` for that length (a shorter
/// table is not a prefix of a longer one).
#[pyfunction]
pub fn pmj02bn(py: Python<'_>, n: usize, seed: u64) -> PyResult<NativeSampler> {
    let work_len = qmckit::pmj::bn::workspace_len(n).map_err(to_py)?;
    let pts = py
        .detach(move || -> qmckit::Result<Vec<u32>> {
            let mut pts = vec![[0u32; 2]; n];
            let mut work = vec![0u32; work_len];
            qmckit::pmj::bn::fill(seed, &mut pts, &mut work, &qmckit::work::Budget::UNLIMITED)?;
            Ok(pts.into_iter().flatten().collect())
        })
        .map_err(to_py)?;
    let set = qmckit::blue_noise::PointSet::new(pts, 2).map_err(to_py)?;
    Ok(NativeSampler::points(boxed(set), u32::MAX, "PMJ02BN table"))
}

/// The `n`-point set of any finite catalog sampler (`qmckit::catalog::SAMPLERS` of size
/// `Set` or `Whole`: stratified, latin, hammersley, lp, cmj, hex, pmj02bn, the blue-noise
/// sets, lloyd, ccvt, sot, bnot, projective-blue-noise, forced-random, ldbn, penrose,
/// aa-patterns, art, the spectral and kernel-density sets), by name or alias, unrandomized, in `d` dimensions
/// (the construction's default when `None`), with the construction's `seed`, and for the
/// relaxed sets their `iterations`, `torus`, (sot) `projective` and (kde-blue-noise)
/// `temperature`: the same bits as `qmckit points NAME -n N`.
#[pyfunction]
#[pyo3(signature = (name, n, d=None, seed=0, iterations=None, torus=false, projective=false, temperature=None))]
#[allow(clippy::too_many_arguments)] // the keyword arguments of the Python function
pub fn catalog_set(
    py: Python<'_>,
    name: &str,
    n: u64,
    d: Option<usize>,
    seed: u64,
    iterations: Option<u32>,
    torus: bool,
    projective: bool,
    temperature: Option<f64>,
) -> PyResult<NativeSampler> {
    use qmckit::catalog::{self, BlueNoiseOptions, Params, Size};
    let entry = catalog::sampler(name).map_err(|e| value_error(e.to_string()))?;
    if !matches!(entry.kind.size(), Size::Set | Size::Whole) {
        return Err(value_error(format!(
            "{}: a sequence, not a finite set (use its own engine)",
            entry.name
        )));
    }
    let params = Params {
        dims: d,
        points: Some(n),
        seed,
        blue_noise: BlueNoiseOptions {
            iterations,
            torus,
            projective,
            temperature,
            ..BlueNoiseOptions::default()
        },
        ..Params::default()
    };
    let none = catalog::randomizer("none").map_err(|e| value_error(e.to_string()))?;
    let (coords, dims) = py
        .detach(move || -> Result<(Vec<u32>, usize), String> {
            let s = catalog::build(entry, none, &params).map_err(|e| e.to_string())?;
            let len = qmckit::size::coordinates(s.len(), s.dims()).map_err(|e| e.to_string())?;
            let mut v = qmckit::size::vec_zeroed::<u32>(len).map_err(|e| e.to_string())?;
            s.fill(0, &mut v).map_err(|e| e.to_string())?;
            Ok((v, s.dims()))
        })
        .map_err(value_error)?;
    let set = qmckit::blue_noise::PointSet::new(coords, dims).map_err(to_py)?;
    Ok(NativeSampler::points(boxed(set), u32::MAX, entry.name))
}
