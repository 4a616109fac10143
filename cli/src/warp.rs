//! `--warp NAME`: map the 2D samples onto a domain. The geometry is validated by the
//! library's constructors (`UniformCone`, `Triangle`, `SphericalTriangle`,
//! `SphericalRectangle`); what they refuse is a one-line usage error.

use clap::{Args, ValueEnum};
use qmckit::warp::sphere::UniformCone;
use qmckit::warp::spherical::{SphericalRectangle, SphericalTriangle};
use qmckit::warp::triangle::Triangle;
use qmckit::warp::{disk, gaussian, sphere, triangle};

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
    /// Map the points through a warp; output is real-valued (--format decimal, csv or npy).
    #[arg(long, value_enum)]
    pub warp: Option<WarpName>,
    /// Cone half-angle in degrees (0 < angle <= 180; at least about 0.014, where its cosine
    /// is still below 1 in f32), for --warp cone [default: 30].
    #[arg(long)]
    pub cone_angle: Option<f32>,
    /// Triangle corners "x,y[,z];x,y[,z];x,y[,z]" for --warp triangle / spherical-triangle.
    /// Coordinates within +-2^64; the triangle not degenerate (collinear within 2^-20), and
    /// for spherical-triangle --origin off its plane (by 2^-20 of the distance) with a solid
    /// angle of at least 2^-24 sr.
    #[arg(long, allow_hyphen_values = true)]
    pub vertices: Option<String>,
    /// Rectangle "corner;edge_x;edge_y" (3 numbers each) for --warp spherical-rectangle.
    /// Coordinates within +-2^64; edges perpendicular (|cos| <= 2^-16) and at least 2^-20 of
    /// the distance long; --origin off the rectangle's plane (by 2^-20 of the distance) with
    /// a solid angle of at least 2^-24 sr.
    #[arg(long, allow_hyphen_values = true)]
    pub rect: Option<String>,
    /// Viewpoint "x,y,z" of the spherical warps [default: 0,0,0].
    #[arg(long, allow_hyphen_values = true)]
    pub origin: Option<String>,
}

impl WarpArgs {
    /// Refuses every warp option that the chosen warp (or no warp) does not use.
    pub fn check_options(&self) -> Result<(), Failure> {
        use WarpName as W;
        let uses: [(&str, bool, &[WarpName]); 4] = [
            ("--cone-angle", self.cone_angle.is_some(), &[W::Cone]),
            (
                "--vertices",
                self.vertices.is_some(),
                &[W::Triangle, W::SphericalTriangle],
            ),
            ("--rect", self.rect.is_some(), &[W::SphericalRectangle]),
            (
                "--origin",
                self.origin.is_some(),
                &[W::SphericalTriangle, W::SphericalRectangle],
            ),
        ];
        for (option, given, warps) in uses {
            if !given {
                continue;
            }
            match self.warp {
                None => {
                    return Err(Failure::usage(format!(
                        "{option} does not apply without --warp"
                    )));
                }
                Some(w) if !warps.contains(&w) => {
                    return Err(Failure::usage(format!(
                        "{option} does not apply to --warp {}",
                        w.to_possible_value()
                            .map(|v| v.get_name().to_owned())
                            .unwrap_or_default()
                    )));
                }
                Some(_) => {}
            }
        }
        Ok(())
    }
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

/// The geometry of a warp, validated by the library.
enum Geometry {
    None,
    Cone(UniformCone),
    Triangle2(Triangle<2>),
    Triangle3(Triangle<3>),
    SphericalTriangle(SphericalTriangle),
    SphericalRectangle(SphericalRectangle),
}

/// A prepared warp: output width and the per-point map of `u` (`dims` fractions in [0, 1)).
pub struct Warp {
    name: WarpName,
    geometry: Geometry,
}

/// A one-line usage error for geometry the library refuses.
fn refused(flags: &str, e: qmckit::Error) -> Failure {
    Failure::usage(format!("{flags}: degenerate or out-of-range geometry: {e}"))
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
        let cone_angle = args.cone_angle.unwrap_or(30.0);
        if name == W::Cone && !(cone_angle > 0.0 && cone_angle <= 180.0) {
            return Err(Failure::usage(format!(
                "--cone-angle {cone_angle} is out of range: it must be in (0, 180] degrees"
            )));
        }
        let origin_text = args.origin.as_deref().unwrap_or("0,0,0");
        let origin = v3(&parse_points("--origin", origin_text, 1, &[3])?[0]);
        let geometry = match (name, &args.vertices, &args.rect) {
            (W::Cone, _, _) => Geometry::Cone(
                UniformCone::new(libm::cosf(cone_angle.to_radians()))
                    .map_err(|e| refused("--cone-angle", e))?,
            ),
            (W::Triangle, Some(v), _) => {
                let p = parse_points("--vertices", v, 3, &[2, 3])?;
                if p[0].len() == 2 {
                    let p2 = |k: usize| [p[k][0], p[k][1]];
                    Geometry::Triangle2(
                        Triangle::new([p2(0), p2(1), p2(2)])
                            .map_err(|e| refused("--vertices", e))?,
                    )
                } else {
                    Geometry::Triangle3(
                        Triangle::new([v3(&p[0]), v3(&p[1]), v3(&p[2])])
                            .map_err(|e| refused("--vertices", e))?,
                    )
                }
            }
            (W::SphericalTriangle, Some(v), _) => {
                let p = parse_points("--vertices", v, 3, &[3])?;
                Geometry::SphericalTriangle(
                    SphericalTriangle::new([v3(&p[0]), v3(&p[1]), v3(&p[2])], origin)
                        .map_err(|e| refused("--vertices/--origin", e))?,
                )
            }
            (W::SphericalTriangle, None, _) => {
                return Err(Failure::usage(
                    "--warp spherical-triangle needs --vertices \"x,y,z;x,y,z;x,y,z\"",
                ));
            }
            (W::SphericalRectangle, _, Some(r)) => {
                let p = parse_points("--rect", r, 3, &[3])?;
                Geometry::SphericalRectangle(
                    SphericalRectangle::new(origin, v3(&p[0]), v3(&p[1]), v3(&p[2]))
                        .map_err(|e| refused("--rect/--origin", e))?,
                )
            }
            (W::SphericalRectangle, _, None) => {
                return Err(Failure::usage(
                    "--warp spherical-rectangle needs --rect \"corner;edge_x;edge_y\"",
                ));
            }
            _ => Geometry::None,
        };
        Ok(Warp { name, geometry })
    }

