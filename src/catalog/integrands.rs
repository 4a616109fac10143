//! The test integrands, one list with one name each: the convergence integrands of
//! [`crate::analysis::integrate`], the torus integrands of
//! [`crate::analysis::variance`], the problems of [`crate::analysis::integrate`] (Genz's
//! families, Keister, two options) and the pixel integrands of
//! [`crate::analysis::screen_error`]. The functions stay where they are; the catalog
//! names them and builds them (`build_integrand`, `analysis`).

use super::{Entry, Param, alias, param};

/// An integrand of [`INTEGRANDS`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum IntegrandKind {
    /// Genz's Gaussian peak with `a = 4` at the centre.
    GaussianPeak,
    /// Genz's oscillatory with `u = 0.3`, `a = 2`.
    Oscillatory,
    /// Indicator of the ball of radius 0.45 about the centre.
    Ball,
    /// Indicator of an oblique half-space through the centre.
    Heaviside,
    /// Disk indicator on the torus.
    TorusDisk,
    /// Periodized Gaussian on the torus.
    TorusGaussian,
    /// Genz's oscillatory family.
    GenzOscillatory,
    /// Genz's product peak family.
    GenzProductPeak,
    /// Genz's corner peak family.
    GenzCornerPeak,
    /// Genz's Gaussian family.
    GenzGaussian,
    /// Genz's continuous family.
    GenzContinuous,
    /// Genz's discontinuous family.
    GenzDiscontinuous,
    /// Keister's integrand.
    Keister,
    /// A European call under Black–Scholes.
    European,
    /// A geometric-average Asian call.
    AsianGeometric,
    /// A smooth bump in the pixel.
    PixelGaussianBump,
    /// A straight edge in the pixel.
    PixelStep,
    /// An edge that moves across the image.
    PixelVisibility,
}

/// Where an integrand lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Domain {
    /// `[0, 1]^d`, any `d`.
    Cube,
    /// The unit torus in 2D, with closed-form Fourier coefficients.
    Torus,
    /// The unit square of a pixel.
    Pixel,
}

impl IntegrandKind {
    /// Its domain.
    pub const fn domain(self) -> Domain {
        match self {
            IntegrandKind::TorusDisk | IntegrandKind::TorusGaussian => Domain::Torus,
            IntegrandKind::PixelGaussianBump
            | IntegrandKind::PixelStep
            | IntegrandKind::PixelVisibility => Domain::Pixel,
            _ => Domain::Cube,
        }
    }

    /// The dimensions when `dims` is not given: 4 for the options (four dates), 2
    /// otherwise.
    pub const fn default_dims(self) -> usize {
        match self {
            IntegrandKind::European | IntegrandKind::AsianGeometric => 4,
            _ => 2,
        }
    }

    /// The largest `dims` it takes (its exact integral's range).
    pub const fn max_dims(self) -> usize {
        match self {
            IntegrandKind::TorusDisk
            | IntegrandKind::TorusGaussian
            | IntegrandKind::PixelGaussianBump
            | IntegrandKind::PixelStep
            | IntegrandKind::PixelVisibility => 2,
            // 2^d terms in the exact integral.
            IntegrandKind::GenzCornerPeak => 24,
            // The radial quadrature's stated accuracy.
            IntegrandKind::Keister => 40,
            _ => 1 << 20,
        }
    }

    /// For a Genz family, the scale `s` of its default difficulty `a_k = s (1 + k) / d`
    /// (as `analysis::integrate::test_suite` has it); `None` for the others.
    pub const fn genz_scale(self) -> Option<f64> {
        Some(match self {
            IntegrandKind::GenzOscillatory => 2.0,
            IntegrandKind::GenzProductPeak => 4.0,
            IntegrandKind::GenzCornerPeak => 1.0,
            IntegrandKind::GenzGaussian => 3.0,
            IntegrandKind::GenzContinuous => 2.0,
            IntegrandKind::GenzDiscontinuous => 1.0,
            _ => return None,
        })
    }
}

/// An entry of [`INTEGRANDS`].
pub type IntegrandEntry = Entry<IntegrandKind>;

const DIMS: Param = param("dims", "dimensions of the integrand", "2", "at least 1");
const DIMS_2: Param = param("dims", "dimensions of the integrand", "2", "2");
const GENZ: [Param; 3] = [
    DIMS,
    param(
        "a",
        "difficulty a_k (dims values)",
        "scale (1 + k) / d, the scale per family as in test_suite",
        "positive",
    ),
    param(
        "u",
        "location u_k (dims values)",
        "0.2 + 0.6 frac(0.618 k)",
        "[0, 1]",
    ),
];
const MARKET: [Param; 2] = [
    param("dims", "dates of the Brownian bridge", "4", "at least 1"),
    param(
        "market",
        "spot, strike, rate, volatility, maturity",
        "100, 100, 0.05, 0.2, 1",
        "positive",
    ),
];

