//! Every draw of tests/golden/pbrt_samplers_compiled.txt: pbrt-v4's own `ZSobolSampler`,
//! `PaddedSobolSampler`, `SobolSampler`, `HaltonSampler` and `StratifiedSampler`, compiled from
//! pbrt's headers by tests/golden/pbrt_harness/build.sh (the commit is in the file's header),
//! over whole images (and 9 pixels of a 300 x 200 image, across Halton's 128-pixel period
//! and the Sobol' samplers' 512 x 512 grid): random access (`Get1D`, `Get2D` after a start at each dimension of the
//! header's `starts`, `GetPixel2D` after starts at 0 and 5) and two streams of mixed draws
//! (the header's `pattern-a` from dimension 0, `pattern-b` from dimension 1). The f32 bit
//! patterns are compared one by one; the test counts them, so a short line cannot pass.

use qmckit::pixel::{
    HALTON_PIXEL_DIMS, HaltonSampler, IMAGE_SOBOL_DIMS, ImageSobol, PBRT_SOBOL_DIMS, PaddedSobol,
    PixelSampler, PreparedHalton, Randomization, StratifiedSampler, ZSobol,
};

fn randomization(name: &str) -> Randomization {
    match name {
        "none" => Randomization::None,
        "permutedigits" => Randomization::PermuteDigits,
        "fastowen" => Randomization::FastOwen,
        "owen" => Randomization::Owen,
        _ => panic!("unknown randomization {name}"),
    }
}

/// The samplers a `config` line describes: `config ID SAMPLER RANDOMIZATION W H SPP SEED [XS
/// YS]` (Halton's with and without its tables).
fn build(words: &[&str]) -> Vec<Box<dyn PixelSampler>> {
    let num = |k: usize| -> u32 {
        words[k]
            .parse()
            .unwrap_or_else(|e| panic!("{words:?}: {e}"))
    };
    let (w, h, spp, seed) = (num(4), num(5), num(6), u64::from(num(7)));
    let r = words[3];
    if words[2] == "halton" {
        let s = HaltonSampler::new(w, h, spp, randomization(r), seed).unwrap();
        let p = PreparedHalton::new(s, HALTON_PIXEL_DIMS).unwrap();
        return vec![Box::new(s), Box::new(p)];
    }
    vec![match words[2] {
        "zsobol" => Box::new(ZSobol::new(w, h, spp, randomization(r), seed).unwrap()),
        "padded-sobol" => Box::new(PaddedSobol::new(w, h, spp, randomization(r), seed).unwrap()),
        "image-sobol" => Box::new(ImageSobol::new(w, h, spp, randomization(r), seed).unwrap()),
        "stratified" => {
            let (xs, ys) = (num(8), num(9));
            assert_eq!(xs * ys, spp);
            Box::new(StratifiedSampler::new(w, h, xs, ys, r == "jitter", seed).unwrap())
        }
        s => panic!("unknown sampler {s}"),
    }]
}

/// One sample's draws in the driver's order, as f32 bit patterns.
fn draws(
    s: &dyn PixelSampler,
    x: u32,
    y: u32,
    i: u32,
    starts: &[usize],
    a: &str,
    b: &str,
) -> Vec<u32> {
    let start = |d: usize| {
        PixelSampler::start_pixel_sample(&s, x, y, i)
            .unwrap_or_else(|e| panic!("start ({x}, {y}) {i}: {e}"))
            .with_dimension(d)
    };
    let mut out = Vec::new();
    for &d in starts {
        out.push(start(d).get_1d_f32().to_bits());
        out.extend(start(d).get_2d_f32().map(f32::to_bits));
    }
    for d in [0, 5] {
        out.extend(start(d).get_pixel_2d_f32().map(f32::to_bits));
    }
    for (d, pattern) in [(0, a), (1, b)] {
        let mut h = start(d);
        for c in pattern.chars() {
            match c {
                '1' => out.push(h.get_1d_f32().to_bits()),
                '2' => out.extend(h.get_2d_f32().map(f32::to_bits)),
                'p' => out.extend(h.get_pixel_2d_f32().map(f32::to_bits)),
                _ => panic!("unknown draw {c}"),
            }
        }
    }
    out
}

#[test]
fn every_draw_equals_compiled_pbrt() {
    let path = format!(
        "{}/tests/golden/pbrt_samplers_compiled.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let header = |key: &str| -> &str {
        text.lines()
            .find_map(|l| l.strip_prefix(key))
            .unwrap_or_else(|| panic!("no {key} in {path}"))
            .trim()
    };
    let starts: Vec<usize> = header("# starts ")
        .split_whitespace()
        .map(|w| w.parse().unwrap())
        .collect();
    let (a, b) = (header("# pattern-a "), header("# pattern-b "));
    let mut configs = std::collections::HashMap::new();
    let mut names = std::collections::HashMap::new();
    let mut covered = std::collections::HashMap::<String, (u64, u64)>::new();
    let (mut checked, mut mismatches) = (0u64, Vec::new());
    for line in text.lines().filter(|l| !l.starts_with('#')) {
        let words: Vec<&str> = line.split_whitespace().collect();
        if words[0] == "config" {
            configs.insert(words[1].to_string(), build(&words));
            names.insert(words[1].to_string(), words[2..].join(" "));
            continue;
        }
        let n = |k: usize| -> u32 { words[k].parse().unwrap() };
        let (x, y, i) = (n(1), n(2), n(3));
        let want: Vec<u32> = words[4..]
            .iter()
            .map(|w| u32::from_str_radix(w, 16).unwrap())
            .collect();
        for s in &configs[words[0]] {
            let got = draws(s.as_ref(), x, y, i, &starts, a, b);
            assert_eq!(got.len(), want.len(), "{line}: draw count");
            // Without the `sobol-dims-1024` feature ImageSobol wraps at its shorter table: the
            // random access past it is not pbrt's (the streams stay below dimension 16).
            let short =
                names[words[0]].starts_with("image-sobol") && IMAGE_SOBOL_DIMS < PBRT_SOBOL_DIMS;
            for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                if short && k < 3 * starts.len() && starts[k / 3] + 2 > IMAGE_SOBOL_DIMS {
                    continue;
                }
                checked += 1;
                if g != w {
                    mismatches.push(format!(
                        "{} ({x}, {y}) i={i} draw {k}: ours {g:08x} ({}), pbrt {w:08x} ({})",
                        names[words[0]],
                        f32::from_bits(*g),
                        f32::from_bits(*w)
                    ));
                }
            }
        }
        let c = covered.entry(names[words[0]].clone()).or_default();
        c.0 += 1;
        c.1 += want.len() as u64;
    }
    // Every pixel sample of every image is in the file (of the sparse ones, 9 pixels).
    for (id, words) in &names {
        if words.ends_with("sparse") {
            let spp: u64 = words.split_whitespace().nth(4).unwrap().parse().unwrap();
            assert_eq!(covered[words].0, 9 * spp, "{id} {words}: pixel samples");
            continue;
        }
        let w: Vec<u64> = words
            .split_whitespace()
            .skip(2)
            .take(3)
            .map(|v| v.parse().unwrap())
            .collect();
        assert_eq!(
            covered[words].0,
            w[0] * w[1] * w[2],
            "{id} {words}: pixel samples"
        );
    }
    assert!(checked > 40_000, "only {checked} draws");
    assert!(
        mismatches.is_empty(),
        "{} of {checked} draws differ, first: {:#?}",
        mismatches.len(),
        &mismatches[..mismatches.len().min(20)]
    );
}
