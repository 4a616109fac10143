//! The sets built whole (`std`; the constructions themselves need `analysis`): the
//! blue-noise sets and PMJ02BN, each estimated against its time budget before it starts
//! and stopped at the budget's deadline.

use super::{CatalogError, SamplerKind};

/// Options of the blue-noise sets (each applies to the sets its field names).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct BlueNoiseOptions {
    /// poisson: the disk radius, instead of `points`.
    pub radius: Option<f64>,
    /// poisson, lloyd, ccvt, bnot: toroidal distance.
    pub torus: bool,
    /// poisson: fill until no further disk fits.
    pub maximal: bool,
    /// poisson: candidates per step (default 30); best-candidate: the multiplier `m`
    /// (default 10).
    pub candidates: Option<u32>,
    /// gaussian-blue-noise: gradient-descent iterations (default 500); lloyd, ccvt
    /// (default 30), sot (default 100), bnot (default 50), step-blue-noise and
    /// single-peak-blue-noise (default 200): their iterations; kde-blue-noise: its sweeps
    /// a level (default 60).
    pub iterations: Option<u32>,
    /// sot: projective sampling (half the directions in the 1D and 2D axis subspaces).
    pub projective: bool,
    /// kde-blue-noise: the temperature (default 0.001).
    pub temperature: Option<f64>,
}

impl BlueNoiseOptions {
    /// The first option given that `kind` does not take, with why.
    pub(super) fn unused(&self, kind: SamplerKind) -> Option<(&'static str, &'static str)> {
        use SamplerKind as S;
        let poisson = kind == S::Poisson;
        let only_poisson = "only poisson takes it";
        [
            ("radius", self.radius.is_some() && !poisson, only_poisson),
            (
                "torus",
                self.torus && !matches!(kind, S::Poisson | S::Lloyd | S::Ccvt | S::Bnot),
                "only poisson, lloyd, ccvt and bnot take it",
            ),
            ("maximal", self.maximal && !poisson, only_poisson),
            (
                "candidates",
                self.candidates.is_some()
                    && !matches!(kind, SamplerKind::Poisson | SamplerKind::BestCandidate),
                "only poisson and best-candidate take it",
            ),
            (
                "iterations",
                self.iterations.is_some()
                    && !matches!(
                        kind,
                        S::GaussianBlueNoise
                            | S::Lloyd
                            | S::Ccvt
                            | S::Sot
                            | S::Bnot
                            | S::StepBlueNoise
                            | S::SinglePeakBlueNoise
                            | S::KdeBlueNoise
                    ),
                "only gaussian-blue-noise, lloyd, ccvt, sot, bnot, step-blue-noise, \
                 single-peak-blue-noise and kde-blue-noise take it",
            ),
            (
                "projective",
                self.projective && kind != S::Sot,
                "only sot takes it; projective-blue-noise is always projective",
            ),
            (
                "temperature",
                self.temperature.is_some() && kind != S::KdeBlueNoise,
                "only kde-blue-noise takes it",
            ),
        ]
        .into_iter()
        .find(|(_, given, _)| *given)
        .map(|(name, _, why)| (name, why))
    }
}

#[cfg(feature = "analysis")]
pub(super) use built::{blue_noise, pmj02bn, relaxed, tiled};

#[cfg(feature = "analysis")]
mod built {
    use super::{BlueNoiseOptions, CatalogError, SamplerKind};
    use crate::blue_noise::{BestCandidate, GaussianBlueNoise, PointSet, PoissonDisk};
    use crate::work::{Budget, Cost, Rate};

