//! `--warp NAME`: map the 2D samples onto a domain (DESIGN.md §4, issue 5).

use clap::{Args, ValueEnum};
use qmckit::warp::{disk, gaussian, sphere, spherical, triangle};

use super::Failure;

/// The warps `points --warp` knows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum WarpName {
    /// Unit disk, concentric map (x y).
    Disk,
    /// Unit disk, polar map (x y).
    DiskPolar,
    /// Uniform hemisphere around +z (x y z).
    Hemisphere,
    /// Cosine-weighted hemisphere around +z (x y z).
    CosineHemisphere,
    /// Uniform sphere (x y z).
    Sphere,
    /// Uniform cone around +z of half-angle --cone-angle degrees (x y z).
    Cone,
    /// Uniform triangle: barycentrics (b0 b1 b2), or points of --vertices (2D or 3D).
    Triangle,
    /// Directions toward the triangle --vertices seen from --origin, by solid angle (x y z).
    SphericalTriangle,
    /// Points of the rectangle --rect seen from --origin, by solid angle (x y z).
    SphericalRectangle,
    /// Box–Muller: each pair of coordinates to two standard normals.
    BoxMuller,
    /// Inverse normal CDF: each coordinate to a standard normal.
    Normal,
}

/// Parameters of the warps.
#[derive(Args, Debug, Clone)]
pub struct WarpArgs {
    /// Map the points through a warp; output is real-valued (--format csv or npy).
    #[arg(long, value_enum)]
    pub warp: Option<WarpName>,
    /// Cone half-angle in degrees (0 < angle <= 180), for --warp cone.
    #[arg(long, default_value_t = 30.0)]
    pub cone_angle: f32,
    /// Triangle corners "x,y[,z];x,y[,z];x,y[,z]" for --warp triangle / spherical-triangle.
    #[arg(long, allow_hyphen_values = true)]
    pub vertices: Option<String>,
    /// Rectangle "corner;edge_x;edge_y" (3 numbers each, edges perpendicular) for
    /// --warp spherical-rectangle.
    #[arg(long, allow_hyphen_values = true)]
    pub rect: Option<String>,
    /// Viewpoint "x,y,z" of the spherical warps.
    #[arg(long, default_value = "0,0,0", allow_hyphen_values = true)]
    pub origin: String,
}

/// A list of `count` points of `dims` numbers: "a,b,c;d,e,f".
fn parse_points(
    flag: &str,
    text: &str,
    count: usize,
    dims: &[usize],
) -> Result<Vec<Vec<f32>>, Failure> {
    let bad = |why: &str| Failure::usage(format!("{flag} {text:?}: {why}"));
    let pts: Vec<Vec<f32>> = text
        .split(';')
        .map(|p| {
            p.split(',')
                .map(|x| {
                    x.trim()
                        .parse::<f32>()
                        .map_err(|_| bad(&format!("{x:?} is not a number")))
                })
                .collect::<Result<Vec<f32>, Failure>>()
        })
        .collect::<Result<_, _>>()?;
    if pts.len() != count {
        return Err(bad(&format!("expected {count} point(s) separated by ';'")));
    }
    let d = pts[0].len();
    if !dims.contains(&d) || pts.iter().any(|p| p.len() != d) {
        return Err(bad(&format!("each point needs {dims:?} coordinates")));
    }
    if pts.iter().flatten().any(|x| !x.is_finite()) {
        return Err(bad("coordinates must be finite"));
    }
    Ok(pts)
}

fn v3(p: &[f32]) -> [f32; 3] {
    [p[0], p[1], p[2]]
}

/// A prepared warp: output width and the per-point map of `u` (`dims` fractions in [0, 1)).
pub struct Warp {
    name: WarpName,
    cos_max: f32,
    vertices: Vec<Vec<f32>>,
    rect: Vec<[f32; 3]>,
    origin: [f32; 3],
}

