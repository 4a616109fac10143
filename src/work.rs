//! Cost estimates, time budgets with deadlines, and progress for every computation whose
//! cost grows faster than its input.
//!
//! Each such computation (exact star discrepancy, its bounds, the L2 discrepancies, t-values,
//! integration-error curves, spectra) first counts the inner-loop steps it will take, turns
//! them into seconds with a [`Rate`] calibrated for that loop, and asks a [`Budget`] whether
//! it may run. Past the budget it returns [`Error::OverBudget`] at once, in far less time
//! than the computation would have taken; within it, it runs and reports progress through a
//! [`Progress`] callback. The command-line tool maps its one `--max-seconds` option (default
//! [`DEFAULT_SECONDS`]) to a [`Budget`] for every command.
//!
//! An estimate can be wrong, so it is not the bound. The bound is a **deadline**: with the
//! `std` feature, [`Budget::started`] fixes the instant `start + GRACE * seconds`
//! ([`GRACE`] = 1.25), and every super-linear loop calls [`Budget::check_deadline`] (or a
//! [`Pacer`], which reads the clock once every few thousand steps, about 20 ns each), so a
//! run admitted under a budget of `B` seconds ends with [`Error::OutOfTime`] within about
//! `1.25 B` plus one check interval, whatever the estimate said. A budget that was never
//! started has no deadline until a computation starts it; a started budget keeps its
//! deadline through every computation it is handed to, so one deadline bounds a whole
//! command. Without `std` there is no clock: the deadline checks always pass, and only the
//! estimate bounds the work.
//!
//! Rates are measured throughputs of a release build. The analysis rates are **per core**:
//! measured as the CPU time of one thread (the least of repeated runs, so that other work on
//! the machine does not slow them down), and a loop that rayon splits over its threads is
//! estimated at [`CORES`] times its rate ([`Cost::parallel`]): the two cores of the machine
//! the rates were measured on. The goal is an estimate within a factor of two of the
//! measured time on that machine, idle (`docs/budgets.md` lists the measurements); a busier
//! or smaller machine runs longer than estimated, and the deadline bounds it.
//!
//! ```
//! use qmckit::work::{Budget, Cost, Rate};
//! const PAIRS: Rate = Rate::per_second(1e9);
//! let budget = Budget::seconds(10.0)?;
//! assert!(budget.check("pairs", Cost::steps(5e9, PAIRS)).is_ok()); // 5 s
//! assert!(budget.check("pairs", Cost::steps(5e10, PAIRS)).is_err()); // 50 s: refused
//! # Ok::<(), qmckit::Error>(())
//! ```

use crate::{Error, Result};

#[cfg(feature = "std")]
mod stop;
#[cfg(feature = "std")]
pub use stop::Stop;

/// How far past its budget a started computation may run before its deadline stops it:
/// the deadline is `start + GRACE * seconds`.
pub const GRACE: f64 = 1.25;

/// The speed-up of a loop split over rayon's threads that [`Cost::parallel`] assumes: the
/// two cores of the machine the per-core rates were measured on. Fixed, not the number of
/// threads of the running machine, so that a request is admitted or refused alike
/// everywhere: with more cores a run ends sooner than estimated, with one core it takes up
/// to twice the estimate (and the deadline bounds it).
pub const CORES: f64 = 2.0;

/// How many [`Pacer::tick`] steps pass between two readings of the clock.
pub const PACER_INTERVAL: u32 = 4096;

/// The default time budget of the command-line tool and of the functions without a budget
/// argument: ten seconds.
pub const DEFAULT_SECONDS: f64 = 10.0;

/// A progress report: `progress(done, total)`, callable from any thread, `done <= total`.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// A [`Progress`] that ignores its reports.
pub fn no_progress(_done: usize, _total: usize) {}

/// A limit on the running time of a computation: an estimate checked before it starts
/// ([`Budget::check`]) and, once started, a deadline checked inside its loops
/// ([`Budget::check_deadline`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    seconds: f64,
    #[cfg(feature = "std")]
    deadline: Option<std::time::Instant>,
}

impl Budget {
    /// The default budget, [`DEFAULT_SECONDS`].
    pub const DEFAULT: Budget = Budget::unstarted(DEFAULT_SECONDS);