    /// Output values per point for `dims` inputs.
    pub fn width(&self, dims: usize) -> usize {
        use WarpName as W;
        match (self.name, &self.geometry) {
            (W::Disk | W::DiskPolar, _) => 2,
            (_, Geometry::Triangle2(_)) => 2,
            (W::BoxMuller | W::Normal, _) => dims,
            _ => 3,
        }
    }

    /// The warped point of `u`: finite for every `u` in [0, 1) (the library's guarantee for
    /// validated geometry).
    pub fn map(&self, u: &[f32]) -> Result<Vec<f32>, Failure> {
        use WarpName as W;
        let uv = || [u[0], u[1]];
        Ok(match (self.name, &self.geometry) {
            (W::Disk, _) => disk::sample_uniform_disk_concentric(uv()).to_vec(),
            (W::DiskPolar, _) => disk::sample_uniform_disk_polar(uv()).to_vec(),
            (W::Hemisphere, _) => sphere::sample_uniform_hemisphere(uv()).to_vec(),
            (W::CosineHemisphere, _) => sphere::sample_cosine_hemisphere(uv()).to_vec(),
            (W::Sphere, _) => sphere::sample_uniform_sphere(uv()).to_vec(),
            (_, Geometry::Cone(c)) => c.sample(uv()).to_vec(),
            (_, Geometry::Triangle2(t)) => t.sample(uv()).0.to_vec(),
            (_, Geometry::Triangle3(t)) => t.sample(uv()).0.to_vec(),
            (_, Geometry::SphericalTriangle(t)) => t.sample(uv()).0.to_vec(),
            (_, Geometry::SphericalRectangle(r)) => r.sample(uv()).0.to_vec(),
            (W::Triangle, _) => triangle::sample_uniform_triangle(uv()).to_vec(),
            (W::BoxMuller, _) => u
                .chunks_exact(2)
                .flat_map(|p| gaussian::sample_box_muller([p[0], p[1]]))
                .collect(),
            (W::Normal, _) => u.iter().map(|&x| gaussian::sample_normal(x)).collect(),
            (W::Cone | W::SphericalTriangle | W::SphericalRectangle, Geometry::None) => {
                return Err(Failure::usage("the warp's geometry is missing"));
            }
        })
    }
}
