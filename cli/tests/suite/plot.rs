//! `qmckit_cli::plot` and `qmckit plot`: figures that can be checked by their content (the
//! elementary-interval counts of a (0,m,2)-net, exact slopes, decoded pixels), pipes from the
//! other commands, and the one-line errors.

use qmckit::{Sobol, bits};
use qmckit_cli::plot::{
    ColourMap, ConvergenceFigure, Curve, Format, ImageFigure, PointsFigure, RadialFigure,
    SpectrumFigure, decode_image, parse_blocks, parse_table, render,
};

use crate::common::cli::{assert_usage_error, run};

fn sobol(n: u32) -> Vec<[f64; 2]> {
    let s = Sobol::new(2).unwrap();
    (0..n)
        .map(|i| {
            [
                bits::to_f64(s.sample(i, 0).unwrap()),
                bits::to_f64(s.sample(i, 1).unwrap()),
            ]
        })
        .collect()
}

/// A unique scratch path.
fn scratch(name: &str) -> std::path::PathBuf {
    static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
    let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let dir = std::env::temp_dir().join(format!("qmckit-plot-{}-{k}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir.join(name)
}

/// Decodes an RGB(A) PNG: (width, height, distinct colours, up to 3).
fn png_colours(bytes: &[u8]) -> (u32, u32, usize) {
    let dec = png::Decoder::new(std::io::Cursor::new(bytes));
    let mut r = dec.read_info().unwrap();
    let mut buf = vec![0; r.output_buffer_size().unwrap()];
    let info = r.next_frame(&mut buf).unwrap();
    let px = info.color_type.samples();
    let mut seen: Vec<&[u8]> = Vec::new();
    for p in buf[..info.buffer_size()].chunks(px) {
        if !seen.contains(&p) {
            seen.push(p);
            if seen.len() == 3 {
                break;
            }
        }
    }
    (info.width, info.height, seen.len())
}

#[test]
fn sobol_32_fills_every_elementary_interval() {
    // The first 2^5 points of 2D Sobol' are a (0,5,2)-net: each of the 32 boxes of every
    // 2^a x 2^(5-a) grid holds exactly one point.
    let p = sobol(32);
    for a in 0..=5u32 {
        let f = PointsFigure::new("", p.clone()).intervals(1 << a, 1 << (5 - a));
        assert_eq!(
            f.balanced_boxes(),
            Some((32, 32)),
            "grid {}x{}",
            1 << a,
            1 << (5 - a)
        );
    }
    // 32 points on the diagonal fill only the diagonal boxes of the 32x32 grid... and no
    // box of a 4x8 grid holds exactly one point of 32 equal points.
    let same = vec![[0.3, 0.3]; 32];
    assert_eq!(
        PointsFigure::new("", same).intervals(4, 8).balanced_boxes(),
        Some((0, 32))
    );
}

#[test]
fn svg_keeps_text_as_text_and_png_is_drawn() {
    let fig = PointsFigure::new("Sobol title", sobol(64)).intervals(8, 8);
    let svg = String::from_utf8(render(&fig, Format::Svg, 400, 400).unwrap()).unwrap();
    assert!(svg.starts_with("<svg"));
    assert!(svg.contains("<text") && svg.contains("Sobol title (64/64 boxes balanced)"));
    assert_eq!(svg.matches("<circle").count(), 64);
    let png = render(&fig, Format::Png, 300, 200).unwrap();
    let (w, h, colours) = png_colours(&png);
    assert_eq!((w, h), (300, 200));
    assert!(colours >= 3, "the PNG is not blank");
}

#[test]
fn fitted_slopes_are_exact_on_power_laws() {
    let curve = |a: f64| Curve {
        label: String::new(),
        points: (2..12)
            .map(|k| ((1u32 << k) as f64, 3.0 * ((1u32 << k) as f64).powf(a)))
            .collect(),
    };
    let fig = ConvergenceFigure::new("", vec![curve(-0.5), curve(-1.5)]);
    let s = fig.slopes();
    assert!((s[0].unwrap() + 0.5).abs() < 1e-12 && (s[1].unwrap() + 1.5).abs() < 1e-12);
    assert!(render(&fig, Format::Svg, 500, 400).is_ok());
    // One N only: no slope, and no plot.
    let flat = ConvergenceFigure::new(
        "",
        vec![Curve {
            label: String::new(),
            points: vec![(4.0, 1.0)],
        }],
    );
    assert_eq!(flat.slopes(), vec![None]);
    assert!(render(&flat, Format::Svg, 500, 400).is_err());
}

#[test]
fn bad_figures_are_errors() {
    assert!(SpectrumFigure::new("", 2, vec![1.0; 24]).is_err()); // (2*2+1)^2 = 25
    assert!(ImageFigure::new("", 3, 2, vec![0.0; 5]).is_err());
    assert!(ImageFigure::new("", 1, 1, vec![f64::NAN]).is_err());
    assert!(Format::from_path("a.jpg").is_err());
    assert_eq!(Format::from_path("A.SVG").unwrap(), Format::Svg);
    let fig = PointsFigure::new("", sobol(4));
    assert!(render(&fig, Format::Png, 0, 10).is_err());
    assert!(
        render(
            &PointsFigure::new("", sobol(4)).intervals(0, 3),
            Format::Svg,
            100,
            100
        )
        .is_err()
    );
}

#[test]
fn images_decode_exactly() {
    let (w, h, v) = decode_image(b"P2\n# comment\n3 2\n255\n0 128 255\n1 2 3\n").unwrap();
    assert_eq!((w, h, v), (3, 2, vec![0.0, 128.0, 255.0, 1.0, 2.0, 3.0]));
    let mut p5 = b"P5 2 1 65535\n".to_vec();
    p5.extend_from_slice(&[0x01, 0x02, 0xff, 0xff]);
    assert_eq!(decode_image(&p5).unwrap(), (2, 1, vec![258.0, 65535.0]));
    assert_eq!(
        decode_image(b"1 2\n3 4\n").unwrap(),
        (2, 2, vec![1.0, 2.0, 3.0, 4.0])
    );
    assert!(decode_image(b"1 2\n3\n").is_err());
    assert!(decode_image(b"P5 4 4 255\n\x00").is_err()); // truncated
    assert!(parse_table("# n rmse\n", 2).is_err());
    let t = parse_table("# set 1\n1 2\n# set 2\n3 4\n", 2).unwrap();
    assert_eq!(t, vec![vec![vec![1.0, 2.0]], vec![vec![3.0, 4.0]]]);
    // A bare '#' separates sets too (as every command's input does), and '# label:' names
    // a set; a header after the separator does not open a third.
    let b = parse_blocks(
        "# label: a\n1 2\n#\n# mean of 2 sets\n# label: b\n3 4\n5 6\n",
        2,
    )
    .unwrap();
    assert_eq!(b.len(), 2);
    assert_eq!((b[0].label.as_deref(), b[0].rows.len()), (Some("a"), 1));
    assert_eq!((b[1].label.as_deref(), b[1].rows.len()), (Some("b"), 2));
}

fn pipe(producer: &[&str], plot: &[&str]) -> std::process::Output {
    let out = run(producer, "");
    assert_eq!(out.status.code(), Some(0), "{producer:?}");
    run(plot, std::str::from_utf8(&out.stdout).unwrap())
}

#[test]
fn plot_reads_points_from_a_pipe() {
    let svg = scratch("p.svg");
    let out = pipe(
        &["points", "sobol", "-n", "32", "-d", "2"],
        &["plot", "--intervals", "4x8", "--out", svg.to_str().unwrap()],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(
        text.contains("32/32 boxes balanced"),
        "4x8 intervals of a (0,5,2)-net"
    );
    // u32 output, a warp, PNG.
    let png = scratch("d.png");
    let out = pipe(
        &[
            "points", "halton", "-n", "256", "-d", "2", "--format", "u32",
        ],
        &["plot", "--warp", "disk", "--out", png.to_str().unwrap()],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(png_colours(&std::fs::read(&png).unwrap()).2 >= 2);
}

#[test]
fn plot_reads_spectra_convergence_and_masks_from_pipes() {
    let pts = run(&["points", "sobol", "-n", "256", "-d", "2"], "");
    let spec = run(
        &["spectrum", "--k-max", "8"],
        std::str::from_utf8(&pts.stdout).unwrap(),
    );
    assert_eq!(spec.status.code(), Some(0));
    let f = scratch("s.png");
    let out = run(
        &["plot", "--out", f.to_str().unwrap()],
        std::str::from_utf8(&spec.stdout).unwrap(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(png_colours(&std::fs::read(&f).unwrap()).2 >= 3);
    let radial = run(
        &["spectrum", "--k-max", "8", "--radial"],
        std::str::from_utf8(&pts.stdout).unwrap(),
    );
    let f = scratch("r.svg");
    let out = run(
        &["plot", "--out", f.to_str().unwrap()],
        std::str::from_utf8(&radial.stdout).unwrap(),
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        std::fs::read_to_string(&f)
            .unwrap()
            .contains("radial power spectrum")
    );
    let f = scratch("c.svg");
    let out = pipe(
        &[
            "convergence",
            "sobol",
            "--integrand",
            "gaussian",
            "-d",
            "2",
            "--max-m",
            "10",
        ],
        &["plot", "--out", f.to_str().unwrap()],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(std::fs::read_to_string(&f).unwrap().contains("slope"));
    let f = scratch("m.png");
    let out = pipe(
        &["mask", "void-and-cluster", "--size", "16x16"],
        &["plot", "--out", f.to_str().unwrap()],
    );
    assert_eq!(
        out.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(png_colours(&std::fs::read(&f).unwrap()).2 >= 3);
}

#[test]
fn plot_bad_input_is_one_line() {
    let out = scratch("x.svg");
    let o = out.to_str().unwrap();
    assert_usage_error(&["plot", "--out", o], "", "empty input");
    assert_usage_error(&["plot", "--out", o], "0.5\n0.25\n", "2D points");
    assert_usage_error(&["plot", "--out", o], "0.5 1.5\n", "outside [0, 1]");
    assert_usage_error(
        &["plot", "--out", "p.jpg"],
        "0.5 0.5\n",
        "unknown figure format",
    );
    assert_usage_error(
        &["plot", "--out", o, "--intervals", "4x0"],
        "0.5 0.5\n",
        "--intervals",
    );
    assert_usage_error(
        &["plot", "--out", o, "--kind", "spectrum"],
        "# kx ky power\n0 0 1\n1 0 1\n",
        "every integer frequency",
    );
    assert_usage_error(
        &["plot", "--out", o, "--kind", "image"],
        "1 2\n3\n",
        "values",
    );
    let r = run(&["plot", "--out", "/nonexistent-dir/p.svg"], "0.5 0.5\n");
    assert_eq!(r.status.code(), Some(1));
    assert_eq!(String::from_utf8(r.stderr).unwrap().lines().count(), 1);
}

/// `f()` on another thread, failing the test if it takes more than `secs` seconds (the
/// figures below used to draw for ever).
fn within<T: Send + 'static>(secs: u64, f: impl FnOnce() -> T + Send + 'static) -> T {
    let (tx, rx) = std::sync::mpsc::channel();
    std::thread::spawn(move || {
        let _ = tx.send(f());
    });
    rx.recv_timeout(std::time::Duration::from_secs(secs))
        .expect("drawing did not finish in time")
}

fn curve(points: Vec<(f64, f64)>) -> Curve {
    Curve {
        label: "c".into(),
        points,
    }
}

#[test]
fn convergence_log_axes_are_bounded() {
    // Errors spanning 1e308 .. 1e-300: the error axis would span 608 decades, and plotters'
    // tick loop ran for ever; now a one-line refusal.
    let fig = ConvergenceFigure::new("", vec![curve(vec![(1.0, 1e308), (2.0, 1e-300)])]);
    let r = within(20, move || render(&fig, Format::Svg, 300, 300));
    let e = r.unwrap_err().0;
    assert!(e.contains("log axis"), "{e}");
    // A subnormal error is numerically zero: left out (and counted), the rest drawn.
    let fig = ConvergenceFigure::new(
        "",
        vec![curve(vec![(1.0, 1e-3), (2.0, 5e-324), (4.0, 1e-4)])],
    );
    assert_eq!(fig.left_out(), 1);
    let r = within(20, move || render(&fig, Format::Png, 300, 300));
    assert!(r.is_ok(), "{r:?}");
    // Every value subnormal: nothing to draw, an error.
    let fig = ConvergenceFigure::new("", vec![curve(vec![(1.0, 1e-310), (2.0, 1e-315)])]);
    assert_eq!(fig.left_out(), 2);
    assert!(within(20, move || render(&fig, Format::Svg, 300, 300)).is_err());
    // N spanning more than a float's ratio.
    let fig = ConvergenceFigure::new("", vec![curve(vec![(1e-300, 1.0), (1e300, 0.5)])]);
    assert!(within(20, move || render(&fig, Format::Svg, 300, 300)).is_err());
}

#[test]
fn image_colour_spans_are_finite() {
    // A span of -1e308 .. 1e308 is infinite: refused (the colour bar's tick loop never ended).
    for map in [ColourMap::Grey, ColourMap::Diverging] {
        let fig = ImageFigure::new("", 2, 1, vec![-1e308, 1e308])
            .unwrap()
            .map(map);
        let e = within(20, move || render(&fig, Format::Svg, 200, 200)).unwrap_err();
        assert!(e.0.contains("colour range"), "{e}");
    }
    // A constant image at the largest float is drawn (its range is widened inside the floats).
    let fig = ImageFigure::new("", 2, 1, vec![f64::MAX, f64::MAX]).unwrap();
    assert!(within(20, move || render(&fig, Format::Svg, 200, 200)).is_ok());
    // A subnormal span is drawn.
    let fig = ImageFigure::new("", 2, 1, vec![0.0, 5e-324]).unwrap();
    assert!(within(20, move || render(&fig, Format::Png, 200, 200)).is_ok());
    // A given range must be finite and increasing: refused, never silently swapped.
    for (lo, hi) in [
        (0.0, f64::INFINITY),
        (1.0, 1.0),
        (2.0, 1.0),
        (f64::NAN, 1.0),
    ] {
        let fig = ImageFigure::new("", 2, 1, vec![0.0, 1.0])
            .unwrap()
            .range(lo, hi);
        assert!(
            within(20, move || render(&fig, Format::Svg, 200, 200)).is_err(),
            "{lo} {hi}"
        );
    }
    // Public fields that disagree: an error, not a division by zero.
    let mut fig = ImageFigure::new("", 2, 1, vec![0.0, 1.0]).unwrap();
    fig.width = 0;
    assert!(render(&fig, Format::Svg, 200, 200).is_err());
}

#[test]
fn radial_axes_are_finite() {
    let fig = RadialFigure {
        title: String::new(),
        x_label: String::new(),
        y_label: String::new(),
        curves: vec![("a".into(), vec![(0.5, 1.0), (1.0, f64::MAX)])],
    };
    // The power axis ends at 1.05 times the largest value: infinite here, refused.
    match within(20, move || render(&fig, Format::Svg, 300, 300)) {
        Err(e) => assert!(e.0.contains("power"), "{e}"),
        Ok(_) => panic!("an infinite power axis was drawn"),
    }
    // Negative values widen the axes instead of leaving the picture.
    let fig = RadialFigure {
        title: String::new(),
        x_label: String::new(),
        y_label: String::new(),
        curves: vec![("a".into(), vec![(-1.0, -2.0), (1.0, 1.0)])],
    };
    assert!(within(20, move || render(&fig, Format::Png, 300, 300)).is_ok());
}

/// Whether every character of `s` may appear in an XML 1.0 document.
fn xml_chars(s: &str) -> bool {
    s.chars().all(|c| {
        matches!(c, '\t' | '\n' | '\r')
            || (('\u{20}'..='\u{d7ff}').contains(&c)
                && c != '\u{7f}'
                && !('\u{80}'..='\u{9f}').contains(&c))
            || ('\u{e000}'..='\u{fffd}').contains(&c)
            || c >= '\u{10000}'
    })
}

#[test]
fn svg_text_is_well_formed() {
    let nasty = "a\u{1}b\u{1b}[31mc<&>\"'\u{7f}\u{85}\u{fffe}d\te";
    let check = |svg: Vec<u8>| {
        let svg = String::from_utf8(svg).unwrap();
        assert!(xml_chars(&svg), "{svg:?}");
        assert!(svg.contains("ab[31mc&lt;&amp;&gt;&quot;&apos;d e"), "{svg}");
    };
    check(render(&PointsFigure::new(nasty, sobol(4)), Format::Svg, 300, 300).unwrap());
    let mut c = curve(vec![(1.0, 1.0), (4.0, 0.5)]);
    c.label = nasty.into();
    let mut fig = ConvergenceFigure::new(nasty, vec![c]);
    fig.y_label = nasty.into();
    check(render(&fig, Format::Svg, 400, 400).unwrap());
    let fig = RadialFigure {
        title: nasty.into(),
        x_label: nasty.into(),
        y_label: nasty.into(),
        curves: vec![(nasty.into(), vec![(0.5, 1.0), (1.0, 2.0)])],
    };
    check(render(&fig, Format::Svg, 400, 400).unwrap());
    let fig = ImageFigure::new(nasty, 2, 2, vec![0.0, 1.0, 2.0, 3.0]).unwrap();
    check(render(&fig, Format::Svg, 300, 300).unwrap());
    let fig = SpectrumFigure::new(nasty, 1, vec![1.0; 9]).unwrap();
    check(render(&fig, Format::Svg, 300, 300).unwrap());
    // Through the command too.
    let out = scratch("title.svg");
    let r = run(
        &["plot", "--out", out.to_str().unwrap(), "--title", nasty],
        "0.5 0.5\n0.25 0.75\n",
    );
    assert_eq!(r.status.code(), Some(0), "{r:?}");
    check(std::fs::read(&out).unwrap());
}

#[test]
fn points_figure_options_are_checked() {
    // Group size 0 and radii outside 1..=MAX_RADIUS are refused, not changed.
    let fig = PointsFigure::new("", sobol(8)).groups(0);
    assert!(render(&fig, Format::Svg, 200, 200).is_err());
    for r in [0, qmckit_cli::plot::MAX_RADIUS + 1, u32::MAX] {
        let fig = PointsFigure::new("", sobol(8)).radius(r);
        assert!(render(&fig, Format::Svg, 200, 200).is_err(), "{r}");
    }
    // Points outside the square are counted and not drawn (no dot at pixel 2^31).
    let mut pts = sobol(8);
    pts.push([1e300, 0.5]);
    pts.push([f64::NAN, 0.5]);
    let fig = PointsFigure::new("p", pts);
    assert_eq!(fig.outside(), 2);
    let svg = String::from_utf8(render(&fig, Format::Svg, 200, 200).unwrap()).unwrap();
    assert!(svg.contains("(2 outside, not drawn)"), "{svg}");
    assert_eq!(svg.matches("<circle").count(), 8);
    assert!(within(20, move || render(&fig, Format::Png, 200, 200)).is_ok());
}

#[test]
fn spectrum_sizes_are_checked() {
    // K = 2^62: 2K + 1 wrapped and the grid index ran out of bounds (a panic); now one line.
    let out = scratch("s.svg");
    let o = out.to_str().unwrap();
    assert_usage_error(
        &["plot", "--out", o],
        "# kx ky power\n4611686018427387904 0 1\n",
        "every integer frequency",
    );
    assert_usage_error(
        &["plot", "--out", o, "--kind", "spectrum"],
        "# kx ky power\n1e300 -1e300 1\n",
        "every integer frequency",
    );
    // Nine lines for K = 1 but (0, 0) twice and (1, 1) missing: refused, not drawn with a
    // hole.
    let mut t = String::from("# kx ky power\n");
    for (kx, ky) in [
        (-1, -1),
        (0, -1),
        (1, -1),
        (-1, 0),
        (0, 0),
        (1, 0),
        (-1, 1),
        (0, 1),
    ] {
        t += &format!("{kx} {ky} 1\n");
    }
    let full = format!("{t}1 1 1\n");
    let r = run(&["plot", "--out", o], &full);
    assert_eq!(r.status.code(), Some(0), "{r:?}");
    assert_usage_error(&["plot", "--out", o], &format!("{t}0 0 1\n"), "once each");
    // The library computes (2K + 1)^2 without overflow.
    assert!(SpectrumFigure::new("", usize::MAX / 2, vec![]).is_err());
    assert!(SpectrumFigure::new("", 1 << 31, vec![0.0; 4]).is_err());
    let mut fig = SpectrumFigure::new("", 1, vec![1.0; 9]).unwrap();
    fig.k_max = usize::MAX / 2;
    assert!(render(&fig, Format::Svg, 200, 200).is_err());
}

#[test]
fn tables_and_images_are_bounded() {
    // A row of more than 1024 numbers, more than 2^22 rows, a text image past 2^22 pixels.
    let wide = format!("{}\n", "1 ".repeat(2000));
    assert!(parse_blocks(&wide, 2).is_err());
    let tall = "1 1\n".repeat((1 << 22) + 1);
    let e = parse_blocks(&tall, 2).unwrap_err();
    assert!(e.0.contains("rows"), "{e}");
    let big = format!("{}\n", "1 ".repeat((1 << 22) + 1));
    assert!(decode_image(big.as_bytes()).is_err());
    // Still fine just below.
    assert_eq!(
        parse_blocks(&"1 1\n".repeat(1000), 2).unwrap()[0]
            .rows
            .len(),
        1000
    );
}
