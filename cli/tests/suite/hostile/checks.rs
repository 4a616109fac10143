//! What the hostile cases share: their inputs (point files, npy headers that lie), the
//! setups that put files in the way, and the checks of a run (a figure written whole, the
//! user's file kept, values echoed, tables well formed). Every check is a property; none
//! compares with qmckit's own earlier output.

use std::path::Path;

use super::runner::{Run, finite_text, well_formed_xml};

/// Bound of a run under `--max-seconds B`: 1.5 B, plus a second for starting, reading the
/// input and writing the output.
pub(super) fn budget(b: f64) -> f64 {
    1.5 * b + 1.0
}

/// Bound of an unbounded read's refusal.
pub(super) const READ_REFUSAL: f64 = 1.0;

/// Bound of a figure of a few numbers (the hangs drew forever).
pub(super) const SMALL_FIGURE: f64 = 5.0;

// ---------------------------------------------------------------------------------------
// Inputs.

/// A `.npy` file: `descr` (e.g. `<f8`), the shape as Python writes it, then `data`.
pub(super) fn npy(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
    let mut header = format!("{{'descr': '{descr}', 'fortran_order': False, 'shape': {shape}, }}");
    while (10 + header.len() + 1) % 64 != 0 {
        header.push(' ');
    }
    header.push('\n');
    let mut out = b"\x93NUMPY\x01\x00".to_vec();
    out.extend_from_slice(&(header.len() as u16).to_le_bytes());
    out.extend_from_slice(header.as_bytes());
    out.extend_from_slice(data);
    out
}

/// 20 data bytes under a header that claims 2^32 - 1 float64 values (one dimension).
pub(super) fn npy_claims_4g() -> Vec<u8> {
    npy("<f8", "(4294967295,)", &[0; 20])
}

/// 20 data bytes under a header that claims (2^32 - 1) x 2 values.
pub(super) fn npy_claims_4g_2d() -> Vec<u8> {
    npy("<f8", "(4294967295, 2)", &[0; 20])
}

/// `n` points in `d` dimensions in [0, 1), text, from a fixed 64-bit generator
/// (SplitMix64): no dependence on qmckit.
pub(super) fn random_points(n: usize, d: usize, seed: u64) -> String {
    let mut state = seed;
    let mut next = move || {
        state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = state;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        (z ^ (z >> 31)) >> 11
    };
    let mut text = String::with_capacity(n * d * 20);
    for _ in 0..n {
        for k in 0..d {
            if k > 0 {
                text.push(' ');
            }
            text.push_str(&format!("{:.17}", next() as f64 / (1u64 << 53) as f64));
        }
        text.push('\n');
    }
    text
}

/// A small 2D point set for the commands that read points.
pub(super) fn few_points() -> String {
    random_points(64, 2, 1)
}

// ---------------------------------------------------------------------------------------
// Setups.

/// A 2 GiB sparse file `sparse` (reads as NUL bytes).
pub(super) fn sparse_2g(dir: &Path) {
    let f = std::fs::File::create(dir.join("sparse")).unwrap();
    f.set_len(2 << 30).unwrap();
}

/// The npy whose header claims 2^32 - 1 values, as `big.npy`.
pub(super) fn big_npy_file(dir: &Path) {
    std::fs::write(dir.join("big.npy"), npy_claims_4g_2d()).unwrap();
}

/// A user's report directory `site` holding their own `index.html`.
pub(super) fn user_site(dir: &Path) {
    std::fs::create_dir_all(dir.join("site")).unwrap();
    std::fs::write(dir.join("site/index.html"), USER_PAGE).unwrap();
}

pub(super) const USER_PAGE: &str = "<html><body>my own page</body></html>\n";

/// An earlier figure `ro/fig.svg` in a directory nobody but root may write (the run is
/// unprivileged when the suite runs as root), and a points file.
pub(super) fn read_only_figure(dir: &Path) {
    earlier_figure(dir, "ro");
    set_mode(&dir.join("ro"), 0o555);
}

/// An earlier figure `DIR/fig.svg`, the input `pts.txt`, and world-writable `dir` (so an
/// unprivileged run may work in it).
pub(super) fn earlier_figure(dir: &Path, sub: &str) {
    std::fs::create_dir_all(dir.join(sub)).unwrap();
    std::fs::write(dir.join(sub).join("fig.svg"), EARLIER_FIGURE).unwrap();
    std::fs::write(dir.join("pts.txt"), few_points()).unwrap();
    set_mode(dir, 0o777);
}

pub(super) const EARLIER_FIGURE: &str = "<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>\n";

pub(super) fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// An earlier figure `fig.svg` beside the input.
pub(super) fn figure_beside(dir: &Path) {
    earlier_figure(dir, ".");
}

/// A generating-vector file of 2 GiB (sparse) and one of a single huge component.
pub(super) fn lattice_files(dir: &Path) {
    sparse_2g(dir);
    std::fs::write(
        dir.join("huge.lattice"),
        "# lattice\n18446744073709551615\n18446744073709551615\n1\n",
    )
    .unwrap();
}

