//! The measures of point sets: discrepancies, net quality, distances, spectra and
//! integration errors. The table is `no_std`; the scalar measures evaluate behind
//! `analysis` (`MeasureEntry::scalar`).

use super::{Entry, Param, alias, param};

/// A measure of [`MEASURES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MeasureKind {
    /// Star discrepancy, exact.
    Star,
    /// Guaranteed lower and upper bounds on the star discrepancy.
    StarBounds,
    /// Extreme (unanchored box) discrepancy, 2D.
    Extreme,
    /// L2-star discrepancy.
    L2Star,
    /// Centered L2 discrepancy.
    Centered,
    /// Wrap-around L2 discrepancy.
    WrapAround,
    /// Mixture L2 discrepancy.
    Mixture,
    /// Symmetric L2 discrepancy.
    Symmetric,
    /// Unanchored L2 discrepancy.
    Unanchored,
    /// Generalized L2 discrepancy.
    Generalized,
    /// Zinterhof's diaphony.
    Diaphony,
    /// The t-value of a net.
    TValue,
    /// Minimum distance between points.
    MinDistance,
    /// Mean nearest-neighbour distance.
    MeanMinDistance,
    /// Minimum distance over the packing bound `d_max(N, d)`.
    NormalizedMinDistance,
    /// Semi-discrete optimal-transport distance `W_2` to the uniform square, 2D.
    OtDistance,
    /// Fourier power spectrum (periodogram) of 2D points.
    Spectrum,
    /// Radial average and anisotropy of the spectrum.
    RadialSpectrum,
    /// Pair correlation function of 2D points.
    Pcf,
    /// Integration error against the number of points.
    IntegrationError,
    /// Integration variance of torus-shifted points, predicted and measured.
    Variance,
    /// Screen-space error of a pixel sampler.
    ScreenError,
}

/// What a measure returns.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Output {
    /// One number (`MeasureEntry::scalar`).
    Scalar,
    /// Two numbers bounding the value.
    Bounds,
    /// A curve (over a radius or a number of points).
    Curve,
    /// Values over a grid of frequencies.
    Grid,
    /// A number per pixel, and bands of its spectrum.
    Image,
}

impl MeasureKind {
    /// What it returns.
    pub const fn output(self) -> Output {
        match self {
            MeasureKind::StarBounds => Output::Bounds,
            MeasureKind::RadialSpectrum
            | MeasureKind::Pcf
            | MeasureKind::IntegrationError
            | MeasureKind::Variance => Output::Curve,
            MeasureKind::Spectrum => Output::Grid,
            MeasureKind::ScreenError => Output::Image,
            _ => Output::Scalar,
        }
    }

    /// The library's L2 measure of this name (`analysis`).
    #[cfg(feature = "analysis")]
    pub const fn l2(self) -> Option<crate::analysis::l2::L2Metric> {
        use crate::analysis::l2::L2Metric as L;
        Some(match self {
            MeasureKind::L2Star => L::L2Star,
            MeasureKind::Centered => L::Centered,
            MeasureKind::WrapAround => L::WrapAround,
            MeasureKind::Mixture => L::Mixture,
            MeasureKind::Symmetric => L::Symmetric,
            MeasureKind::Unanchored => L::Unanchored,
            MeasureKind::Generalized => L::Generalized,
            MeasureKind::Diaphony => L::Diaphony,
            _ => return None,
        })
    }

    /// The measures of `qmckit discrepancy --metric all`, in its order: star and the eight
    /// L2 measures.
    pub const ALL_DISCREPANCIES: [MeasureKind; 9] = [
        MeasureKind::Star,
        MeasureKind::L2Star,
        MeasureKind::Centered,
        MeasureKind::WrapAround,
        MeasureKind::Mixture,
        MeasureKind::Symmetric,
        MeasureKind::Unanchored,
        MeasureKind::Generalized,
        MeasureKind::Diaphony,
    ];
}

/// An entry of [`MEASURES`].
pub type MeasureEntry = Entry<MeasureKind>;

