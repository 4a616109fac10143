//! The hostile cases, as data: `name => Case::new(ARGS, EXPECT)` with input, environment,
//! bound, setup and check. Each becomes its own `#[test]`; the shared runner is
//! [`super::runner::run_case`]. No expected value here is copied from qmckit's output:
//! checks are properties (finite values, well-formed SVG, a file left as the user wrote it,
//! an option echoed as given, padding equal to an earlier dimension as pbrt-v4 defines it).

use std::path::Path;

use super::runner::{Case, Expect, Input, Run, finite_text, run_case, well_formed_xml};

use Expect::{Answer, AnswerOrRefuse, Fail, Refuse};

/// Bound of a run under `--max-seconds B`: 1.5 B, plus a second for starting, reading the
/// input and writing the output.
fn budget(b: f64) -> f64 {
    1.5 * b + 1.0
}

/// Bound of an unbounded read's refusal.
const READ_REFUSAL: f64 = 1.0;

/// Bound of a figure of a few numbers (the hangs drew forever).
const SMALL_FIGURE: f64 = 5.0;

// ---------------------------------------------------------------------------------------
// Inputs.

/// A `.npy` file: `descr` (e.g. `<f8`), the shape as Python writes it, then `data`.
fn npy(descr: &str, shape: &str, data: &[u8]) -> Vec<u8> {
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
fn npy_claims_4g() -> Vec<u8> {
    npy("<f8", "(4294967295,)", &[0; 20])
}

/// 20 data bytes under a header that claims (2^32 - 1) x 2 values.
fn npy_claims_4g_2d() -> Vec<u8> {
    npy("<f8", "(4294967295, 2)", &[0; 20])
}

/// `n` points in `d` dimensions in [0, 1), text, from a fixed 64-bit generator
/// (SplitMix64): no dependence on qmckit.
fn random_points(n: usize, d: usize, seed: u64) -> String {
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
fn few_points() -> String {
    random_points(64, 2, 1)
}

// ---------------------------------------------------------------------------------------
// Setups.

/// A 2 GiB sparse file `sparse` (reads as NUL bytes).
fn sparse_2g(dir: &Path) {
    let f = std::fs::File::create(dir.join("sparse")).unwrap();
    f.set_len(2 << 30).unwrap();
}

/// The npy whose header claims 2^32 - 1 values, as `big.npy`.
fn big_npy_file(dir: &Path) {
    std::fs::write(dir.join("big.npy"), npy_claims_4g_2d()).unwrap();
}

/// A user's report directory `site` holding their own `index.html`.
fn user_site(dir: &Path) {
    std::fs::create_dir_all(dir.join("site")).unwrap();
    std::fs::write(dir.join("site/index.html"), USER_PAGE).unwrap();
}

const USER_PAGE: &str = "<html><body>my own page</body></html>\n";

/// An earlier figure `ro/fig.svg` in a directory nobody but root may write (the run is
/// unprivileged when the suite runs as root), and a points file.
fn read_only_figure(dir: &Path) {
    earlier_figure(dir, "ro");
    set_mode(&dir.join("ro"), 0o555);
}

/// An earlier figure `DIR/fig.svg`, the input `pts.txt`, and world-writable `dir` (so an
/// unprivileged run may work in it).
fn earlier_figure(dir: &Path, sub: &str) {
    std::fs::create_dir_all(dir.join(sub)).unwrap();
    std::fs::write(dir.join(sub).join("fig.svg"), EARLIER_FIGURE).unwrap();
    std::fs::write(dir.join("pts.txt"), few_points()).unwrap();
    set_mode(dir, 0o777);
}

const EARLIER_FIGURE: &str = "<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>\n";

fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    std::fs::set_permissions(path, std::fs::Permissions::from_mode(mode)).unwrap();
}

/// An earlier figure `fig.svg` beside the input.
fn figure_beside(dir: &Path) {
    earlier_figure(dir, ".");
}

/// A generating-vector file of 2 GiB (sparse) and one of a single huge component.
fn lattice_files(dir: &Path) {
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
fn names(dir: &Path) -> Vec<String> {
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
fn svg_written(run: &Run) -> Result<(), String> {
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
fn png_written(run: &Run) -> Result<(), String> {
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
fn no_temporaries(dir: &Path) -> Result<(), String> {
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
fn earlier_figure_kept(run: &Run, sub: &str) -> Result<(), String> {
    let text = std::fs::read_to_string(run.dir.join(sub).join("fig.svg"))
        .map_err(|e| format!("the earlier figure is gone: {e}"))?;
    if text != EARLIER_FIGURE {
        return Err("the earlier figure was changed by a failing plot".into());
    }
    no_temporaries(&run.dir)
}

fn read_only_figure_kept(run: &Run) -> Result<(), String> {
    earlier_figure_kept(run, "ro")
}

fn figure_kept(run: &Run) -> Result<(), String> {
    earlier_figure_kept(run, ".")
}

/// The user's `site/index.html` is as they wrote it, and nothing else was put in `site`.
fn user_site_kept(run: &Run) -> Result<(), String> {
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
fn keyed(run: &Run) -> Vec<(String, String)> {
    String::from_utf8_lossy(&run.stdout)
        .lines()
        .filter(|l| !l.starts_with('#'))
        .filter_map(|l| l.split_once(' '))
        .map(|(k, v)| (k.to_owned(), v.trim().to_owned()))
        .collect()
}

/// An answer's `key` line holds `want` (as a number), or the run refused.
fn echoes(run: &Run, key: &str, want: f64) -> Result<(), String> {
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

fn radius_honoured(run: &Run) -> Result<(), String> {
    echoes(run, "parameter", 1e-200)
}

fn k_max_honoured(run: &Run) -> Result<(), String> {
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
fn pcf_rows(run: &Run) -> Result<(), String> {
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
fn convergence_table(run: &Run) -> Result<(), String> {
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
fn qmckit(args: &[&str]) -> Result<String, String> {
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
fn values(text: &str, from: usize) -> Vec<String> {
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
fn sobol_pads_like_pbrt(run: &Run) -> Result<(), String> {
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
fn eight_lines(run: &Run) -> Result<(), String> {
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
fn rectangular(run: &Run) -> Result<(), String> {
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

// ---------------------------------------------------------------------------------------
// The table.

macro_rules! cases {
    ($($name:ident => $case:expr;)*) => {
        $(
            #[test]
            fn $name() {
                if let Err(e) = run_case(stringify!($name), $case) {
                    panic!("{}: {:?}: {e}", stringify!($name), ($case).args);
                }
            }
        )*

        /// Every case with its name.
        fn table() -> Vec<(&'static str, Case)> {
            vec![$((stringify!($name), $case)),*]
        }
    };
}

cases! {
    // --- panics and aborts -------------------------------------------------------------
    panic_plot_spectrum_frequency_2_62 => Case::new(&["plot", "--out", "out.svg"], Refuse)
        .stdin("# kx ky power\n4611686018427387904 0 1\n")
        .check(svg_written);
    panic_plot_spectrum_frequency_negative => Case::new(
        &["plot", "--kind", "spectrum", "--out", "out.png"], Refuse)
        .stdin("-9.3e18 0 1\n0 0 1\n")
        .check(png_written);
    panic_plot_spectrum_fuzzed_frequencies => Case::new(
        &["plot", "--kind", "spectrum", "--out", "out.svg"], Refuse)
        .stdin("5179970051  0517 7\r01 0 000")
        .check(svg_written);
    panic_plot_spectrum_one_cell => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# kx ky power\n0 0 1\n")
        .check(svg_written);
    panic_plot_radial_no_rows_but_labels => Case::new(
        &["plot", "--kind", "radial", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# label: a\n#\n# label: b\n1 1 1e308 1\n2 1 -1e308 1\n")
        .check(svg_written);
    panic_discrepancy_npy_claims_4g => Case::new(&["discrepancy"], Refuse)
        .stdin(npy_claims_4g());
    panic_discrepancy_npy_file_claims_4g => Case::new(&["discrepancy", "big.npy"], Refuse)
        .setup(big_npy_file);
    panic_spectrum_npy_claims_4g => Case::new(&["spectrum"], Refuse)
        .stdin(npy_claims_4g_2d());
    panic_pcf_npy_claims_4g => Case::new(&["pcf"], Refuse).stdin(npy_claims_4g_2d());
    panic_pcf_npy_dims_2_62 => Case::new(&["pcf"], Refuse)
        .stdin(npy("<f8", "(1, 4611686018427387904)", &[0; 16]));
    panic_discrepancy_npy_shape_overflow => Case::new(&["discrepancy"], Refuse)
        .stdin(npy("<f8", "(4294967296, 4294967296)", &[0; 16]));
    panic_discrepancy_npy_big_endian_nan => Case::new(&["discrepancy"], Refuse)
        .stdin(npy("<f8", "(2, 1)", &[0xff; 16]));
    panic_variance_sets_2_29 => Case::new(
        &["variance", "halton", "-n", "1", "--sets", "536870912"], AnswerOrRefuse)
        .within(budget(10.0));
    panic_variance_sets_max_poisson => Case::new(
        &["variance", "poisson", "-n", "4294967295", "--sets", "4294967295"], Refuse);
    panic_discrepancy_gigabyte_of_zeros => Case::new(&["discrepancy"], AnswerOrRefuse)
        .input(Input::Repeat(b"0\n", 1 << 29))
        .within(10.0);
    panic_points_csv_line_of_2_27 => Case::new(
        &["points", "independent", "-n", "1", "-d", "134217728", "--format", "csv"],
        AnswerOrRefuse);
    panic_points_npy_line_of_2_27 => Case::new(
        &["points", "independent", "-n", "2", "-d", "134217728", "--format", "npy"],
        AnswerOrRefuse);
    panic_rayon_4000_threads => Case::new(&["discrepancy", "--metric", "star"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "4000")]);
    panic_rayon_threads_not_a_number => Case::new(&["spectrum", "--k-max", "4"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "-1")]);
    panic_rayon_threads_max => Case::new(&["pcf", "--bins", "8"], Answer)
        .stdin(few_points())
        .env(&[("RAYON_NUM_THREADS", "18446744073709551615")]);
    panic_points_stratified_dims_max => Case::new(
        &["points", "stratified", "-n", "1", "-d", "18446744073709551615"], Refuse);
    panic_points_stratified_dims_64 => Case::new(
        &["points", "stratified", "-n", "2", "-d", "64"], AnswerOrRefuse);
    panic_points_faure_dims_max => Case::new(
        &["points", "faure", "-n", "1", "-d", "4294967295"], Refuse);
    panic_points_kronecker_dims_2_27 => Case::new(
        &["points", "kronecker", "-n", "1", "-d", "134217728"], AnswerOrRefuse);
    panic_pixel_zsobol_spp_2_31 => Case::new(
        &["pixel", "zsobol", "--resolution", "4294967295x4294967295", "--spp", "2147483648",
          "--pixel", "4294967294,4294967294"], AnswerOrRefuse);
    panic_pixel_pmj02bn_spp_max => Case::new(
        &["pixel", "pmj02bn", "--resolution", "1x1", "--spp", "4294967295", "--pixel", "0,0"],
        AnswerOrRefuse);
    panic_pixel_padded_sobol_far_pixel => Case::new(
        &["pixel", "padded-sobol", "--resolution", "4294967295x1", "--spp", "4",
          "--pixel", "4294967294,0", "--dim", "4294967295"], AnswerOrRefuse);
    panic_tvalue_faure_base_past_u16 => Case::new(
        &["tvalue", "faure", "-m", "2", "-d", "2", "--base", "4294967291"], Refuse);
    panic_tvalue_sobol_dims_past_table => Case::new(
        &["tvalue", "sobol", "-m", "4", "-d", "21202"], Refuse);
    panic_convergence_stratified_dims_64 => Case::new(
        &["convergence", "stratified", "-d", "64", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    panic_convergence_seeds_max => Case::new(
        &["convergence", "sobol", "--scramble", "owen", "--seeds", "18446744073709551615"],
        Refuse);
    panic_mask_size_overflow => Case::new(
        &["mask", "void-and-cluster", "--size", "4294967296x4294967296"], Refuse);
    panic_mask_sigma_subnormal => Case::new(
        &["mask", "void-and-cluster", "--size", "8x8", "--sigma", "5e-324"], Refuse);
    panic_report_png_budget_zero => Case::new(
        &["report", "--quick", "--png", "--out", "r", "--max-seconds", "1e-300"], Refuse);

    // --- hangs -------------------------------------------------------------------------
    hang_plot_convergence_span_1e308_1e_308 => Case::new(&["plot", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("# n rmse\n1 1e308\n2 1e-308\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_convergence_subnormal => Case::new(&["plot", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("# n rmse\n1 0.5\n2 5e-324\n4 0.25\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_convergence_n_span => Case::new(&["plot", "--out", "out.png"], AnswerOrRefuse)
        .stdin("# n rmse\n1e-300 1\n1e300 2\n")
        .within(SMALL_FIGURE)
        .check(png_written);
    hang_plot_radial_span => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("# radius count mean anisotropy\n1 4 1e308 1\n2 4 4.9e-324 1\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_image_colour_span_inf => Case::new(
        &["plot", "--kind", "image", "--out", "out.svg"], AnswerOrRefuse)
        .stdin("-1.7e308 1.7e308\n0 1\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_image_diverging_span_inf => Case::new(
        &["plot", "--kind", "image", "--colours", "diverging", "--out", "out.png"],
        AnswerOrRefuse)
        .stdin("-1.7e308 1.7e308\n1e-320 0\n")
        .within(SMALL_FIGURE)
        .check(png_written);
    hang_plot_spectrum_power_span => Case::new(&["plot", "--out", "out.svg"], AnswerOrRefuse)
        .stdin(
            "# kx ky power\n-1 -1 1e308\n0 -1 5e-324\n1 -1 0\n-1 0 1\n0 0 1e-308\n1 0 1\n\
             -1 1 1\n0 1 1\n1 1 1e300\n",
        )
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_plot_points_on_the_boundary => Case::new(
        &["plot", "--intervals", "4096x4096", "--groups", "1", "--out", "out.svg"],
        AnswerOrRefuse)
        .stdin("1 1\n0 0\n1 0\n")
        .within(SMALL_FIGURE)
        .check(svg_written);
    hang_pcf_sigma_huge => Case::new(&["pcf", "--sigma", "1e308"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    hang_spectrum_tolerance_tiny => Case::new(
        &["spectrum", "--tolerance", "5e-324", "--k-max", "2048", "--max-seconds", "1"],
        AnswerOrRefuse)
        .stdin(few_points())
        .within(budget(1.0));
    hang_discrepancy_delta_tiny => Case::new(
        &["discrepancy", "--metric", "star-bounds", "--delta", "5e-324",
          "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(few_points())
        .within(budget(1.0));
    hang_tvalue_faure_many_dims => Case::new(
        &["tvalue", "faure", "-m", "32", "-d", "1000", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    hang_variance_gaussian_sigma_subnormal => Case::new(
        &["variance", "sobol", "-n", "16", "--integrand", "gaussian", "--sigma", "5e-324",
          "--sets", "4"], AnswerOrRefuse);

    // --- the budget bounds the run -----------------------------------------------------
    budget_mask_void_and_cluster_1540 => Case::new(
        &["mask", "void-and-cluster", "--size", "1540x1540", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0))
        .check(rectangular);
    budget_mask_void_and_cluster_4096 => Case::new(
        &["mask", "void-and-cluster", "--size", "4096x1024", "--max-seconds", "2",
          "--format", "png"], AnswerOrRefuse)
        .within(budget(2.0));
    budget_points_poisson_maximal_7d => Case::new(
        &["points", "poisson", "--radius", "1", "-d", "7", "--torus", "--maximal",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_poisson_maximal_8d_small_radius => Case::new(
        &["points", "poisson", "--radius", "0.3", "-d", "8", "--maximal",
          "--max-seconds", "2"], AnswerOrRefuse)
        .within(budget(2.0));
    budget_points_poisson_n_11256250 => Case::new(
        &["points", "poisson", "-n", "11256250", "-d", "1", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_gaussian_blue_noise => Case::new(
        &["points", "gaussian-blue-noise", "-n", "4096", "--iterations", "4294967295",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_best_candidate => Case::new(
        &["points", "best-candidate", "-n", "100000", "--candidates", "4294967295",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_points_pmj02bn => Case::new(
        &["points", "pmj02bn", "-n", "4194304", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_discrepancy_star_3d => Case::new(
        &["discrepancy", "--metric", "star", "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(random_points(20000, 3, 2))
        .within(budget(1.0));
    budget_discrepancy_all_20d => Case::new(
        &["discrepancy", "--metric", "all", "--max-seconds", "1"], AnswerOrRefuse)
        .stdin(random_points(4000, 20, 3))
        .within(budget(1.0));
    budget_spectrum_direct => Case::new(
        &["spectrum", "--method", "direct", "--k-max", "256", "--max-seconds", "1"],
        AnswerOrRefuse)
        .stdin(random_points(20000, 2, 4))
        .within(budget(1.0));
    budget_pcf_many_points => Case::new(&["pcf", "--max-seconds", "1", "--r-max", "0.5"],
        AnswerOrRefuse)
        .stdin(random_points(40000, 2, 5))
        .within(budget(1.0));
    budget_tvalue_counted => Case::new(
        &["tvalue", "sobol", "-m", "21", "-d", "3", "--scramble", "owen",
          "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_convergence_owen_halton => Case::new(
        &["convergence", "halton", "-d", "16", "--scramble", "owen", "--max-m", "20",
          "--seeds", "2", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_convergence_poisson => Case::new(
        &["convergence", "poisson", "--max-m", "16", "--max-seconds", "1"], AnswerOrRefuse)
        .within(budget(1.0));
    budget_variance_poisson => Case::new(
        &["variance", "poisson", "-n", "4096", "--sets", "64", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_variance_halton_many_sets => Case::new(
        &["variance", "halton", "-n", "1", "--sets", "536870912", "--max-seconds", "1"],
        AnswerOrRefuse)
        .within(budget(1.0));
    budget_report_quick => Case::new(
        &["report", "--quick", "--out", "r", "--max-seconds", "2"], AnswerOrRefuse)
        .within(budget(2.0) + 2.0);

    // --- unbounded reads ---------------------------------------------------------------
    read_points_lattice_vector_dev_zero => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "/dev/zero"], Refuse)
        .within(READ_REFUSAL);
    read_points_lattice_vector_sparse => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "sparse"], Refuse)
        .setup(lattice_files)
        .within(READ_REFUSAL);
    read_points_lattice_vector_huge_header => Case::new(
        &["points", "lattice", "-n", "4", "--vector", "huge.lattice"], Refuse)
        .setup(lattice_files);
    read_discrepancy_stdin_dev_zero => Case::new(&["discrepancy"], Refuse)
        .input(Input::File("/dev/zero"))
        .within(READ_REFUSAL);
    read_discrepancy_file_dev_zero => Case::new(&["discrepancy", "/dev/zero"], Refuse)
        .within(READ_REFUSAL);
    read_discrepancy_sparse_2g => Case::new(&["discrepancy", "sparse"], Refuse)
        .setup(sparse_2g)
        .within(READ_REFUSAL);
    read_spectrum_sparse_2g_stdin => Case::new(&["spectrum"], Refuse)
        .setup(sparse_2g)
        .input(Input::File("sparse"))
        .within(READ_REFUSAL);
    read_pcf_dev_urandom => Case::new(&["pcf", "/dev/urandom"], Refuse)
        .within(READ_REFUSAL);
    read_plot_dev_zero => Case::new(&["plot", "--out", "out.svg"], Refuse)
        .input(Input::File("/dev/zero"))
        .within(READ_REFUSAL)
        .check(svg_written);
    read_plot_image_sparse_2g => Case::new(
        &["plot", "--kind", "image", "--out", "out.png", "sparse"], Refuse)
        .setup(sparse_2g)
        .within(READ_REFUSAL)
        .check(png_written);
    read_plot_endless_pgm_header => Case::new(&["plot", "--out", "out.png"], Refuse)
        .input(Input::Repeat(b"P5 ", 1 << 28))
        .within(5.0)
        .check(png_written);
    read_discrepancy_endless_comment => Case::new(&["discrepancy"], Refuse)
        .input(Input::Repeat(b"################", 1 << 27))
        .within(5.0);

    // --- data loss ---------------------------------------------------------------------
    loss_report_out_empty => Case::new(&["report", "--quick", "--out", ""], Refuse);
    loss_report_keeps_user_index => Case::new(
        &["report", "--quick", "--out", "site", "--max-seconds", "2"], AnswerOrRefuse)
        .setup(user_site)
        .within(budget(2.0) + 2.0)
        .check(user_site_kept);
    loss_plot_read_only_dir => Case::new(
        &["plot", "--out", "ro/fig.svg", "pts.txt"], Fail)
        .setup(read_only_figure)
        .unprivileged()
        .check(read_only_figure_kept);
    loss_plot_refused_input_keeps_figure => Case::new(
        &["plot", "--out", "fig.svg", "--kind", "spectrum", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);
    loss_plot_out_is_a_directory => Case::new(&["plot", "--out", "ro.svg", "pts.txt"], Fail)
        .setup(|dir| {
            earlier_figure(dir, "ro.svg");
        })
        .check(|run| earlier_figure_kept(run, "ro.svg"));
    loss_plot_out_empty => Case::new(&["plot", "--out", "", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);
    loss_plot_out_has_no_extension => Case::new(&["plot", "--out", "fig", "pts.txt"], Refuse)
        .setup(figure_beside)
        .check(figure_kept);

    // --- wrong answers presented as answers --------------------------------------------
    wrong_pcf_sigma_5e_324 => Case::new(&["pcf", "--sigma", "5e-324"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    wrong_pcf_sigma_nan => Case::new(&["pcf", "--sigma", "nan"], Refuse).stdin(few_points());
    wrong_pcf_r_max_subnormal => Case::new(&["pcf", "--r-max", "5e-324"], AnswerOrRefuse)
        .stdin(few_points())
        .check(pcf_rows);
    wrong_variance_radius_1e_200 => Case::new(
        &["variance", "sobol", "-n", "16", "--radius", "1e-200", "--sets", "8"],
        AnswerOrRefuse)
        .check(radius_honoured);
    wrong_variance_k_max_0 => Case::new(
        &["variance", "sobol", "-n", "16", "--k-max", "0", "--sets", "8"], AnswerOrRefuse)
        .check(k_max_honoured);
    wrong_variance_radius_nan => Case::new(
        &["variance", "sobol", "-n", "16", "--radius", "nan"], Refuse);
    wrong_plot_title_control_character => Case::new(
        &["plot", "--title", "a\u{1}b\u{1b}[31m <&> ]]> \"q\" \u{fffe}", "--out", "out.svg"],
        Answer)
        .stdin(few_points())
        .check(svg_written);
    wrong_plot_title_control_character_image => Case::new(
        &["plot", "--kind", "image", "--title", "\u{7}\u{8}\r\n\t&amp", "--out", "out.svg"],
        Answer)
        .stdin("0 1\n2 3\n")
        .check(svg_written);
    wrong_plot_curve_label_control_character => Case::new(
        &["plot", "--out", "out.svg"], Answer)
        .stdin("# n rmse\n# label: x\u{2}y<z&\n1 0.5\n2 0.25\n4 0.125\n")
        .check(svg_written);
    wrong_npy_header_syntax_error_is_one_line => Case::new(&["discrepancy"], Refuse)
        .stdin(&b"\x93NUMPY\x01\x00\x04\x00{x}\n"[..]);
    wrong_npy_header_of_python_code_is_one_line => Case::new(&["spectrum"], Refuse)
        .stdin(npy("<f8", "__import__('os')", &[0; 16]));
    wrong_spectrum_tolerance_nan => Case::new(&["spectrum", "--tolerance", "nan"], Refuse)
        .stdin(few_points());
    wrong_discrepancy_delta_nan => Case::new(
        &["discrepancy", "--metric", "star-bounds", "--delta", "nan"], Refuse)
        .stdin(few_points());
    wrong_discrepancy_coordinate_past_one => Case::new(&["discrepancy"], Refuse)
        .stdin("0.5 1.0000000000000002\n");
    wrong_points_u32_coordinate_2_32 => Case::new(&["discrepancy", "--input-format", "u32"],
        Refuse)
        .stdin("4294967296 0\n");
    wrong_tvalue_m_past_32 => Case::new(&["tvalue", "sobol", "-m", "33"], Refuse);
    wrong_convergence_max_m_past_24 => Case::new(
        &["convergence", "sobol", "--max-m", "25"], Refuse);
    wrong_mask_sigma_nan => Case::new(
        &["mask", "void-and-cluster", "--size", "8x8", "--sigma", "nan"], Refuse);
    wrong_pixel_outside_the_image => Case::new(
        &["pixel", "independent", "--resolution", "4x4", "--spp", "4", "--pixel", "4,0"],
        Refuse);
    wrong_pixel_zsobol_spp_not_power_of_two => Case::new(
        &["pixel", "zsobol", "--resolution", "4x4", "--spp", "3", "--pixel", "0,0"], Refuse);
    wrong_report_budget_nan => Case::new(
        &["report", "--quick", "--out", "r", "--max-seconds", "nan"], Refuse);

    // --- listed but broken -------------------------------------------------------------
    listed_convergence_poisson => Case::new(&["convergence", "poisson"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_gaussian_blue_noise => Case::new(
        &["convergence", "gaussian-blue-noise"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_best_candidate => Case::new(&["convergence", "best-candidate"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_convergence_pmj02bn => Case::new(&["convergence", "pmj02bn"], Answer)
        .within(budget(10.0))
        .check(convergence_table);
    listed_pixel_sobol_pads_like_pbrt => Case::new(
        &["pixel", "sobol", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "4294967295"], Answer)
        .check(|run| eight_lines(run).and_then(|()| sobol_pads_like_pbrt(run)));
    listed_pixel_every_sampler_past_dims => Case::new(
        &["pixel", "padded-sobol", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "21201"], Answer)
        .check(eight_lines);
    listed_pixel_pmj02_past_dims => Case::new(
        &["pixel", "pmj02", "--resolution", "16x16", "--spp", "8", "--pixel", "3,5",
          "--dim", "4294967295"], Answer)
        .check(eight_lines);
    listed_tvalue_every_base2_sampler => Case::new(&["tvalue", "lp", "-m", "32"], Answer);
    listed_spectrum_radial_of_one_point => Case::new(
        &["spectrum", "--radial", "--k-max", "1"], Answer)
        .stdin("0.5 0.5\n");
    listed_pcf_torus_of_two_points => Case::new(&["pcf", "--torus", "--r-max", "0.5"], Answer)
        .stdin("0.1 0.1\n0.6 0.6\n")
        .check(pcf_rows);
    listed_discrepancy_npy_of_float32 => Case::new(&["discrepancy", "--metric", "star"], Answer)
        .stdin(npy("<f4", "(2, 2)", &[0, 0, 0, 0x3f, 0, 0, 0x80, 0x3e, 0, 0, 0x40, 0x3f, 0, 0, 0, 0]));
    listed_mask_one_pixel => Case::new(&["mask", "void-and-cluster", "--size", "1x1"],
        AnswerOrRefuse);
    listed_variance_every_sampler => Case::new(
        &["variance", "gaussian-blue-noise", "-n", "64", "--sets", "2"], Answer);
    listed_plot_points_of_own_output => Case::new(&["plot", "--out", "out.svg"], Answer)
        .stdin(random_points(16, 3, 6))
        .check(svg_written);
    listed_report_help => Case::new(&["report", "--help"], Answer);
}

/// The commands of `qmckit --help`, and the classes of the module docs.
const COMMANDS: [&str; 11] = [
    "points",
    "pixel",
    "discrepancy",
    "tvalue",
    "convergence",
    "spectrum",
    "pcf",
    "variance",
    "mask",
    "plot",
    "report",
];
const CLASSES: [&str; 7] = [
    "panic_", "hang_", "budget_", "read_", "loss_", "wrong_", "listed_",
];

#[test]
fn covers_every_class_and_command() {
    let table = table();
    for class in CLASSES {
        assert!(
            table.iter().any(|(n, _)| n.starts_with(class)),
            "no {class} case"
        );
    }
    for command in COMMANDS {
        assert!(
            table.iter().any(|(_, c)| c.args.first() == Some(&command)),
            "no case for {command}"
        );
    }
    for (name, _) in &table {
        assert!(
            CLASSES.iter().any(|c| name.starts_with(c)),
            "{name}: no class"
        );
    }
    // Every class reaches most commands: the cross table is printed for the record.
    for class in CLASSES {
        let hit: Vec<&str> = COMMANDS
            .iter()
            .copied()
            .filter(|cmd| {
                table
                    .iter()
                    .any(|(n, c)| n.starts_with(class) && c.args.first() == Some(cmd))
            })
            .collect();
        eprintln!("{class:8} {hit:?}");
    }
}
