//! Bridson's algorithm and the maximal fill, generic over the dimension.
//!
//! Bridson (SIGGRAPH 2007 sketch, "Fast Poisson disk sampling in arbitrary dimensions"):
//! start from one uniform point, keep an active list; take a random active point, try up to
//! `k` candidates uniform in the spherical shell `r <= |y - x| < 2r` around it; accept the
//! first that is free (at least `r` from every point, checked in the grid), else retire the
//! point. `O(N)` time and memory.
//!
//! Maximal fill (in the manner of Ebeida et al., "Efficient maximal Poisson-disk sampling",
//! SIGGRAPH 2011): the empty grid cells not inside a single disk of radius `r` are the
//! active cubes; throw as many darts as there are cubes (a random cube, a uniform point in
//! it, kept when free), then split every cube not inside one disk into `2^d` children and
//! keep those not inside one disk; repeat. A cube survives only near the corners of the
//! union of disks, so the cube count shrinks geometrically. Cubes below the finest side
//! [`FINEST`]` r` get one last dart at their centre and are dropped.

use super::grid::{Grid, SCALE, axis_gap, quantize_units, to_unit};
use super::rng::Rng;
use super::shell::Shell;
use crate::Result;
use crate::work::Budget;

/// The side, relative to `r`, below which a cube is no longer split: its points lie within
/// `r (1 + sqrt(d) 2^-21)` of a sample at the end.
pub(crate) const FINEST: f64 = 1.0 / (1u64 << 20) as f64;

/// Runs Bridson's algorithm with `k` candidates a step (on the sphere of radius `1.001 r`
/// when `surface`, else in the shell `r .. 2r`) into `grid` (empty), checking the
/// deadline of the (started) `budget` about once every [`crate::work::PACER_INTERVAL`]
/// neighbour-cell visits' worth of candidates.
///
/// # Errors
/// [`crate::Error::OutOfTime`] past the deadline.
pub(crate) fn bridson<const D: usize>(
    grid: &mut Grid<D>,
    k: u32,
    surface: bool,
    rng: &mut Rng,
    budget: &Budget,
) -> Result<()> {
    let mut pacer = budget.pacer("Poisson-disk sampling");
    let step_weight = k.saturating_mul(grid.test_weight());
    let torus = grid.torus;
    let shell = Shell::<D>::with_surface(grid.r * SCALE, surface);
    let mut first = [0u32; D];
    for v in first.iter_mut() {
        *v = rng.fraction();
    }
    let Some(i0) = grid.insert(first) else {
        return Ok(());
    };
    let mut active: Vec<u32> = vec![i0 as u32];
    while !active.is_empty() {
        pacer.tick_n(step_weight)?;
        let slot = rng.below(active.len());
        let Some(&centre_idx) = active.get(slot) else {
            break;
        };
        let Some(&centre) = grid.pts.get(centre_idx as usize) else {
            break;
        };
        let mut placed = false;
        'tries: for _ in 0..k {
            let off = shell.draw(rng);
            let mut p = [0u32; D];
            for ((pk, &c), o) in p.iter_mut().zip(&centre).zip(&off) {
                match quantize_units(f64::from(c) + o, torus) {
                    Some(x) => *pk = x,
                    None => continue 'tries,
                }
            }
            if grid.is_free(&p) {
                if let Some(i) = grid.insert(p) {
                    active.push(i as u32);
                    placed = true;
                    break;
                }
                return Ok(()); // the point limit: stop with what we have
            }
        }
        if !placed {
            active.swap_remove(slot);
        }
    }
    Ok(())
}

/// An axis-aligned cube of the maximal fill.
#[derive(Clone, Copy)]
struct Cube<const D: usize> {
    lo: [f64; D],
    side: f64,
}

