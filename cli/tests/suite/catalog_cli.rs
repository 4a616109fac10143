//! The catalog against the `qmckit` command while the command is in this package: the
//! command's names are the canonical names, and the builders give the command's bits.

use super::{cases, fill};
use crate::common::cli::run;
use qmckit::Sampler;
use qmckit::catalog::{self, PIXEL_SAMPLERS, Params, RANDOMIZERS, SAMPLERS, Size};
use qmckit::digital::sobol::Order;
use qmckit::pixel::PixelSampler;

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
    // The pixel command's `sobol` is image-sobol's alias.
    for name in possible_values(&["pixel", "--help"], "<SAMPLER>") {
        catalog::pixel_sampler(&name).unwrap();
    }
    for name in possible_values(&["discrepancy", "--help"], "--metric") {
        if name != "all" {
            assert_eq!(catalog::measure(&name).unwrap().name, name);
        }
    }
}

/// The command line of a case: `points NAME -n N ...`.
fn command(name: &str, r: &str, p: &Params, n: u64) -> Vec<String> {
    let mut a: Vec<String> = vec!["points".into(), name.into(), "-n".into(), n.to_string()];
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
    // The catalog takes rotate on faure (the rotation applies to any sampler) and on
    // the blue-noise sets (as `qmckit convergence` does); `qmckit points` refuses them.
    refused.sort();
    assert_eq!(
        refused,
        [
            "best-candidate rotate",
            "faure rotate",
            "faure rotate",
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
        for r in randomizers {
            let cli_name = if entry.name == "image-sobol" {
                "sobol"
            } else {
                entry.name
            };
            let mut args = vec![
                "pixel",
                cli_name,
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
            for (i, line) in text.lines().enumerate() {
                let f: Vec<&str> = line.split(' ').collect();
                let v: Vec<u32> = f[1..].iter().map(|t| t.parse().unwrap()).collect();
                let start = || s.start_pixel_sample(3, 5, i as u32).unwrap().with_dimension(2);
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
