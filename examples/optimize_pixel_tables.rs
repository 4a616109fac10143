//! Optimizes the blue-noise pixel tables of `qmckit::pixel::{BlueNoiseSobol,
//! BlueNoiseLattice}` and writes them to `tables/` (little-endian `u32`s, row-major):
//! `pixel-bn-sobol-keys-64.bin` (one Owen-scrambling key a pixel) and
//! `pixel-bn-lattice-shifts-64.bin` (one Cranley–Patterson shift `(sx, sy)` a pixel).
//! It also searches the lattice's generator and prints it.
//!
//! ```text
//! cargo run --release --features analysis --example optimize_pixel_tables -- [--iterations N] [--seed S] [--out DIR]
//!     [--sigma SIGMA] [--spp-weights W1,W2,W4,W8,W16]
//! cargo run --release --features analysis --example optimize_pixel_tables -- --evaluate DIR
//! ```
//!
//! After optimizing (or, with `--evaluate`, for the tables in `DIR`) it prints the
//! screen-space error of the samplers on the tables against PaddedSobol.
//!
//! The method (Heitz & Belcour 2019; Belcour & Heitz 2021): a pool of `64^2` uniformly
//! random keys (shifts) is assigned to the pixels of a toroidal `64 x 64` tile, and
//! pairs of pixels swap keys by simulated annealing to minimize the low-frequency power of
//! the error images of a family of test integrands:
//!
//! ```text
//! E = sum_c sum_{p, q} e_c(p) K(p - q) e_c(q),   K(r) = exp(-|r|^2 / (2 sigma^2)) on the torus
//! ```
//!
//! `e_c(p)` is the error of pixel `p`'s estimate for channel `c`: one of 64 integrands
//! (56 Heavisides `[(u - a) cos t + (v - b) sin t < 0]` with random `(a, b, t)`, exact
//! integral by clipping the square, and 8 Gaussian bumps with random centre and width)
//! at one of the sample counts 1, 2, 4, 8, 16, each channel scaled to RMS `w_n` over the
//! pool (`--spp-weights`, default all 1). The pixel's points are computed through `qmckit::pixel::domain` exactly as the
//! samplers compute them. `E` is `sum_c |FT(e_c)|^2 FT(K)`, so with `sigma = 2` it weighs
//! frequencies below about `1/8` cycle a pixel. A swap of `p` and `q` changes it by
//! `sum_c 2 a_c (F_c(p) - F_c(q)) + a_c^2 (2 K(0) - 2 K(p - q))`, `a_c = e_c(q) - e_c(p)`,
//! `F_c = K * e_c` kept up to date (`sigma`: `--sigma`, default 2), so a proposal costs one pass over the channels.
//! Only swaps: the table is a permutation of the random pool, so a pixel under a random
//! offset still gets a uniform key of the pool (unbiased for any integrand).
//!
//! The iteration count is the budget (default 30 million proposals a table, about a
//! minute on one core); the run is deterministic for a seed.

use qmckit::hash::mix64;
use qmckit::pixel::domain::{Domain, DomainBase, Table};
use std::f64::consts::PI;

const LOG2_SIDE: u32 = 6;
const SIDE: usize = 1 << LOG2_SIDE;
const PIXELS: usize = SIDE * SIDE;
const SPPS: [u32; 5] = [1, 2, 4, 8, 16];
const HEAVISIDES: usize = 56;
const GAUSSIANS: usize = 8;

/// A splitmix64 stream.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        mix64(self.0)
    }
    fn unit(&mut self) -> f64 {
        (self.next() >> 11) as f64 / (1u64 << 53) as f64
    }
    fn below(&mut self, n: usize) -> usize {
        (((self.next() >> 32) * n as u64) >> 32) as usize
    }
}

#[derive(Clone, Copy)]
enum Integrand {
    /// `[(u - a) c + (v - b) s < 0]`.
    Heaviside { a: f64, b: f64, c: f64, s: f64 },
    /// `exp(-|x - m|^2 / (2 w^2))`.
    Gaussian { mx: f64, my: f64, w: f64 },
}

