//! Bridson's candidates: uniform points of the spherical shell `r <= |y| < 2r` around an
//! active point, in any unit (the grid passes `r` in units of `2^-32`).
//!
//! * **2D**, without rejection: one `u64` draw gives the angle (32 bits) and the radius (32
//!   bits). The radius is `r sqrt(1 + 3v)` (the area of the annulus grows as `rho^2 - r^2`);
//!   the direction `(cos t, sin t)`, `t = 2 pi u`, is a table entry at the top
//!   [`ANGLE_BITS`] bits of `u` rotated by the remaining angle `delta < 2 pi / 1024`, whose
//!   cosine and sine are Taylor polynomials to `delta^4` and `delta^5` (remainders below
//!   `delta^6 / 6! < 10^-16`: the direction is exact to rounding). No branch depends on the
//!   draw, so candidates cost no mispredictions.
//! * **3D and below otherwise** (1D, 3D): rejection from the cube `[-2r, 2r)^d`, accepting
//!   `1/2` (1D) and `7 pi / 48` (3D) of the draws; 32 bits a coordinate.
//! * **4D and up**: a normal vector for the direction and the radius
//!   `r (1 + u (2^d - 1))^(1/d)`.
//!
//! On the **surface** instead ([`Shell::surface`], SciPy's `hypersphere="surface"`): the
//! direction of the shell's draw, uniform on the sphere by symmetry, rescaled to the
//! radius [`SURFACE_FACTOR`]` r`, just outside the disk so that the candidate is not
//! rejected by its own centre; one square root more a candidate.

use super::rng::Rng;

/// The radius of a surface candidate, relative to `r` (SciPy's factor).
pub(crate) const SURFACE_FACTOR: f64 = 1.001;

/// Table bits of the 2D angle.
pub(crate) const ANGLE_BITS: u32 = 10;

/// The candidate generator of one construction (radius fixed).
pub(crate) struct Shell<const D: usize> {
    r: f64,
    /// `Some(rho)`: candidates on the sphere of radius `rho` (see [`Shell::surface`]).
    surface: Option<f64>,
    /// 2D: `(cos, sin)` at `2 pi j / 2^ANGLE_BITS`; empty otherwise.
    directions: Vec<[f64; 2]>,
}

impl<const D: usize> Shell<D> {
    /// The shell of inner radius `r`.
    pub(crate) fn new(r: f64) -> Self {
        let directions = if D == 2 {
            (0..1u32 << ANGLE_BITS)
                .map(|j| {
                    let t = core::f64::consts::TAU * f64::from(j) / f64::from(1u32 << ANGLE_BITS);
                    [t.cos(), t.sin()]
                })
                .collect()
        } else {
            Vec::new()
        };
        Shell {
            r,
            surface: None,
            directions,
        }
    }

    /// The sphere of radius [`SURFACE_FACTOR`]` r` when `surface`, else the shell of
    /// [`new`](Self::new).
    pub(crate) fn with_surface(r: f64, surface: bool) -> Self {
        let mut s = Self::new(r);
        if surface {
            s.surface = Some(r * SURFACE_FACTOR);
        }
        s
    }

    /// A uniform point of the shell (of the sphere, for a surface shell).
    #[inline]
    pub(crate) fn draw(&self, rng: &mut Rng) -> [f64; D] {
        let y = self.draw_shell(rng);
        let Some(rho) = self.surface else {
            return y;
        };
        // |y| >= r > 0: the shell's draw is never the origin.
        let s: f64 = y.iter().map(|v| v * v).sum();
        let scale = if s > 0.0 { rho / s.sqrt() } else { 0.0 };
        y.map(|v| v * scale)
    }

    #[inline]
    fn draw_shell(&self, rng: &mut Rng) -> [f64; D] {
        if D == 2 {
            return self.draw_2d(rng);
        }
        if D <= 3 {
            return self.draw_cube(rng);
        }
        self.draw_normal(rng)
    }

    #[inline]
    fn draw_2d(&self, rng: &mut Rng) -> [f64; D] {
        const FRAC: f64 = 1.0 / 4_294_967_296.0;
        let bits = rng.next_u64();
        let u = (bits >> 32) as u32;
        let v = bits as u32;
        let j = (u >> (32 - ANGLE_BITS)) as usize;
        let [c0, s0] = self.directions.get(j).copied().unwrap_or([1.0, 0.0]);
        let rest = u & ((1u32 << (32 - ANGLE_BITS)) - 1);
        let d = f64::from(rest) * (core::f64::consts::TAU * FRAC);
        let d2 = d * d;
        let cd = 1.0 - d2 * (0.5 - d2 * (1.0 / 24.0));
        let sd = d * (1.0 - d2 * (1.0 / 6.0 - d2 * (1.0 / 120.0)));
        let rho = self.r * (1.0 + 3.0 * f64::from(v) * FRAC).sqrt();
        let mut y = [0.0; D];
        if let [x0, x1, ..] = &mut y[..] {
            *x0 = rho * (c0 * cd - s0 * sd);
            *x1 = rho * (s0 * cd + c0 * sd);
        }
        y
    }

    fn draw_cube(&self, rng: &mut Rng) -> [f64; D] {
        let r = self.r;
        let (lo, hi) = (r * r, 4.0 * r * r);
        let step = 4.0 * r / 4_294_967_296.0;
        let mut y = [0.0; D];
        loop {
            let mut s = 0.0;
            let mut bits = 0u64;
            for (k, v) in y.iter_mut().enumerate() {
                if k % 2 == 0 {
                    bits = rng.next_u64();
                }
                let half = if k % 2 == 0 {
                    bits >> 32
                } else {
                    bits & 0xFFFF_FFFF
                };
                *v = half as f64 * step - 2.0 * r;
                s += *v * *v;
            }
            if s >= lo && s < hi {
                return y;
            }
        }
    }

    fn draw_normal(&self, rng: &mut Rng) -> [f64; D] {
        let mut y = [0.0; D];
        let mut s = 0.0;
        for v in y.iter_mut() {
            *v = rng.normal();
            s += *v * *v;
        }
        let u = rng.unit();
        let rho = self.r * (1.0 + u * ((1u64 << D) as f64 - 1.0)).powf(1.0 / D as f64);
        let scale = if s > 0.0 { rho / s.sqrt() } else { 0.0 };
        for v in y.iter_mut() {
            *v *= scale;
        }
        y
    }
}
