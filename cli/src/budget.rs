//! `--max-seconds`: the one time budget of every command whose cost grows faster than its
//! input (`discrepancy`, `tvalue`, `convergence`, `spectrum`).

use clap::Args;
use qmckit::work::{Budget, DEFAULT_SECONDS};

use super::Failure;

/// The time budget option, flattened into each command that needs it.
#[derive(Args, Debug, Clone, Copy)]
pub struct BudgetArgs {
    /// Refuse, before starting, any computation whose estimated running time exceeds this
    /// many seconds ('inf': no limit). Accepted work shows progress on a terminal.
    #[arg(long, default_value_t = DEFAULT_SECONDS, value_name = "SECONDS")]
    pub max_seconds: f64,
}

impl BudgetArgs {
    /// The budget, started: its deadline (1.25 times the budget from now) bounds every
    /// computation of the command it is handed to. A usage error for a value that is not a
    /// positive number.
    pub fn budget(&self) -> Result<Budget, Failure> {
        Budget::seconds(self.max_seconds)
            .map(Budget::started)
            .map_err(|_| {
                Failure::usage(format!(
                    "--max-seconds must be a positive number of seconds, not {}",
                    self.max_seconds
                ))
            })
    }
}

/// The message of a refusal by the budget: the library's reason and the way out.
pub fn over_budget(e: qmckit::Error) -> String {
    match e {
        qmckit::Error::OverBudget { .. } => format!("{e} (raise --max-seconds to run it)"),
        qmckit::Error::OutOfTime { .. } => {
            format!("{e}: the estimate was too low (raise --max-seconds to let it finish)")
        }
        other => other.to_string(),
    }
}