impl Integrand {
    fn eval(self, u: f64, v: f64) -> f64 {
        match self {
            Integrand::Heaviside { a, b, c, s } => {
                f64::from(u8::from((u - a) * c + (v - b) * s < 0.0))
            }
            Integrand::Gaussian { mx, my, w } => {
                (-((u - mx).powi(2) + (v - my).powi(2)) / (2.0 * w * w)).exp()
            }
        }
    }

    fn exact(self) -> f64 {
        match self {
            Integrand::Heaviside { a, b, c, s } => {
                // Clip the unit square by the half-plane, then the shoelace formula.
                let sq = [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)];
                let f = |p: (f64, f64)| (p.0 - a) * c + (p.1 - b) * s;
                let mut poly = Vec::new();
                for k in 0..4 {
                    let (p, q) = (sq[k], sq[(k + 1) % 4]);
                    let (fp, fq) = (f(p), f(q));
                    if fp < 0.0 {
                        poly.push(p);
                    }
                    if (fp < 0.0) != (fq < 0.0) {
                        let t = fp / (fp - fq);
                        poly.push((p.0 + t * (q.0 - p.0), p.1 + t * (q.1 - p.1)));
                    }
                }
                let n = poly.len();
                (0..n)
                    .map(|k| {
                        let (p, q) = (poly[k], poly[(k + 1) % n]);
                        p.0 * q.1 - q.0 * p.1
                    })
                    .sum::<f64>()
                    .abs()
                    / 2.0
            }
            Integrand::Gaussian { mx, my, w } => {
                let one = |m: f64| {
                    let r = w * (PI / 2.0).sqrt();
                    r * (libm::erf((1.0 - m) / (2f64.sqrt() * w))
                        + libm::erf(m / (2f64.sqrt() * w)))
                };
                one(mx) * one(my)
            }
        }
    }
}

fn family(rng: &mut Rng) -> Vec<Integrand> {
    let mut f = Vec::new();
    for _ in 0..HEAVISIDES {
        let t = 2.0 * PI * rng.unit();
        f.push(Integrand::Heaviside {
            a: rng.unit(),
            b: rng.unit(),
            c: t.cos(),
            s: t.sin(),
        });
    }
    for _ in 0..GAUSSIANS {
        f.push(Integrand::Gaussian {
            mx: 0.2 + 0.6 * rng.unit(),
            my: 0.2 + 0.6 * rng.unit(),
            w: 0.1 + 0.2 * rng.unit(),
        });
    }
    f
}

/// The error vectors (channels = integrands x sample counts) of a key whose points `pts(n,
/// i)` are given, scaled later.
fn errors(fam: &[Integrand], exact: &[f64], pts: impl Fn(u32, u32) -> [u32; 2]) -> Vec<f64> {
    let mut out = Vec::with_capacity(fam.len() * SPPS.len());
    for &n in &SPPS {
        let p: Vec<[f64; 2]> = (0..n)
            .map(|i| pts(n, i).map(qmckit::bits::to_f64))
            .collect();
        for (f, ex) in fam.iter().zip(exact) {
            let m = p.iter().map(|q| f.eval(q[0], q[1])).sum::<f64>() / n as f64;
            out.push(m - ex);
        }
    }
    out
}

