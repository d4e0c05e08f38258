//! `solve_many`'s engine room: the joints solved in parallel on a rayon pool of `threads`
//! threads while the calling thread, the GIL released between polls, collects the rows, reports
//! progress and watches for Ctrl-C.
//!
//! Method: the pool runs on a thread of its own and sends each finished joint down a channel;
//! the caller waits on the channel at most [`POLL`] at a time without the GIL, then takes the
//! GIL to call the progress callback and `PyErr_CheckSignals`. On a signal (KeyboardInterrupt)
//! it raises the cancel flag, keeps every row received and returns at once: joints not started
//! are never started, the at most `threads` joints running finish on the pool's thread and are
//! dropped. A joint that fails, or panics, is a row with its message.
//!
//! # Accuracy
//!
//! Each row is the single call's, bit for bit: `python/tests/test_many.py` (200 joints in CI,
//! 1,000 in its slow test).
//!
//! # Cost
//!
//! The joints' costs over the threads; the caller's polling wakes every [`POLL`].

use crate::engine::{self, Failure};
use boltzone::scene::Scene;
use pyo3::prelude::*;
use rayon::prelude::*;
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{mpsc, Arc};
use std::time::{Duration, Instant};

/// Longest wait without looking at signals and progress (Ctrl-C is seen within this).
pub const POLL: Duration = Duration::from_millis(50);

/// One joint's row: the asked keys of its `solve --json` object (those it has), or why it has
/// none.
pub type Row = Result<serde_json::Map<String, serde_json::Value>, Failure>;

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
fn one(scene: &Result<Scene, Failure>, keys: &[String]) -> Row {
    match scene {
        Ok(s) => guarded(|| {
            let a = engine::solve(s, Instant::now())?;
            Ok(keys
                .iter()
                .filter_map(|k| a.key(k).map(|v| (k.clone(), v)))
                .collect())
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
    scenes: Vec<Result<Scene, Failure>>,
    keys: Vec<String>,
    threads: usize,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<Outcome> {
    let n = scenes.len();
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| pyo3::exceptions::PyRuntimeError::new_err(e.to_string()))?;
    let scenes = Arc::new(scenes);
    let cancel = Arc::new(AtomicBool::new(false));
    let (tx, mut rx) = mpsc::channel::<(usize, Row)>();
    let worker = {
        let (scenes, cancel) = (Arc::clone(&scenes), Arc::clone(&cancel));
        std::thread::spawn(move || {
            pool.install(|| {
                (0..n).into_par_iter().for_each_with(tx, |tx, i| {
                    if !cancel.load(Ordering::Relaxed) {
                        let _ = tx.send((i, one(&scenes[i], &keys)));
                    }
                })
            })
        })
    };
    let mut rows: Vec<Option<Row>> = (0..n).map(|_| None).collect();
    let (mut done, mut shown) = (0, usize::MAX);
    let mut stopped = None;
    while done < n {
        let (back, got) = py.detach(move || {
            let got = rx.recv_timeout(POLL);
            (rx, got)
        });
        rx = back;
        match got {
            Ok((i, row)) => {
                rows[i] = Some(row);
                done += 1;
                while let Ok((i, row)) = rx.try_recv() {
                    rows[i] = Some(row);
                    done += 1;
                }
            }
            Err(mpsc::RecvTimeoutError::Timeout) => {}
            Err(mpsc::RecvTimeoutError::Disconnected) => break,
        }
        let reported = match progress {
            Some(cb) if done != shown => cb.call1((done, n)).map(|_| ()),
            _ => Ok(()),
        };
        shown = done;
        if let Err(e) = reported.and_then(|_| py.check_signals()) {
            cancel.store(true, Ordering::Relaxed);
            while let Ok((i, row)) = rx.try_recv() {
                rows[i] = Some(row);
            }
            stopped = Some(e);
            break;
        }
    }
    if stopped.is_none() {
        // every row is in: the pool's thread is ending; joining costs nothing
        py.detach(move || worker.join())
            .map_err(|_| pyo3::exceptions::PyRuntimeError::new_err("the batch thread panicked"))?;
    }
    Ok(Outcome { rows, stopped })
}