    /// No limit: every estimate is admitted and no deadline is set.
    pub const UNLIMITED: Budget = Budget::unstarted(f64::INFINITY);

    const fn unstarted(seconds: f64) -> Budget {
        Budget {
            seconds,
            #[cfg(feature = "std")]
            deadline: None,
        }
    }

    /// A budget of `seconds` (positive; `f64::INFINITY` for no limit).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for zero, a negative number or NaN.
    pub fn seconds(seconds: f64) -> Result<Self> {
        if seconds > 0.0 {
            Ok(Budget::unstarted(seconds))
        } else {
            Err(Error::InvalidParameter {
                what: "a time budget must be a positive number of seconds",
            })
        }
    }

    /// The budget in seconds.
    pub fn max_seconds(&self) -> f64 {
        self.seconds
    }

    /// This budget with its deadline fixed: `now + GRACE * seconds` if it had none (and is
    /// finite), else unchanged. Every budgeted computation starts its budget on entry, so
    /// a caller that starts it first shares one deadline among all the work it hands it to.
    /// Without `std` there is no clock and this returns the budget unchanged.
    #[must_use]
    pub fn started(self) -> Budget {
        #[cfg(feature = "std")]
        {
            let mut b = self;
            if b.deadline.is_none() && self.seconds.is_finite() {
                let grace = std::time::Duration::try_from_secs_f64(self.seconds * GRACE).ok();
                b.deadline = grace.and_then(|g| std::time::Instant::now().checked_add(g));
            }
            b
        }
        #[cfg(not(feature = "std"))]
        {
            self
        }
    }

    /// `Ok` while the deadline (if started) has not passed.
    ///
    /// Cost: one reading of the monotonic clock (about 20 ns); call it once per chunk of
    /// work, or use a [`Pacer`].
    ///
    /// # Errors
    /// [`Error::OutOfTime`] naming `what` once the deadline has passed.
    pub fn check_deadline(&self, what: &'static str) -> Result<()> {
        #[cfg(feature = "std")]
        if let Some(deadline) = self.deadline
            && std::time::Instant::now() > deadline
        {
            return Err(Error::OutOfTime {
                what,
                budget_ms: millis(self.seconds),
            });
        }
        let _ = what;
        Ok(())
    }

    /// A [`Pacer`] for a loop named `what` of this (started) budget.
    pub fn pacer(&self, what: &'static str) -> Pacer {
        Pacer {
            budget: self.started(),
            what,
            count: 0,
        }
    }

    /// The seconds left before the deadline (`None`: not started or no clock).
    pub fn remaining_seconds(&self) -> Option<f64> {
        #[cfg(feature = "std")]
        if let Some(deadline) = self.deadline {
            let now = std::time::Instant::now();
            return Some(deadline.saturating_duration_since(now).as_secs_f64());
        }
        None
    }

    /// The steps of a loop running at `rate` that fit in the budget.
    pub fn steps(&self, rate: Rate) -> f64 {
        self.seconds * rate.steps_per_second
    }

    /// `Ok` when `cost` fits in the budget.
    ///
    /// # Errors
    /// [`Error::OverBudget`] naming `what`, with the estimate and the budget.
    pub fn check(&self, what: &'static str, cost: Cost) -> Result<()> {
        let estimated = cost.seconds();
        if estimated <= self.seconds {
            Ok(())
        } else {
            Err(Error::OverBudget {
                what,
                estimated_ms: millis(estimated),
                budget_ms: millis(self.seconds),
            })
        }
    }
}

impl Default for Budget {
    fn default() -> Self {
        Budget::DEFAULT
    }
}

/// The one limits argument of a budgeted computation: its [`Budget`] and a [`Progress`]
/// callback (none by default).
///
/// Every budgeted analysis entry point takes `limits: impl Into<Limits<'a>>`, so a caller
/// passes a reference to a budget, `&Budget::DEFAULT` or `&budget`, or limits with a
/// progress report from [`Limits::with_progress`]:
///
/// ```
/// use qmckit::work::{Budget, Limits};
/// let budget = Budget::seconds(2.0)?;
/// let plain: Limits = (&budget).into();
/// assert_eq!(plain.budget(), &budget);
/// let report = |done: usize, total: usize| assert!(done <= total);
/// let with = Limits::new(budget).with_progress(&report);
/// (with.progress())(1, 2);
/// assert_eq!(Limits::DEFAULT.budget(), &Budget::DEFAULT);
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Copy)]
pub struct Limits<'a> {
    budget: Budget,
    progress: Progress<'a>,
}

