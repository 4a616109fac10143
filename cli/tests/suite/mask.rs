//! `qmckit mask void-and-cluster`: the library's ranks, and one-line refusals.

use crate::common::cli::{assert_usage_error, run};

#[test]
fn mask_command_writes_the_ranks() {
    let out = run(
        &["mask", "void-and-cluster", "--size", "16x8", "--seed", "2"],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8(out.stdout).unwrap();
    // The header names the kind for 'qmckit plot'.
    assert!(text.starts_with("# qmckit mask 16x8"), "{text}");
    let rows: Vec<Vec<u32>> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(' ').map(|v| v.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 8);
    assert!(rows.iter().all(|r| r.len() == 16));
    let mut all: Vec<u32> = rows.concat();
    all.sort_unstable();
    assert_eq!(all, (0..128).collect::<Vec<u32>>());
    let lib = qmckit::blue_noise::VoidAndCluster::new(16, 8)
        .unwrap()
        .seed(2)
        .generate(&qmckit::work::Budget::DEFAULT)
        .unwrap();
    assert_eq!(rows.concat(), lib.ranks());
}

#[test]
fn mask_images() {
    let out = run(
        &[
            "mask",
            "void-and-cluster",
            "--size",
            "4x2",
            "--format",
            "pgm",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.starts_with(b"P5\n4 2\n65535\n"));
    assert_eq!(out.stdout.len(), b"P5\n4 2\n65535\n".len() + 16);
    let out = run(
        &[
            "mask",
            "void-and-cluster",
            "--size",
            "8x8",
            "--format",
            "png",
        ],
        "",
    );
    assert_eq!(out.status.code(), Some(0));
    assert!(out.stdout.starts_with(b"\x89PNG\r\n\x1a\n"));
}

#[test]
fn mask_usage_errors() {
    let mask = ["mask", "void-and-cluster"];
    for (extra, needle) in [
        (&["--size", "0x4"][..], "mask side"),
        (&["--size", "abc"][..], "not WxH"),
        (&["--size", "5000x5000"][..], "mask side"),
        (&["--size", "64x64", "--sigma", "0"][..], "sigma"),
        (
            &["--size", "1024x1024", "--max-seconds", "0.001"][..],
            "time budget",
        ),
        (&["--size", "8x8", "--max-seconds", "0"][..], "max-seconds"),
    ] {
        let args: Vec<&str> = mask.iter().chain(extra).copied().collect();
        assert_usage_error(&args, "", needle);
    }
}
