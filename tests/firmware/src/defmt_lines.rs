//! The lines the defmt firmware (`src/bin/defmt_log.rs`) logs, compiled twice: there, `out!`
//! is `defmt::println!` (the values are encoded on the target with qmckit's
//! `defmt::Format` derives, sent over semihosting and decoded on the host by
//! `defmt-print`); in the host generator (`host/src/bin/defmt_expected.rs`), `out!` is
//! `println!` with the same format string, so `{:?}` is `core::fmt::Debug`. The derived
//! `defmt::Format` and `Debug` print the same text for these types, so `defmt_check.sh`
//! diffs the decoded log against the host's output line for line.
//!
//! Format strings use only `{:?}` (valid in both macro languages) and values whose two
//! renderings agree: integers, arrays, `Option`/`Result`, and qmckit's derived types.

use core::hint::black_box;

use qmckit::randomize::{FastOwen, OwenHash};
use qmckit::digital::sobol::{Order, Sobol, SobolDimension};
use qmckit::{Halton, Hammersley, LarcherPillichshammer, RadicalInverse, Sampler, VanDerCorput};

/// Logs every line; returns the number of lines.
pub fn log_all() -> u32 {
    let mut n = 0u32;
    // Errors (Error derives defmt::Format under qmckit's `defmt` feature).
    out!("err Halton::new(0) {:?}", Halton::new(black_box(0)).err());
    out!(
        "err Halton::new(1025) {:?}",
        Halton::new(black_box(1025)).err()
    );
    out!(
        "err RadicalInverse::new(1) {:?}",
        RadicalInverse::new(black_box(1)).err()
    );
    out!(
        "err LP::new(33) {:?}",
        LarcherPillichshammer::new(black_box(33)).err()
    );
    out!(
        "err LP::with_points(48) {:?}",
        LarcherPillichshammer::with_points(black_box(48)).err()
    );
    out!(
        "err Hammersley::new(0,2) {:?}",
        Hammersley::new(black_box(0), 2).err()
    );
    out!("err Sobol::new(65) {:?}", Sobol::new(black_box(65)).err());
    out!(
        "err VanDerCorput::new(0) {:?}",
        VanDerCorput::new(black_box(0)).err()
    );
    n += 8;
    // Results of sampling calls, Ok and Err.
    if let Ok(h) = Halton::new(black_box(3)) {
        out!("halton3 {:?}", h);
        for i in [0u32, 1, 2, 1000, 4_000_000_000] {
            let p = [
                h.sample(black_box(i), 0).unwrap_or(0),
                h.sample(black_box(i), 1).unwrap_or(0),
                h.sample(black_box(i), 2).unwrap_or(0),
            ];
            out!("halton3 {:?} {:?}", i, p);
            n += 1;
        }
        out!("halton3 sample(7, 3) {:?}", h.sample(black_box(7), 3));
        n += 2;
    }
    if let Ok(phi3) = RadicalInverse::new(black_box(3)) {
        out!(
            "ri3 digits {:?} {:?}",
            phi3.digits(),
            phi3.sample(black_box(1000))
        );
        out!("ri3 inverse {:?}", phi3.inverse(black_box(0), 21));
        n += 2;
    }
    for order in [Order::Natural, Order::Gray] {
        if let Ok(s) = Sobol::with_order(black_box(2), order) {
            let mut buf = [0u32; 8];
            let r = Sampler::fill(&s, black_box(0), &mut buf);
            out!("sobol {:?} fill {:?} {:?}", s, r, buf);
            n += 1;
        }
    }
    if let Ok(d) = SobolDimension::new(black_box(1)) {
        out!(
            "sobol dim1 {:?}",
            [d.sample(1), d.sample(2), d.sample(3), d.sample(0xFFFF_FFFF)]
        );
        n += 1;
    }
    for owen in [
        FastOwen::new(black_box(7)),
        FastOwen::with_hash(7, OwenHash::LaineKarras),
    ] {
        out!(
            "{:?} {:?}",
            owen,
            [
                owen.scramble(black_box(1 << 31), 0),
                owen.scramble(1 << 31, 1)
            ]
        );
        n += 1;
    }
    if let Ok(lp) = LarcherPillichshammer::new(black_box(4)) {
        out!(
            "lp {:?} {:?} {:?}",
            lp,
            lp.sample(black_box(5), 1),
            lp.sample(black_box(16), 0)
        );
        n += 1;
    }
    n
}