impl Limits<'static> {
    /// [`Budget::DEFAULT`] without progress reports.
    pub const DEFAULT: Limits<'static> = Limits::new(Budget::DEFAULT);

    /// [`Budget::UNLIMITED`] without progress reports.
    pub const UNLIMITED: Limits<'static> = Limits::new(Budget::UNLIMITED);

    /// `budget` without progress reports.
    pub const fn new(budget: Budget) -> Limits<'static> {
        Limits {
            budget,
            progress: &no_progress,
        }
    }
}

impl<'a> Limits<'a> {
    /// These limits, reporting progress to `progress`.
    #[must_use]
    pub fn with_progress<'b>(self, progress: Progress<'b>) -> Limits<'b> {
        Limits {
            budget: self.budget,
            progress,
        }
    }

    /// The budget.
    pub fn budget(&self) -> &Budget {
        &self.budget
    }

    /// The progress callback ([`no_progress`] unless one was given).
    pub fn progress(&self) -> Progress<'a> {
        self.progress
    }
}

impl Default for Limits<'static> {
    fn default() -> Self {
        Limits::DEFAULT
    }
}

impl From<&Budget> for Limits<'static> {
    fn from(budget: &Budget) -> Self {
        Limits::new(*budget)
    }
}

impl core::fmt::Debug for Limits<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Limits")
            .field("budget", &self.budget)
            .finish_non_exhaustive()
    }
}

/// `seconds` in whole milliseconds, saturated (NaN counts as too long).
fn millis(seconds: f64) -> u64 {
    let ms = seconds * 1000.0;
    if ms.is_nan() || ms >= u64::MAX as f64 {
        return u64::MAX;
    }
    // Rounded up without `f64::ceil`, which `core` lacks.
    let whole = ms as u64;
    if (whole as f64) < ms {
        whole + 1
    } else {
        whole
    }
}

/// A cheap deadline check for an inner loop: [`Pacer::tick`] counts steps and reads the
/// clock once every [`PACER_INTERVAL`] of them.
///
/// ```
/// use qmckit::work::Budget;
/// let mut pacer = Budget::seconds(10.0)?.started().pacer("counting");
/// for _ in 0..100_000 {
///     pacer.tick()?;
/// }
/// # Ok::<(), qmckit::Error>(())
/// ```
#[derive(Clone, Debug)]
pub struct Pacer {
    budget: Budget,
    what: &'static str,
    count: u32,
}

impl Pacer {
    /// Counts one step; every [`PACER_INTERVAL`] steps, checks the deadline.
    ///
    /// # Errors
    /// [`Error::OutOfTime`] once the deadline has passed.
    #[inline]
    pub fn tick(&mut self) -> Result<()> {
        self.count = self.count.wrapping_add(1);
        if self.count.is_multiple_of(PACER_INTERVAL) {
            self.budget.check_deadline(self.what)
        } else {
            Ok(())
        }
    }

    /// Counts `steps` steps at once (a chunk of cheap work), checking the deadline when the
    /// count passes a multiple of [`PACER_INTERVAL`].
    ///
    /// # Errors
    /// [`Error::OutOfTime`] once the deadline has passed.
    #[inline]
    pub fn tick_n(&mut self, steps: u32) -> Result<()> {
        let before = self.count / PACER_INTERVAL;
        self.count = self.count.wrapping_add(steps);
        if steps >= PACER_INTERVAL || self.count / PACER_INTERVAL != before {
            self.budget.check_deadline(self.what)
        } else {
            Ok(())
        }
    }

    /// The budget this pacer checks.
    pub fn budget(&self) -> &Budget {
        &self.budget
    }
}

/// The calibrated throughput of one kind of inner-loop step.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rate {
    steps_per_second: f64,
}

