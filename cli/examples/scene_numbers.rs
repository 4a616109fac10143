//! The render studies' MSE tables (`qmckit_cli::scene`), with the lecture's ratios
//! beside ours and the time each study took. `--full` uses `StudyOptions::full()` (the
//! numbers of docs/scenes.md), else `quick()`; `--pgm DIR` also writes the reference, the
//! seed-0 renders and the error images as 8-bit PGM files into DIR for a look.
//!
//! `--seeds N`, `--reference N` and `--spp N` override the options' fields.
//!
//! `cargo run --release -p qmckit-cli --example scene_numbers -- [--full] [--seeds N] [--reference N] [--spp N] [--pgm DIR]`

use std::time::Instant;

use qmckit::work::Budget;
use qmckit_cli::scene::{SceneImage, Study, StudyOptions, cost};

/// The lecture's "MSE 1/r x" ratios, `r` per non-baseline sampler.
fn lecture(s: Study) -> &'static str {
    match s {
        Study::PixelArea => "stratified 1/2.41x, Sobol' 1/3.38x",
        Study::SoftShadow => "stratified 1/2.12x, Sobol' 1/3.95x",
        Study::MotionDefocus => "Halton 1/1.13x, Sobol' 1/1.80x",
        Study::PixelLight => "(figure only)",
        Study::AmbientOcclusion => "(figure only: blue-noise error)",
    }
}

fn write_pgm(path: &std::path::Path, img: &SceneImage, signed: bool) -> std::io::Result<()> {
    let max = img
        .pixels
        .iter()
        .fold(0f64, |m, v| m.max(v.abs()))
        .max(1e-12);
    let mut out = format!("P5\n{} {}\n255\n", img.width, img.height).into_bytes();
    for &v in &img.pixels {
        let g = if signed {
            0.5 + 0.5 * v / max
        } else {
            (v / max).powf(1.0 / 2.2)
        };
        out.push((g.clamp(0.0, 1.0) * 255.0).round() as u8);
    }
    std::fs::write(path, out)
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let full = args.iter().any(|a| a == "--full");
    let pgm = args
        .iter()
        .position(|a| a == "--pgm")
        .and_then(|k| args.get(k + 1))
        .map(std::path::PathBuf::from);
    let flag = |name: &str| -> Option<u32> {
        let k = args.iter().position(|a| a == name)?;
        match args.get(k + 1).and_then(|v| v.parse().ok()) {
            Some(v) => Some(v),
            None => {
                eprintln!("{name} needs a number");
                std::process::exit(2);
            }
        }
    };
    let mut o = if full {
        StudyOptions::full()
    } else {
        StudyOptions::quick()
    };
    o.seeds = flag("--seeds").unwrap_or(o.seeds);
    o.reference_spp = flag("--reference").unwrap_or(o.reference_spp);
    o.spp = flag("--spp").unwrap_or(o.spp);
    println!(
        "{}x{} pixels, n = {}, {} seeds, reference {} spp; estimated {} samples",
        o.width,
        o.height,
        o.spp,
        o.seeds,
        o.reference_spp,
        cost(&o)
    );
    let all = Instant::now();
    for s in Study::ALL {
        let t = Instant::now();
        let st = match s.run(&o, &Budget::UNLIMITED) {
            Ok(st) => st,
            Err(e) => {
                eprintln!("{}: {e}", s.title(o.spp));
                std::process::exit(2);
            }
        };
        println!(
            "\n{} ({:.2} s); lecture: {}",
            st.name,
            t.elapsed().as_secs_f64(),
            lecture(s)
        );
        println!("  sampler        MSE          +-         ratio     low band (norm, abs)");
        for e in &st.mse {
            println!(
                "  {:<13} {:.4e}  {:.2e}  1/{:<6.2}x  {:.3}  {:.3e}",
                e.sampler, e.mse, e.mse_stderr, e.relative, e.low_band, e.low_band_absolute
            );
        }
        if let Some(dir) = &pgm {
            let tag = format!("{s:?}").to_lowercase();
            let _ = std::fs::create_dir_all(dir);
            let _ = write_pgm(
                &dir.join(format!("{tag}_reference.pgm")),
                &st.reference,
                false,
            );
            for ((name, r), (_, e)) in st.renders.iter().zip(&st.errors) {
                let n: String = name.chars().filter(|c| c.is_alphanumeric()).collect();
                let _ = write_pgm(&dir.join(format!("{tag}_{n}.pgm")), r, false);
                let _ = write_pgm(&dir.join(format!("{tag}_{n}_error.pgm")), e, true);
            }
        }
    }
    println!("\nall studies: {:.2} s", all.elapsed().as_secs_f64());
}
