//! Fuzzes the digital-net reader (`qmckit::digital::parse_dnet`, LDData `dnet`/`dnetup`
//! files): any text must give a net or an error, never a panic, and an accepted net's
//! points are computed (first, last, past the end) without a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use qmckit::Sampler;
use qmckit::digital::parse_dnet;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let Ok(net) = parse_dnet(text) else {
        return;
    };
    let n = net.len();
    let dims = net.dims();
    assert!(dims >= 1 && n >= 1, "{dims} dims, {n} points");
    let last = (n - 1).min(u64::from(u32::MAX)) as u32;
    let mut point = vec![0u32; dims];
    for i in [0, 1.min(last), last / 2, last] {
        assert!(net.point(i, &mut point).is_ok(), "point {i} of {n}");
    }
    if n <= u64::from(u32::MAX) {
        assert!(net.sample(n as u32, 0).is_err(), "point {n} of {n}");
    }
    assert!(net.sample(0, dims).is_err(), "dimension {dims} of {dims}");
});