/// Simulated annealing over swaps; returns the permutation `pixel -> pool index`.
fn anneal(e: &[Vec<f64>], iterations: u64, sigma: f64, rng: &mut Rng) -> Vec<usize> {
    let c = e[0].len();
    let r = (3.0 * sigma).ceil() as i64;
    let kern = |dx: i64, dy: i64| (-((dx * dx + dy * dy) as f64) / (2.0 * sigma * sigma)).exp();
    let offsets: Vec<(i64, i64, f64)> = (-r..=r)
        .flat_map(|dy| (-r..=r).map(move |dx| (dx, dy)))
        .filter(|&(dx, dy)| dx * dx + dy * dy <= r * r)
        .map(|(dx, dy)| (dx, dy, kern(dx, dy)))
        .collect();
    let wrap = |v: i64| v.rem_euclid(SIDE as i64) as usize;
    let kdist = |p: usize, q: usize| {
        let d = |a: usize, b: usize| {
            let t = (a as i64 - b as i64).rem_euclid(SIDE as i64);
            t.min(SIDE as i64 - t)
        };
        let (dx, dy) = (d(p % SIDE, q % SIDE), d(p / SIDE, q / SIDE));
        if dx * dx + dy * dy <= r * r {
            kern(dx, dy)
        } else {
            0.0
        }
    };
    let mut perm: Vec<usize> = (0..PIXELS).collect();
    let mut filt = vec![0.0f64; PIXELS * c];
    let refilter = |perm: &[usize], filt: &mut [f64]| {
        filt.iter_mut().for_each(|v| *v = 0.0);
        for p in 0..PIXELS {
            let (x, y) = ((p % SIDE) as i64, (p / SIDE) as i64);
            for &(dx, dy, k) in &offsets {
                let q = wrap(y + dy) * SIDE + wrap(x + dx);
                let (fq, ep) = (&mut filt[q * c..(q + 1) * c], &e[perm[p]]);
                fq.iter_mut().zip(ep).for_each(|(f, v)| *f += k * v);
            }
        }
    };
    let energy = |perm: &[usize], filt: &[f64]| -> f64 {
        (0..PIXELS)
            .map(|p| {
                e[perm[p]]
                    .iter()
                    .zip(&filt[p * c..(p + 1) * c])
                    .map(|(a, b)| a * b)
                    .sum::<f64>()
            })
            .sum()
    };
    refilter(&perm, &mut filt);
    let e0 = energy(&perm, &filt);
    let propose = |rng: &mut Rng| {
        let p = rng.below(PIXELS);
        let q = if rng.next() & 1 == 0 {
            rng.below(PIXELS)
        } else {
            let (x, y) = ((p % SIDE) as i64, (p / SIDE) as i64);
            let dx = rng.below(2 * r as usize + 1) as i64 - r;
            let dy = rng.below(2 * r as usize + 1) as i64 - r;
            wrap(y + dy) * SIDE + wrap(x + dx)
        };
        (p, q)
    };
    let delta = |perm: &[usize], filt: &[f64], p: usize, q: usize| -> f64 {
        let (ep, eq) = (&e[perm[p]], &e[perm[q]]);
        let (fp, fq) = (&filt[p * c..(p + 1) * c], &filt[q * c..(q + 1) * c]);
        let self_term = 2.0 - 2.0 * kdist(p, q);
        let mut s = 0.0;
        for (((a, b), f), g) in eq.iter().zip(ep).zip(fp).zip(fq) {
            let d = a - b;
            s += 2.0 * d * (f - g) + d * d * self_term;
        }
        s
    };
    // The starting temperature: a tenth of the mean |dE| of random proposals.
    let t0 = (0..2000)
        .map(|_| {
            let (p, q) = propose(rng);
            delta(&perm, &filt, p, q).abs()
        })
        .sum::<f64>()
        / 2000.0
        * 0.1;
    let mut accepted = 0u64;
    let report = iterations / 10;
    for it in 0..iterations {
        let (p, q) = propose(rng);
        if p == q {
            continue;
        }
        let t = t0 * (1e-4f64).powf(it as f64 / iterations as f64);
        let d = delta(&perm, &filt, p, q);
        if d < 0.0 || rng.unit() < (-d / t).exp() {
            accepted += 1;
            let a: Vec<f64> = e[perm[q]]
                .iter()
                .zip(&e[perm[p]])
                .map(|(x, y)| x - y)
                .collect();
            for (centre, sign) in [(p, 1.0), (q, -1.0)] {
                let (x, y) = ((centre % SIDE) as i64, (centre / SIDE) as i64);
                for &(dx, dy, k) in &offsets {
                    let o = wrap(y + dy) * SIDE + wrap(x + dx);
                    let fo = &mut filt[o * c..(o + 1) * c];
                    fo.iter_mut().zip(&a).for_each(|(f, v)| *f += sign * k * v);
                }
            }
            perm.swap(p, q);
        }
        if report > 0 && (it + 1) % report == 0 {
            refilter(&perm, &mut filt);
            eprintln!(
                "  {:>3}%: E / E(random) = {:.4}, accepted {accepted}",
                (it + 1) * 100 / iterations,
                energy(&perm, &filt) / e0
            );
        }
    }
    perm
}

