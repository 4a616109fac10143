//! Void-and-cluster dither masks (Ulichney, "The void-and-cluster method for dither array
//! generation", SPIE 1913, 1993): a toroidal rank image whose every threshold is a
//! blue-noise binary pattern.
//!
//! The energy of a binary pattern `B` on the `W x H` torus is `E = G * B` (circular
//! convolution), `G(dx, dy) = exp(-(dx^2 + dy^2) / (2 sigma^2))`, `sigma = 1.5` pixels
//! (Ulichney), truncated at `|dx|, |dy| <= ceil(4 sigma)` (the dropped weights are below
//! `e^-8` of the centre) and periodised when the torus is smaller than the window. The
//! weights are integers (`round(2^24 G)`), so energies add exactly and every platform
//! ranks the same pixels. The *tightest cluster* is the one of largest energy, the
//! *largest void* the zero of smallest energy (ties: the lower row-major index).
//!
//! 1. `n1 = max(1, min((N - 1) / 2, floor(N / 10)))` ones at distinct random pixels (the
//!    only random step).
//! 2. Relax: move the tightest cluster to the largest void until the two coincide.
//! 3. From the relaxed pattern, remove tightest clusters: ranks `n1 - 1` down to 0.
//! 4. From the relaxed pattern, fill largest voids: ranks `n1` to `N - 1`. (Past half
//!    full, Ulichney takes the tightest cluster of *zeros* in the energy of the zeros,
//!    `S - E` for the constant kernel sum `S`: the same pixel as the largest void of `E`.)
//!
//! The result is a permutation of `0..W H`; thresholding at `t` (pixels of rank `< t W H`)
//! gives the pattern of `round(t W H)` ones. Cost: each flip adds the kernel (`(2R+1)^2 =
//! 169` weights) and updates two tournament trees (`O(R (R + log N))`); about `1.3 N`
//! flips, so `O(N R (R + log N))` in all — 256×256 in half a second on one core, but
//! past `2^16` pixels the trees leave the caches and a pixel costs up to five times more
//! (2048×2048: about two minutes; see [`VoidAndCluster::cost`]). The estimate is checked
//! against a [`Budget`] before anything runs, and the budget's deadline stops the loops.
//!
//! ```
//! use qmckit::blue_noise::VoidAndCluster;
//! use qmckit::work::Budget;
//! let mask = VoidAndCluster::new(16, 16)?.seed(3).generate(&Budget::DEFAULT)?;
//! let mut seen = mask.ranks().to_vec();
//! seen.sort_unstable();
//! assert!(seen.iter().enumerate().all(|(i, &r)| r as usize == i));
//! # Ok::<(), qmckit::Error>(())
//! ```

use super::rng::Rng;
use super::tournament::{Best, Tournament};
use crate::work::{Budget, Cost, Rate};

use crate::{Error, Result};

/// The largest side of a mask.
pub const MASK_MAX_SIDE: usize = 4096;

/// The most pixels of a mask: 2^22.
pub const MASK_MAX_PIXELS: usize = 1 << 22;

/// The unit of [`VoidAndCluster::cost`]: pixel-microseconds.
const PIXEL_MICROS: Rate = Rate::per_second(1e6);

/// A void-and-cluster construction (builder).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VoidAndCluster {
    width: usize,
    height: usize,
    sigma: f64,
    seed: u64,
}

/// A rank image: `ranks()[y * width + x]` is the rank of pixel `(x, y)`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct RankMask {
    width: usize,
    height: usize,
    ranks: Vec<u32>,
}

impl RankMask {
    /// Width in pixels.
    pub fn width(&self) -> usize {
        self.width
    }

    /// Height in pixels.
    pub fn height(&self) -> usize {
        self.height
    }

    /// The ranks, row-major, a permutation of `0..width * height`.
    pub fn ranks(&self) -> &[u32] {
        &self.ranks
    }

    /// The pattern of the pixels with rank below `ones` (row-major, `true` = on).
    pub fn threshold(&self, ones: usize) -> Vec<bool> {
        self.ranks.iter().map(|&r| (r as usize) < ones).collect()
    }
}

impl VoidAndCluster {
    /// A `width x height` mask, `sigma = 1.5`, seed 0.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for a side of 0 or past [`MASK_MAX_SIDE`];
    /// [`Error::TooLarge`] past [`MASK_MAX_PIXELS`].
    pub fn new(width: usize, height: usize) -> Result<Self> {
        if width == 0 || height == 0 || width > MASK_MAX_SIDE || height > MASK_MAX_SIDE {
            return Err(Error::InvalidParameter {
                what: "a mask side must be 1 to 4096 pixels",
            });
        }
        let n = width * height;
        if n > MASK_MAX_PIXELS {
            return Err(Error::TooLarge {
                what: "mask pixels",
                requested: n as u64,
                max: MASK_MAX_PIXELS as u64,
            });
        }
        Ok(VoidAndCluster {
            width,
            height,
            sigma: 1.5,
            seed: 0,
        })
    }

