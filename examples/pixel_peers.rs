//! The driver of `scripts/bench_pixel_peers.sh`: qmckit's pixel samplers next to pbrt-v4's
//! and OpenQMC's (compiled by the script into a static library and linked with `--cfg
//! qmckit_peers`), in one process, on one workload: a 256 x 256 image, 16 samples a pixel,
//! two 2D draws a sample as `f32`. Each row renders the whole image, a pixel's 64 values
//! into a stack buffer passed to `black_box`; rounds interleave the rows and the table
//! gives each row's best round in ns per 4D sample (`time / (256 * 256 * 16)`).
//!
//! Before timing, the rows that must agree are compared over the whole image: each qmckit
//! path of ZSobol, PaddedSobol, ImageSobol, Halton and Stratified against pbrt's sampler
//! of the same configuration, value for value (`f32` bits), and every prepared path
//! against its sampler's handle.
//!
//! Arguments: the number of rounds (15), then optionally substrings separated by `|`:
//! only the rows whose names contain one run. With `PIXEL_PEERS_CPU_TIME=1` (Linux) a row
//! is timed by the thread's CPU time rather than the wall clock, so that time other jobs
//! take on the shared core is not counted (their cache traffic still is). Without the
//! peers (a plain `cargo run --example pixel_peers`) it only says how to build.

#[cfg(not(qmckit_peers))]
fn main() {
    eprintln!(
        "build and run with scripts/bench_pixel_peers.sh PBRT_V4_DIR OPENQMC_DIR [ROUNDS] [CPU]"
    );
}

#[cfg(qmckit_peers)]
fn main() {
    if let Err(e) = peers::run() {
        eprintln!("pixel_peers: {e}");
        std::process::exit(1);
    }
}

#[cfg(qmckit_peers)]
mod peers {
    use std::hint::black_box;
    use std::time::Instant;

    use qmckit::digital::sobol::OwenSobol;
    use qmckit::hash::mix64;
    use qmckit::pixel::{
        BlueNoiseLattice, BlueNoiseSobol, HaltonSampler, ImageSobol, IndependentPixels,
        PaddedSobol, PixelSampler, Pmj02BnTables, Pmj02Pixels, PreparedHalton, Randomization,
        StratifiedSampler, ZSobol,
    };

    const SIDE: u32 = 256;
    const SPP: u32 = 16;
    const VALUES: usize = (SIDE * SIDE * SPP * 4) as usize;

    unsafe extern "C" {
        fn peers_run(id: i32, out: *mut f32) -> i32;
        fn peers_set_pmj02bn_table(points: *const u32);
        fn peers_set_blue_noise(values: *const u16);
    }

    #[cfg(target_os = "linux")]
    unsafe extern "C" {
        fn clock_gettime(clock: i32, ts: *mut [i64; 2]) -> i32;
    }

    /// This thread's CPU time in ns (Linux `CLOCK_THREAD_CPUTIME_ID`), or `None` elsewhere
    /// or on failure.
    fn thread_cpu_ns() -> Option<f64> {
        #[cfg(target_os = "linux")]
        {
            let mut ts = [0i64; 2];
            // SAFETY: clock 3 is CLOCK_THREAD_CPUTIME_ID; `ts` is a `struct timespec`
            // (two 64-bit fields on the 64-bit Linux targets this bench runs on).
            let rc = unsafe { clock_gettime(3, &mut ts) };
            (rc == 0).then(|| ts[0] as f64 * 1e9 + ts[1] as f64)
        }
        #[cfg(not(target_os = "linux"))]
        None
    }

    /// A peer sampler over the whole image, into `out` (all `VALUES`) when given.
    fn peer(id: i32, out: Option<&mut [f32]>) {
        let ptr = match out {
            Some(o) => {
                assert_eq!(o.len(), VALUES);
                o.as_mut_ptr()
            }
            None => std::ptr::null_mut(),
        };
        // SAFETY: `peers_run` writes VALUES floats to a non-null `out` and reads nothing.
        let rc = unsafe { peers_run(id, ptr) };
        assert_eq!(rc, 0, "peer id {id}");
    }