/// Scales every channel to RMS `weights[sample count]` over the pool.
fn normalize(e: &mut [Vec<f64>], weights: &[f64]) {
    let c = e[0].len();
    let per = c / SPPS.len();
    for k in 0..c {
        let rms = (e.iter().map(|v| v[k] * v[k]).sum::<f64>() / e.len() as f64).sqrt();
        if rms > 0.0 {
            let w = weights[k / per];
            e.iter_mut().for_each(|v| v[k] = v[k] / rms * w);
        }
    }
}

/// The shortest vector of the 2D lattice `(a, a g mod n)`, over the hexagonal spacing
/// `sqrt(2 / (sqrt(3) n))` (1 is the best possible).
fn shortest(g: u64, m: u32) -> f64 {
    let n = 1u64 << m;
    let bound = ((1.2 * n as f64).sqrt() as u64 + 2).min(n - 1);
    let mut best = f64::INFINITY;
    for a in 1..=bound {
        let y = (a * g) % n;
        let dy = y.min(n - y) as f64;
        best = best.min(((a * a) as f64 + dy * dy).sqrt());
    }
    best / n as f64 / (2.0 / (3f64.sqrt() * n as f64)).sqrt()
}

/// The odd `g < 2^16` whose lattices of `2^m` points, `m = 2..16`, have the largest
/// smallest normalized shortest vector.
fn search_generator() -> (u32, f64) {
    let mut best = (1u32, 0.0);
    for g in (1..1u64 << 16).step_by(2) {
        let mut score = f64::INFINITY;
        for m in 2..=16 {
            score = score.min(shortest(g, m));
            if score <= best.1 {
                break;
            }
        }
        if score > best.1 {
            best = (g as u32, score);
        }
    }
    best
}

/// Low-band power and RMSE of the tables' samplers over PaddedSobol's (per-pixel hashed
/// Owen-Sobol'), `analysis::screen_error` at 128 x 128, 4 seeds.
fn evaluate(keys: &[u32], shifts: &[[u32; 2]], g: u32) -> qmckit::Result<()> {
    use qmckit::analysis::screen_error::{PixelIntegrand, screen_error};
    use qmckit::pixel::{BlueNoiseLattice, BlueNoiseSobol, PaddedSobol, Randomization};
    use qmckit::work::Budget;
    let (kt, st) = (Table::new(LOG2_SIDE, keys)?, Table::new(LOG2_SIDE, shifts)?);
    let u = Budget::UNLIMITED;
    println!("integrand spp | low band / padded: sobol lattice | RMSE / padded: sobol lattice");
    for f in [
        PixelIntegrand::GaussianBump,
        PixelIntegrand::Step,
        PixelIntegrand::Visibility,
    ] {
        for spp in [1u32, 4, 16] {
            let mut acc = [[0.0f64; 2]; 3];
            for seed in 0..4u64 {
                let p = PaddedSobol::new(128, 128, spp, Randomization::FastOwen, seed)?;
                let b = BlueNoiseSobol::with_table(128, 128, spp, seed, kt)?;
                let l = BlueNoiseLattice::with_table(128, 128, spp, seed, st, g)?;
                let e = [
                    screen_error(&p, f, &u)?,
                    screen_error(&b, f, &u)?,
                    screen_error(&l, f, &u)?,
                ];
                for (a, e) in acc.iter_mut().zip(e) {
                    a[0] += e.rmse * e.rmse;
                    a[1] += e.low_band_absolute;
                }
            }
            let low = |k: usize| acc[k][1] / acc[0][1];
            let rmse = |k: usize| (acc[k][0] / acc[0][0]).sqrt();
            println!(
                "{f:?} {spp} | {:.3} {:.3} | {:.3} {:.3}",
                low(1),
                low(2),
                rmse(1),
                rmse(2)
            );
        }
    }
    Ok(())
}

