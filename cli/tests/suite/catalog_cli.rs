//! The command against `qmckit::catalog`, which it reads: its value lists are the
//! catalog's canonical names, its points are the builders' bits, and every command that
//! takes a sampler, given any catalog name, either answers or refuses in one line.

use crate::common::cli::run;
use qmckit::Sampler;
use qmckit::catalog::{self, PIXEL_SAMPLERS, Params, RANDOMIZERS, SAMPLERS, Size};
use qmckit::digital::sobol::Order;
use qmckit::pixel::PixelSampler;

/// The parameter sets every sampler is walked with: the catalog's examples.
fn cases() -> Vec<(&'static str, Params)> {
    catalog::examples()
        .into_iter()
        .map(|(e, p)| (e.name, p))
        .collect()
}

/// The first `n` points of `s`.
fn fill(s: &dyn Sampler, n: usize) -> Vec<u32> {
    let mut v = vec![0u32; n * s.dims()];
    s.fill(0, &mut v).unwrap();
    v
}

/// The values the command names, from its help text (the `Possible values:` list
/// after `after`).
fn possible_values(args: &[&str], after: &str) -> Vec<String> {
    let out = run(args, "");
    let text = String::from_utf8(out.stdout).unwrap();
    let at = text
        .find(after)
        .unwrap_or_else(|| panic!("{after} in {text}"));
    let rest = &text[at..];
    let list = rest.find("Possible values:").unwrap();
    rest[list..]
        .lines()
        .skip(1)
        .map(str::trim)
        .take_while(|l| l.starts_with("- "))
        .map(|l| l[2..].split(':').next().unwrap().to_owned())
        .collect()
}

#[test]
fn the_command_names_are_canonical_names() {
    let samplers = possible_values(&["points", "--help"], "<SAMPLER>");
    let names: Vec<&str> = SAMPLERS.iter().map(|e| e.name).collect();
    assert_eq!(samplers, names);
    let scrambles = possible_values(&["points", "--help"], "--scramble");
    let names: Vec<&str> = RANDOMIZERS.iter().map(|e| e.name).collect();
    assert_eq!(scrambles, names);
    let pixel = possible_values(&["pixel", "--help"], "<SAMPLER>");
    let names: Vec<&str> = PIXEL_SAMPLERS.iter().map(|e| e.name).collect();
    assert_eq!(pixel, names);
    for name in possible_values(&["discrepancy", "--help"], "--metric") {
        if name != "all" {
            assert_eq!(catalog::measure(&name).unwrap().name, name);
        }
    }
}

/// The command line of a case: `points NAME -n N ...`.
fn command(name: &str, r: &str, p: &Params, n: u64) -> Vec<String> {
    let mut a: Vec<String> = vec![
        "points".into(),
        name.into(),
        "-n".into(),
        n.to_string(),
        "--format".into(),
        "u32".into(),
    ];
    let mut push = |k: &str, v: String| {
        a.push(k.into());
        a.push(v);
    };
    if let Some(d) = p.dims {
        push("-d", d.to_string());
    }
    if let Some(t) = p.points
        && catalog::sampler(name).unwrap().kind.size() != Size::Whole
    {
        push("--total", t.to_string());
    }
    if let Some(b) = p.base {
        push("--base", b.to_string());
    }
    if let Some(s) = &p.strata {
        push(
            "--strata",
            s.iter().map(u32::to_string).collect::<Vec<_>>().join("x"),
        );
    }
    if let Some(k) = p.korobov {
        push("--korobov", k.to_string());
    }
    if p.order == Order::Gray {
        push("--order", "gray".into());
    }
    if let Some(i) = p.blue_noise.iterations {
        push("--iterations", i.to_string());
    }
    if let Some(t) = p.blue_noise.temperature {
        push("--temperature", t.to_string());
    }
    let s = catalog::sampler(name).unwrap();
    let random = (s.kind.is_random() && !p.centered) || r != "none";
    if random {
        push("--seed", p.seed.to_string());
    }
    if r != "none" {
        push("--scramble", r.into());
    }
    if p.centered {
        a.push("--centered".into());
    }
    a
}

