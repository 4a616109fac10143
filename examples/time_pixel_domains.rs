//! Time per 4D sample (two 2D draws as `f32`) of the domain API and the blue-noise pixel
//! samplers beside ZSobol and PaddedSobol, in one process, rounds interleaved, best of
//! `--rounds` (default 15). The workload of issue 30: 256 x 256 pixels, 16 spp.
//!
//! ```text
//! cargo run --release --example time_pixel_domains -- [--rounds N]
//! ```

use qmckit::pixel::domain::{Domain, DomainBase};
use qmckit::pixel::{
    BlueNoiseLattice, BlueNoiseSobol, PaddedSobol, PixelSampler, Randomization, ZSobol,
};
use std::hint::black_box;
use std::time::Instant;

const SIDE: u32 = 256;
const SPP: u32 = 16;

/// Two 2D draws from every pixel sample of a pixel sampler; the sum of the values.
fn run_sampler<S: PixelSampler>(s: &S) -> f32 {
    let mut acc = 0.0f32;
    for y in 0..SIDE {
        for x in 0..SIDE {
            for i in 0..SPP {
                if let Ok(mut p) = s.start_pixel_sample(x, y, i) {
                    let [a, b] = p.get_2d_f32();
                    let [c, d] = p.get_2d_f32();
                    acc += a + b + c + d;
                }
            }
        }
    }
    acc
}

/// Two domains (`new_domain(0)`, `new_domain(1)`) of every pixel sample's root.
fn run_domains(base: DomainBase) -> f32 {
    let mut acc = 0.0f32;
    for y in 0..SIDE {
        for x in 0..SIDE {
            for i in 0..SPP {
                if let Ok(r) = Domain::root(base, x, y, i, SPP, 7) {
                    let [a, b] = r.new_domain(0).draw_2d_f32();
                    let [c, d] = r.new_domain(1).draw_2d_f32();
                    acc += a + b + c + d;
                }
            }
        }
    }
    acc
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let rounds: usize = match args.as_slice() {
        [] => 15,
        [flag, v] if flag == "--rounds" => v.parse()?,
        _ => return Err("usage: time_pixel_domains [--rounds N]".into()),
    };
    let z = ZSobol::new(SIDE, SIDE, SPP, Randomization::FastOwen, 7)?;
    let p = PaddedSobol::new(SIDE, SIDE, SPP, Randomization::FastOwen, 7)?;
    let b = BlueNoiseSobol::new(SIDE, SIDE, SPP, 7)?;
    let l = BlueNoiseLattice::new(SIDE, SIDE, SPP, 7)?;
    let bt = b.domain(0, 0, 0)?.base();
    let names = [
        "ZSobol (random access)",
        "PaddedSobol",
        "BlueNoiseSobol",
        "BlueNoiseLattice",
        "Domain, OwenSobol (hashed keys)",
        "Domain, OwenSobolTable",
    ];
    let mut best = [f64::INFINITY; 6];
    for _ in 0..rounds {
        for (k, slot) in best.iter_mut().enumerate() {
            let t = Instant::now();
            let v = match k {
                0 => run_sampler(&z),
                1 => run_sampler(&p),
                2 => run_sampler(&b),
                3 => run_sampler(&l),
                4 => run_domains(DomainBase::OwenSobol),
                _ => run_domains(bt),
            };
            black_box(v);
            *slot = slot.min(t.elapsed().as_secs_f64());
        }
    }
    let n = (SIDE * SIDE * SPP) as f64;
    println!("{SIDE}x{SIDE} pixels x {SPP} spp, two 2D f32 draws a sample, best of {rounds}");
    println!("| sampler | ns per 4D sample | vs ZSobol |");
    println!("|---|---|---|");
    for (name, t) in names.iter().zip(best) {
        println!("| {name} | {:.1} | {:.2}x |", t / n * 1e9, best[0] / t);
    }
    Ok(())
}