impl Warp {
    /// Validates the parameters for `name` and input dimension `dims`.
    pub fn new(args: &WarpArgs, name: WarpName, dims: usize) -> Result<Self, Failure> {
        use WarpName as W;
        let two_d = !matches!(name, W::BoxMuller | W::Normal);
        if two_d && dims != 2 {
            return Err(Failure::usage(format!(
                "--warp {} maps 2D points: -d must be 2, got {dims}",
                name.to_possible_value()
                    .map(|v| v.get_name().to_owned())
                    .unwrap_or_default()
            )));
        }
        if name == W::BoxMuller && !dims.is_multiple_of(2) {
            return Err(Failure::usage(format!(
                "--warp box-muller maps pairs: -d must be even, got {dims}"
            )));
        }
        if name == W::Cone && !(args.cone_angle > 0.0 && args.cone_angle <= 180.0) {
            return Err(Failure::usage(format!(
                "--cone-angle {} is out of range: it must be in (0, 180] degrees",
                args.cone_angle
            )));
        }
        let origin = parse_points("--origin", &args.origin, 1, &[3])?;
        let vertices = match (name, &args.vertices) {
            (W::Triangle, Some(v)) => parse_points("--vertices", v, 3, &[2, 3])?,
            (W::SphericalTriangle, Some(v)) => parse_points("--vertices", v, 3, &[3])?,
            (W::SphericalTriangle, None) => {
                return Err(Failure::usage(
                    "--warp spherical-triangle needs --vertices \"x,y,z;x,y,z;x,y,z\"",
                ));
            }
            _ => Vec::new(),
        };
        let rect = match (name, &args.rect) {
            (W::SphericalRectangle, Some(r)) => parse_points("--rect", r, 3, &[3])?
                .iter()
                .map(|p| v3(p))
                .collect(),
            (W::SphericalRectangle, None) => {
                return Err(Failure::usage(
                    "--warp spherical-rectangle needs --rect \"corner;edge_x;edge_y\"",
                ));
            }
            _ => Vec::new(),
        };
        let w = Warp {
            name,
            cos_max: libm::cosf(args.cone_angle.to_radians()),
            vertices,
            rect,
            origin: v3(&origin[0]),
        };
        // Refuse degenerate geometry once, instead of failing on every point.
        if w.map(&[0.5, 0.5])?.iter().any(|x| !x.is_finite()) {
            return Err(Failure::usage("the warp's geometry is degenerate"));
        }
        Ok(w)
    }

    /// Output values per point for `dims` inputs.
    pub fn width(&self, dims: usize) -> usize {
        use WarpName as W;
        match self.name {
            W::Disk | W::DiskPolar => 2,
            W::Triangle if self.vertices.first().is_some_and(|v| v.len() == 2) => 2,
            W::BoxMuller | W::Normal => dims,
            _ => 3,
        }
    }

    /// The warped point of `u`.
    pub fn map(&self, u: &[f32]) -> Result<Vec<f32>, Failure> {
        use WarpName as W;
        let uv = || [u[0], u[1]];
        Ok(match self.name {
            W::Disk => disk::sample_uniform_disk_concentric(uv()).to_vec(),
            W::DiskPolar => disk::sample_uniform_disk_polar(uv()).to_vec(),
            W::Hemisphere => sphere::sample_uniform_hemisphere(uv()).to_vec(),
            W::CosineHemisphere => sphere::sample_cosine_hemisphere(uv()).to_vec(),
            W::Sphere => sphere::sample_uniform_sphere(uv()).to_vec(),
            W::Cone => sphere::sample_uniform_cone(uv(), self.cos_max).to_vec(),
            W::Triangle => {
                let b = triangle::sample_uniform_triangle(uv());
                match self.vertices.as_slice() {
                    [p0, p1, p2] => (0..p0.len())
                        .map(|k| b[0] * p0[k] + b[1] * p1[k] + b[2] * p2[k])
                        .collect(),
                    _ => b.to_vec(),
                }
            }
            W::SphericalTriangle => {
                let v = [
                    v3(&self.vertices[0]),
                    v3(&self.vertices[1]),
                    v3(&self.vertices[2]),
                ];
                spherical::sample_spherical_triangle(v, self.origin, uv())
                    .ok_or_else(|| {
                        Failure::usage("the spherical triangle is degenerate seen from --origin")
                    })?
                    .0
                    .to_vec()
            }
            W::SphericalRectangle => spherical::sample_spherical_rectangle(
                self.origin,
                self.rect[0],
                self.rect[1],
                self.rect[2],
                uv(),
            )
            .ok_or_else(|| Failure::usage("the rectangle is degenerate seen from --origin"))?
            .0
            .to_vec(),
            W::BoxMuller => u
                .chunks_exact(2)
                .flat_map(|p| gaussian::sample_box_muller([p[0], p[1]]))
                .collect(),
            W::Normal => u.iter().map(|&x| gaussian::sample_normal(x)).collect(),
        })
    }
}