    /// The seed.
    pub fn seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The Gaussian's standard deviation in pixels, 0.5 to 8.
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] outside that range.
    pub fn sigma(mut self, sigma: f64) -> Result<Self> {
        if !(0.5..=8.0).contains(&sigma) {
            return Err(Error::InvalidParameter {
                what: "the void-and-cluster sigma must be 0.5 to 8 pixels",
            });
        }
        self.sigma = sigma;
        Ok(self)
    }

    fn reach(&self) -> usize {
        (4.0 * self.sigma).ceil() as usize
    }

    /// The estimated running time, calibrated on measured masks (docs/budgets.md):
    /// `N` pixels cost `t(L) W(sigma) / W(1.5)` each, `L = log2 N`, with
    /// `t(L) = 4.9 + 0.3 (L - 12)+ + 0.55 (L - 16)+^2` microseconds (the trees and energies
    /// outgrow the caches past `2^16` pixels, and every flip's reads miss) and `W` a flip's
    /// work, `kw kh + kh (kw + 2 L)` for the `kw x kh` kernel window.
    pub fn cost(&self) -> Cost {
        let n = (self.width * self.height) as f64;
        let l = n.log2().max(1.0);
        let work = |reach: usize| {
            let win = (2 * reach + 1) as f64;
            let (kw, kh) = (win.min(self.width as f64), win.min(self.height as f64));
            kw * kh + kh * (kw + 2.0 * l)
        };
        let default = VoidAndCluster {
            sigma: 1.5,
            ..*self
        };
        let scale = work(self.reach()) / work(default.reach());
        let micros = 4.9 + 0.3 * (l - 12.0).max(0.0) + 0.55 * (l - 16.0).max(0.0).powi(2);
        Cost::steps(n * micros * scale, PIXEL_MICROS)
    }

    /// The mask, refused before it starts when [`cost`](Self::cost) exceeds `budget`, and
    /// stopped at the budget's deadline (started here if the caller has not; the clock is
    /// read about once every [`crate::work::PACER_INTERVAL`] flips of the 13 x 13 kernel).
    ///
    /// # Errors
    /// [`Error::OverBudget`], [`Error::TooLarge`], [`Error::OutOfTime`].
    pub fn generate(&self, budget: &Budget) -> Result<RankMask> {
        let ranks = self.ranks_below(self.width * self.height, budget)?;
        Ok(RankMask {
            width: self.width,
            height: self.height,
            ranks,
        })
    }

    /// The ranks of [`generate`](Self::generate) below `limit`, the others `u32::MAX`:
    /// with `limit` at most the initial pattern's size (`N / 10`) only that pattern is
    /// ranked and the filling phase, most of the cost, is skipped. The ranks below `limit`
    /// are the full mask's (the filling phase does not change them).
    pub(crate) fn ranks_below(&self, limit: usize, budget: &Budget) -> Result<Vec<u32>> {
        let budget = budget.started();
        budget.check("void-and-cluster mask", self.cost())?;
        let mut pacer = budget.pacer("void-and-cluster mask");
        let n = self.width * self.height;
        let kernel = Kernel::new(self.width, self.height, self.sigma, self.reach());
        // One flip's weight for the pacer: its kernel weights over the default 13 x 13.
        let weight = u32::try_from(kernel.w.len() / 169)
            .unwrap_or(u32::MAX)
            .max(1);
        let mut state = State::new(self.width, self.height, kernel)?;
        let n1 = (n / 10).min((n - 1) / 2).max(1).min(n);
        // Distinct random pixels: a partial Fisher–Yates shuffle.
        let mut order: Vec<u32> = crate::size::vec_zeroed(n)?;
        for (i, o) in order.iter_mut().enumerate() {
            *o = i as u32;
        }
        let mut rng = Rng::new(self.seed, 0x564F_4944_434C_5553);
        for i in 0..n1 {
            let j = i + rng.below(n - i);
            order.swap(i, j);
        }
        for &p in order.get(..n1).unwrap_or(&[]) {
            pacer.tick_n(weight)?;
            state.flip(p as usize, true);
        }
        // Relax (bounded, so no input can loop forever; it settles in far fewer steps).
        for _ in 0..4 * n {
            pacer.tick_n(2 * weight)?;
            let Some(c) = state.cluster() else { break };
            state.flip(c, false);
            match state.void() {
                Some(v) if v != c => state.flip(v, true),
                _ => {
                    state.flip(c, true);
                    break;
                }
            }
        }
        let mut ranks = crate::size::vec_zeroed::<u32>(n)?;
        if limit < n {
            // The cells the filling phase would rank stay unranked.
            ranks.fill(u32::MAX);
        }
        let mut removing = state.clone();
        for rank in (0..n1).rev() {
            pacer.tick_n(weight)?;
            let Some(c) = removing.cluster() else { break };
            removing.flip(c, false);
            if let Some(slot) = ranks.get_mut(c) {
                *slot = rank as u32;
            }
        }
        drop(removing);
        for rank in n1..n.min(limit) {
            pacer.tick_n(weight)?;
            let Some(v) = state.void() else { break };
            state.flip(v, true);
            if let Some(slot) = ranks.get_mut(v) {
                *slot = rank as u32;
            }
        }
        if limit < n {
            ranks
                .iter_mut()
                .filter(|r| **r as usize >= limit)
                .for_each(|r| *r = u32::MAX);
        }
        Ok(ranks)
    }
}