#[cfg(feature = "analysis")]
impl Entry<MeasureKind> {
    /// The value of a scalar measure of `points`, within `budget` (estimated first where
    /// the measure has an estimate; the deadline bounds the rest): star (exact), extreme
    /// (2D), the eight L2 measures, min-distance, mean-min-distance,
    /// normalized-min-distance (in the cube) and ot-distance (2D).
    ///
    /// ```
    /// use qmckit::{analysis::Points, catalog, work::Budget};
    /// let p = Points::new(&[0.25, 0.75, 0.75, 0.25], 2)?;
    /// let cd = catalog::measure("centered")?.scalar(p, &Budget::DEFAULT)?;
    /// assert_eq!(cd, qmckit::analysis::l2::centered(p)?);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// The measure's own ([`crate::Error::OverBudget`], ...) as
    /// [`super::CatalogError::Build`]; [`super::CatalogError::Unused`] for a measure that is
    /// not one number (see its [`Entry::item`]).
    pub fn scalar(
        &self,
        points: crate::analysis::Points<'_>,
        budget: &crate::work::Budget,
    ) -> Result<f64, super::CatalogError> {
        use crate::analysis::{distance, star};
        if let Some(l2) = self.kind.l2() {
            return Ok(l2.eval(points, budget)?);
        }
        Ok(match self.kind {
            MeasureKind::Star => star::star_exact(points, budget)?,
            MeasureKind::Extreme => star::extreme_2d(points, budget)?,
            MeasureKind::MinDistance => distance::min_distance(points, false),
            MeasureKind::MeanMinDistance => distance::mean_min_distance(points, false),
            MeasureKind::NormalizedMinDistance => {
                crate::analysis::spacing::normalized_min_distance(points, false, budget)?
            }
            MeasureKind::OtDistance => crate::analysis::transport::ot_distance(points, budget)?,
            _ => {
                return Err(super::CatalogError::Unused {
                    entry: self.name,
                    param: "scalar",
                    why: "not one number of a point set: see its item",
                });
            }
        })
    }
}

const BUDGET: Param = param(
    "budget",
    "time budget, estimated first",
    "10 s",
    "positive seconds",
);