    /// The handle's way: per sample, start, then `get_2d_f32` twice.
    fn handle<S: PixelSampler>(s: &S, mut out: Option<&mut [f32]>) {
        let mut px = [0f32; 64];
        for y in 0..SIDE {
            for x in 0..SIDE {
                for i in 0..SPP {
                    let Ok(mut h) = s.start_pixel_sample(x, y, i) else {
                        return;
                    };
                    let [a, b] = h.get_2d_f32();
                    let [c, d] = h.get_2d_f32();
                    let k = 4 * i as usize;
                    px[k..k + 4].copy_from_slice(&[a, b, c, d]);
                }
                black_box(&mut px);
                if let Some(o) = out.as_deref_mut() {
                    let k = 64 * (y * SIDE + x) as usize;
                    o[k..k + 64].copy_from_slice(&px);
                }
            }
        }
    }

    /// The prepared way: per pixel, `fill_2d_f32` at the counter of the first draw and at
    /// that of the second.
    fn prepared<S: PixelSampler>(s: &S, mut out: Option<&mut [f32]>) {
        let Ok(mut h) = s.start_pixel_sample(0, 0, 0) else {
            return;
        };
        h.get_2d();
        let second = h.dimension();
        let (mut a, mut b) = ([[0f32; 2]; SPP as usize], [[0f32; 2]; SPP as usize]);
        for y in 0..SIDE {
            for x in 0..SIDE {
                if s.fill_2d_f32(x, y, 0, &mut a).is_err()
                    || s.fill_2d_f32(x, y, second, &mut b).is_err()
                {
                    return;
                }
                black_box((&mut a, &mut b));
                if let Some(o) = out.as_deref_mut() {
                    let k = 64 * (y * SIDE + x) as usize;
                    for (j, (p, q)) in a.iter().zip(&b).enumerate() {
                        o[k + 4 * j..k + 4 * j + 4].copy_from_slice(&[p[0], p[1], q[0], q[1]]);
                    }
                }
            }
        }
    }

    /// `OwenSobol` (4 dimensions) reseeded per pixel, `fill_f32` of the 16 indices.
    fn owen_sobol(base: &OwenSobol, out: Option<&mut [f32]>) {
        let _ = out;
        let indices: [u32; SPP as usize] = core::array::from_fn(|k| k as u32);
        let mut s = *base;
        let mut px = [[0f32; 4]; SPP as usize];
        for p in 0..SIDE * SIDE {
            s.reseed(mix64(p as u64 ^ 0x9E37_79B9_7F4A_7C15));
            if s.fill_f32(black_box(&indices), &mut px).is_err() {
                return;
            }
            black_box(&mut px);
        }
    }

    type Run<'a> = Box<dyn Fn(Option<&mut [f32]>) + 'a>;