fn write(path: &std::path::Path, words: &[u32]) -> std::io::Result<()> {
    let bytes: Vec<u8> = words.iter().flat_map(|w| w.to_le_bytes()).collect();
    let tmp = path.with_extension("tmp");
    std::fs::write(&tmp, bytes)?;
    std::fs::rename(tmp, path)
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut iterations = 30_000_000u64;
    let mut seed = 2026u64;
    let mut out = std::path::PathBuf::from("tables");
    let mut sigma = 2.0f64;
    let mut weights = vec![1.0f64; SPPS.len()];
    let mut evaluate_only: Option<std::path::PathBuf> = None;
    let args: Vec<String> = std::env::args().skip(1).collect();
    let mut k = 0;
    while k < args.len() {
        let v = args.get(k + 1).ok_or("a flag needs a value")?;
        match args[k].as_str() {
            "--iterations" => iterations = v.parse()?,
            "--seed" => seed = v.parse()?,
            "--out" => out = v.into(),
            "--sigma" => sigma = v.parse()?,
            "--evaluate" => evaluate_only = Some(v.into()),
            "--spp-weights" => {
                weights = v.split(',').map(str::parse).collect::<Result<_, _>>()?;
                if weights.len() != SPPS.len() {
                    return Err("--spp-weights takes 5 numbers (spp 1, 2, 4, 8, 16)".into());
                }
            }
            f => return Err(format!("unknown flag {f}").into()),
        }
        k += 2;
    }
    if let Some(dir) = evaluate_only {
        let read = |name: &str| -> std::io::Result<Vec<u32>> {
            let b = std::fs::read(dir.join(name))?;
            Ok(b.chunks_exact(4)
                .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                .collect())
        };
        let keys = read("pixel-bn-sobol-keys-64.bin")?;
        let shifts: Vec<[u32; 2]> = read("pixel-bn-lattice-shifts-64.bin")?
            .chunks_exact(2)
            .map(|c| [c[0], c[1]])
            .collect();
        evaluate(&keys, &shifts, qmckit::pixel::BLUE_NOISE_LATTICE_GENERATOR)?;
        return Ok(());
    }
    let (g, score) = search_generator();
    println!(
        "lattice generator g = {g:#x} ({g}), smallest normalized shortest vector {score:.3} (m = 2..16)"
    );
    let mut rng = Rng(seed);
    let fam = family(&mut rng);
    let exact: Vec<f64> = fam.iter().map(|f| f.exact()).collect();

    // Owen-scrambled Sobol' keys.
    let keys: Vec<u32> = (0..PIXELS).map(|_| rng.next() as u32).collect();
    let mut e: Vec<Vec<f64>> = Vec::with_capacity(PIXELS);
    for &key in &keys {
        let cell = [key];
        let base = DomainBase::OwenSobolTable(Table::new(0, &cell)?);
        e.push(errors(&fam, &exact, |n, i| {
            Domain::root(base, 0, 0, i, n, 0).map_or([0, 0], |d| d.draw_2d())
        }));
    }
    normalize(&mut e, &weights);
    println!("Owen-Sobol' keys: {iterations} proposals");
    let perm = anneal(&e, iterations, sigma, &mut rng);
    let key_table: Vec<u32> = perm.iter().map(|&i| keys[i]).collect();
    write(&out.join("pixel-bn-sobol-keys-64.bin"), &key_table)?;

    // Lattice shifts.
    let shifts: Vec<[u32; 2]> = (0..PIXELS)
        .map(|_| {
            let v = rng.next();
            [v as u32, (v >> 32) as u32]
        })
        .collect();
    let mut e: Vec<Vec<f64>> = Vec::with_capacity(PIXELS);
    for &shift in &shifts {
        let cell = [shift];
        let base = DomainBase::LatticeTable(Table::new(0, &cell)?, g);
        e.push(errors(&fam, &exact, |n, i| {
            Domain::root(base, 0, 0, i, n, 0).map_or([0, 0], |d| d.draw_2d())
        }));
    }
    normalize(&mut e, &weights);
    println!("lattice shifts: {iterations} proposals");
    let perm = anneal(&e, iterations, sigma, &mut rng);
    let shift_table: Vec<[u32; 2]> = perm.iter().map(|&i| shifts[i]).collect();
    let flat: Vec<u32> = shift_table.iter().flatten().copied().collect();
    write(&out.join("pixel-bn-lattice-shifts-64.bin"), &flat)?;
    println!("wrote {}", out.display());
    evaluate(&key_table, &shift_table, g)?;
    Ok(())
}