// ---------------------------------------------------------------------------------------
// Checks.

/// The files of `dir` (names), sorted.
pub(super) fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .map(|r| {
            r.filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .collect()
        })
        .unwrap_or_default();
    v.sort();
    v
}

/// `out.svg` exists when the run answered, and is well-formed; nothing else appeared.
pub(super) fn svg_written(run: &Run) -> Result<(), String> {
    let path = run.dir.join("out.svg");
    if run.code != 0 {
        return if path.exists() {
            Err("a refused plot left out.svg".into())
        } else {
            no_temporaries(&run.dir)
        };
    }
    let text = std::fs::read_to_string(&path).map_err(|e| format!("out.svg: {e}"))?;
    well_formed_xml(&text).map_err(|e| format!("out.svg is not well-formed XML: {e}"))?;
    if text.contains("NaN") || text.contains("inf\"") {
        return Err("out.svg holds NaN or inf coordinates".into());
    }
    no_temporaries(&run.dir)
}

/// `out.png` exists and is a PNG when the run answered.
pub(super) fn png_written(run: &Run) -> Result<(), String> {
    let path = run.dir.join("out.png");
    if run.code == 0 {
        let bytes = std::fs::read(&path).map_err(|e| format!("out.png: {e}"))?;
        if !bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
            return Err("out.png is not a PNG".into());
        }
    } else if path.exists() {
        return Err("a refused plot left out.png".into());
    }
    no_temporaries(&run.dir)
}

/// No file of `dir` (or of its subdirectories one level down) looks like a leftover
/// temporary.
pub(super) fn no_temporaries(dir: &Path) -> Result<(), String> {
    let mut all = names(dir);
    for sub in names(dir) {
        all.extend(names(&dir.join(&sub)));
    }
    match all.iter().find(|n| n.contains("tmp") || n.starts_with(".")) {
        Some(n) => Err(format!("a temporary file {n:?} was left behind")),
        None => Ok(()),
    }
}

/// The earlier figure `SUB/fig.svg` is as it was, and no temporary was left.
pub(super) fn earlier_figure_kept(run: &Run, sub: &str) -> Result<(), String> {
    let text = std::fs::read_to_string(run.dir.join(sub).join("fig.svg"))
        .map_err(|e| format!("the earlier figure is gone: {e}"))?;
    if text != EARLIER_FIGURE {
        return Err("the earlier figure was changed by a failing plot".into());
    }
    no_temporaries(&run.dir)
}

pub(super) fn read_only_figure_kept(run: &Run) -> Result<(), String> {
    earlier_figure_kept(run, "ro")
}

pub(super) fn figure_kept(run: &Run) -> Result<(), String> {
    earlier_figure_kept(run, ".")
}

/// The user's `site/index.html` is as they wrote it, and nothing else was put in `site`.
pub(super) fn user_site_kept(run: &Run) -> Result<(), String> {
    let site = run.dir.join("site");
    let page = std::fs::read_to_string(site.join("index.html"))
        .map_err(|e| format!("the user's index.html is gone: {e}"))?;
    if page != USER_PAGE {
        return Err("the user's index.html was overwritten".into());
    }
    if names(&site) != ["index.html"] {
        return Err(format!("the user's directory now holds {:?}", names(&site)));
    }
    Ok(())
}

/// The `key value` lines of an answer.
pub(super) fn keyed(run: &Run) -> Vec<(String, String)> {
    String::from_utf8_lossy(&run.stdout)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(k, v)| (k.to_owned(), v.trim().to_owned()))
        .collect()
}

/// An answer's `key` line holds `want` (as a number), or the run refused.
pub(super) fn echoes(run: &Run, key: &str, want: f64) -> Result<(), String> {
    if run.code != 0 {
        return Ok(());
    }
    let lines = keyed(run);
    let Some((_, v)) = lines.iter().find(|(k, _)| k == key) else {
        return Err(format!("no '{key}' line in the answer"));
    };
    match v.parse::<f64>() {
        Ok(x) if x == want => Ok(()),
        _ => Err(format!(
            "'{key} {v}': the request was {want:e}, silently changed"
        )),
    }
}

pub(super) fn radius_honoured(run: &Run) -> Result<(), String> {
    echoes(run, "parameter", 1e-200)
}

pub(super) fn k_max_honoured(run: &Run) -> Result<(), String> {
    echoes(run, "k_max", 0.0)?;
    if run.code == 0 {
        // With no frequency but 0 kept, the whole Parseval sum is the tail.
        let lines = keyed(run);
        let get = |key: &str| {
            lines
                .iter()
                .find(|(k, _)| k == key)
                .and_then(|(_, v)| v.parse::<f64>().ok())
        };
        if let (Some(p), Some(t)) = (get("predicted"), get("tail"))
            && (p - t).abs() > 1e-12 * p.abs()
        {
            return Err(format!("k_max 0 but predicted {p} != tail {t}"));
        }
    }
    Ok(())
}

