//! Times Sobol' fills against a plain write of the same bytes, on one thread, into buffers
//! already touched (so page faults do not count):
//!
//! * `f64 [LOG2_N] [DIMS] [REPS]` (defaults 20, 8, 20): `Scrambled<Sobol, FastOwen>` in
//!   Gray order (the Python default) through `fill_as::<f64>`, and its `u32` fill alone;
//! * `f32 [LOG2_N] [REPS]` (defaults 16, 200): `OwenSobol::fill_f32` of 4-dimensional
//!   points with one seed and with a reseed every 16 points (as `benches/render.rs`), and
//!   `OwenSobol::fill_f32_reseeded` with the same seeds, 64 pixels a call.
//!
//! Usage: `cargo run --release --example time_sobol_fill -- f64|f32 ...`. Each line: the
//! case, its least wall time over `REPS` runs (the cases run in turn, so that load on the
//! machine slows them alike; the least time is the run least disturbed) and its ratio to
//! the write.

use qmckit::digital::sobol::{Order, OwenSobol};
use qmckit::hash::mix64;
use qmckit::randomize::{FastOwen, Scrambled};
use qmckit::{Sampler, Sobol};
use std::hint::black_box;
use std::time::Instant;

type Case<'a, T> = (&'a str, Box<dyn FnMut(&mut [T]) + 'a>);

fn run<T>(cases: &mut [Case<'_, T>], out: &mut [T], reps: usize) {
    let mut best = vec![f64::INFINITY; cases.len()];
    for _ in 0..reps {
        for (k, (_, f)) in cases.iter_mut().enumerate() {
            let t = Instant::now();
            f(out);
            black_box(&mut *out);
            best[k] = best[k].min(t.elapsed().as_secs_f64());
        }
    }
    for ((name, _), t) in cases.iter().zip(&best) {
        println!("{name:<36} {:10.1} us  {:5.2}x write", t * 1e6, t / best[0]);
    }
}

fn main() -> Result<(), qmckit::Error> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let num =
        |k: usize, default: usize| args.get(k).and_then(|a| a.parse().ok()).unwrap_or(default);
    if args.first().map(String::as_str) == Some("f32") {
        let n = 1usize << num(1, 16);
        let reps = num(2, 200);
        let base = OwenSobol::new(4, 0)?;
        let seeded = base.with_seed(mix64(7));
        let seq: Vec<u32> = (0..n as u32).collect();
        let mut cases: Vec<Case<'_, [f32; 4]>> = vec![
            (
                "write",
                Box::new(|o| black_box(o).fill(black_box([0.0; 4]))),
            ),
            (
                "fill_f32, one seed",
                Box::new(|o| black_box(&seeded).fill_f32(&seq, o).unwrap_or(())),
            ),
            (
                "fill_f32, one seed, 16 a call",
                Box::new(|o| {
                    let s = black_box(seeded);
                    for (idx, o) in seq.chunks_exact(16).zip(o.chunks_exact_mut(16)) {
                        s.fill_f32(idx, o).unwrap_or(());
                    }
                }),
            ),
            (
                "reseed every 16 alone",
                Box::new(|o| {
                    let mut s = black_box(base);
                    for p in 0..o.len() / 16 {
                        s.reseed(mix64(p as u64 ^ 0x9E37_79B9_7F4A_7C15));
                        black_box(&s);
                    }
                }),
            ),
            (
                "fill_f32, reseed every 16",
                Box::new(|o| {
                    let mut s = black_box(base);
                    for (p, (idx, o)) in
                        seq.chunks_exact(16).zip(o.chunks_exact_mut(16)).enumerate()
                    {
                        s.reseed(mix64(p as u64 ^ 0x9E37_79B9_7F4A_7C15));
                        s.fill_f32(idx, o).unwrap_or(());
                    }
                }),
            ),
            (
                "fill_f32_reseeded, 64 seeds a call",
                Box::new(|o| {
                    let s = black_box(base);
                    for (t, (idx, o)) in seq
                        .chunks_exact(16 * 64)
                        .zip(o.chunks_exact_mut(16 * 64))
                        .enumerate()
                    {
                        let seeds: [u64; 64] = core::array::from_fn(|k| {
                            mix64((64 * t + k) as u64 ^ 0x9E37_79B9_7F4A_7C15)
                        });
                        s.fill_f32_reseeded(&seeds, idx, o).unwrap_or(());
                    }
                }),
            ),
        ];
        let mut out = vec![[0f32; 4]; n];
        run(&mut cases, &mut out, reps);
        return Ok(());
    }
    let n = 1usize << num(1, 20);
    let dims = num(2, 8);
    let reps = num(3, 20);
    let s = Scrambled::new(Sobol::with_order(dims, Order::Gray)?, FastOwen::new(1));
    let mut tmp = vec![0u32; 1 << 15];
    let mut cases: Vec<Case<'_, f64>> = vec![
        ("write", Box::new(|o| black_box(o).fill(black_box(0.5)))),
        (
            "fill_as::<f64>",
            Box::new(|o| s.fill_as(0, o).unwrap_or(())),
        ),
        (
            "u32 fill alone (128 KiB chunks)",
            Box::new(|_| {
                let per = tmp.len() / dims;
                for c in 0..n / per {
                    s.fill((c * per) as u32, &mut tmp).unwrap_or(());
                }
            }),
        ),
    ];
    let mut out = vec![0f64; n * dims];
    run(&mut cases, &mut out, reps);
    Ok(())
}
