//! `solve_many`'s engine room: the joints solved in parallel on a rayon pool of `threads`
//! threads while the calling thread, the GIL released between polls, collects the rows, reports
//! progress and watches for Ctrl-C.
//!
//! Method: the pool runs on a thread of its own; each worker writes its finished joint's row
//! into the joint's slot and counts it. The caller waits for the batch's end at most [`POLL`]
//! at a time without the GIL, then takes the GIL to call the progress callback with the count
//! and `PyErr_CheckSignals`. On a signal (KeyboardInterrupt) it raises the cancel flag, keeps
//! every row written and returns at once: joints not started are never started, the at most
//! `threads` joints running finish on the pool's thread and are dropped. A joint that fails, or panics, is a row with its message.
//!
//! # Accuracy
//!
//! Each row is the single call's, bit for bit: `python/tests/test_many.py` (200 joints in CI,
//! 1,000 in its slow test).
//!
//! # Cost
//!
//! The joints' costs over the threads; the caller's polling wakes every [`POLL`].

use crate::columns::{self, Cell};
use crate::engine::{self, Failure};
use boltzone::scene::Scene;
use pyo3::prelude::*;
use rayon::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{mpsc, Arc, OnceLock};
use std::time::{Duration, Instant};

/// Longest wait without looking at signals and progress (Ctrl-C is seen within this).
pub const POLL: Duration = Duration::from_millis(50);

/// One joint's row: the asked keys of its `solve --json` object in order (None where it lacks
/// one), or why it has none.
pub type Row = Result<Vec<Cell>, Failure>;

/// Runs `f`, a panic becoming a solver failure with its message.
pub fn guarded<T>(f: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|p| {
        let msg = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "(no message)".into());
        Err(Failure::Solver(format!(
            "internal error (a panic in boltzone): {msg}"
        )))
    })
}

/// One joint: its scene (or why it has none) solved, the `keys` of its answer read on the
/// worker (only those cross to Python: a table-answered joint costs microseconds, its whole
/// JSON object tens).
fn one(scene: &Result<Arc<Scene>, Failure>, keys: &[String]) -> Row {
    match scene {
        Ok(s) => guarded(|| {
            let a = engine::solve(s, Instant::now())?;
            Ok(columns::cells(&a, keys))
        }),
        Err(f) => Err(f.clone()),
    }
}

/// What the batch ended with: the rows in input order (None: not finished) and the exception
/// that stopped it early (KeyboardInterrupt, or the progress callback's), if any.
pub struct Outcome {
    /// One entry per joint.
    pub rows: Vec<Option<Row>>,
    /// Why the batch stopped before the end.
    pub stopped: Option<PyErr>,
}

/// Solves `scenes` on `threads` threads (0: rayon's default), each row holding the answer's
/// `keys`, calling `progress(done, total)` whenever rows arrived since the last poll.
pub fn run(
    py: Python<'_>,
    scenes: Vec<Result<Arc<Scene>, Failure>>,
    keys: Vec<String>,
    threads: usize,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<Outcome> {
    let n = scenes.len();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    // each worker writes its joint's row in place and counts it; the caller is woken only by
    // the end of the batch or by its poll (a wake-up per row cost microseconds per joint)
    let slots: Arc<Vec<OnceLock<Row>>> = Arc::new((0..n).map(|_| OnceLock::new()).collect());
    let done = Arc::new(AtomicUsize::new(0));
    let cancel = Arc::new(AtomicBool::new(false));
    let (end_tx, mut end_rx) = mpsc::channel::<()>();
    let worker = {
        let (slots, done, cancel) = (Arc::clone(&slots), Arc::clone(&done), Arc::clone(&cancel));
        std::thread::spawn(move || {
            pool.install(|| {
                (0..n).into_par_iter().for_each(|i| {
                    if !cancel.load(Ordering::Relaxed) {
                        let _ = slots[i].set(one(&scenes[i], &keys));
                        done.fetch_add(1, Ordering::Release);
                    }
                })
            });
            let _ = end_tx.send(());
        })
    };
    let mut shown = usize::MAX;
    let mut stopped = None;
    loop {
        let (back, got) = py.detach(move || {
            let got = end_rx.recv_timeout(POLL);
            (end_rx, got)
        });
        end_rx = back;
        let finished = !matches!(got, Err(mpsc::RecvTimeoutError::Timeout));
        let now = done.load(Ordering::Acquire);
        let reported = match progress {
            Some(cb) if now != shown => cb.call1((now, n)).map(|_| ()),
            _ => Ok(()),
        };
        shown = now;
        if let Err(e) = reported.and_then(|_| py.check_signals()) {
            cancel.store(true, Ordering::Relaxed);
            stopped = Some(e);
            break;
        }
        if finished {
            break;
        }
    }
    let rows = if stopped.is_none() {
        // every row is in: the pool's thread is ending; joining costs nothing
        py.detach(move || worker.join())
            .map_err(|_| pyo3::exceptions::PyRuntimeError::new_err("the batch thread panicked"))?;
        match Arc::try_unwrap(slots) {
            Ok(slots) => slots.into_iter().map(OnceLock::into_inner).collect(),
            Err(slots) => slots.iter().map(|s| s.get().cloned()).collect(),
        }
    } else {
        // the at most `threads` joints still running finish on the pool's thread, unseen
        slots.iter().map(|s| s.get().cloned()).collect()
    };
    Ok(Outcome { rows, stopped })
}