/// Every test integrand.
pub static INTEGRANDS: &[IntegrandEntry] = &[
    Entry {
        kind: IntegrandKind::GaussianPeak,
        name: "gaussian-peak",
        aliases: &[alias("gaussian", "qmckit convergence --integrand gaussian")],
        summary: "Genz's Gaussian peak at the centre, exp(-16 |x - c|^2)",
        math: "I = (sqrt(pi) erf(2) / 4)^d (Genz 1984)",
        params: &[DIMS],
        item: "qmckit::analysis::integrate::Integrand::Gaussian",
    },
    Entry {
        kind: IntegrandKind::Oscillatory,
        name: "oscillatory",
        aliases: &[alias("cosine", "its shape")],
        summary: "Genz's oscillatory, cos(0.6 pi + 2 sum_k x_k)",
        math: "I = Re(e^(0.6 pi i) z^d), z = (e^(2i) - 1) / (2i) (Genz 1984)",
        params: &[DIMS],
        item: "qmckit::analysis::integrate::Integrand::Oscillatory",
    },
    Entry {
        kind: IntegrandKind::Ball,
        name: "ball",
        aliases: &[alias("ball-indicator", "the full name")],
        summary: "1 inside the ball of radius 0.45 about the centre",
        math: "I = V_d = V_(d-2) 2 pi r^2 / d (Owen, Practical QMC)",
        params: &[DIMS],
        item: "qmckit::analysis::integrate::Integrand::Ball",
    },
    Entry {
        kind: IntegrandKind::Heaviside,
        name: "heaviside",
        aliases: &[alias("half-space", "the set it indicates")],
        summary: "1 where sum_k sqrt(k + 2) (x_k - 1/2) >= 0",
        math: "I = 1/2 (the cube is symmetric about its centre)",
        params: &[DIMS],
        item: "qmckit::analysis::integrate::Integrand::Heaviside",
    },
    Entry {
        kind: IntegrandKind::TorusDisk,
        name: "torus-disk",
        aliases: &[alias("disk", "qmckit variance --integrand disk")],
        summary: "indicator of the disk of radius R about (1/2, 1/2) on the torus",
        math: "c_0 = pi R^2, |c_k| = R J1(2 pi R |k|) / |k| (Pilleboue et al. 2015)",
        params: &[DIMS_2, param("radius", "R", "0.25", "[1e-50, 0.5]")],
        item: "qmckit::analysis::variance::TorusIntegrand::Disk",
    },
    Entry {
        kind: IntegrandKind::TorusGaussian,
        name: "torus-gaussian",
        aliases: &[alias(
            "periodic-gaussian",
            "qmckit variance --integrand gaussian",
        )],
        summary: "periodized Gaussian of standard deviation sigma about (1/2, 1/2)",
        math: "c_k = 2 pi s^2 exp(-2 pi^2 s^2 |k|^2) (Pilleboue et al. 2015)",
        params: &[DIMS_2, param("sigma", "s", "0.1", "[1e-50, 0.15]")],
        item: "qmckit::analysis::variance::TorusIntegrand::Gaussian",
    },
    Entry {
        kind: IntegrandKind::GenzOscillatory,
        name: "genz-oscillatory",
        aliases: &[alias("genz-1", "Genz's numbering")],
        summary: "Genz's oscillatory family",
        math: "cos(2 pi u_1 + sum a_k x_k); I = Re(e^(2 pi i u_1) prod (e^(i a_k) - 1)/(i a_k)) (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::Oscillatory",
    },
    Entry {
        kind: IntegrandKind::GenzProductPeak,
        name: "genz-product-peak",
        aliases: &[alias("genz-2", "Genz's numbering")],
        summary: "Genz's product peak family",
        math: "prod 1/(a_k^-2 + (x_k - u_k)^2); I = prod a_k (atan(a_k (1 - u_k)) + atan(a_k u_k)) (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::ProductPeak",
    },
    Entry {
        kind: IntegrandKind::GenzCornerPeak,
        name: "genz-corner-peak",
        aliases: &[alias("genz-3", "Genz's numbering")],
        summary: "Genz's corner peak family (at most 24 dimensions: 2^d terms in I)",
        math: "(1 + sum a_k x_k)^-(d+1); I = (1/(d! prod a_k)) sum_v (-1)^|v| / (1 + a.v) (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::CornerPeak",
    },
    Entry {
        kind: IntegrandKind::GenzGaussian,
        name: "genz-gaussian",
        aliases: &[alias("genz-4", "Genz's numbering")],
        summary: "Genz's Gaussian family",
        math: "exp(-sum a_k^2 (x_k - u_k)^2); I = prod sqrt(pi)/(2 a_k) (erf(a_k (1-u_k)) + erf(a_k u_k)) (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::Gaussian",
    },
    Entry {
        kind: IntegrandKind::GenzContinuous,
        name: "genz-continuous",
        aliases: &[alias("genz-5", "Genz's numbering")],
        summary: "Genz's continuous family",
        math: "exp(-sum a_k |x_k - u_k|); I = prod (2 - e^(-a_k u_k) - e^(-a_k (1-u_k))) / a_k (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::Continuous",
    },
    Entry {
        kind: IntegrandKind::GenzDiscontinuous,
        name: "genz-discontinuous",
        aliases: &[alias("genz-6", "Genz's numbering")],
        summary: "Genz's discontinuous family",
        math: "exp(sum a_k x_k) where x_1 <= u_1, x_2 <= u_2; I = prod (e^(a_k c_k) - 1)/a_k (Genz 1984)",
        params: &GENZ,
        item: "qmckit::analysis::integrate::GenzFamily::Discontinuous",
    },
    Entry {
        kind: IntegrandKind::Keister,
        name: "keister",
        aliases: &[alias("keister-1996", "the paper")],
        summary: "Keister's cos(|x|) exp(-|x|^2) over R^d, by the normal quantile (at most 40 dimensions)",
        math: "I = pi^(d/2) E cos(|Z| / sqrt 2), x = Phi^-1(u) / sqrt 2 (Keister 1996)",
        params: &[param("dims", "dimensions", "2", "1 to 40")],
        item: "qmckit::analysis::integrate::ProblemKind::Keister",
    },
    Entry {
        kind: IntegrandKind::European,
        name: "european",
        aliases: &[alias("european-call", "the full name")],
        summary: "a European call, geometric Brownian motion by the Brownian bridge",
        math: "e^(-rT) max(S_T - K, 0); I by Black–Scholes (Glasserman 2004, 3.1)",
        params: &MARKET,
        item: "qmckit::analysis::integrate::ProblemKind::European",
    },
    Entry {
        kind: IntegrandKind::AsianGeometric,
        name: "asian-geometric",
        aliases: &[alias("asian-geometric-call", "the full name")],
        summary: "a geometric-average Asian call by the Brownian bridge",
        math: "e^(-rT) max((prod S_(jT/d))^(1/d) - K, 0); I in closed form (Glasserman 2004, 3.2)",
        params: &MARKET,
        item: "qmckit::analysis::integrate::ProblemKind::AsianGeometric",
    },
    Entry {
        kind: IntegrandKind::PixelGaussianBump,
        name: "pixel-gaussian-bump",
        aliases: &[alias("gaussian-bump", "qmckit::analysis::screen_error")],
        summary: "a smooth bump in the pixel, exp(-|u - 1/2|^2 / (2 0.2^2))",
        math: "I = (s sqrt(2 pi) erf(1 / (2 sqrt 2 s)))^2, s = 0.2 (Heitz & Belcour 2019)",
        params: &[DIMS_2],
        item: "qmckit::analysis::screen_error::PixelIntegrand::GaussianBump",
    },
    Entry {
        kind: IntegrandKind::PixelStep,
        name: "pixel-step",
        aliases: &[alias("step", "qmckit::analysis::screen_error")],
        summary: "a straight edge in the pixel, 1 where u + 0.37 v < 0.61",
        math: "I = 0.425 (Heitz & Belcour 2019)",
        params: &[DIMS_2],
        item: "qmckit::analysis::screen_error::PixelIntegrand::Step",
    },
    Entry {
        kind: IntegrandKind::PixelVisibility,
        name: "pixel-visibility",
        aliases: &[alias("visibility", "qmckit::analysis::screen_error")],
        summary: "an edge whose threshold moves across the image (evaluated at the centre)",
        math: "1 where u + 0.37 v < t(x, y); I = t - 0.185 (Heitz & Belcour 2019)",
        params: &[DIMS_2],
        item: "qmckit::analysis::screen_error::PixelIntegrand::Visibility",
    },
];