#[test]
fn the_builder_gives_the_command_s_bits() {
    let mut refused = Vec::new();
    let mut compared = 0;
    for (name, params) in cases() {
        let s = catalog::sampler(name).unwrap();
        for r in RANDOMIZERS
            .iter()
            .filter(|r| catalog::applies(r, s, params.base).is_ok())
        {
            let p = params.clone().with_seed(777);
            let built = catalog::build(s, r, &p).unwrap();
            // A set built whole is asked for by its size (`-n`); all of it is compared.
            let whole = s.kind.size() == Size::Whole;
            let n = if whole {
                built.len()
            } else {
                built.len().min(200)
            };
            let asked = if whole { p.points.unwrap() } else { n };
            let args = command(name, r.name, &p, asked);
            let argv: Vec<&str> = args.iter().map(String::as_str).collect();
            let out = run(&argv, "");
            if out.status.code() != Some(0) {
                refused.push(format!("{name} {}", r.name));
                continue;
            }
            let text = String::from_utf8(out.stdout).unwrap();
            let got: Vec<u32> = text
                .split_whitespace()
                .map(|t| t.parse().unwrap())
                .collect();
            let want = fill(&*built, n as usize);
            assert_eq!(got, want, "{argv:?}");
            compared += 1;
        }
    }
    // The catalog takes rotate on the blue-noise sets (as `qmckit convergence` does);
    // `qmckit points` writes those sets whole, as built, and refuses --scramble.
    refused.sort();
    assert_eq!(
        refused,
        [
            "best-candidate rotate",
            "gaussian-blue-noise rotate",
            "poisson rotate"
        ]
    );
    assert!(compared >= 60, "{compared}");
}

#[test]
fn the_pixel_builder_gives_the_command_s_values() {
    let params = catalog::PixelParams {
        width: 16,
        height: 9,
        spp: 8,
        seed: 5,
    };
    for entry in PIXEL_SAMPLERS {
        let randomizers: &[Option<&str>] = if entry.kind.takes_randomizer() {
            &[
                None,
                Some("none"),
                Some("xor"),
                Some("fast-owen"),
                Some("owen"),
            ]
        } else {
            &[None]
        };
        let randomizers = randomizers.iter().filter(|r| {
            r.is_none_or(|r| {
                let p = catalog::randomizer(r).unwrap().kind.pixel().unwrap();
                entry.kind.accepts(p)
            })
        });
        for r in randomizers {
            let mut args = vec![
                "pixel",
                entry.name,
                "--resolution",
                "16x9",
                "--spp",
                "8",
                "--seed",
                "5",
                "--pixel",
                "3,5",
                "--dim",
                "2",
                "--format",
                "u32",
            ];
            if let Some(r) = r {
                args.extend(["--randomize", r]);
            }
            let out = run(&args, "");
            assert_eq!(out.status.code(), Some(0), "{args:?}");
            let text = String::from_utf8(out.stdout).unwrap();
            let s =
                catalog::build_pixel(entry, r.map(|r| catalog::randomizer(r).unwrap()), &params)
                    .unwrap();
            for (i, line) in text.lines().filter(|l| !l.starts_with('#')).enumerate() {
                let f: Vec<&str> = line.split(' ').collect();
                let v: Vec<u32> = f[1..].iter().map(|t| t.parse().unwrap()).collect();
                let start = || {
                    s.start_pixel_sample(3, 5, i as u32)
                        .unwrap()
                        .with_dimension(2)
                };
                let [a, b] = start().get_2d();
                assert_eq!(v, [start().get_1d(), a, b], "{args:?}");
            }
        }
    }
}

/// `points lattice --vector FILE` and the catalog on the same vector.
#[test]
fn a_vector_file_gives_the_command_s_lattice() {
    let path = std::env::temp_dir().join(format!("qmckit-catalog-{}.txt", std::process::id()));
    let text = "# lattice\n3 # dims\n64 # n\n1\n19\n27\n";
    std::fs::write(&path, text).unwrap();
    let file = path.to_string_lossy().into_owned();
    let args = [
        "points",
        "lattice",
        "-n",
        "64",
        "-d",
        "3",
        "--vector",
        &file,
        "--scramble",
        "shift-tent",
        "--seed",
        "4",
        "--format",
        "u32",
    ];
    let out = run(&args, "");
    std::fs::remove_file(&path).unwrap();
    assert_eq!(out.status.code(), Some(0), "{args:?}");
    let got: Vec<u32> = String::from_utf8(out.stdout)
        .unwrap()
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .collect();
    let p = Params {
        vector: Some(catalog::GeneratingVector::parse(text, 3).unwrap()),
        ..Params::dims(3).with_seed(4)
    };
    let built = catalog::build_named("lattice", "shift-tent", &p).unwrap();
    assert_eq!(got, fill(&*built, 64));
}

