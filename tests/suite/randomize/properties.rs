//! Property tests: every constructor at extreme parameters (0, 1, the largest values,
//! around overflow) either refuses with an error or builds a sampler whose every answer is
//! an `Ok` in range or an `Err`, never a panic. The expected outcome of each constructor is
//! its documented domain, computed independently (in `u128` where products are involved).

use super::*;
use proptest::prelude::*;
use qmckit::random::stratified::STRATIFIED_MAX_DIMS;
use qmckit::{HALTON_MAX_DIMS, Independent, Jitter, LatinHypercube, SOBOL_MAX_DIMS, Stratified};

const FULL: u64 = 1 << 32;

fn counts() -> impl Strategy<Value = u64> {
    prop_oneof![
        prop::sample::select(vec![
            0,
            1,
            2,
            3,
            (1 << 31) - 1,
            1 << 31,
            FULL - 1,
            FULL,
            FULL + 1,
            u64::MAX / 2,
            u64::MAX - 1,
            u64::MAX,
        ]),
        any::<u64>(),
        0u64..100_000,
    ]
}

fn dims(max: usize) -> impl Strategy<Value = usize> {
    prop_oneof![
        prop::sample::select(vec![
            0,
            1,
            2,
            max.saturating_sub(1),
            max,
            max + 1,
            usize::MAX / 2,
            usize::MAX - 1,
            usize::MAX,
        ]),
        any::<usize>(),
        0usize..(max + 3),
    ]
}

fn u32s() -> impl Strategy<Value = u32> {
    prop_oneof![
        prop::sample::select(vec![
            0,
            1,
            2,
            3,
            1 << 16,
            (1 << 31) - 1,
            1 << 31,
            u32::MAX - 1,
            u32::MAX
        ]),
        any::<u32>(),
    ]
}