#[cfg(feature = "analysis")]
pub use built::{IntegrandParams, TestIntegrand, build_integrand};

#[cfg(feature = "analysis")]
mod built {
    use super::super::CatalogError;
    use super::{IntegrandEntry, IntegrandKind as I};
    use crate::analysis::integrate::Integrand;
    use crate::analysis::integrate::{GenzFamily, Market, Problem, ProblemKind};
    use crate::analysis::screen_error::PixelIntegrand;
    use crate::analysis::variance::TorusIntegrand;
    use std::format;
    use std::vec::Vec;

    /// The parameters of `build_integrand`; each applies to the integrands its field
    /// names.
    #[derive(Clone, Debug, Default, PartialEq)]
    pub struct IntegrandParams {
        /// Dimensions (default 4 for the options, 2 otherwise).
        pub dims: Option<usize>,
        /// torus-disk: the radius (default 0.25).
        pub radius: Option<f64>,
        /// torus-gaussian: the standard deviation (default 0.1).
        pub sigma: Option<f64>,
        /// Genz: the difficulties `a_k` (default as `test_suite`).
        pub a: Option<Vec<f64>>,
        /// Genz: the locations `u_k` (default as `test_suite`).
        pub u: Option<Vec<f64>>,
        /// The options: the market (default 100, 100, 0.05, 0.2, 1).
        pub market: Option<Market>,
    }