/// The periodised integer kernel on a `kw x kh` window.
#[derive(Clone, Debug)]
struct Kernel {
    /// Window size and the offset of its first column/row (`-R`, or 0 when the window is
    /// the whole torus width/height).
    kw: usize,
    kh: usize,
    x0: usize,
    y0: usize,
    w: Vec<i64>,
}

impl Kernel {
    fn new(width: usize, height: usize, sigma: f64, reach: usize) -> Self {
        let win = 2 * reach + 1;
        let (kw, x0) = if width >= win {
            (win, width - reach)
        } else {
            (width, 0)
        };
        let (kh, y0) = if height >= win {
            (win, height - reach)
        } else {
            (height, 0)
        };
        let mut w = vec![0i64; kw * kh];
        let r = reach as i64;
        for dy in -r..=r {
            for dx in -r..=r {
                let g = libm::exp(-((dx * dx + dy * dy) as f64) / (2.0 * sigma * sigma));
                let v = libm::round(g * (1u64 << 24) as f64) as i64;
                // Window column of dx: dx + R in a full window, dx mod W in a wrapped one.
                let cx = if kw == win {
                    (dx + r) as usize
                } else {
                    dx.rem_euclid(width as i64) as usize
                };
                let cy = if kh == win {
                    (dy + r) as usize
                } else {
                    dy.rem_euclid(height as i64) as usize
                };
                if let Some(slot) = w.get_mut(cy * kw + cx) {
                    *slot += v;
                }
            }
        }
        Kernel { kw, kh, x0, y0, w }
    }
}

/// A binary pattern with its energy in two trees: ones by largest energy, zeros by
/// smallest.
#[derive(Clone, Debug)]
struct State {
    width: usize,
    height: usize,
    kernel: Kernel,
    energy: Vec<i64>,
    ones: Tournament,
    zeros: Tournament,
}

impl State {
    fn new(width: usize, height: usize, kernel: Kernel) -> Result<Self> {
        let n = width * height;
        let mut energy = crate::size::vec_zeroed::<i64>(n)?;
        energy.fill(Tournament::sentinel(Best::Max));
        let ones = Tournament::new(Best::Max, &energy)?;
        energy.fill(0);
        let zeros = Tournament::new(Best::Min, &energy)?;
        Ok(State {
            width,
            height,
            kernel,
            energy,
            ones,
            zeros,
        })
    }

    fn cluster(&self) -> Option<usize> {
        self.ones.top()
    }

    fn void(&self) -> Option<usize> {
        self.zeros.top()
    }

    /// Sets pixel `p` to `value` (it must differ) and updates energies and trees.
    fn flip(&mut self, p: usize, value: bool) {
        let (w, h) = (self.width, self.height);
        let (px, py) = (p % w, p / w);
        let sign = if value { 1 } else { -1 };
        let e = self.energy.get(p).copied().unwrap_or(0);
        if value {
            self.ones.set(p, e);
            self.zeros.set(p, Tournament::sentinel(Best::Min));
        } else {
            self.ones.set(p, Tournament::sentinel(Best::Max));
            self.zeros.set(p, e);
        }
        let k = &self.kernel;
        let xs = (px + k.x0) % w; // first column touched
        for cy in 0..k.kh {
            let y = (py + k.y0 + cy) % h;
            let row = y * w;
            let weights = k.w.get(cy * k.kw..(cy + 1) * k.kw).unwrap_or(&[]);
            for (cx, &wt) in weights.iter().enumerate() {
                let mut x = xs + cx;
                if x >= w {
                    x -= w;
                }
                let i = row + x;
                if let Some(slot) = self.energy.get_mut(i) {
                    *slot += sign * wt;
                }
                self.ones.add(i, sign * wt);
                self.zeros.add(i, sign * wt);
            }
            // The touched run of the row: one segment, or two when it wraps.
            let end = xs + k.kw - 1;
            if end < w {
                self.ones.refresh(row + xs, row + end);
                self.zeros.refresh(row + xs, row + end);
            } else {
                self.ones.refresh(row + xs, row + w - 1);
                self.zeros.refresh(row + xs, row + w - 1);
                self.ones.refresh(row, row + end - w);
                self.zeros.refresh(row, row + end - w);
            }
        }
    }
}
