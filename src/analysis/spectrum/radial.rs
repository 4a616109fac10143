//! Radial power spectrum and anisotropy of a periodogram (Ulichney 1988; the conventions of
//! psa, Heck, Schlömer & Deussen 2013, and of UTK's radial spectrum).
//!
//! Conventions: the annulus of integer radius `r` holds the frequencies `k != 0` with
//! `round(|k|) = r` (bins of width 1 centred on the integers, `1 <= r <= K`, so every
//! annulus lies inside the computed square `[-K, K]^2`); the radial mean is the plain mean
//! of `P(k)` over the annulus (both `k` and `-k` counted); the anisotropy is the sample
//! variance over the annulus (divisor `count - 1`) over the squared mean, 1 (0 dB) for white
//! noise, whose values are exponentially distributed. psa and UTK plot frequency in units
//! of `sqrt(N)` (the mean spacing's inverse): `r / sqrt(N)`, the abscissa
//! [`RadialBin::frequency`] gives. Cost: two passes over the `(2K + 1)^2` values.

use super::{RadialBin, Spectrum};

impl RadialBin {
    /// The radius in units of `sqrt(N)`: `r / sqrt(points)`, the abscissa on which the
    /// spectra of sets of different sizes coincide (psa, UTK).
    pub fn frequency(&self, points: usize) -> f64 {
        self.radius as f64 / (points.max(1) as f64).sqrt()
    }
}

impl Spectrum {
    /// The radial power spectrum and anisotropy for `r = 1 ..= K` (empty for `K = 0`), in
    /// the conventions of the module documentation.
    ///
    /// ```
    /// use qmckit::analysis::{Points, spectrum::spectrum_2d};
    /// // One point: P(k) = 1 everywhere but k = 0, so every annulus has mean 1 and
    /// // anisotropy 0.
    /// let s = spectrum_2d(Points::new(&[0.3, 0.7], 2)?, 3, &qmckit::work::Budget::DEFAULT)?;
    /// let radial = s.radial();
    /// assert_eq!(radial.len(), 3);
    /// assert_eq!(radial[0].count, 8); // (±1, 0), (0, ±1), (±1, ±1): |k| rounds to 1
    /// assert!(radial.iter().all(|b| (b.mean - 1.0).abs() < 1e-12 && b.anisotropy < 1e-20));
    /// # Ok::<(), qmckit::Error>(())
    /// ```
    pub fn radial(&self) -> Vec<RadialBin> {
        let bins = self.k_max + 1;
        let (mut count, mut sum) = (vec![0usize; bins], vec![0.0f64; bins]);
        let ring = |kx: i64, ky: i64| ((kx * kx + ky * ky) as f64).sqrt().round() as usize;
        for (kx, ky, p) in self.iter() {
            let r = ring(kx, ky);
            if let (Some(c), Some(s)) = (count.get_mut(r), sum.get_mut(r))
                && (kx, ky) != (0, 0)
            {
                *c += 1;
                *s += p;
            }
        }
        let mean = |r: usize| {
            let c = count.get(r).copied().unwrap_or(0).max(1) as f64;
            sum.get(r).copied().unwrap_or(0.0) / c
        };
        let mut squares = vec![0.0f64; bins];
        for (kx, ky, p) in self.iter() {
            let r = ring(kx, ky);
            if let Some(q) = squares.get_mut(r)
                && (kx, ky) != (0, 0)
            {
                let dev = p - mean(r);
                *q += dev * dev;
            }
        }
        (1..bins)
            .map(|r| {
                let (m, c) = (mean(r), count.get(r).copied().unwrap_or(0));
                let variance =
                    squares.get(r).copied().unwrap_or(0.0) / c.saturating_sub(1).max(1) as f64;
                RadialBin {
                    radius: r,
                    count: c,
                    mean: m,
                    anisotropy: if m > 0.0 { variance / (m * m) } else { 0.0 },
                }
            })
            .collect()
    }
}