/// A run that answers (exit 0, something on stdout) or refuses in exactly one line
/// naming why (exit 2, nothing on stdout).
fn answers_or_refuses(args: &[&str]) -> bool {
    let out = run(args, "");
    let err = String::from_utf8(out.stderr).unwrap();
    match out.status.code() {
        Some(0) => {
            assert!(!out.stdout.is_empty(), "{args:?}: no output");
            true
        }
        Some(2) => {
            assert_eq!(err.lines().count(), 1, "{args:?}: {err:?}");
            assert!(err.starts_with("qmckit: error: "), "{args:?}: {err:?}");
            assert!(
                err.len() > "qmckit: error: ".len() + 10,
                "{args:?}: {err:?}"
            );
            assert!(!err.contains("panicked"), "{args:?}: {err:?}");
            assert!(out.stdout.is_empty(), "{args:?}");
            false
        }
        other => panic!("{args:?}: exit {other:?}: {err}"),
    }
}

/// The must-show test: every command that takes a sampler, with every catalog sampler
/// name (and `points` with every randomizer, `pixel` with every pixel sampler and
/// randomizer), answers or refuses in one line.
#[test]
fn every_catalog_name_answers_or_is_refused_in_one_line() {
    let mut answered = Vec::new();
    for s in SAMPLERS {
        let name = s.name;
        for r in RANDOMIZERS {
            let mut args = vec!["points", name, "-n", "16"];
            if r.name != "none" {
                args.extend(["--scramble", r.name]);
            }
            if answers_or_refuses(&args) {
                answered.push(format!("points {name} {}", r.name));
            }
        }
        for args in [
            vec!["variance", name, "-n", "16", "--sets", "4"],
            vec!["convergence", name, "--max-m", "4"],
            vec!["tvalue", name, "-m", "4"],
        ] {
            if answers_or_refuses(&args) {
                answered.push(format!("{} {name}", args[0]));
            }
        }
    }
    for p in PIXEL_SAMPLERS {
        for r in std::iter::once("").chain(RANDOMIZERS.iter().map(|r| r.name)) {
            let mut args = vec![
                "pixel",
                p.name,
                "--resolution",
                "4x4",
                "--spp",
                "4",
                "--pixel",
                "1,1",
            ];
            if !r.is_empty() {
                args.extend(["--randomize", r]);
            }
            if answers_or_refuses(&args) {
                answered.push(format!("pixel {} {r}", p.name));
            }
        }
    }
    // What must answer: every sampler unrandomized in points (the sets at their default
    // size), the base-2 randomizers on sobol, the judged samplers in tvalue, the 2D
    // samplers in variance and every pixel sampler with its default.
    for must in [
        "points sobol fast-owen",
        "points sobol lms",
        "points halton owen",
        "points lattice shift-tent",
        "points faure perm",
        "tvalue sobol",
        "tvalue pmj02",
        "tvalue pmj02bn",
        "tvalue faure",
        "variance stratified",
        "variance halton",
        "variance pmj02",
        "convergence sobol",
        "convergence kronecker",
        "pixel zsobol ",
        "pixel pmj02bn ",
        "pixel halton ",
        "pixel halton owen",
        "pixel stratified ",
        "pixel stratified none",
    ] {
        assert!(answered.iter().any(|a| a == must), "{must} did not answer");
    }
    for s in SAMPLERS {
        let want = format!("points {} none", s.name);
        assert!(answered.contains(&want), "{want} did not answer");
    }
}

/// `variance` and `convergence` read one integrand catalog: every integrand name answers
/// or is refused in one line in both; `convergence` integrates every integrand of the
/// catalog in its default dimensions and reports a finite error that falls from N = 1 to
/// N = 256 with Owen-scrambled Sobol' (every integrand here has bounded variation or is
/// smooth, so 256 scrambled points beat one by far), and `variance` takes the torus ones.
#[test]
fn every_catalog_integrand_answers_or_is_refused_in_one_line() {
    for f in catalog::INTEGRANDS {
        let args = [
            "convergence",
            "sobol",
            "--scramble",
            "owen",
            "--seeds",
            "8",
            "--max-m",
            "8",
            "--integrand",
            f.name,
        ];
        assert!(answers_or_refuses(&args), "{args:?} refused");
        let text = String::from_utf8(run(&args, "").stdout).unwrap();
        let rmse: Vec<f64> = text
            .lines()
            .skip(1)
            .map(|l| l.split(' ').nth(1).unwrap().parse().unwrap())
            .collect();
        assert_eq!(rmse.len(), 9, "{text}");
        assert!(rmse.iter().all(|e| e.is_finite() && *e >= 0.0), "{text}");
        assert!(rmse[8] < 0.5 * rmse[0], "{}: {rmse:?}", f.name);
        let torus = answers_or_refuses(&[
            "variance",
            "halton",
            "-n",
            "16",
            "--sets",
            "4",
            "--integrand",
            f.name,
        ]);
        assert_eq!(torus, f.name.starts_with("torus-"), "variance {}", f.name);
    }
}