/// Every question a caller can ask at the edges: an `Ok` in range for valid indices and
/// dimensions, an `Err` past them, and fills that refuse what does not fit.
fn probe(s: &dyn Sampler) -> Result<(), TestCaseError> {
    let (d, len) = (s.dims(), s.len());
    prop_assert!(d >= 1 && (1..=FULL).contains(&len), "dims {d} len {len}");
    let last = (len - 1) as u32;
    for index in [0, last / 2, last] {
        for dim in [0, d / 2, d - 1] {
            prop_assert!(s.sample(index, dim).is_ok(), "index {index} dim {dim}");
        }
        prop_assert!(s.sample(index, d).is_err());
        prop_assert!(s.sample(index, usize::MAX).is_err());
    }
    if len < FULL {
        prop_assert!(s.sample(len as u32, 0).is_err());
        prop_assert!(s.sample(u32::MAX, 0).is_err());
    }
    if d <= 64 {
        let mut one = vec![0u32; d];
        prop_assert!(s.fill(last, &mut one).is_ok());
        for (dim, &x) in one.iter().enumerate() {
            prop_assert_eq!(Ok(x), s.sample(last, dim));
        }
        let mut two = vec![0u32; 2 * d];
        prop_assert!(s.fill(last, &mut two).is_err()); // one point past the end
        let mut ragged = vec![0u32; d + 1];
        prop_assert!(s.fill(0, &mut ragged).is_err() || d == 1);
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn halton_and_sobol(d in dims(SOBOL_MAX_DIMS.max(HALTON_MAX_DIMS)), seed in any::<u64>()) {
        match Halton::new(d) {
            Ok(h) => {
                prop_assert!((1..=HALTON_MAX_DIMS).contains(&d));
                probe(&h)?;
            }
            Err(_) => prop_assert!(d == 0 || d > HALTON_MAX_DIMS),
        }
        match Halton::with_scramble(d, DigitScramble::Owen(seed)) {
            Ok(h) => probe(&h)?,
            Err(_) => prop_assert!(d == 0 || d > HALTON_MAX_DIMS),
        }
        match Sobol::new(d) {
            Ok(s) => {
                prop_assert!((1..=SOBOL_MAX_DIMS).contains(&d));
                probe(&s)?;
                probe(&Scrambled::new(s, FastOwen::new(seed)))?;
                probe(&Scrambled::new(s, ExactOwen::new(seed)))?;
                probe(&qmckit::digital::sobol::OwenSobol::new(d, seed).unwrap())?;
                probe(&Scrambled::new(
                    s,
                    (Lms::new(seed), DigitalShift::new(seed)),
                ))?;
                probe(&Scrambled::new(s, CranleyPatterson::new(seed)))?;
                for group in [0, 1, usize::MAX] {
                    probe(&Shuffled::new(s, seed, group).unwrap())?;
                }
            }
            Err(_) => prop_assert!(d == 0 || d > SOBOL_MAX_DIMS),
        }
    }

    #[test]
    fn finite_sets(n in counts(), d in dims(HALTON_MAX_DIMS + 1), seed in any::<u64>()) {
        let n_ok = (1..=FULL).contains(&n);
        match LatinHypercube::new(n, d, seed) {
            Ok(l) => {
                prop_assert!(n_ok && d >= 1);
                probe(&l)?;
                // One point per slab: point i's slab along dim 0 is in 0..n.
                let x = l.sample((n - 1) as u32, d - 1).unwrap();
                prop_assert!(((x as u128 * n as u128) >> 32) < n as u128);
            }
            Err(_) => prop_assert!(!(n_ok && d >= 1)),
        }
        match Hammersley::new(n, d) {
            Ok(h) => {
                prop_assert!(n_ok && (1..=HALTON_MAX_DIMS + 1).contains(&d));
                probe(&h)?;
            }
            Err(_) => prop_assert!(!(n_ok && (1..=HALTON_MAX_DIMS + 1).contains(&d))),
        }
        match Independent::new(d, seed) {
            Ok(i) => {
                prop_assert!(d >= 1);
                probe(&i)?;
            }
            Err(_) => prop_assert_eq!(d, 0),
        }
        match LarcherPillichshammer::with_points(n) {
            Ok(lp) => {
                prop_assert!(n_ok && n.is_power_of_two());
                probe(&lp)?;
            }
            Err(_) => prop_assert!(!(n_ok && n.is_power_of_two())),
        }
        // A shuffle needs a power-of-two length.
        if let Ok(h) = Hammersley::new(n, 2) {
            prop_assert_eq!(Shuffled::new(h, seed, 1).is_ok(), n.is_power_of_two());
        }
    }

    #[test]
    fn stratified(
        strata in prop_oneof![
            prop::collection::vec(u32s(), 0..STRATIFIED_MAX_DIMS + 3),
            // Powers of two: products that land on 2^32 exactly, and just past.
            prop::collection::vec(
                prop::sample::select(vec![1u32, 2, 4, 1 << 8, 1 << 16]),
                1..STRATIFIED_MAX_DIMS + 2,
            ),
            prop::collection::vec(
                prop::sample::select(vec![1u32, 2, 3, 65_535, 65_536, 65_537]),
                1..4,
            ),
        ],
        seed in any::<u64>(),
        center in any::<bool>(),
    ) {
        let jitter = if center {
            Jitter::Center
        } else {
            Jitter::Random(seed)
        };
        let product = strata.iter().try_fold(1u128, |p, &s| {
            let p = p * s as u128;
            (p <= FULL as u128).then_some(p)
        });
        let ok = !strata.is_empty()
            && strata.len() <= STRATIFIED_MAX_DIMS
            && strata.iter().all(|&s| s > 0)
            && product.is_some();
        match Stratified::new(&strata, jitter) {
            Ok(st) => {
                prop_assert!(ok);
                prop_assert_eq!(st.len() as u128, product.unwrap());
                probe(&st)?;
            }
            Err(_) => prop_assert!(!ok, "{:?}", strata),
        }
        let per = strata.first().copied().unwrap_or(0);
        let d = strata.len();
        let ok = (1..=STRATIFIED_MAX_DIMS).contains(&d)
            && per > 0
            && (per as u128)
                .checked_pow(d as u32)
                .is_some_and(|p| p <= FULL as u128);
        prop_assert_eq!(Stratified::uniform(per, d, jitter).is_ok(), ok);
        prop_assert!(Stratified::uniform(per, usize::MAX, jitter).is_err());
    }

    #[test]
    fn radical_inverses(base in u32s(), index in u32s(), digits in u32s(), m in u32s()) {
        match RadicalInverse::new(base) {
            Ok(ri) => {
                prop_assert!(base >= 2);
                let x = ri.sample(index);
                prop_assert_eq!(ri.sample(0), 0);
                let mut out = [0u32; 3];
                prop_assert_eq!(ri.fill(index, &mut out).is_ok(), index <= u32::MAX - 2);
                prop_assert!(ri.fill_strided(0, &mut out, 0).is_err());
                prop_assert!(ri.fill_strided(index, &mut out, usize::MAX).is_ok());
                // The inverse on indices of at most `digits` digits (b^digits <= 2^32):
                // refused past that, exact below it.
                let modulus = (base as u128).checked_pow(digits.min(64));
                match ri.inverse(x, digits) {
                    Ok(j) => {
                        prop_assert!(modulus.is_some_and(|m| m <= FULL as u128));
                        if modulus.is_some_and(|m| (index as u128) < m) {
                            prop_assert_eq!(j, index);
                        }
                    }
                    Err(_) => prop_assert!(modulus.is_none_or(|m| m > FULL as u128)),
                }
            }
            Err(_) => prop_assert!(base < 2),
        }
        prop_assert_eq!(VanDerCorput::new(base).is_ok(), base >= 2);
        prop_assert_eq!(LarcherPillichshammer::new(m).is_ok(), m <= 32);
    }

    #[test]
    fn permutations_are_bijections_and_total(
        n in prop_oneof![1u64..600, Just(FULL), Just(FULL + 1), Just(u64::MAX)],
        key in any::<u64>(),
        index in any::<u32>(),
    ) {
        use qmckit::hash::permute;
        let bound = n.min(FULL);
        prop_assert!((permute(index, n, key) as u64) < bound);
        if n < 600 {
            let mut seen = vec![false; n as usize];
            for i in 0..n as u32 {
                seen[permute(i, n, key) as usize] = true;
            }
            prop_assert!(seen.iter().all(|&s| s), "not a bijection of 0..{}", n);
        }
    }

    #[test]
    fn lms_caches(
        seed in any::<u64>(),
        small in 0usize..64,
        huge in prop::sample::select(
            vec![(1usize << 23) + 1, 1 << 40, usize::MAX / 128 + 1, usize::MAX],
        ),
    ) {
        let lms = Lms::new(seed);
        let cache = lms.cached(small).unwrap();
        for dim in [0, small, small + 1, usize::MAX] {
            prop_assert_eq!(cache.apply(0x9E37_79B9, dim), lms.apply(0x9E37_79B9, dim));
        }
        let refused = matches!(lms.cached(huge), Err(qmckit::Error::TooLarge { .. }));
        prop_assert!(refused);
    }

    #[test]
    fn scramblers_are_total(seed in any::<u64>(), x in u32s(), dim in dims(SOBOL_MAX_DIMS)) {
        for (_, r) in randomizers(seed) {
            let _ = r.apply(x, dim);
        }
        // Owen scrambling is a bijection that keeps the top bit's interval structure:
        // two values differing only in the last bit still differ only in the last bit.
        let sd = SobolDimension::new(dim % SOBOL_MAX_DIMS).unwrap();
        let owen = FastOwen::new(seed);
        let (a, b) = (
            owen.scramble(sd.sample(x), dim),
            owen.scramble(sd.sample(x) ^ 1, dim),
        );
        prop_assert_eq!(a ^ b, 1);
        // Sobol' strided fills at the end of the index range and with any stride.
        let mut out = [0u32; 5];
        for stride in [1usize, 2, 4, 5, usize::MAX] {
            let count = out.len().div_ceil(stride) as u64;
            let fits = x as u64 + count <= FULL;
            prop_assert_eq!(sd.fill_strided(x, &mut out, stride).is_ok(), fits);
            if fits {
                prop_assert_eq!(out[0], sd.sample(x));
            }
        }
        prop_assert!(sd.fill_strided(x, &mut out, 0).is_err());
        for digit in [0u32, 1, 2, u32::MAX] {
            for base in [2u32, 3, 29, u32::MAX] {
                let y = faure(base, digit % base);
                prop_assert!(y < base);
            }
        }
    }
}