    struct Row<'a> {
        name: &'static str,
        run: Run<'a>,
    }

    fn row<'a>(name: &'static str, run: impl Fn(Option<&mut [f32]>) + 'a) -> Row<'a> {
        Row {
            name,
            run: Box::new(run),
        }
    }

    /// How many of the image's values differ in their bits.
    fn differ(a: &[f32], b: &[f32]) -> usize {
        a.iter()
            .zip(b)
            .filter(|(p, q)| p.to_bits() != q.to_bits())
            .count()
    }

    pub fn run() -> qmckit::Result<()> {
        let rounds: usize = std::env::args()
            .nth(1)
            .and_then(|a| a.parse().ok())
            .unwrap_or(15);
        // An optional second argument keeps only the rows whose names contain it.
        let only = std::env::args().nth(2).unwrap_or_default();
        // PIXEL_PEERS_CPU_TIME=1: time each row by this thread's CPU time instead of the
        // wall clock (time other jobs take on the core is then not counted).
        let cpu_time = std::env::var_os("PIXEL_PEERS_CPU_TIME").is_some_and(|v| v == "1");
        let fo = Randomization::FastOwen;
        let zsobol = ZSobol::new(SIDE, SIDE, SPP, fo, 0)?;
        let padded = PaddedSobol::new(SIDE, SIDE, SPP, fo, 0)?;
        let image = ImageSobol::new(SIDE, SIDE, SPP, fo, 0)?;
        let halton = HaltonSampler::new(SIDE, SIDE, SPP, Randomization::PermuteDigits, 0)?;
        let halton_tables = PreparedHalton::new(halton, 64)?;
        let halton_owen = HaltonSampler::new(SIDE, SIDE, SPP, Randomization::Owen, 0)?;
        let halton_owen_tables = PreparedHalton::new(halton_owen, 64)?;
        let strat = StratifiedSampler::new(SIDE, SIDE, 4, 4, true, 0)?;
        let indep = IndependentPixels::new(SIDE, SIDE, SPP, 0)?;
        let pmj = Pmj02Pixels::new(SIDE, SIDE, SPP, 0)?;
        let tables = Pmj02BnTables::new(SPP, 0)?;
        let pmjbn = tables.sampler(SIDE, SIDE, 0)?;
        let owen = OwenSobol::new(4, 0)?;
        let bn_sobol = BlueNoiseSobol::new(SIDE, SIDE, SPP, 0)?;
        let bn_lattice = BlueNoiseLattice::new(SIDE, SIDE, SPP, 0)?;

        // pbrt's PMJ02BN reads our PMJ02BN sequence and hashed stand-in blue noise. Its
        // constructor buckets the points into pixels after rounding them to `float`; cutting
        // each coordinate to 24 significant bits keeps that rounding inside the cell.
        let float_exact = |v: u32| {
            let drop = (32 - v.leading_zeros()).saturating_sub(24);
            v & !((1u32 << drop) - 1)
        };
        let flat: Vec<u32> = tables
            .sequence()
            .iter()
            .flatten()
            .map(|&v| float_exact(v))
            .collect();
        let noise: Vec<u16> = (0..48 * 128 * 128u64)
            .map(|k| (mix64(k) >> 48) as u16)
            .collect();
        // SAFETY: the buffers hold 65536 pairs and 48 * 128 * 128 values, as the C side reads.
        unsafe {
            peers_set_pmj02bn_table(flat.as_ptr());
            peers_set_blue_noise(noise.as_ptr());
        }

        let mut rows: Vec<Row> = vec![
            row("qmckit ZSobol handle", |o| handle(&zsobol, o)),
            row("qmckit ZSobol prepared", |o| prepared(&zsobol, o)),
            row("pbrt ZSobolSampler", |o| peer(0, o)),
            row("qmckit PaddedSobol handle", |o| handle(&padded, o)),
            row("qmckit PaddedSobol prepared", |o| prepared(&padded, o)),
            row("pbrt PaddedSobolSampler", |o| peer(1, o)),
            row("qmckit ImageSobol handle", |o| handle(&image, o)),
            row("qmckit ImageSobol prepared", |o| prepared(&image, o)),
            row("pbrt SobolSampler", |o| peer(2, o)),
            row("qmckit Pmj02BnPixels handle", |o| handle(&pmjbn, o)),
            row("qmckit Pmj02BnPixels prepared", |o| prepared(&pmjbn, o)),
            row("pbrt PMJ02BNSampler", |o| peer(3, o)),
            row("qmckit Pmj02Pixels handle", |o| handle(&pmj, o)),
            row("qmckit Pmj02Pixels prepared", |o| prepared(&pmj, o)),
            row("qmckit HaltonSampler handle", |o| handle(&halton, o)),
            row("qmckit HaltonSampler prepared", |o| prepared(&halton, o)),
            row("qmckit PreparedHalton prepared", |o| {
                prepared(&halton_tables, o)
            }),
            row("pbrt HaltonSampler", |o| peer(4, o)),
            row("qmckit HaltonSampler Owen prepared", |o| {
                prepared(&halton_owen, o)
            }),
            row("qmckit PreparedHalton Owen prepared", |o| {
                prepared(&halton_owen_tables, o)
            }),
            row("qmckit StratifiedSampler handle", |o| handle(&strat, o)),
            row("qmckit StratifiedSampler prepared", |o| prepared(&strat, o)),
            row("pbrt StratifiedSampler", |o| peer(5, o)),
            row("qmckit IndependentPixels handle", |o| handle(&indep, o)),
            row("qmckit IndependentPixels prepared", |o| prepared(&indep, o)),
            row("pbrt IndependentSampler", |o| peer(6, o)),
            row("qmckit BlueNoiseSobol handle", |o| handle(&bn_sobol, o)),
            row("qmckit BlueNoiseSobol prepared", |o| prepared(&bn_sobol, o)),
            row("qmckit BlueNoiseLattice handle", |o| handle(&bn_lattice, o)),
            row("qmckit BlueNoiseLattice prepared", |o| {
                prepared(&bn_lattice, o)
            }),
            row("qmckit OwenSobol reseeded per pixel", |o| {
                owen_sobol(&owen, o)
            }),
            row("OpenQMC Sobol", |o| peer(10, o)),
            row("OpenQMC SobolBn", |o| peer(11, o)),
            row("OpenQMC Pmj", |o| peer(12, o)),
            row("OpenQMC PmjBn", |o| peer(13, o)),
            row("OpenQMC Lattice", |o| peer(14, o)),
            row("OpenQMC LatticeBn", |o| peer(15, o)),
        ];

        rows.retain(|r| only.split('|').any(|o| r.name.contains(o)));

        // Whole-image agreement: (qmckit row, the row it must equal).
        let pairs = [
            ("qmckit ZSobol handle", "pbrt ZSobolSampler"),
            ("qmckit ZSobol prepared", "pbrt ZSobolSampler"),
            ("qmckit PaddedSobol handle", "pbrt PaddedSobolSampler"),
            ("qmckit PaddedSobol prepared", "pbrt PaddedSobolSampler"),
            ("qmckit ImageSobol handle", "pbrt SobolSampler"),
            ("qmckit ImageSobol prepared", "pbrt SobolSampler"),
            ("qmckit HaltonSampler handle", "pbrt HaltonSampler"),
            ("qmckit HaltonSampler prepared", "pbrt HaltonSampler"),
            ("qmckit PreparedHalton prepared", "pbrt HaltonSampler"),
            (
                "qmckit PreparedHalton Owen prepared",
                "qmckit HaltonSampler Owen prepared",
            ),
            ("qmckit StratifiedSampler handle", "pbrt StratifiedSampler"),
            (
                "qmckit StratifiedSampler prepared",
                "pbrt StratifiedSampler",
            ),
            (
                "qmckit Pmj02BnPixels prepared",
                "qmckit Pmj02BnPixels handle",
            ),
            ("qmckit Pmj02Pixels prepared", "qmckit Pmj02Pixels handle"),
            (
                "qmckit BlueNoiseSobol prepared",
                "qmckit BlueNoiseSobol handle",
            ),
            (
                "qmckit BlueNoiseLattice prepared",
                "qmckit BlueNoiseLattice handle",
            ),
            (
                "qmckit IndependentPixels prepared",
                "qmckit IndependentPixels handle",
            ),
        ];
        let find = |name: &str| rows.iter().find(|r| r.name == name);
        let (mut a, mut b) = (vec![0f32; VALUES], vec![0f32; VALUES]);
        let mut bad = 0;
        println!("whole-image agreement (values whose f32 bits differ, of {VALUES}):");
        for (x, y) in pairs {
            if let (Some(p), Some(q)) = (find(x), find(y)) {
                (p.run)(Some(&mut a));
                (q.run)(Some(&mut b));
                let n = differ(&a, &b);
                bad += n;
                println!("  {x} vs {y}: {n}");
            }
        }

        let mut best = vec![f64::INFINITY; rows.len()];
        for _ in 0..rounds {
            for (r, t) in rows.iter().zip(best.iter_mut()) {
                let (start, cpu) = (Instant::now(), thread_cpu_ns().filter(|_| cpu_time));
                (r.run)(None);
                let spent = match (cpu, thread_cpu_ns()) {
                    (Some(a), Some(b)) => b - a,
                    _ => start.elapsed().as_secs_f64() * 1e9,
                };
                let ns = spent / (SIDE * SIDE * SPP) as f64;
                *t = t.min(ns);
            }
        }
        let clock = if cpu_time && thread_cpu_ns().is_some() {
            "thread CPU time"
        } else {
            "wall clock"
        };
        println!(
            "\nns per 4D sample (two 2D draws), best of {rounds} interleaved rounds, {clock}:"
        );
        println!("| row | ns |\n|---|---|");
        for (r, t) in rows.iter().zip(&best) {
            println!("| {} | {t:.2} |", r.name);
        }
        if bad > 0 {
            eprintln!("{bad} values differ");
            std::process::exit(2);
        }
        Ok(())
    }
}