/// `qmckit points pmj02bn -n 256 | qmckit tvalue -`: PMJ02BN's (0, 2) claim checked from
/// the shell, and a point set that is no net gets its t.
#[test]
fn tvalue_judges_a_point_file() {
    for format in ["decimal", "u32", "csv"] {
        let out = run(&["points", "pmj02bn", "-n", "256", "--format", format], "");
        assert_eq!(out.status.code(), Some(0));
        let text = String::from_utf8(out.stdout).unwrap();
        let judged = run(&["tvalue", "-"], &text);
        assert_eq!(judged.status.code(), Some(0), "{format}");
        let answer = String::from_utf8(judged.stdout).unwrap();
        assert!(
            answer.contains("base 2\nm 8\nd 2\nmethod count\nt 0\n"),
            "{answer}"
        );
    }
    // Sobol' 3D: t of the file is the rank test's t.
    let out = run(&["points", "sobol", "-n", "1024", "-d", "3"], "");
    let file = String::from_utf8(out.stdout).unwrap();
    let from_file = String::from_utf8(run(&["tvalue", "-"], &file).stdout).unwrap();
    let ranked =
        String::from_utf8(run(&["tvalue", "sobol", "-m", "10", "-d", "3"], "").stdout).unwrap();
    let t = |s: &str| s.lines().find(|l| l.starts_with("t ")).unwrap().to_owned();
    assert_eq!(t(&from_file), t(&ranked));
    // Independent points are no (0, 2)-net.
    let out = run(&["points", "independent", "-n", "64", "--seed", "3"], "");
    let answer =
        String::from_utf8(run(&["tvalue", "-"], &String::from_utf8(out.stdout).unwrap()).stdout)
            .unwrap();
    assert!(!answer.contains("\nt 0\n"), "{answer}");
    crate::common::cli::assert_usage_error(
        &["tvalue", "-"],
        "0.5 0.5\n0.1 0.2\n0.3 0.3\n",
        "power of the base",
    );
    crate::common::cli::assert_usage_error(&["tvalue", "latin", "-m", "4"], "", "qmckit tvalue -");
}

/// `plot` reads what the tool writes, or refuses in one line what it cannot draw.
#[test]
fn plot_reads_every_output_or_refuses() {
    let dir = std::env::temp_dir().join(format!("qmckit-plot-kinds-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let svg = dir.join("f.svg");
    let o = svg.to_str().unwrap();
    let output = |args: &[&str], input: &str| {
        let out = run(args, input);
        assert_eq!(out.status.code(), Some(0), "{args:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    // pcf: g(r) against r.
    let pts = output(&["points", "sobol", "-n", "256"], "");
    let pcf = output(&["pcf"], &pts);
    assert_eq!(output(&["plot", "--out", o], &pcf), "");
    assert!(
        std::fs::read_to_string(&svg)
            .unwrap()
            .contains("pair correlation")
    );
    // npy point files.
    let npy = dir.join("p.npy");
    let out = run(&["points", "halton", "-n", "64", "--format", "npy"], "");
    std::fs::write(&npy, &out.stdout).unwrap();
    let out = run(&["plot", "--out", o, npy.to_str().unwrap()], "");
    assert_eq!(out.status.code(), Some(0), "{:?}", out.stderr);
    assert!(std::fs::read_to_string(&svg).unwrap().contains("64 points"));
    // Masks are images, pixel output is refused.
    let mask = output(&["mask", "void-and-cluster", "--size", "8x8"], "");
    let out = run(&["plot", "--out", o], &mask);
    assert_eq!(out.status.code(), Some(0));
    assert!(std::fs::read_to_string(&svg).unwrap().contains("8x8 image"));
    let pixel = output(
        &[
            "pixel",
            "zsobol",
            "--resolution",
            "4x4",
            "--spp",
            "4",
            "--pixel",
            "0,0",
        ],
        "",
    );
    crate::common::cli::assert_usage_error(&["plot", "--out", o], &pixel, "qmckit pixel");
    // The readers skip the header comments.
    let out = run(&["discrepancy", "--metric", "cd"], &mask);
    assert_eq!(out.status.code(), Some(0));
    std::fs::remove_dir_all(&dir).unwrap();
}
