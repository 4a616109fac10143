//! A shared stop signal for the loops of a budgeted computation (the measurements of
//! `analysis`, the rank test of [`crate::digital::rank`]): the deadline of a started
//! [`Budget`] seen by every task of the computation.
//!
//! A task calls [`Stop::check`] once per chunk of work (a row, a slab, a shape): it reads the
//! clock (about 20 ns) and, past the deadline, raises a flag that every other task sees at
//! its next check without reading the clock again. A stopped task returns early with a
//! placeholder value; the computation then ends with [`Stop::result`], which turns the flag
//! into [`Error::OutOfTime`], so no partial value ever escapes. A run that is not stopped
//! computes exactly what it computed without the checks (bit for bit).

use crate::work::Budget;
use crate::{Error, Result};
use core::sync::atomic::{AtomicBool, Ordering};

/// The deadline of one computation, shared by its tasks.
#[derive(Debug)]
pub struct Stop {
    budget: Budget,
    what: &'static str,
    flag: AtomicBool,
}

impl Stop {
    /// The stop signal of the computation `what` under `budget` (started here if it was not).
    pub fn new(budget: &Budget, what: &'static str) -> Self {
        Stop {
            budget: budget.started(),
            what,
            flag: AtomicBool::new(false),
        }
    }

    /// The stop of a computation without a deadline (never raised).
    pub const fn never(what: &'static str) -> Self {
        Stop {
            budget: Budget::UNLIMITED,
            what,
            flag: AtomicBool::new(false),
        }
    }

    /// `true` when the computation must stop: already stopped, or the deadline has passed
    /// (one clock reading).
    #[inline]
    pub fn check(&self) -> bool {
        if self.flag.load(Ordering::Relaxed) {
            return true;
        }
        if self.budget.check_deadline(self.what).is_err() {
            self.flag.store(true, Ordering::Relaxed);
            return true;
        }
        false
    }

    /// `Ok` while the deadline has not passed (one clock reading): for sequential loops.
    ///
    /// # Errors
    /// [`Error::OutOfTime`] naming the computation.
    #[inline]
    pub fn budget_check(&self) -> Result<()> {
        if self.check() {
            Err(self.error())
        } else {
            Ok(())
        }
    }

    /// `true` once some task saw the deadline pass (no clock reading).
    #[inline]
    pub fn stopped(&self) -> bool {
        self.flag.load(Ordering::Relaxed)
    }

    /// `Ok` unless the computation was stopped.
    ///
    /// # Errors
    /// [`Error::OutOfTime`] naming the computation.
    pub fn result(&self) -> Result<()> {
        if self.stopped() {
            Err(self.error())
        } else {
            Ok(())
        }
    }

    /// The error of a stopped computation.
    pub fn error(&self) -> Error {
        Error::OutOfTime {
            what: self.what,
            budget_ms: millis(self.budget.max_seconds()),
        }
    }

    /// `value` unless the computation was stopped.
    ///
    /// # Errors
    /// [`Error::OutOfTime`] naming the computation.
    pub fn finish<T>(&self, value: T) -> Result<T> {
        self.result().map(|()| value)
    }
}

/// `seconds` in whole milliseconds, saturated, as [`Error::OutOfTime`] reports it.
fn millis(seconds: f64) -> u64 {
    let ms = (seconds * 1000.0).ceil();
    if ms.is_nan() || ms >= u64::MAX as f64 {
        u64::MAX
    } else {
        ms as u64
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_unstarted_unlimited_budget_never_stops() {
        let s = Stop::new(&Budget::UNLIMITED, "x");
        assert!(!s.check());
        assert!(s.result().is_ok());
    }

    #[test]
    fn a_passed_deadline_stops_every_task() {
        let b = Budget::seconds(1e-9).unwrap().started();
        std::thread::sleep(std::time::Duration::from_millis(2));
        let s = Stop::new(&b, "loop");
        assert!(s.check());
        assert!(s.stopped());
        assert!(matches!(
            s.result(),
            Err(Error::OutOfTime { what: "loop", .. })
        ));
    }
}