impl Rate {
    /// A loop that does `steps_per_second` steps a second.
    pub const fn per_second(steps_per_second: f64) -> Self {
        Rate { steps_per_second }
    }

    /// Steps per second.
    pub const fn steps_per_second(&self) -> f64 {
        self.steps_per_second
    }
}

/// An estimated cost: a number of steps at a [`Rate`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cost {
    seconds: f64,
}

impl Cost {
    /// `steps` steps of a loop running at `rate`. A NaN step count (an estimate that
    /// overflowed) counts as infinitely long.
    pub fn steps(steps: f64, rate: Rate) -> Self {
        let seconds = steps / rate.steps_per_second;
        Cost {
            seconds: if seconds.is_nan() {
                f64::INFINITY
            } else {
                seconds
            },
        }
    }

    /// `steps` steps of a loop split over rayon's threads, running at `rate` on each of
    /// [`CORES`] cores: `steps / (CORES rate)` seconds (NaN counts as infinitely long).
    ///
    /// ```
    /// use qmckit::work::{Cost, Rate};
    /// assert_eq!(Cost::parallel(4e9, Rate::per_second(1e9)).seconds(), 2.0);
    /// ```
    pub fn parallel(steps: f64, rate: Rate) -> Self {
        Cost::steps(steps / CORES, rate)
    }

    /// A cost of `seconds` seconds (negative and NaN count as infinitely long).
    pub fn from_seconds(seconds: f64) -> Self {
        Cost {
            seconds: if seconds >= 0.0 {
                seconds
            } else {
                f64::INFINITY
            },
        }
    }

    /// The estimated running time in seconds.
    pub fn seconds(&self) -> f64 {
        self.seconds
    }

    /// The cost of doing this and `other`.
    pub fn plus(self, other: Cost) -> Cost {
        Cost {
            seconds: self.seconds + other.seconds,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn budgets_refuse_what_exceeds_them() {
        const R: Rate = Rate::per_second(100.0);
        let b = Budget::seconds(2.0).unwrap();
        assert_eq!(b.steps(R), 200.0);
        assert!(b.check("x", Cost::steps(200.0, R)).is_ok());
        assert_eq!(
            b.check("x", Cost::steps(250.0, R)),
            Err(Error::OverBudget {
                what: "x",
                estimated_ms: 2500,
                budget_ms: 2000
            })
        );
        assert!(b.check("x", Cost::steps(f64::NAN, R)).is_err());
        assert!(b.check("x", Cost::steps(f64::INFINITY, R)).is_err());
        assert!(Budget::UNLIMITED.check("x", Cost::steps(1e300, R)).is_ok());
        for bad in [0.0, -1.0, f64::NAN] {
            assert!(Budget::seconds(bad).is_err());
        }
        let e = b.check("x", Cost::steps(1e300, R)).unwrap_err();
        assert!(
            b.check_deadline("x").is_ok(),
            "an unstarted budget has no deadline"
        );
        assert_eq!(
            e.to_string(),
            "x: estimated more than 10^15 s, more than the time budget of 2.0 s"
        );
    }

    #[test]
    fn a_started_budget_stops_at_its_deadline() {
        // The clock starts before the budget does, so the measured time can
        // only overstate the time to the deadline.
        let start = std::time::Instant::now();
        let b = Budget::seconds(0.02).unwrap().started();
        assert!(b.check_deadline("x").is_ok());
        assert!(b.remaining_seconds().unwrap() <= 0.02 * GRACE);
        // Starting again keeps the first deadline.
        assert_eq!(b.started(), b);
        let mut pacer = b.pacer("spin");
        let e = loop {
            if let Err(e) = pacer.tick() {
                break e;
            }
        };
        let took = start.elapsed().as_secs_f64();
        assert!(
            (0.02 * GRACE..0.5).contains(&took),
            "stopped after {took} s"
        );
        assert_eq!(
            e,
            Error::OutOfTime {
                what: "spin",
                budget_ms: 20
            }
        );
        assert!(Budget::UNLIMITED.started().check_deadline("x").is_ok());
        assert_eq!(Budget::UNLIMITED.started().remaining_seconds(), None);
    }
}
