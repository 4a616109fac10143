//! Fuzzes what `qmckit plot` decodes and draws: PGM/PNG/text images (`decode_image`), the
//! measurement tables (`parse_blocks`), and the whole command on the same bytes (read from a
//! private file, drawn into a small figure, written atomically to a private output). The
//! decoders must keep their promises (sizes within 2^22 pixels, every value finite, rows as
//! wide as asked) and the command must end in exit code 0 or 2 without a panic or a hang.
//! The first byte picks the figure kind and format.
#![no_main]

use libfuzzer_sys::fuzz_target;
use qmckit_cli::plot::{decode_image, parse_blocks};

const KINDS: [&str; 6] = [
    "auto",
    "points",
    "spectrum",
    "radial",
    "convergence",
    "image",
];

fn scratch(name: &str) -> String {
    let dir = if std::path::Path::new("/dev/shm").is_dir() {
        "/dev/shm".to_owned()
    } else {
        std::env::temp_dir().to_string_lossy().into_owned()
    };
    format!("{dir}/qmckit-fuzz-plot-{}-{name}", std::process::id())
}

fuzz_target!(|data: &[u8]| {
    let Some((&first, rest)) = data.split_first() else {
        return;
    };
    if let Ok((w, h, v)) = decode_image(rest) {
        assert!(w >= 1 && h >= 1 && w * h <= 1 << 22, "{w}x{h}");
        assert_eq!(v.len(), w * h);
        assert!(v.iter().all(|x| x.is_finite()));
    }
    if let Ok(text) = std::str::from_utf8(rest) {
        let min = 1 + (first as usize >> 6);
        if let Ok(blocks) = parse_blocks(text, min) {
            assert!(!blocks.is_empty());
            for b in &blocks {
                assert!(!b.rows.is_empty());
                for r in &b.rows {
                    assert!(r.len() >= min);
                    assert!(r.iter().all(|x| x.is_finite()));
                }
            }
        }
    }
    let kind = KINDS[first as usize % KINDS.len()];
    let ext = if first & 0x20 == 0 { "svg" } else { "png" };
    let input = scratch("in");
    let out = scratch(&format!("out.{ext}"));
    std::fs::write(&input, rest).expect("write the fuzz input");
    let mut args = vec![
        "qmckit".to_owned(),
        "plot".into(),
        "--kind".into(),
        kind.into(),
        "--size".into(),
        "96x80".into(),
        "--out".into(),
        out,
        input,
    ];
    if first & 0x10 != 0 {
        args.extend(["--colours".into(), "diverging".into()]);
    }
    let code = qmckit_cli::run_cli(args);
    assert!(code == 0 || code == 2, "exit code {code}");
});