    /// A built integrand: `f`, its dimensions and its exact integral.
    #[derive(Clone, Debug, PartialEq)]
    pub enum TestIntegrand {
        /// An integrand of [`crate::analysis::integrate`] in `dims` dimensions.
        Cube {
            /// The integrand.
            f: Integrand,
            /// Its dimensions.
            dims: usize,
        },
        /// A problem of [`crate::analysis::integrate`].
        Problem(Problem),
        /// A torus integrand of [`crate::analysis::variance`].
        Torus(TorusIntegrand),
        /// A pixel integrand of [`crate::analysis::screen_error`] (at the image centre).
        Pixel(PixelIntegrand),
    }

    impl TestIntegrand {
        /// Its dimensions.
        pub fn dims(&self) -> usize {
            match self {
                TestIntegrand::Cube { dims, .. } => *dims,
                TestIntegrand::Problem(p) => p.dims,
                TestIntegrand::Torus(_) | TestIntegrand::Pixel(_) => 2,
            }
        }

        /// `f(x)`, `x` holding [`dims`](Self::dims) coordinates in `[0, 1]` (the
        /// problems' inverse-CDF transforms need `(0, 1)`).
        pub fn eval(&self, x: &[f64]) -> f64 {
            let at = |k: usize| x.get(k).copied().unwrap_or(0.5);
            match self {
                TestIntegrand::Cube { f, .. } => f.eval(x),
                TestIntegrand::Problem(p) => p.eval(x),
                TestIntegrand::Torus(t) => t.eval(at(0), at(1)),
                TestIntegrand::Pixel(p) => p.eval(at(0), at(1)),
            }
        }

        /// The coordinate this integrand reads from a 32-bit sample `r` ([`crate::bits`]'s
        /// fixed point): `r / 2^32` for the integrands defined on the closed cube, the
        /// cell's midpoint `(r + 1/2) / 2^32` for the problems, whose inverse-CDF
        /// transforms need `(0, 1)` (as [`crate::analysis::integrate::integrate`] maps
        /// them). Exact in `f64`.
        pub fn coordinate(&self, r: u32) -> f64 {
            match self {
                TestIntegrand::Problem(_) => (f64::from(r) + 0.5) * (1.0 / 4_294_967_296.0),
                _ => crate::bits::to_f64(r),
            }
        }

        /// The exact integral.
        pub fn exact(&self) -> f64 {
            match self {
                TestIntegrand::Cube { f, dims } => f.exact(*dims),
                TestIntegrand::Problem(p) => p.exact(),
                TestIntegrand::Torus(t) => t.integral(),
                TestIntegrand::Pixel(p) => p.exact(),
            }
        }
    }

