//! `qmckit pixel`: the samples of one pixel from the pbrt-v4 pixel samplers, and one-line
//! refusals.

use crate::common::cli::{assert_usage_error, run};

/// The sample lines (after the '# qmckit pixel' header, which names the kind).
fn lines(args: &[&str]) -> Vec<String> {
    let out = run(args, "");
    assert_eq!(out.status.code(), Some(0), "{args:?}: {:?}", out.stderr);
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(text.starts_with("# qmckit pixel "), "{text}");
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(str::to_string)
        .collect()
}

/// pbrt's check values through the command (16x9, seed 0, FastOwen).
#[test]
fn pixel_prints_pbrt_values() {
    let base = ["pixel", "zsobol", "--resolution", "16x9", "--pixel", "1,0"];
    let one = lines(&[&base[..], &["--spp", "1", "--format", "csv"]].concat());
    assert_eq!(one, ["1,0.57022893,0.7021838,0.8538905"]);
    let four = lines(&[&base[..], &["--spp", "4", "--format", "csv"]].concat());
    assert_eq!(four.len(), 4);
    assert!(four[3].starts_with("4,0.33697805,"), "{four:?}");
    let padded = lines(&[
        "pixel",
        "padded-sobol",
        "--resolution",
        "16x16",
        "--spp",
        "16",
        "--pixel",
        "3,5",
        "--randomize",
        "none",
        "--format",
        "csv",
    ]);
    assert_eq!(padded[0], "-,0.5625,0.5625,0.4375");
    let ind = lines(&[
        "pixel",
        "independent",
        "--resolution",
        "4x4",
        "--spp",
        "3",
        "--pixel",
        "0,0",
    ]);
    assert_eq!(ind.len(), 3);
    assert!(
        ind.iter()
            .all(|l| l.starts_with("- ") && l.split(' ').count() == 4)
    );
    let pmj = lines(&[
        "pixel",
        "pmj02",
        "--resolution",
        "4x4",
        "--spp",
        "8",
        "--pixel",
        "1,2",
    ]);
    assert_eq!(pmj.len(), 8);
    let sobol = lines(&[
        "pixel",
        "sobol",
        "--resolution",
        "16x9",
        "--spp",
        "2",
        "--pixel",
        "3,5",
    ]);
    let idx: Vec<u64> = sobol
        .iter()
        .map(|l| l.split(' ').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(idx.iter().map(|i| i >> 8).collect::<Vec<_>>(), [0, 1]);
}

#[test]
fn pixel_refuses_bad_input() {
    let z = ["pixel", "zsobol", "--pixel", "1,0"];
    assert_usage_error(
        &[&z[..], &["--resolution", "16x9", "--spp", "3"]].concat(),
        "",
        "--spp 3",
    );
    assert_usage_error(
        &[&z[..], &["--resolution", "16y9", "--spp", "4"]].concat(),
        "",
        "--resolution",
    );
    assert_usage_error(
        &[&z[..], &["--resolution", "0x9", "--spp", "4"]].concat(),
        "",
        "at least 1",
    );
    assert_usage_error(
        &[
            "pixel",
            "zsobol",
            "--resolution",
            "16x9",
            "--spp",
            "4",
            "--pixel",
            "16,0",
        ],
        "",
        "outside the image",
    );
    assert_usage_error(
        &[
            "pixel",
            "zsobol",
            "--resolution",
            "16x9",
            "--spp",
            "4",
            "--pixel=-1,0",
        ],
        "",
        "--pixel",
    );
    assert_usage_error(
        &[
            "pixel",
            "sobol",
            "--resolution",
            "65536x1",
            "--spp",
            "4",
            "--pixel",
            "0,0",
        ],
        "",
        "too many",
    );
    assert_usage_error(
        &[
            "pixel",
            "independent",
            "--resolution",
            "4x4",
            "--spp",
            "4",
            "--pixel",
            "0,0",
            "--randomize",
            "owen",
        ],
        "",
        "--randomize",
    );
}

/// `qmckit pixel halton|stratified --format csv` prints pbrt-v4's own floats: the values at
/// dimension 5 (random access, the 1D and the 2D draw) of compiled pbrt's goldens
/// (tests/golden/pbrt_samplers_compiled.txt, 4x3 image, 4 samples, seed 0), bit for bit.
#[test]
fn halton_and_stratified_print_compiled_pbrt_floats() {
    let path = format!(
        "{}/../tests/golden/pbrt_samplers_compiled.txt",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap();
    // Random access comes first: starts 0, 1, 2, 5, ...; three values each.
    let starts: Vec<&str> = text
        .lines()
        .find_map(|l| l.strip_prefix("# starts "))
        .unwrap()
        .split(' ')
        .collect();
    let at = 3 * starts.iter().position(|&d| d == "5").unwrap();
    for (config, golden, randomize) in [
        ("halton permutedigits 4 3 4 0", "halton", None),
        ("halton owen 4 3 4 0", "halton", Some("owen")),
        ("stratified jitter 4 3 4 0 2 2", "stratified", None),
        ("stratified none 4 3 4 0 2 2", "stratified", Some("none")),
    ] {
        let id = text
            .lines()
            .find_map(|l| l.strip_prefix("config ")?.strip_suffix(config))
            .unwrap_or_else(|| panic!("no {config}"))
            .trim()
            .to_string();
        let mut args = vec![
            "pixel",
            golden,
            "--resolution",
            "4x3",
            "--spp",
            "4",
            "--pixel",
            "2,1",
            "--dim",
            "5",
            "--format",
            "csv",
        ];
        if let Some(r) = randomize {
            args.extend(["--randomize", r]);
        }
        let got = lines(&args);
        assert_eq!(got.len(), 4);
        for (i, line) in got.iter().enumerate() {
            let prefix = format!("{id} 2 1 {i} ");
            let want: Vec<u32> = text
                .lines()
                .find_map(|l| l.strip_prefix(&prefix))
                .unwrap()
                .split(' ')
                .skip(at)
                .take(3)
                .map(|w| u32::from_str_radix(w, 16).unwrap())
                .collect();
            let ours: Vec<u32> = line
                .split(',')
                .skip(1)
                .map(|v| v.parse::<f32>().unwrap().to_bits())
                .collect();
            assert_eq!(ours, want, "{config} i={i}: {line}");
        }
    }
    assert_usage_error(
        &[
            "pixel",
            "halton",
            "--resolution",
            "4x3",
            "--spp",
            "4",
            "--pixel",
            "0,0",
            "--randomize",
            "fast-owen",
        ],
        "",
        "fast-owen does not apply to halton",
    );
}