/// Every measure.
pub static MEASURES: &[MeasureEntry] = &[
    Entry {
        kind: MeasureKind::Star,
        name: "star",
        aliases: &[
            alias("star-discrepancy", "the full name"),
            alias("d-star", "D*_N"),
        ],
        summary: "star discrepancy D*, exact (1D closed form, 2D sweep, d-D decomposition)",
        math: "D* = sup_y |#{x_i in [0, y)}/N - vol[0, y)| (Niederreiter 1992; Dobkin, Eppstein & Mitchell 1996)",
        params: &[BUDGET],
        item: "qmckit::analysis::star::star_exact",
    },
    Entry {
        kind: MeasureKind::StarBounds,
        name: "star-bounds",
        aliases: &[alias("thiemard", "the cover's author")],
        summary: "guaranteed lower and upper bounds on D* (Thiémard's cover, threshold accepting)",
        math: "lower <= D* <= upper <= lower + delta (Thiémard 2001; Winker & Fang 1997)",
        params: &[
            param("delta", "gap of the bounds", "0.05", "(0, 1]"),
            BUDGET,
        ],
        item: "qmckit::analysis::star::thiemard::bounds",
    },
    Entry {
        kind: MeasureKind::Extreme,
        name: "extreme",
        aliases: &[alias("extreme-discrepancy", "the full name")],
        summary: "extreme (unanchored box) discrepancy, exact, 2D",
        math: "D = sup_(a <= b) |#{x_i in [a, b)}/N - vol[a, b)| (Niederreiter 1992)",
        params: &[BUDGET],
        item: "qmckit::analysis::star::extreme_2d",
    },
    Entry {
        kind: MeasureKind::L2Star,
        name: "l2-star",
        aliases: &[alias("warnock", "Warnock's formula")],
        summary: "L2-star discrepancy, square root taken (SciPy method='L2-star')",
        math: "D^2 = 3^-d - (2/N) sum_i prod_k (1 - x_ik^2)/2 + (1/N^2) sum_ij prod_k (1 - max) (Warnock 1972)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::l2_star",
    },
    Entry {
        kind: MeasureKind::Centered,
        name: "cd",
        aliases: &[
            alias("centered", "qmckit::analysis::l2::centered"),
            alias("centered-l2", "the full name"),
        ],
        summary: "centered L2 discrepancy, squared (SciPy method='CD')",
        math: "kernel prod (1 + |x - 1/2|/2 + |y - 1/2|/2 - |x - y|/2) (Hickernell 1998)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::centered",
    },
    Entry {
        kind: MeasureKind::WrapAround,
        name: "wd",
        aliases: &[
            alias("wrap-around", "qmckit::analysis::l2::wrap_around"),
            alias("wrap-around-l2", "the full name"),
        ],
        summary: "wrap-around L2 discrepancy, squared (SciPy method='WD')",
        math: "kernel prod (3/2 - |x - y| (1 - |x - y|)) (Hickernell 1998)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::wrap_around",
    },
    Entry {
        kind: MeasureKind::Mixture,
        name: "md",
        aliases: &[
            alias("mixture", "qmckit::analysis::l2::mixture"),
            alias("mixture-l2", "the full name"),
        ],
        summary: "mixture L2 discrepancy, squared (SciPy method='MD')",
        math: "kernel prod (15/8 - |x - 1/2|/4 - |y - 1/2|/4 - 3|x - y|/4 + |x - y|^2/2) (Zhou, Fang & Ning 2013)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::mixture",
    },
    Entry {
        kind: MeasureKind::Symmetric,
        name: "sl2",
        aliases: &[
            alias("symmetric", "qmckit::analysis::l2::symmetric"),
            alias("SymmetricL2Discrepancy", "UTK"),
        ],
        summary: "symmetric L2 discrepancy, square root taken (UTK SymmetricL2Discrepancy)",
        math: "kernel prod (2 - |x - y|) (Hickernell 1998)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::symmetric",
    },
    Entry {
        kind: MeasureKind::Unanchored,
        name: "ul2",
        aliases: &[
            alias("unanchored", "qmckit::analysis::l2::unanchored"),
            alias("UnanchoredL2Discrepancy", "UTK"),
        ],
        summary: "unanchored L2 discrepancy, square root taken (UTK UnanchoredL2Discrepancy)",
        math: "squared discrepancy averaged over all boxes [a, b) (Morokoff & Caflisch 1994; Hickernell 1998)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::unanchored",
    },
    Entry {
        kind: MeasureKind::Generalized,
        name: "gl2",
        aliases: &[
            alias("generalized", "qmckit::analysis::l2::generalized"),
            alias("GL2Discrepancy", "UTK"),
        ],
        summary: "generalized L2 discrepancy, square root taken (UTK GL2Discrepancy)",
        math: "kernel prod (2 - max(x, y)) (Hickernell 1998)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::generalized",
    },
    Entry {
        kind: MeasureKind::Diaphony,
        name: "diaphony",
        aliases: &[alias("zinterhof", "the measure's author")],
        summary: "Zinterhof's diaphony, square root taken (UTK Diaphony)",
        math: "F^2 = sum_(k != 0) r(k)^-2 |(1/N) sum_i e(k x_i)|^2 normalized (Zinterhof 1976)",
        params: &[BUDGET],
        item: "qmckit::analysis::l2::diaphony",
    },
    Entry {
        kind: MeasureKind::TValue,
        name: "t-value",
        aliases: &[alias("quality-parameter", "Niederreiter's name for t")],
        summary: "the t-value of a (t, m, s)-net: rank test on base-2 generator matrices, or \
                  counting points in elementary intervals",
        math: "smallest t with b^t points in every elementary interval of volume b^(t-m) (Niederreiter 1987; Pirsic & Schmid 2001)",
        params: &[
            param(
                "m",
                "the net has b^m points",
                "none: needed",
                "0 to 32 (21 when counting)",
            ),
            BUDGET,
        ],
        item: "qmckit::analysis::tvalue::t_value",
    },
    Entry {
        kind: MeasureKind::MinDistance,
        name: "min-distance",
        aliases: &[alias("minimum-distance", "the full name")],
        summary: "minimum Euclidean distance between two points (in the cube)",
        math: "min_(i != j) |x_i - x_j|",
        params: &[param("toroidal", "distance on the torus", "false", "bool")],
        item: "qmckit::analysis::distance::min_distance",
    },
    Entry {
        kind: MeasureKind::MeanMinDistance,
        name: "mean-min-distance",
        aliases: &[alias("mean-nearest-neighbor", "what it averages")],
        summary: "mean distance from each point to its nearest neighbour (in the cube)",
        math: "(1/N) sum_i min_(j != i) |x_i - x_j|",
        params: &[param("toroidal", "distance on the torus", "false", "bool")],
        item: "qmckit::analysis::distance::mean_min_distance",
    },
    Entry {
        kind: MeasureKind::NormalizedMinDistance,
        name: "normalized-min-distance",
        aliases: &[
            alias("relative-radius", "Lagae & Dutré 2008's rho"),
            alias("min-distance-ratio", "what it is"),
        ],
        summary: "minimum distance over the packing bound d_max(N, d) (1 for the hexagonal \
                  grid tiling the torus), grid search, 1 to 8 dimensions",
        math: "min_(i != j) |x_i - x_j| / d_max, d_max = 2 (Delta_d / (N V_d))^(1/d), in 2D sqrt(2 / (sqrt(3) N)) (Lagae & Dutré 2008)",
        params: &[
            param("toroidal", "distance on the torus", "false", "bool"),
            BUDGET,
        ],
        item: "qmckit::analysis::spacing::normalized_min_distance",
    },
    Entry {
        kind: MeasureKind::OtDistance,
        name: "ot-distance",
        aliases: &[
            alias("wasserstein", "the W_2 distance it is"),
            alias("transport-distance", "what it measures"),
        ],
        summary: "semi-discrete optimal-transport distance W_2 from 2D points (mass 1/N each) to \
                  the uniform square, exact Laguerre cells",
        math: "W_2^2 = sum_i int_(L_i) |x - p_i|^2, L_i the power cells of area 1/N (Aurenhammer, Hoffmann & Aronov 1998; Mérigot 2011; Kitagawa, Mérigot & Thibert 2019)",
        params: &[BUDGET],
        item: "qmckit::analysis::transport::ot_distance",
    },
    Entry {
        kind: MeasureKind::Spectrum,
        name: "spectrum",
        aliases: &[
            alias("periodogram", "the estimator's name"),
            alias("power-spectrum", "the usual name"),
        ],
        summary: "Fourier power spectrum of 2D points on [-K, K]^2 (direct sums or a NUFFT)",
        math: "P(k) = |sum_j exp(-2 pi i k . x_j)|^2 / N (Ulichney 1988)",
        params: &[
            param(
                "k_max",
                "largest frequency K",
                "2 ceil(sqrt N), at least 16",
                "1 to 2048",
            ),
            BUDGET,
        ],
        item: "qmckit::analysis::spectrum::periodogram_2d",
    },
    Entry {
        kind: MeasureKind::RadialSpectrum,
        name: "radial-spectrum",
        aliases: &[
            alias("radial-power", "the radial power spectrum"),
            alias("anisotropy", "its companion curve"),
        ],
        summary: "radial average and anisotropy of the periodogram over annuli round(|k|) = r",
        math: "P(r) = mean over round(|k|) = r of P(k); anisotropy = variance / mean^2 (Ulichney 1988; Lagae & Dutré 2008)",
        params: &[param(
            "k_max",
            "largest frequency K",
            "as spectrum",
            "1 to 2048",
        )],
        item: "qmckit::analysis::spectrum::radial",
    },
    Entry {
        kind: MeasureKind::Pcf,
        name: "pcf",
        aliases: &[alias("pair-correlation", "the full name")],
        summary: "pair correlation function of 2D points (UTK's definition, optionally toroidal)",
        math: "g(r) = sum_(i != j) k_s(r - |x_i - x_j|) / (N (N - 1) 2 pi r e(r)) (Öztireli & Gross 2012; Heck et al. 2013)",
        params: &[
            param("r_max", "largest radius", "none: needed", "positive"),
            param("bins", "number of radii", "none: needed", "at least 1"),
            param("torus", "toroidal distance", "false", "bool"),
            BUDGET,
        ],
        item: "qmckit::analysis::pcf::pcf_2d",
    },
    Entry {
        kind: MeasureKind::IntegrationError,
        name: "integration-error",
        aliases: &[alias("convergence", "qmckit convergence")],
        summary: "signed integration error of a test integrand against the number of points",
        math: "(1/N) sum_i f(x_i) - I(f) (Owen, Practical QMC)",
        params: &[param(
            "integrand",
            "the test integrand",
            "gaussian-peak",
            "INTEGRANDS",
        )],
        item: "qmckit::analysis::integrate::integration_error",
    },
    Entry {
        kind: MeasureKind::Variance,
        name: "variance",
        aliases: &[alias("integration-variance", "the full name")],
        summary: "integration variance of torus-shifted points, predicted from the mean \
                  periodogram and measured",
        math: "Var = (1/N) sum_(k != 0) |c_k|^2 E P(k) (Pilleboue et al. 2015)",
        params: &[
            param(
                "integrand",
                "torus-disk or torus-gaussian",
                "torus-disk",
                "the torus integrands",
            ),
            param("sets", "randomized sets", "1000", "at least 1"),
            BUDGET,
        ],
        item: "qmckit::analysis::variance::predicted_variance",
    },
    Entry {
        kind: MeasureKind::ScreenError,
        name: "screen-error",
        aliases: &[alias("screen-space-error", "the full name")],
        summary: "per-pixel error image of a pixel sampler and its low- and high-band power",
        math: "E(x, y) = estimate - I; P(k) = |DFT(E)(k)|^2 / (W H var E) (Heitz & Belcour 2019)",
        params: &[param(
            "integrand",
            "a pixel integrand",
            "none: needed",
            "pixel-*",
        )],
        item: "qmckit::analysis::screen_error::screen_error",
    },
];
