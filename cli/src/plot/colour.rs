//! Colour maps: grey levels and a perceptually ordered dark-blue-to-yellow ramp.

use plotters::style::RGBColor;

/// Grey level of `t` in `[0, 1]` (clamped): 0 black, 1 white.
pub fn grey(t: f64) -> RGBColor {
    let v = (t.clamp(0.0, 1.0) * 255.0).round() as u8;
    RGBColor(v, v, v)
}

/// A viridis-like ramp for `t` in `[0, 1]` (clamped; NaN reads as 0): linear interpolation
/// between nine colours sampled along matplotlib's viridis (dark purple, blue, green, yellow).
pub fn viridis(t: f64) -> RGBColor {
    const STOPS: [(u8, u8, u8); 9] = [
        (68, 1, 84),
        (71, 45, 123),
        (59, 82, 139),
        (44, 114, 142),
        (33, 145, 140),
        (40, 174, 128),
        (94, 201, 98),
        (173, 220, 48),
        (253, 231, 37),
    ];
    let t = if t.is_nan() { 0.0 } else { t.clamp(0.0, 1.0) };
    let x = t * (STOPS.len() - 1) as f64;
    let i = (x.floor() as usize).min(STOPS.len() - 2);
    let f = x - i as f64;
    let mix = |a: u8, b: u8| (a as f64 + (b as f64 - a as f64) * f).round() as u8;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// A diverging blue-white-red ramp for `t` in `[-1, 1]` (clamped).
pub(crate) fn diverging(t: f64) -> RGBColor {
    let t = if t.is_nan() { 0.0 } else { t.clamp(-1.0, 1.0) };
    let (r, g, b) = if t < 0.0 {
        (1.0 + t * 0.8, 1.0 + t * 0.6, 1.0)
    } else {
        (1.0, 1.0 - t * 0.6, 1.0 - t * 0.8)
    };
    RGBColor((r * 255.0) as u8, (g * 255.0) as u8, (b * 255.0) as u8)
}

/// Distinct colours for curves and groups.
pub(crate) const PALETTE: [RGBColor; 10] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(255, 127, 14),
    RGBColor(148, 103, 189),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
    RGBColor(188, 189, 34),
    RGBColor(64, 64, 64),
];
