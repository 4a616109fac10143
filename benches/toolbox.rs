//! Per-value speed of the lattice, Kronecker, Faure and interlaced Sobol' generators
//! (`fill_as::<f64>` of 2^20 points in 8 dimensions, best of 5), printed as
//! `name ns-per-value` lines for `benches/peers_python.py`.

use std::hint::black_box;
use std::time::Instant;

use qmckit::digital::DigitalNetB;
use qmckit::digital::sobol::interlaced::Interlaced;
use qmckit::lattice::Rank1Lattice;
use qmckit::lattice::kronecker::Kronecker;
use qmckit::randomize::{CranleyPatterson, DigitalShift, Lms, Scrambled};
use qmckit::{Sampler, Sobol};

const N: usize = 1 << 20;
const D: usize = 8;

fn time<S: Sampler>(name: &str, s: &S, n: usize) {
    let mut buf = vec![0f64; n * D];
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        s.fill_as(0, &mut buf).expect("fill");
        black_box(&buf);
        best = best.min(t.elapsed().as_secs_f64());
    }
    println!("{name} {:.3}", best / (n * D) as f64 * 1e9);
}

fn main() {
    let lat = Scrambled::new(Rank1Lattice::kuo(D).expect("kuo"), CranleyPatterson::new(7));
    time("lattice-shift", &lat, N);
    let kr = Scrambled::new(Kronecker::r_d(D).expect("r_d"), CranleyPatterson::new(7));
    time("kronecker-shift", &kr, N);
    let sobol = Sobol::new(D).expect("sobol");
    time("sobol", &sobol, N);
    let lms = Scrambled::new(sobol, (Lms::new(7), DigitalShift::new(7)));
    time("sobol-lms-shift", &lms, N);
    let faure = DigitalNetB::faure(11, D).expect("faure");
    time("faure-b11", &faure, N / 16);
    let inter = Scrambled::new(
        Interlaced::new(D, 2).expect("interlaced"),
        DigitalShift::new(7),
    );
    time("interlaced2-shift", &inter, N);
}
