//! A spinner or a progress bar on stderr for computations that take more than a second.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressStyle};

/// How long a computation runs before the spinner or bar appears.
const QUIET: Duration = Duration::from_secs(1);

/// How often the bar reads the progress.
const TICK: Duration = Duration::from_millis(100);

/// Runs `work` on a worker thread and returns its result. If it is still running after a
/// second and stderr is a terminal, shows a spinner labelled `label` until it finishes
/// (and clears it); otherwise prints nothing.
pub fn with_spinner<T: Send>(label: &str, work: impl FnOnce() -> T + Send) -> T {
    with_progress(label, |_| work())
}

/// [`with_spinner`] for work that reports progress: `work` gets a function to call, from
/// any thread, with `(done, total)`. Once a report has come in, the spinner becomes a bar
/// of `done` out of `total` with an estimate of the time left.
pub fn with_progress<T: Send>(
    label: &str,
    work: impl FnOnce(&(dyn Fn(usize, usize) + Sync)) -> T + Send,
) -> T {
    let done = AtomicUsize::new(0);
    let total = AtomicUsize::new(0);
    let report = |d: usize, t: usize| {
        done.fetch_max(d, Ordering::Relaxed);
        total.store(t, Ordering::Relaxed);
    };
    std::thread::scope(|scope| {
        let (tx, rx) = mpsc::channel();
        let worker = scope.spawn(move || {
            // The receiver outlives the worker; a failed send only means it stopped waiting.
            let _ = tx.send(work(&report));
        });
        let result = match rx.recv_timeout(QUIET) {
            Ok(value) => Some(value),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                let bar = std::io::stderr().is_terminal().then(|| spinner(label));
                let mut is_bar = false;
                let value = loop {
                    match rx.recv_timeout(TICK) {
                        Ok(value) => break Some(value),
                        Err(mpsc::RecvTimeoutError::Disconnected) => break None,
                        Err(mpsc::RecvTimeoutError::Timeout) => {}
                    }
                    let t = total.load(Ordering::Relaxed);
                    if let Some(bar) = bar.as_ref().filter(|_| t > 0) {
                        if !is_bar {
                            make_bar(bar, t);
                            is_bar = true;
                        }
                        bar.set_position(done.load(Ordering::Relaxed) as u64);
                    }
                };
                if let Some(b) = &bar {
                    b.finish_and_clear();
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
    bar.enable_steady_tick(TICK);
    bar
}

/// Turns the spinner `bar` into a bar of `total` steps.
fn make_bar(bar: &ProgressBar, total: usize) {
    bar.set_length(total as u64);
    if let Ok(style) =
        ProgressStyle::with_template("{msg} [{bar:30}] {percent}% ({elapsed}, about {eta} left)")
    {
        bar.set_style(style.progress_chars("=> "));
    }
}
