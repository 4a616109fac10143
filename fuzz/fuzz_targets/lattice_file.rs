//! Fuzzes the generating-vector reader (`qmckit::lattice::parse_lattice`, behind
//! `qmckit points lattice --vector FILE`): any text must give a header and components that
//! keep the reader's promises, or an error, never a panic; an accepted vector then builds a
//! lattice whose points are computed without a panic. The first byte is the number of
//! components asked for (0 to 255).
#![no_main]

use libfuzzer_sys::fuzz_target;
use qmckit::Sampler;
use qmckit::lattice::{Rank1Lattice, parse_lattice};

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    let Ok(text) = std::str::from_utf8(rest) else {
        return;
    };
    let mut z = vec![0u32; first as usize];
    let Ok(info) = parse_lattice(text, &mut z) else {
        return;
    };
    assert!(info.read <= z.len(), "{info:?}");
    if let Some(n) = info.modulus {
        assert!((1..=1u64 << 32).contains(&n), "{info:?}");
    }
    if let Some(s) = info.declared_dims {
        assert!(info.read <= s.max(z.len()), "{info:?}");
    }
    let z = &z[..info.read];
    if z.is_empty() {
        return;
    }
    let n = info.modulus.unwrap_or(1 << 20);
    if let Ok(lattice) = Rank1Lattice::linear(z.to_vec(), n) {
        assert_eq!(lattice.dims(), z.len());
        for i in [0u32, 1, (n - 1).min(u64::from(u32::MAX)) as u32] {
            for d in 0..lattice.dims() {
                let _ = lattice.sample(i, d);
            }
        }
        // One past the end is an error, not a wrapped point.
        if n < 1 << 32 {
            assert!(lattice.sample(n as u32, 0).is_err());
        }
    }
    if let Ok(lattice) = Rank1Lattice::extensible(z.to_vec(), 20) {
        let _ = lattice.sample(u32::MAX, z.len() - 1);
    }
});
