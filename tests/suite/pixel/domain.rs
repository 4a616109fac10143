//! `pixel::domain`: the documented bits (recomputed here from the formulas of the module
//! documentation, with Sobol' dimension 1 from its direction numbers), independence of
//! distinct derivations, nets within a domain, determinism and the refusals.

use crate::common::first_net_failure;
use qmckit::Error;
use qmckit::pixel::domain::{Domain, DomainBase, Table};

/// The documented formulas, written out again.
mod spec {
    pub const W: u64 = 0x9e37_79b9_7f4a_7c15;

    pub fn mix(mut z: u64) -> u64 {
        z ^= z >> 30;
        z = z.wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z ^= z >> 27;
        z = z.wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    pub fn h(s: u64, a: u64, b: u64) -> u64 {
        let t = mix(s.wrapping_add(W));
        let t = mix(t ^ a.wrapping_add(W.wrapping_mul(2)));
        mix(t ^ b.wrapping_add(W.wrapping_mul(3)))
    }

    pub fn rev(v: u32) -> u32 {
        (0..32).fold(0, |acc, b| acc | (((v >> b) & 1) << (31 - b)))
    }

    pub fn vegdahl(r: u32, k: u32) -> u32 {
        let mut z = r ^ r.wrapping_mul(0x3d20_adea);
        z = z.wrapping_add(k);
        z = z.wrapping_mul((k >> 16) | 1);
        z ^= z.wrapping_mul(0x0552_6c56);
        z ^ z.wrapping_mul(0x53a2_2864)
    }

    pub fn owen(v: u32, k: u32) -> u32 {
        rev(vegdahl(rev(v), k))
    }

    /// Sobol' dimension 1 from its direction numbers: c_0 = 2^31, c_{b+1} = c_b ^ (c_b >> 1).
    pub fn sobol1(j: u32) -> u32 {
        let mut c = 1u32 << 31;
        let mut out = 0;
        for b in 0..32 {
            if (j >> b) & 1 == 1 {
                out ^= c;
            }
            c ^= c >> 1;
        }
        out
    }

    pub const ROOT: u64 = 0x524f_4f54;
    pub const NEW: u64 = 0x4e45_5744;
    pub const CHAIN: u64 = 0x4348_4149;
    pub const SPLIT: u64 = 0x5350_4c54;
    pub const PIXEL: u64 = 0x5049_584c;
    pub const SHUFFLE: u64 = 0x5348_5546;

    pub enum Base<'a> {
        Hashed,
        Keys(u32, &'a [u32]),
        Shifts(u32, &'a [[u32; 2]], u32),
    }

    /// `draw_2d` of state `s`, pixel `(x, y)`, index `index` of `len`.
    pub fn draw(base: &Base, s: u64, x: u32, y: u32, index: u32, len: u64) -> [u32; 2] {
        let cell = |log2: u32| {
            let side = 1u64 << log2;
            let (ox, oy) = ((s >> 32) % side, (s >> 48) % side);
            (((y as u64 + oy) % side) * side + (x as u64 + ox) % side) as usize
        };
        let k = match base {
            Base::Hashed => h(s, ((y as u64) << 32) + x as u64, PIXEL),
            Base::Keys(log2, t) => t[cell(*log2)] as u64,
            Base::Shifts(log2, t, _) => {
                let [sx, sy] = t[cell(*log2)];
                sx as u64 + ((sy as u64) << 32)
            }
        };
        let m = (0..=32).find(|&m| (1u64 << m) >= len).unwrap();
        let j = (rev(vegdahl(rev(index), h(s, k, SHUFFLE) as u32)) as u64 % (1u64 << m)) as u32;
        match base {
            Base::Shifts(_, _, g) => [
                rev(j).wrapping_add(k as u32),
                rev(j).wrapping_mul(*g).wrapping_add((k >> 32) as u32),
            ],
            _ => {
                let o = mix(k);
                [owen(rev(j), o as u32), owen(sobol1(j), (o >> 32) as u32)]
            }
        }
    }
}

const KEYS: [u32; 16] = [
    0x1234_5678,
    0x9abc_def0,
    0x0fed_cba9,
    0x8765_4321,
    1,
    2,
    3,
    4,
    0xdead_beef,
    0xcafe_f00d,
    0x0bad_f00d,
    0x1357_9bdf,
    0x2468_ace0,
    0xffff_ffff,
    0,
    0x5555_5555,
];
const SHIFTS: [[u32; 2]; 4] = [
    [0x1000_0000, 0x2000_0000],
    [0xabcd_ef01, 0x2345_6789],
    [7, 0xffff_fff0],
    [0x8000_0000, 0x4000_0000],
];

#[test]
fn bits_follow_the_documented_hash_chain() {
    let keys = Table::new(2, &KEYS).unwrap();
    let shifts = Table::new(1, &SHIFTS).unwrap();
    let g = 0x4613;
    let cases: [(DomainBase, spec::Base); 3] = [
        (DomainBase::OwenSobol, spec::Base::Hashed),
        (DomainBase::OwenSobolTable(keys), spec::Base::Keys(2, &KEYS)),
        (
            DomainBase::LatticeTable(shifts, g),
            spec::Base::Shifts(1, &SHIFTS, g),
        ),
    ];
    for (base, sb) in &cases {
        for (seed, x, y, i, spp) in [
            (0u64, 0u32, 0u32, 0u32, 1u32),
            (7, 3, 5, 11, 16),
            (u64::MAX, 1919, 1079, 2, 3),
            (12345, 70, 9, 1023, 1024),
        ] {
            let root = Domain::root(*base, x, y, i, spp, seed).unwrap();
            let s0 = spec::h(seed, 0, spec::ROOT);
            assert_eq!(root.state(), s0);
            let len = spp as u64;
            assert_eq!(root.draw_2d(), spec::draw(sb, s0, x, y, i, len));
            // new_domain(42).chain().new_domain(7)
            let d = root.new_domain(42).chain().new_domain(7);
            let s = spec::h(
                spec::h(spec::h(s0, 42, spec::NEW), 0, spec::CHAIN),
                7,
                spec::NEW,
            );
            assert_eq!(d.state(), s);
            let want = spec::draw(sb, s, x, y, i, len);
            assert_eq!(d.draw_2d(), want);
            assert_eq!(d.draw_1d(), want[0]);
            // split(9, 4, 3): index 4 i + 3 of 4 spp
            let sp = root.new_domain(1).split(9, 4, 3).unwrap();
            let s = spec::h(spec::h(s0, 1, spec::NEW), 9, spec::SPLIT);
            assert_eq!((sp.index(), sp.len()), (4 * i + 3, 4 * len));
            assert_eq!(sp.draw_2d(), spec::draw(sb, s, x, y, 4 * i + 3, 4 * len));
            // f32: to nearest, below 1
            let [a, b] = d.draw_2d_f32();
            let f = |v: u32| ((v as f64 / 4_294_967_296.0) as f32).min(1.0 - f32::EPSILON / 2.0);
            assert_eq!([a, b], [f(want[0]), f(want[1])]);
        }
    }
}

/// Pearson correlation of two samples.
fn correlation(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    sab / (saa * sbb).sqrt()
}

/// Every pair of distinct derivations, over 2^16 draws (64 x 64 pixels x 16 samples, and
/// one pixel x 2^16 samples): |correlation| of every coordinate pair below 4 / sqrt(n).
#[test]
fn distinct_domains_are_uncorrelated() {
    let keys: Vec<u32> = (0..4096u64)
        .map(|i| qmckit::hash::mix64(i) as u32)
        .collect();
    let table = Table::new(6, &keys).unwrap();
    let derive: [fn(Domain) -> Domain; 6] = [
        |d| d,
        |d| d.new_domain(1),
        |d| d.new_domain(2),
        |d| d.new_domain(1).chain(),
        |d| d.new_domain(1).chain().chain(),
        |d| d.new_domain(1).new_domain(1),
    ];
    for base in [DomainBase::OwenSobol, DomainBase::OwenSobolTable(table)] {
        for (pixels, spp) in [(64u32, 16u32), (1, 1 << 16)] {
            let mut draws: Vec<[Vec<f64>; 2]> = vec![[vec![], vec![]]; derive.len()];
            for y in 0..pixels {
                for x in 0..pixels {
                    for i in 0..spp {
                        let root = Domain::root(base, x, y, i, spp, 3).unwrap();
                        for (k, f) in derive.iter().enumerate() {
                            let [u, v] = f(root).draw_2d();
                            draws[k][0].push(qmckit::bits::to_f64(u));
                            draws[k][1].push(qmckit::bits::to_f64(v));
                        }
                    }
                }
            }
            let n = draws[0][0].len();
            assert_eq!(n, 1 << 16);
            let bound = 4.0 / (n as f64).sqrt();
            for a in 0..derive.len() {
                for b in a + 1..derive.len() {
                    for ca in 0..2 {
                        for cb in 0..2 {
                            let r = correlation(&draws[a][ca], &draws[b][cb]);
                            assert!(
                                r.abs() < bound,
                                "{base:?} {pixels}px spp {spp}: derivations {a}, {b}, coords \
                                 {ca}, {cb}: r = {r}"
                            );
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn each_pixel_of_a_domain_is_a_net() {
    let keys: Vec<u32> = (0..4096u64)
        .map(|i| qmckit::hash::mix64(i ^ 77) as u32)
        .collect();
    let table = Table::new(6, &keys).unwrap();
    for base in [DomainBase::OwenSobol, DomainBase::OwenSobolTable(table)] {
        for seed in [0u64, 1, 99] {
            for (x, y) in [(0u32, 0u32), (5, 9), (63, 2), (1000, 77)] {
                for derive in [0u64, 1, 2, 1000] {
                    // 16 samples: a (0, 4, 2)-net.
                    let pts: Vec<[u32; 2]> = (0..16)
                        .map(|i| {
                            let r = Domain::root(base, x, y, i, 16, seed).unwrap();
                            r.new_domain(derive).chain().draw_2d()
                        })
                        .collect();
                    assert_eq!(
                        first_net_failure(&pts, 4),
                        None,
                        "{base:?} {x} {y} {derive}"
                    );
                    // Split 4 ways: the 64 sub-samples are one (0, 6, 2)-net.
                    let pts: Vec<[u32; 2]> = (0..16)
                        .flat_map(|i| {
                            let r = Domain::root(base, x, y, i, 16, seed).unwrap();
                            (0..4).map(move |j| {
                                r.new_domain(derive).split(5, 4, j).unwrap().draw_2d()
                            })
                        })
                        .collect();
                    assert_eq!(first_net_failure(&pts, 6), None, "{base:?} split");
                }
            }
        }
    }
    // The lattice: 16 samples are a shifted 16-point lattice, one x in each 1/16.
    let shifts: Vec<[u32; 2]> = (0..16u64)
        .map(|i| {
            let h = qmckit::hash::mix64(i);
            [h as u32, (h >> 32) as u32]
        })
        .collect();
    let t = Table::new(2, &shifts).unwrap();
    let base = DomainBase::LatticeTable(t, 0x4613);
    let pts: Vec<[u32; 2]> = (0..16)
        .map(|i| {
            Domain::root(base, 3, 1, i, 16, 4)
                .unwrap()
                .new_domain(8)
                .draw_2d()
        })
        .collect();
    let mut xs: Vec<u32> = pts
        .iter()
        .map(|p| p[0].wrapping_sub(pts[0][0]) >> 28)
        .collect();
    xs.sort_unstable();
    assert_eq!(xs, (0..16).collect::<Vec<u32>>());
    // ... and the differences are multiples of (1, g) / 16 mod 1.
    for p in &pts {
        let dx = p[0].wrapping_sub(pts[0][0]) >> 28;
        let dy = p[1].wrapping_sub(pts[0][1]);
        assert_eq!(dy, ((dx.wrapping_mul(0x4613)) & 15) << 28);
    }
}

#[test]
fn domains_are_deterministic_and_keyed() {
    let a = Domain::root(DomainBase::OwenSobol, 4, 2, 3, 8, 11).unwrap();
    let b = Domain::root(DomainBase::OwenSobol, 4, 2, 3, 8, 11).unwrap();
    assert_eq!(a.new_domain(5).draw_2d(), b.new_domain(5).draw_2d());
    assert_eq!(a.chain().draw_2d(), b.chain().draw_2d());
    assert_ne!(a.new_domain(5).state(), a.new_domain(6).state());
    assert_ne!(a.new_domain(0).state(), a.chain().state());
    assert_ne!(a.new_domain(5).state(), a.split(5, 1, 0).unwrap().state());
    assert!(core::mem::size_of::<Domain>() <= 64);
    let other_seed = Domain::root(DomainBase::OwenSobol, 4, 2, 3, 8, 12).unwrap();
    assert_ne!(a.state(), other_seed.state());
    // The state does not depend on the pixel (the tables' offsets are shared).
    let other_pixel = Domain::root(DomainBase::OwenSobol, 5, 2, 3, 8, 11).unwrap();
    assert_eq!(a.new_domain(3).state(), other_pixel.new_domain(3).state());
    assert_ne!(
        a.new_domain(3).draw_2d(),
        other_pixel.new_domain(3).draw_2d()
    );
}

#[test]
fn bad_domains_are_errors() {
    let b = DomainBase::OwenSobol;
    assert_eq!(Domain::root(b, 0, 0, 0, 0, 0), Err(Error::ZeroPoints));
    assert!(matches!(
        Domain::root(b, 0, 0, 4, 4, 0),
        Err(Error::IndexOutOfRange { index: 4, len: 4 })
    ));
    let r = Domain::root(b, 0, 0, 1, 4, 0).unwrap();
    assert!(r.split(0, 0, 0).is_err());
    assert!(r.split(0, 3, 3).is_err());
    let big = r.split(0, 1 << 30, 5).unwrap();
    assert_eq!(big.len(), 1 << 32);
    assert!(matches!(big.split(0, 2, 1), Err(Error::TooLarge { .. })));
    // The largest domain still draws (m = 32).
    let _ = big.draw_2d();
    let cells = [0u32; 15];
    assert!(Table::new(2, &cells).is_err());
    assert!(Table::new(13, &cells).is_err());
}