    /// The set `kind` names: `n` points (poisson: about `n`, or `opts.radius`), `dims`
    /// (poisson: 1 to 8, default 2; the others 2), `seed`, within `budget` (started here
    /// if it was not). The same sets, bit for bit, as `qmckit points`.
    pub(in crate::catalog) fn blue_noise(
        kind: SamplerKind,
        name: &'static str,
        opts: &BlueNoiseOptions,
        n: Option<u64>,
        dims: Option<usize>,
        seed: u64,
        budget: &Budget,
    ) -> Result<PointSet, CatalogError> {
        let budget = budget.started();
        let need_n = || {
            n.ok_or(CatalogError::Parameter {
                entry: name,
                param: "points",
                got: None,
                expected: "needed: the number of points",
            })
        };
        Ok(match kind {
            SamplerKind::Poisson => {
                let d = dims.unwrap_or(2);
                let pd = match (opts.radius, n) {
                    (Some(_), Some(_)) => {
                        return Err(CatalogError::Parameter {
                            entry: name,
                            param: "radius",
                            got: None,
                            expected: "takes a radius or points (about N), not both",
                        });
                    }
                    (Some(r), None) => PoissonDisk::new(d, r)?,
                    (None, Some(n)) => PoissonDisk::with_points(d, n)?,
                    (None, None) => {
                        return Err(CatalogError::Parameter {
                            entry: name,
                            param: "points",
                            got: None,
                            expected: "needed, or a radius",
                        });
                    }
                };
                let mut pd = pd.torus(opts.torus).maximal(opts.maximal).seed(seed);
                if let Some(k) = opts.candidates {
                    pd = pd.candidates(k)?;
                }
                pd.generate(&budget)?
            }
            SamplerKind::BestCandidate => {
                let mut bc = BestCandidate::new(need_n()?)?.seed(seed);
                if let Some(m) = opts.candidates {
                    bc = bc.candidates(m)?;
                }
                bc.generate(&budget)?
            }
            _ => {
                let mut g = GaussianBlueNoise::new(need_n()?)?.seed(seed);
                if let Some(i) = opts.iterations {
                    g = g.iterations(i)?;
                }
                g.generate(&budget)?
            }
        })
    }

    /// The relaxed sets: lloyd, ccvt, bnot (2D; on the torus if `opts.torus`) and sot
    /// (projective if `opts.projective`), `n` points of `dims`, their iterations from
    /// `opts` (else their defaults), within `budget`; and projective-blue-noise, `n`
    /// points of `dims` within `budget`; forced-random, `n` points of the constant density; the spectral sets
    /// and kde-blue-noise, `n` points of `dims`, their iterations (and temperature) from
    /// `opts`.
    pub(in crate::catalog) fn relaxed(
        kind: SamplerKind,
        opts: &BlueNoiseOptions,
        n: u64,
        dims: usize,
        seed: u64,
        budget: &Budget,
    ) -> Result<PointSet, CatalogError> {
        use crate::blue_noise::spectral::Profile;
        use crate::blue_noise::{
            Bnot, ForcedRandom, KdeBlueNoise, Lloyd, ProjectiveBlueNoise, Sot, SpectralBlueNoise,
        };
        let budget = budget.started();
        if matches!(
            kind,
            SamplerKind::StepBlueNoise | SamplerKind::SinglePeakBlueNoise
        ) {
            let profile = if kind == SamplerKind::StepBlueNoise {
                Profile::step(dims)?
            } else {
                Profile::single_peak(dims)?
            };
            let mut s = SpectralBlueNoise::new(n, dims, profile)?.seed(seed);
            if let Some(i) = opts.iterations {
                s = s.iterations(i)?;
            }
            return Ok(s.generate(&budget)?);
        }
        if kind == SamplerKind::KdeBlueNoise {
            let mut k = KdeBlueNoise::new(n, dims)?.seed(seed);
            if let Some(i) = opts.iterations {
                k = k.sweeps(i)?;
            }
            if let Some(t) = opts.temperature {
                k = k.temperature(t)?;
            }
            return Ok(k.generate(&budget)?);
        }
        Ok(if kind == SamplerKind::ForcedRandom {
            ForcedRandom::new(n)?.seed(seed).generate(&budget)?
        } else if kind == SamplerKind::Bnot {
            if dims != 2 {
                return Err(crate::Error::DimensionOutOfRange { dim: dims, dims: 2 }.into());
            }
            let mut b = Bnot::new(n)?.seed(seed).torus(opts.torus);
            if let Some(i) = opts.iterations {
                b = b.iterations(i)?;
            }
            b.generate(&budget)?
        } else if kind == SamplerKind::ProjectiveBlueNoise {
            ProjectiveBlueNoise::new(n, dims)?
                .seed(seed)
                .generate(&budget)?
        } else if kind == SamplerKind::Sot {
            let mut s = Sot::new(n, dims)?.seed(seed).projective(opts.projective);
            if let Some(i) = opts.iterations {
                s = s.iterations(i)?;
            }
            s.generate(&budget)?
        } else {
            let mut l = Lloyd::new(n, dims)?
                .seed(seed)
                .torus(opts.torus)
                .capacity_constrained(kind == SamplerKind::Ccvt);
            if let Some(i) = opts.iterations {
                l = l.iterations(i)?;
            }
            l.generate(&budget)?
        })
    }