    /// The integrand `entry` names with `params`. The problems get the names and, by
    /// default, the parameters of `analysis::integrate::test_suite`
    /// (`genz-oscillatory-d5`, `keister-d3`, `european-d4`).
    ///
    /// ```
    /// use qmckit::catalog::{self, IntegrandParams};
    /// let p = IntegrandParams { dims: Some(5), ..Default::default() };
    /// let f = catalog::build_integrand(catalog::integrand("genz-2")?, &p)?;
    /// let suite = qmckit::analysis::integrate::test_suite();
    /// assert!(suite.iter().any(|q| catalog::TestIntegrand::Problem(q.clone()) == f));
    /// # Ok::<(), qmckit::catalog::CatalogError>(())
    /// ```
    ///
    /// # Errors
    /// [`CatalogError::Unused`] for a parameter the integrand does not take;
    /// [`CatalogError::Parameter`] for `dims` out of range or `a`, `u` of the wrong length;
    /// the torus integrands' range errors.
    pub fn build_integrand(
        entry: &IntegrandEntry,
        params: &IntegrandParams,
    ) -> Result<TestIntegrand, CatalogError> {
        let kind = entry.kind;
        let refuse = |param, why| {
            Err(CatalogError::Unused {
                entry: entry.name,
                param,
                why,
            })
        };
        let genz = kind.genz_scale();
        let options = matches!(kind, I::European | I::AsianGeometric);
        if params.radius.is_some() && kind != I::TorusDisk {
            return refuse("radius", "only torus-disk has a radius");
        }
        if params.sigma.is_some() && kind != I::TorusGaussian {
            return refuse("sigma", "only torus-gaussian has a sigma");
        }
        if (params.a.is_some() || params.u.is_some()) && genz.is_none() {
            return refuse("a/u", "only the Genz families take a and u");
        }
        if params.market.is_some() && !options {
            return refuse("market", "only european and asian-geometric take a market");
        }
        let d = params.dims.unwrap_or(kind.default_dims());
        let bad = |param, got: usize, expected| CatalogError::Parameter {
            entry: entry.name,
            param,
            got: Some(got as u64),
            expected,
        };
        if d == 0 || d > kind.max_dims() {
            return Err(bad("dims", d, "out of range (see the entry's params)"));
        }
        let cube = |f| Ok(TestIntegrand::Cube { f, dims: d });
        let problem = |kind| {
            Ok(TestIntegrand::Problem(Problem {
                name: format!("{}-d{d}", entry.name),
                dims: d,
                kind,
            }))
        };
        let market = params.market.unwrap_or(Market {
            spot: 100.0,
            strike: 100.0,
            rate: 0.05,
            vol: 0.2,
            maturity: 1.0,
        });
        match kind {
            I::GaussianPeak => cube(Integrand::Gaussian),
            I::Oscillatory => cube(Integrand::Oscillatory),
            I::Ball => cube(Integrand::Ball),
            I::Heaviside => cube(Integrand::Heaviside),
            I::TorusDisk => Ok(TestIntegrand::Torus(TorusIntegrand::disk(
                params.radius.unwrap_or(0.25),
            )?)),
            I::TorusGaussian => Ok(TestIntegrand::Torus(TorusIntegrand::gaussian(
                params.sigma.unwrap_or(0.1),
            )?)),
            I::PixelGaussianBump => Ok(TestIntegrand::Pixel(PixelIntegrand::GaussianBump)),
            I::PixelStep => Ok(TestIntegrand::Pixel(PixelIntegrand::Step)),
            I::PixelVisibility => Ok(TestIntegrand::Pixel(PixelIntegrand::Visibility)),
            I::Keister => problem(ProblemKind::Keister),
            I::European => problem(ProblemKind::European(market)),
            I::AsianGeometric => problem(ProblemKind::AsianGeometric(market)),
            _ => {
                let scale = genz.unwrap_or(1.0);
                let a = match &params.a {
                    Some(a) if a.len() == d => a.clone(),
                    Some(a) => return Err(bad("a", a.len(), "values: not dims")),
                    None => (0..d)
                        .map(|k| scale * (1.0 + k as f64) / d as f64)
                        .collect(),
                };
                let u = match &params.u {
                    Some(u) if u.len() == d => u.clone(),
                    Some(u) => return Err(bad("u", u.len(), "values: not dims")),
                    None => (0..d)
                        .map(|k| 0.2 + 0.6 * ((k as f64 * 0.618).fract()))
                        .collect(),
                };
                let family = match kind {
                    I::GenzOscillatory => GenzFamily::Oscillatory,
                    I::GenzProductPeak => GenzFamily::ProductPeak,
                    I::GenzCornerPeak => GenzFamily::CornerPeak,
                    I::GenzGaussian => GenzFamily::Gaussian,
                    I::GenzContinuous => GenzFamily::Continuous,
                    _ => GenzFamily::Discontinuous,
                };
                problem(ProblemKind::Genz { family, a, u })
            }
        }
    }
}