/// A `pcf --sigma S` answer: `radius g` rows, every g finite and non-negative.
pub(super) fn pcf_rows(run: &Run) -> Result<(), String> {
    if run.code != 0 {
        return Ok(());
    }
    let text = String::from_utf8_lossy(&run.stdout);
    let rows: Vec<&str> = text.lines().filter(|l| !l.starts_with('#')).collect();
    if rows.is_empty() {
        return Err("no rows".into());
    }
    for r in rows {
        let g: f64 = r
            .split_whitespace()
            .nth(1)
            .and_then(|v| v.parse().ok())
            .ok_or(format!("row {r:?}"))?;
        if !(g >= 0.0 && g.is_finite()) {
            return Err(format!("row {r:?}: g = {g}"));
        }
    }
    Ok(())
}

/// A convergence table: a `# n rmse` header and rows `N RMSE` with N = 1, 2, 4, ... (or
/// growing for stratified), RMSE finite and non-negative.
pub(super) fn convergence_table(run: &Run) -> Result<(), String> {
    let text = String::from_utf8_lossy(&run.stdout);
    if !text.lines().any(|l| l.starts_with("# n rmse")) {
        return Err("no '# n rmse' header".into());
    }
    let rows: Vec<(f64, f64)> = text
        .lines()
        .filter(|l| !l.starts_with('#') && !l.trim().is_empty())
        .map(|l| {
            let mut it = l.split_whitespace().map(|v| v.parse::<f64>());
            match (it.next(), it.next()) {
                (Some(Ok(n)), Some(Ok(e))) => Ok((n, e)),
                _ => Err(format!("row {l:?}")),
            }
        })
        .collect::<Result<_, _>>()?;
    if rows.len() < 2 {
        return Err(format!("{} rows", rows.len()));
    }
    for w in rows.windows(2) {
        if w[1].0 <= w[0].0 {
            return Err(format!("N does not grow: {:?}", w));
        }
    }
    if let Some(r) = rows.iter().find(|r| !(r.1 >= 0.0 && r.1.is_finite())) {
        return Err(format!("rmse {r:?}"));
    }
    Ok(())
}

/// Runs `qmckit ARGS` plainly (no limit) for a comparison; its stdout.
pub(super) fn qmckit(args: &[&str]) -> Result<String, String> {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_qmckit"))
        .args(args)
        .output()
        .map_err(|e| e.to_string())?;
    if !out.status.success() {
        return Err(format!(
            "{args:?}: {}",
            String::from_utf8_lossy(&out.stderr).trim()
        ));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// Columns 2.. (the values, without the global index) of `pixel` output lines.
pub(super) fn values(text: &str, from: usize) -> Vec<String> {
    // The '# qmckit pixel' header names the run, not its values.
    text.lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| {
            l.split_whitespace()
                .skip(from)
                .collect::<Vec<_>>()
                .join(" ")
        })
        .collect()
}

/// pbrt-v4's SobolSampler pads past its dimensions by restarting at dimension 2: Get1D and
/// Get2D at a counter D past the table read dimension 2 (and 2, 3). So the values at
/// D = 4294967295 are those at D = 2, and the 2D value at the last dimension (D + 1 past
/// the table) is the 2D value at D = 2.
pub(super) fn sobol_pads_like_pbrt(run: &Run) -> Result<(), String> {
    let base = [
        "pixel",
        "sobol",
        "--resolution",
        "16x16",
        "--spp",
        "8",
        "--pixel",
        "3,5",
    ];
    let at = |d: &str| qmckit(&[&base[..], &["--dim", d]].concat());
    let past = String::from_utf8_lossy(&run.stdout).into_owned();
    let two = at("2")?;
    if values(&past, 1) != values(&two, 1) {
        return Err(format!(
            "dimension 4294967295 is not padded to dimension 2:\n{past}\nvs\n{two}"
        ));
    }
    let last = at("21200")?;
    if values(&last, 2) != values(&two, 2) {
        return Err(format!(
            "the 2D value at the last dimension is not padded to dimensions 2, 3:\n{last}\nvs\n{two}"
        ));
    }
    Ok(())
}

/// As many lines as samples per pixel (8).
pub(super) fn eight_lines(run: &Run) -> Result<(), String> {
    let n = String::from_utf8_lossy(&run.stdout)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .count();
    if run.code == 0 && n != 8 {
        return Err(format!("{n} lines for 8 samples"));
    }
    Ok(())
}

/// A mask's text: every row the same length.
pub(super) fn rectangular(run: &Run) -> Result<(), String> {
    if run.code != 0 || run.truncated {
        return Ok(());
    }
    let text = String::from_utf8_lossy(&run.stdout);
    let widths: Vec<usize> = text
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split_whitespace().count())
        .collect();
    if widths.windows(2).any(|w| w[0] != w[1]) {
        return Err("ragged mask rows".into());
    }
    finite_text(&text)
}
