//! Long calls that Ctrl-C stops: the work runs on its own thread with the
//! GIL released while the calling (Python) thread polls for signals and
//! runs a callback between polls (progress). On an interrupt the work's
//! cancel flag is set, the work is waited for (it checks the flag often and
//! stops soon after) and the `KeyboardInterrupt` is raised.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// How often the calling thread checks for signals and runs `tick`.
const POLL: Duration = Duration::from_millis(20);

/// Runs `work(cancel)` on its own thread; every [`POLL`] (and at the end)
/// the calling thread, holding the GIL, checks for signals and calls
/// `tick`. An error of `tick` or a signal cancels the work and is raised.
pub fn interruptible<T: Send>(
    py: Python<'_>,
    work: impl FnOnce(&AtomicBool) -> T + Send,
    mut tick: impl FnMut() -> PyResult<()>,
) -> PyResult<T> {
    let (cancel, done) = (AtomicBool::new(false), AtomicBool::new(false));
    std::thread::scope(|scope| {
        let handle = scope.spawn(|| {
            let result = work(&cancel);
            done.store(true, Ordering::Release);
            result
        });
        loop {
            let finished = py.detach(|| wait(&done));
            if let Err(e) = py.check_signals().and_then(|()| tick()) {
                cancel.store(true, Ordering::Relaxed);
                py.detach(|| handle.join()).ok();
                return Err(e);
            }
            if finished {
                break;
            }
        }
        py.detach(|| handle.join())
            .map_err(|_| PyRuntimeError::new_err("the worker thread panicked"))
    })
}

/// Waits up to [`POLL`] for `done`, checking every millisecond; whether it
/// was set.
fn wait(done: &AtomicBool) -> bool {
    let steps = POLL.as_millis() as u32;
    (0..steps).any(|_| {
        std::thread::sleep(Duration::from_millis(1));
        done.load(Ordering::Acquire)
    })
}

/// No callback between polls.
pub fn no_tick() -> PyResult<()> {
    Ok(())
}