    /// The tile-based sets: penrose, aa-patterns, art, `n` points, within `budget`.
    pub(in crate::catalog) fn tiled(
        kind: SamplerKind,
        n: u64,
        seed: u64,
        budget: &Budget,
    ) -> Result<PointSet, CatalogError> {
        use crate::blue_noise::{AaPattern, Art, Penrose};
        let budget = budget.started();
        Ok(match kind {
            SamplerKind::AaPatterns => AaPattern::new(n, seed)?.generate(&budget)?,
            SamplerKind::Art => Art::new(n)?.seed(seed).generate(&budget)?,
            _ => Penrose::new(n)?.seed(seed).generate(&budget)?,
        })
    }

    /// PMJ02BN's throughput in cache: spread steps (a point at one of the `ceil(log2 n)`
    /// levels) a second, one core, release (measured 2.5e6 to 2.8e6 for 10^4 to 10^5
    /// points).
    const PMJ02BN_STEPS: Rate = Rate::per_second(2.8e6);

    /// The growth of a step's cost per doubling of `n` past `2^16` points, when the
    /// workspace (`8n` to `16n` words) leaves the caches (measured: 10^6 points, 20
    /// levels, 15 s).
    const PMJ02BN_MEMORY: f64 = 0.3;

    /// The first `n` points of the PMJ02BN sequence of `seed`, as a point set:
    /// `O(n log n)`, estimated and refused past `budget`, stopped at its deadline, memory
    /// checked by [`crate::size::vec_zeroed`]. The same points as `qmckit points pmj02bn`.
    pub(in crate::catalog) fn pmj02bn(
        n: u64,
        seed: u64,
        budget: &Budget,
    ) -> Result<PointSet, CatalogError> {
        use crate::pmj::bn;
        let budget = budget.started();
        let len = usize::try_from(n).unwrap_or(usize::MAX);
        let work_len = bn::workspace_len(len)?;
        let log = (n.max(2) as f64).log2();
        let memory = 1.0 + PMJ02BN_MEMORY * (log - 16.0).max(0.0);
        let steps = n as f64 * log.ceil() * memory;
        budget.check("pmj02bn points", Cost::steps(steps, PMJ02BN_STEPS))?;
        let mut pts = crate::size::vec_zeroed::<[u32; 2]>(len)?;
        let mut work = crate::size::vec_zeroed::<u32>(work_len)?;
        bn::fill(seed, &mut pts, &mut work, &budget)?;
        drop(work);
        let mut coords = crate::size::vec_with_capacity(crate::size::coordinates(n, 2)?)?;
        coords.extend(pts.into_iter().flatten());
        Ok(PointSet::new(coords, 2)?)
    }
}

/// Without `analysis` the sets built whole are not compiled in.
#[cfg(not(feature = "analysis"))]
pub(super) const fn unavailable(name: &'static str) -> CatalogError {
    CatalogError::Unused {
        entry: name,
        param: "the construction",
        why: "the sets built whole need the analysis feature",
    }
}
