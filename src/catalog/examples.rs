//! Example parameters (`std`): for every sampler entry, parameter sets that build it and
//! exercise its options (a size, strata, a base, the Gray-code order, a Korobov vector, ...).
//! The conformance tests of the library, the command's tests and the Python tests walk these,
//! so a new construction is exercised everywhere by adding its line here (a test checks that
//! every entry has one).

use std::vec;
use std::vec::Vec;

use crate::digital::sobol::Order;

use super::{Params, SAMPLERS, SamplerEntry};

/// The example parameter sets, each with its sampler entry; every entry of [`SAMPLERS`]
/// whose builder is compiled in appears at least once (the blue-noise sets and PMJ02BN need
/// the `analysis` feature). Each builds with every randomizer that
/// [`applies`](super::applies) to it. Cost: a few small allocations.
///
/// ```
/// use qmckit::catalog;
/// for (entry, params) in catalog::examples() {
///     let s = catalog::build(entry, catalog::randomizer("none")?, &params)?;
///     assert!(s.dims() >= 1);
/// }
/// # Ok::<(), qmckit::catalog::CatalogError>(())
/// ```
pub fn examples() -> Vec<(&'static SamplerEntry, Params)> {
    let p = Params::default;
    #[allow(unused_mut)]
    let mut v: Vec<(&str, Params)> = vec![
        ("independent", Params::dims(3)),
        ("stratified", Params::dims(2).with_points(64)),
        (
            "stratified",
            Params {
                strata: Some(vec![4, 3, 2]),
                ..p()
            },
        ),
        (
            "stratified",
            Params {
                centered: true,
                ..Params::dims(2).with_points(16)
            },
        ),
        ("latin", Params::dims(3).with_points(100)),
        ("vdc", p()),
        (
            "vdc",
            Params {
                base: Some(3),
                ..p()
            },
        ),
        ("halton", Params::dims(5)),
        ("hammersley", Params::dims(3).with_points(100)),
        ("lp", p().with_points(64)),
        ("sobol", Params::dims(5)),
        (
            "sobol",
            Params {
                order: Order::Gray,
                ..Params::dims(3)
            },
        ),
        ("lattice", Params::dims(4)),
        ("lattice", Params::dims(3).with_points(101)),
        (
            "lattice",
            Params {
                korobov: Some(17),
                ..Params::dims(3).with_points(89)
            },
        ),
        ("kronecker", Params::dims(3)),
        ("faure", Params::dims(3)),
        (
            "faure",
            Params {
                base: Some(5),
                ..Params::dims(3)
            },
        ),
        ("pmj02", p()),
        ("cmj", Params::dims(3).with_points(64)),
        ("cmj", p().with_points(10)),
        ("cascaded-sobol", Params::dims(4).with_points(64)),
        ("hex", p().with_points(56)),
        ("maximin-lattice", p().with_points(89)),
    ];
    // The slow sets with few iterations (a quick example; the defaults are in the entries).
    #[cfg(feature = "analysis")]
    let few = |n: u64| Params {
        blue_noise: super::BlueNoiseOptions {
            iterations: Some(30),
            ..Default::default()
        },
        ..p().with_points(n)
    };
    #[cfg(feature = "analysis")]
    v.extend([
        ("pmj02bn", p().with_points(256)),
        ("poisson", p().with_points(100)),
        ("best-candidate", p().with_points(64)),
        ("gaussian-blue-noise", p().with_points(32)),
        ("lloyd", p().with_points(24)),
        ("ccvt", Params::dims(3).with_points(16)),
        ("sot", p().with_points(20)),
        ("bnot", p().with_points(24)),
        ("projective-blue-noise", Params::dims(3).with_points(32)),
        ("forced-random", p().with_points(100)),
        ("ldbn", p().with_points(256)),
        ("penrose", p().with_points(100)),
        ("aa-patterns", p().with_points(100)),
        ("art", p().with_points(100)),
        ("step-blue-noise", few(160)),
        ("single-peak-blue-noise", few(160)),
        ("kde-blue-noise", few(160)),
    ]);
    v.into_iter()
        .filter_map(|(name, params)| {
            let entry = SAMPLERS.iter().find(|e| e.name == name)?;
            Some((entry, params))
        })
        .collect()
}