/// Whether the whole cube lies within `r` of one stored point.
fn covered<const D: usize>(grid: &Grid<D>, cube: &Cube<D>) -> bool {
    let mut centre = [0.0; D];
    for (c, lo) in centre.iter_mut().zip(&cube.lo) {
        *c = (lo + 0.5 * cube.side).min(1.0 - f64::EPSILON);
    }
    let cell = grid.cell_of_unit(&centre);
    let (r2, torus, half) = (grid.r * grid.r, grid.torus, 0.5 * cube.side);
    grid.any_near(&cell, |q| {
        let p = to_unit(q);
        let mut far2 = 0.0;
        for (x, c) in p.iter().zip(&centre) {
            let far = axis_gap(*x, *c, torus) + half;
            far2 += far * far;
        }
        far2 <= r2
    })
}

/// Pushes `v`, growing `list` through [`crate::size::reserve`]: the cubes of a maximal fill
/// in high dimension can multiply past any memory, and are refused at 1 GiB.
fn push_checked<T>(list: &mut Vec<T>, v: T) -> Result<()> {
    if list.len() == list.capacity() {
        let more = list.len().max(64);
        crate::size::reserve(list, more)?;
    }
    list.push(v);
    Ok(())
}

/// A dart at the point `x` (quantized): inserted when free.
fn dart<const D: usize>(grid: &mut Grid<D>, x: &[f64; D]) {
    let mut p = [0u32; D];
    for (pk, v) in p.iter_mut().zip(x) {
        match quantize_units(*v * SCALE, grid.torus) {
            Some(q) => *pk = q,
            None => return,
        }
    }
    if grid.is_free(&p) {
        let _ = grid.insert(p);
    }
}

/// Fills `grid` up to a maximal set (see the module text), checking the deadline of the
/// (started) `budget` as it goes. In 3 or more dimensions the cubes along the
/// `(d - 2)`-dimensional intersections of sphere boundaries multiply at each split
/// (`2^(d - 2)` a level, down to [`FINEST`]), so the running time cannot be bounded
/// usefully in advance: the deadline is the bound.
///
/// # Errors
/// [`crate::Error::OutOfTime`] past the deadline.
pub(crate) fn fill_maximal<const D: usize>(
    grid: &mut Grid<D>,
    rng: &mut Rng,
    budget: &Budget,
) -> Result<()> {
    let mut pacer = budget.pacer("maximal Poisson-disk fill");
    let weight = grid.test_weight();
    let g = grid.g;
    let side = 1.0 / g as f64;
    let mut active: Vec<Cube<D>> = Vec::new();
    let cells = g.pow(D as u32);
    for code in 0..cells {
        pacer.tick_n(weight)?;
        let mut c = [0usize; D];
        let mut rest = code;
        for ck in c.iter_mut() {
            *ck = rest % g;
            rest /= g;
        }
        if grid.occupied(&c) {
            continue;
        }
        let mut lo = [0.0; D];
        for (l, ck) in lo.iter_mut().zip(&c) {
            *l = *ck as f64 * side;
        }
        let cube = Cube { lo, side };
        if !covered(grid, &cube) {
            push_checked(&mut active, cube)?;
        }
    }
    let finest = grid.r * FINEST;
    while !active.is_empty() {
        for _ in 0..active.len() {
            pacer.tick_n(weight)?;
            let Some(cube) = active.get(rng.below(active.len())).copied() else {
                break;
            };
            let mut x = cube.lo;
            for v in x.iter_mut() {
                *v += rng.unit() * cube.side;
            }
            dart(grid, &x);
        }
        let mut next = Vec::new();
        for cube in &active {
            pacer.tick_n(weight.saturating_mul(1 << D))?;
            if covered(grid, cube) {
                continue;
            }
            let half = 0.5 * cube.side;
            if half < finest {
                let mut x = cube.lo;
                for v in x.iter_mut() {
                    *v += half;
                }
                dart(grid, &x);
                continue;
            }
            for child in 0..(1usize << D) {
                let mut lo = cube.lo;
                for (k, l) in lo.iter_mut().enumerate() {
                    if child >> k & 1 == 1 {
                        *l += half;
                    }
                }
                let c = Cube { lo, side: half };
                if !covered(grid, &c) {
                    push_checked(&mut next, c)?;
                }
            }
        }
        active = next;
    }
    Ok(())
}
