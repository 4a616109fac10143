//! A spinner on stderr for computations that take more than a second.

use std::io::IsTerminal;
use std::sync::mpsc;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

/// How long a computation runs before the spinner appears.
const QUIET: Duration = Duration::from_secs(1);

/// Runs `work` on a worker thread and returns its result. If it is still running after a
/// second and stderr is a terminal, shows a spinner labelled `label` until it finishes
/// (and clears it); otherwise prints nothing.
pub fn with_spinner<T: Send>(label: &str, work: impl FnOnce() -> T + Send) -> T {
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel();
        let worker = scope.spawn(move || {
            // The receiver outlives the worker; a failed send only means it stopped waiting.
            let _ = tx.send(work());
        });
        let result = match rx.recv_timeout(QUIET) {
            Ok(value) => Some(value),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                let spinner = std::io::stderr().is_terminal().then(|| spinner(label));
                let value = rx.recv().ok();
                if let Some(s) = spinner {
                    s.finish_and_clear();
                }
                value
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => None,
        };
        match result {
            Some(value) => value,
            // The worker ended without a result: it panicked; pass the panic on.
            None => match worker.join() {
                Err(panic) => std::panic::resume_unwind(panic),
                Ok(()) => unreachable!("the worker sends before it returns"),
            },
        }
    })
}

/// A ticking spinner with `label`.
fn spinner(label: &str) -> ProgressBar {
    let bar = ProgressBar::new_spinner().with_elapsed(QUIET);
    if let Ok(style) = ProgressStyle::with_template("{spinner} {msg} ({elapsed})") {
        bar.set_style(style);
    }
    bar.set_message(label.to_owned());
    bar.enable_steady_tick(Duration::from_millis(100));
    bar
}
