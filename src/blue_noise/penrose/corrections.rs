//! The correction vectors of [`super`]: the structural class of a leaf, the band of the
//! threshold fraction, the trained table and the placement of a sample.

use super::tiling::{Frame, Kind, Leaf, PHI, inside, leaves};

/// The class of a leaf with fewer than [`CLASS_DEPTH`] levels above it.
pub(crate) const NO_CLASS: u8 = u8::MAX;

/// Levels between a leaf and the ancestor that defines its class.
pub(crate) const CLASS_DEPTH: usize = 5;

/// Classes of leaves: 89 below a thin ancestor five levels up (`F(11)`), 144 below a
/// thick one (`F(12)`).
pub(crate) const CLASSES: usize = 233;

/// Bands of the threshold fraction `t` in `(phi^-2, 1]`, equal in `log t` (each `t` within
/// a factor `phi^(2/21) = 1.047`): which leaves of a class's ancestor are kept changes with
/// `t`, and with it the move that spaces them; with four bands (a factor 1.27 each) the
/// sets of 1024 points kept a low band of 0.143, with these 0.047.
pub(crate) const BANDS: usize = 21;

/// A correction table: for each band and class, the offset `(alpha, beta)` of the sample
/// from the leaf's centroid in the leaf's frame, `alpha (b - a) + beta (c - a)`.
pub type Table = [[[f64; 2]; CLASSES]; BANDS];

/// The correction table made by [`crate::blue_noise::penrose_train`] (see
/// `examples/gen_penrose_table.rs`).
// Trained data: an entry may come near a named constant (1.57070 against pi / 2).
#[allow(clippy::approx_constant)]
pub(super) static CORRECTIONS: Table = include!("../../../tables/penrose_corrections.rs");

/// The band of a threshold fraction `t` (`(phi^-2, 1]` maps onto `0 .. BANDS`, outside
/// clamped to the ends).
pub(crate) fn band(t: f64) -> usize {
    let u = (1.0 / t).ln() / (PHI * PHI).ln();
    ((u * BANDS as f64).floor().max(0.0) as usize).min(BANDS - 1)
}

/// The class of the leaf at the end of `path` (module doc of [`Leaf::class`]).
pub(super) fn class(path: &[(Kind, u8)]) -> u8 {
    let Some(tail) = path
        .len()
        .checked_sub(CLASS_DEPTH)
        .and_then(|s| path.get(s..))
    else {
        return NO_CLASS;
    };
    let mut local = 0u64;
    for (i, &(kind, child)) in tail.iter().enumerate() {
        let (tn, tk) = leaves(CLASS_DEPTH - 1 - i);
        local += match kind {
            Kind::Thin => u64::from(child) * tn,
            Kind::Thick => u64::from(child) * tk,
        };
    }
    let base = if tail[0].0 == Kind::Thick {
        leaves(CLASS_DEPTH).0
    } else {
        0
    };
    (local + base) as u8
}

/// The direction of `v` in steps of 18° (`0 .. 20`).
pub(super) fn direction(v: [f64; 2]) -> u8 {
    let k = (v[1].atan2(v[0]) / (core::f64::consts::PI / 10.0)).round() as i64;
    k.rem_euclid(20) as u8
}

/// The sample of `leaf`: its centroid moved by `table[band][class]` in its frame (legs of
/// length `leg`), or the centroid when it has no class. A move that would leave the square
/// stops at its border (each coordinate clamped into `[0, 1)`): left at its centroid, the
/// sample would sit on a neighbour that moved towards it.
pub(crate) fn place(leaf: &Leaf, frame: &Frame, leg: f64, band: usize, table: &Table) -> [f64; 2] {
    let Some(&[alpha, beta]) = table
        .get(band)
        .and_then(|row| row.get(usize::from(leaf.class)))
    else {
        return leaf.p;
    };
    let [e1, e2] = leaf.dirs.map(|k| {
        let t = f64::from(k) * core::f64::consts::PI / 10.0;
        frame.rotate([leg * t.cos(), leg * t.sin()])
    });
    let moved = [
        leaf.p[0] + alpha * e1[0] + beta * e2[0],
        leaf.p[1] + alpha * e1[1] + beta * e2[1],
    ];
    if inside(moved) {
        moved
    } else {
        moved.map(|v| v.clamp(0.0, LAST_BELOW_ONE))
    }
}

/// The largest `f64` below 1.
const LAST_BELOW_ONE: f64 = 1.0 - f64::EPSILON / 2.0;

#[cfg(test)]
mod tests {
    use super::*;

    /// The classes count the leaves of a thin and a thick triangle `CLASS_DEPTH` levels
    /// down: consecutive Fibonacci numbers (thin `F(2h+1)`, thick `F(2h+2)`).
    #[test]
    fn classes_are_the_leaves_below_the_ancestor() {
        let (thin, thick) = leaves(CLASS_DEPTH);
        assert_eq!((thin, thick), (89, 144));
        assert_eq!((thin + thick) as usize, CLASSES);
        assert!(CLASSES < usize::from(NO_CLASS));
    }

    /// The bands cut `(phi^-2, 1]` into `BANDS` equal steps of `log t`: the middle of the
    /// step `b`, `t = phi^(-2 (b + 1/2) / BANDS)`, falls in band `b`, and the ends clamp.
    #[test]
    fn bands_are_equal_steps_of_log_t() {
        for b in 0..BANDS {
            let mid = PHI.powf(-2.0 * (b as f64 + 0.5) / BANDS as f64);
            assert_eq!(band(mid), b);
            let lo = PHI.powf(-2.0 * (b as f64 + 0.99) / BANDS as f64);
            assert_eq!(band(lo), b, "{b}");
        }
        assert_eq!(band(1.0), 0);
        assert_eq!(band(2.0), 0);
        assert_eq!(band(1.0 / (PHI * PHI) + 1e-9), BANDS - 1);
        assert_eq!(band(0.01), BANDS - 1);
    }
}
