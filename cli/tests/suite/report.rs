//! `qmckit report --quick`: every slide's section, every figure it references, and the
//! lecture's numbers beside ours.

use crate::common::cli::run;

/// The slides of issue 18, by section id.
pub const SECTIONS: [&str; 25] = [
    "warping",
    "radical-inverse",
    "van-der-corput",
    "halton",
    "hammersley",
    "permuted-radical-inverse",
    "owen-scrambling",
    "three-point-sets",
    "low-discrepancy-definition",
    "koksma-hlawka",
    "measured-qmc-error",
    "elementary-intervals",
    "mse-tables-n16",
    "quad-light",
    "motion-blur-defocus",
    "zero-two-sequences",
    "pixel-light",
    "ambient-occlusion",
    "blue-noise-dithering",
    "power-spectrum",
    "colours-of-noise",
    "blue-noise-sobol",
    "ld-spectra",
    "variance-spectra",
    "integration-benchmark",
];

#[test]
fn quick_report_has_every_section_and_figure() {
    let dir = std::env::temp_dir().join(format!("qmckit-report-{}", std::process::id()));
    let out = run(&["report", "--quick", "--out", dir.to_str().unwrap()], "");
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let html = std::fs::read_to_string(dir.join("index.html")).unwrap();
    for id in SECTIONS {
        assert!(
            html.contains(&format!("<section id=\"{id}\">")),
            "section {id} missing"
        );
    }
    let mut figures = 0;
    for part in html.split("<img src=\"").skip(1) {
        let file = &part[..part.find('"').unwrap()];
        let bytes = std::fs::read(dir.join(file)).unwrap_or_default();
        assert!(bytes.len() > 200, "figure {file} missing or empty");
        assert!(
            bytes.starts_with(b"<svg") || bytes.starts_with(b"\x89PNG"),
            "{file}"
        );
        figures += 1;
    }
    assert!(figures >= 40, "{figures} figures");
    // Our numbers beside the lecture's: D* of the Larcher-Pillichshammer net of 64 points is
    // 0.0410 by exact computation, the lecture prints 0.041.
    assert!(html.contains(
        "<td>D* Larcher-Pillichshammer</td><td>0.0410</td><td class=\"lecture\">0.041</td>"
    ));
    assert!(
        html.contains("<td>t-value of the first 32 points (t_value_u32, m = 5)</td><td>0</td>")
    );
    // Sentences about measured numbers are computed from them: the variance note counts
    // the rows that agree, with each row's distance in standard errors.
    assert!(
        html.contains("Prediction and measurement agree within 2 standard errors in "),
        "the variance note"
    );
    assert!(html.contains("(|predicted - measured| / standard error: jittered "));
    assert!(html.contains("In all 6 grids, every box holds exactly one point"));
    // Error images carry their colour scale, one for the images compared side by side.
    let scales: Vec<&str> = html
        .split("error, independent: colour scale ±")
        .skip(1)
        .map(|rest| &rest[..rest.find(',').unwrap()])
        .collect();
    assert!(scales.len() >= 6, "{scales:?}");
    assert!(html.contains("the 99th percentile of |error| over the 3 images compared"));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn report_into_an_unwritable_dir_fails_with_one_line() {
    let out = run(&["report", "--quick", "--out", "/proc/qmckit-no"], "");
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(String::from_utf8(out.stderr).unwrap().lines().count(), 1);
}

/// A report killed while it runs (SIGTERM, as a job scheduler or `timeout` sends) leaves
/// nothing behind: no staging directory beside the target, no target, status 130.
#[cfg(unix)]
#[test]
fn a_terminated_report_leaves_no_staging_directory() {
    use std::process::{Command, Stdio};
    use std::time::{Duration, Instant};
    let dir = std::env::temp_dir().join(format!("qmckit-term-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args(["report", "--quick", "--out", "out"])
        .current_dir(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Wait until the staging directory exists (the report is under way), then terminate.
    let start = Instant::now();
    while std::fs::read_dir(&dir).unwrap().next().is_none() {
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no staging directory"
        );
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(300));
    let killed = Command::new("kill")
        .args(["-TERM", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(killed.success());
    let out = child.wait_with_output().unwrap();
    let left: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name())
        .collect();
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(out.status.code(), Some(130), "{out:?}");
    assert!(left.is_empty(), "left behind: {left:?}");
    let err = String::from_utf8(out.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
}
