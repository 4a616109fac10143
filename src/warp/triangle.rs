//! Uniform points in a triangle by Heitz's low-distortion map ("A low-distortion map between
//! triangle and square", 2019), as barycentric coordinates.
//!
//! The square is split along its diagonal and each half is sheared onto the triangle, so
//! neighbouring strata stay neighbours (the classic `sqrt` map folds them). The density is
//! uniform: `1 / area` on a triangle of that area (2 on the reference triangle).

use super::MAX_COORDINATE;

/// Barycentric coordinates `(b0, b1, b2)`, `b0 + b1 + b2 = 1`, of a uniform point:
/// `b0 = u0 / 2, b1 = u1 - b0` when `u0 < u1`, otherwise `b1 = u1 / 2, b0 = u0 - b1`.
///
/// ```
/// use qmckit::warp::triangle::{invert_uniform_triangle, sample_uniform_triangle};
/// let b = sample_uniform_triangle([0.25, 0.75]);
/// assert_eq!(b, [0.125, 0.625, 0.25]); // u0 < u1: b0 = u0 / 2, b1 = u1 - b0
/// assert_eq!(invert_uniform_triangle(b), [0.25, 0.75]);
/// ```
#[inline]
pub fn sample_uniform_triangle(u: [f32; 2]) -> [f32; 3] {
    let (b0, b1) = if u[0] < u[1] {
        let b0 = u[0] / 2.0;
        (b0, u[1] - b0)
    } else {
        let b1 = u[1] / 2.0;
        (u[0] - b1, b1)
    };
    [b0, b1, 1.0 - b0 - b1]
}

/// Inverse of [`sample_uniform_triangle`]: `u = (2 b0, b0 + b1)` when `b0 < b1`, otherwise
/// `(b0 + b1, 2 b1)`.
#[inline]
pub fn invert_uniform_triangle(b: [f32; 3]) -> [f32; 2] {
    if b[0] < b[1] {
        [2.0 * b[0], b[0] + b[1]]
    } else {
        [b[0] + b[1], 2.0 * b[1]]
    }
}

/// The point of triangle `(p0, p1, p2)` with barycentrics `b`, and the uniform density
/// `1 / area` (0 for a degenerate triangle). Works in 2D or 3D (`N` = 2 or 3). No
/// validation: [`Triangle::new`] checks the vertices once.
pub fn point_in_triangle<const N: usize>(p: [[f32; N]; 3], b: [f32; 3]) -> ([f32; N], f32) {
    let mut x = [0f32; N];
    for (k, xk) in x.iter_mut().enumerate() {
        *xk = b[0] * p[0][k] + b[1] * p[1][k] + b[2] * p[2][k];
    }
    let area = triangle_area(p);
    (x, if area > 0.0 { 1.0 / area } else { 0.0 })
}

/// Area of a triangle in 2D or 3D (half the norm of the edge cross product).
pub fn triangle_area<const N: usize>(p: [[f32; N]; 3]) -> f32 {
    let mut e1 = [0f32; 3];
    let mut e2 = [0f32; 3];
    for k in 0..N.min(3) {
        e1[k] = p[1][k] - p[0][k];
        e2[k] = p[2][k] - p[0][k];
    }
    let c = [
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ];
    0.5 * libm::sqrtf(c[0] * c[0] + c[1] * c[1] + c[2] * c[2])
}

/// A triangle in 2D or 3D (`N` = 2 or 3), validated once for uniform sampling by
/// [`sample_uniform_triangle`].
///
/// ```
/// use qmckit::warp::triangle::Triangle;
/// let t = Triangle::new([[0.0, 0.0], [4.0, 0.0], [0.0, 2.0]])?;
/// assert_eq!(t.pdf(), 0.25); // 1 / area
/// assert_eq!(t.sample([0.25, 0.75]).0, [2.5, 0.5]); // b = (0.125, 0.625, 0.25)
/// assert!(Triangle::new([[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]).is_err()); // collinear
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
#[cfg_attr(feature = "defmt", derive(defmt::Format))]
pub struct Triangle<const N: usize> {
    p: [[f32; N]; 3],
    pdf: f32,
}

impl<const N: usize> Triangle<N> {
    /// The triangle `p`.
    ///
    /// # Errors
    /// [`crate::Error::InvalidParameter`] when `N` is not 2 or 3, a coordinate is not
    /// finite or larger than [`MAX_COORDINATE`] (`2^64`) in magnitude, the triangle is degenerate
    /// (twice its area below `2^-20` of its longest edge squared: collinear to about `f32`
    /// rounding), or its density `1 / area` is not a finite `f32`. The area is computed in
    /// `f64`.
    pub fn new(p: [[f32; N]; 3]) -> crate::Result<Self> {
        let bad = |what| Err(crate::Error::InvalidParameter { what });
        if N != 2 && N != 3 {
            return bad("a triangle has 2 or 3 coordinates a vertex");
        }
        if !p
            .iter()
            .flatten()
            .all(|x| x.is_finite() && x.abs() <= MAX_COORDINATE)
        {
            return bad("a coordinate is not finite or is larger than 2^64 in magnitude");
        }
        let edge = |i: usize, j: usize| {
            let mut e = [0f64; 3];
            for (k, ek) in e.iter_mut().enumerate().take(N) {
                *ek = p[j][k] as f64 - p[i][k] as f64;
            }
            e
        };
        let (e1, e2, e3) = (edge(0, 1), edge(0, 2), edge(1, 2));
        let norm2 = |e: [f64; 3]| e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        let c = [
            e1[1] * e2[2] - e1[2] * e2[1],
            e1[2] * e2[0] - e1[0] * e2[2],
            e1[0] * e2[1] - e1[1] * e2[0],
        ];
        let twice_area = libm::sqrt(norm2(c));
        let longest2 = norm2(e1).max(norm2(e2)).max(norm2(e3));
        if twice_area < longest2 / 1_048_576.0 {
            return bad("the triangle is degenerate (its vertices are collinear)");
        }
        let pdf = (2.0 / twice_area) as f32;
        if !(pdf.is_finite() && pdf > 0.0) {
            return bad("the triangle's density 1 / area is not a finite f32");
        }
        Ok(Triangle { p, pdf })
    }

    /// The uniform density `1 / area`.
    pub fn pdf(&self) -> f32 {
        self.pdf
    }

    /// The point of barycentrics [`sample_uniform_triangle`]`(u)` and the density: the same
    /// point as [`point_in_triangle`], finite for every `u` in `[0, 1]^2`.
    pub fn sample(&self, u: [f32; 2]) -> ([f32; N], f32) {
        let b = sample_uniform_triangle(u);
        let mut x = [0f32; N];
        for (k, xk) in x.iter_mut().enumerate() {
            *xk = b[0] * self.p[0][k] + b[1] * self.p[1][k] + b[2] * self.p[2][k];
        }
        (x, self.pdf)
    }
}
