//! Cost estimates, time budgets and progress for every computation whose cost grows faster
//! than its input.
//!
//! Each such computation (exact star discrepancy, its bounds, the L2 discrepancies, t-values,
//! integration-error curves, spectra) first counts the inner-loop steps it will take, turns
//! them into seconds with a [`Rate`] calibrated for that loop, and asks a [`Budget`] whether
//! it may run. Past the budget it returns [`Error::OverBudget`] at once, in far less time
//! than the computation would have taken; within it, it runs and reports progress through a
//! [`Progress`] callback. The command-line tool maps its one `--max-seconds` option (default
//! [`DEFAULT_SECONDS`]) to a [`Budget`] for every command.
//!
//! Rates are measured single-machine throughputs (two cores, release build) and are meant to
//! be conservative: an estimate errs on the long side, so a refused request would really
//! have taken about as long as the message says, and an accepted one seldom runs much
//! longer than the budget.
//!
//! ```
//! use qmckit::analysis::budget::{Budget, Cost, Rate};
//! const PAIRS: Rate = Rate::per_second(1e9);
//! let budget = Budget::seconds(10.0)?;
//! assert!(budget.check("pairs", Cost::steps(5e9, PAIRS)).is_ok()); // 5 s
//! assert!(budget.check("pairs", Cost::steps(5e10, PAIRS)).is_err()); // 50 s: refused
//! # Ok::<(), qmckit::Error>(())
//! ```

use crate::{Error, Result};

/// The default time budget of the command-line tool and of the functions without a budget
/// argument: ten seconds.
pub const DEFAULT_SECONDS: f64 = 10.0;

/// A progress report: `progress(done, total)`, callable from any thread, `done <= total`.
pub type Progress<'a> = &'a (dyn Fn(usize, usize) + Sync);

/// A [`Progress`] that ignores its reports.
pub fn no_progress(_done: usize, _total: usize) {}

/// A limit on the estimated running time of one computation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Budget {
    seconds: f64,
}

impl Budget {
    /// The default budget, [`DEFAULT_SECONDS`].
    pub const DEFAULT: Budget = Budget {
        seconds: DEFAULT_SECONDS,
    };

    /// No limit: every estimate is admitted.
    pub const UNLIMITED: Budget = Budget {
        seconds: f64::INFINITY,
    };

    /// A budget of `seconds` (positive; `f64::INFINITY` for no limit).
    ///
    /// # Errors
    /// [`Error::InvalidParameter`] for zero, a negative number or NaN.
    pub fn seconds(seconds: f64) -> Result<Self> {
        if seconds > 0.0 {
            Ok(Budget { seconds })
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

/// `seconds` in whole milliseconds, saturated (NaN counts as too long).
fn millis(seconds: f64) -> u64 {
    let ms = (seconds * 1000.0).ceil();
    if ms.is_nan() || ms >= u64::MAX as f64 {
        u64::MAX
    } else {
        ms as u64
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
        assert_eq!(
            e.to_string(),
            "x: estimated more than 10^15 s, more than the time budget of 2.0 s"
        );
    }
}
