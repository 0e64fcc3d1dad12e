//! The batch protocol from Python: `answer_line` (one line, the exact bytes
//! `quadsect batch` prints for it, without the newline) and `Batch`, a
//! streaming iterator that answers an iterable of lines in order on a pool
//! of Rust worker threads.
//!
//! Design: the consumer (`__next__`, holding the GIL) pulls lines from the
//! Python iterable and sends them, numbered, to the workers until
//! `window` lines are in flight (the bounded look-ahead); it then waits
//! with the GIL released for the answer of the next line in order, keeping
//! answers that arrive early in a map.  Workers never touch Python.
//! Dropping the iterator (or exhausting it) closes the job channel, raises
//! the cancellation flag that every worker's budget carries, and the
//! workers stop.

use crate::guard::{self, input_error};
use pyo3::exceptions::{PyRuntimeError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBytes, PyString};
use quadsect::{Budget, ErrorKind};
use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::sync::{Arc, Mutex};

/// Lines in flight per worker thread (the look-ahead is `threads` times
/// this): enough to keep every worker busy behind one slow line.
const WINDOW_PER_THREAD: usize = 32;

/// answer_line(line: str, *, time_limit: float | None = None) -> str
///
/// The answer of one batch line, exactly as ``quadsect batch`` prints it
/// (one JSON object, no newline): ``{"id":…,"ok":true,"result":{…}}`` or
/// ``{"id":…,"ok":false,"error":{"kind":…,"message":…}}``.  Never raises
/// for bad input: a bad line gets an error answer.  A trailing newline is
/// ignored.  ``time_limit`` is the line's time limit in seconds, as
/// ``quadsect batch --time-limit`` (``None``: the default, 10 s).  With
/// ``echo=True`` the answer also carries the line itself as ``"request"``
/// (``quadsect batch --echo``: what the checker ``quadsect_check`` reads).
///
/// >>> quadsect.answer_line('{"id":1,"op":"roots","poly":"x^2-2"}')[:30]
/// '{"id":1,"ok":true,"result":{"d'
#[pyfunction]
#[pyo3(signature = (line, *, time_limit = None, echo = false))]
pub(crate) fn answer_line(
    py: Python<'_>,
    line: &str,
    time_limit: Option<f64>,
    echo: bool,
) -> PyResult<String> {
    let line = strip_newline(line);
    let budget = guard::budget(py, time_limit)?;
    guard::run(py, || Ok(answer(line, &budget, echo)))
}

/// The answer text of one line (`echo`: with the line as `"request"`).
fn answer(line: &str, budget: &Budget, echo: bool) -> String {
    if echo {
        quadsect::batch::answer_line_text_echoed(line, budget)
    } else {
        quadsect::batch::answer_line_text_within(line, budget)
    }
}

/// The line without its line ending (as the CLI reads lines).
fn strip_newline(line: &str) -> &str {
    let l = line.strip_suffix('\n').unwrap_or(line);
    l.strip_suffix('\r').unwrap_or(l)
}

/// The consumer's side of a running batch.
struct State {
    /// The Python iterator of input lines.
    source: Py<PyAny>,
    /// Job channel to the workers (`None` once the input is exhausted).
    jobs: Option<Sender<(u64, String)>>,
    answers: Receiver<(u64, String)>,
    /// Answers that arrived before their turn.
    early: HashMap<u64, String>,
    /// Lines sent, and the index of the next answer to return.
    sent: u64,
    next: u64,
    window: usize,
}

/// Batch(lines: Iterable[str], threads: int | None = None, time_limit: float | None = None, echo: bool = False)
///
/// An iterator of the answers to ``lines`` (``str`` or ``bytes``, with or
/// without the trailing newline), in order, computed on ``threads`` Rust
/// worker threads (default: the number of CPUs) with the GIL released;
/// at most ``32 * threads`` lines are read ahead.  Each line runs under
/// its own budget (``time_limit`` seconds, ``None``: the default 10 s), as
/// in ``quadsect batch``; ``echo=True`` puts each line into its answer as
/// ``"request"`` (``quadsect batch --echo``).
#[pyclass(frozen, module = "quadsect._quadsect")]
pub(crate) struct Batch {
    state: Mutex<State>,
    cancel: Arc<AtomicBool>,
}

#[pymethods]
impl Batch {
    #[new]
    #[pyo3(signature = (lines, threads = None, time_limit = None, echo = false))]
    fn py_new(
        py: Python<'_>,
        lines: &Bound<'_, PyAny>,
        threads: Option<usize>,
        time_limit: Option<f64>,
        echo: bool,
    ) -> PyResult<Self> {
        let per_line = guard::budget(py, time_limit)?;
        let threads = match threads {
            Some(0) => {
                return Err(input_error(
                    py,
                    ErrorKind::Input,
                    "threads must be at least 1",
                ));
            }
            Some(n) => n,
            None => std::thread::available_parallelism().map_or(1, |n| n.get()),
        };
        let source = lines.try_iter()?.into_any().unbind();
        let (job_tx, job_rx) = channel::<(u64, String)>();
        let (answer_tx, answer_rx) = channel::<(u64, String)>();
        let job_rx = Arc::new(Mutex::new(job_rx));
        let cancel = Arc::new(AtomicBool::new(false));
        for i in 0..threads {
            let jobs = Arc::clone(&job_rx);
            let out = answer_tx.clone();
            let budget = per_line.clone().with_cancel_flag(Arc::clone(&cancel));
            std::thread::Builder::new()
                .name(format!("quadsect-batch-{i}"))
                .spawn(move || worker(&jobs, &out, &budget, echo))
                .map_err(|e| {
                    PyRuntimeError::new_err(format!("cannot start a worker thread: {e}"))
                })?;
        }
        Ok(Batch {
            state: Mutex::new(State {
                source,
                jobs: Some(job_tx),
                answers: answer_rx,
                early: HashMap::new(),
                sent: 0,
                next: 0,
                window: threads * WINDOW_PER_THREAD,
            }),
            cancel,
        })
    }

    fn __iter__(slf: PyRef<'_, Self>) -> PyRef<'_, Self> {
        slf
    }

    fn __next__(&self, py: Python<'_>) -> PyResult<Option<String>> {
        // one consumer at a time (like a generator): waiting on the lock
        // while holding the GIL could deadlock with a consumer that needs it
        let Ok(mut guard) = self.state.try_lock() else {
            return Err(PyRuntimeError::new_err(
                "the batch iterator is already running",
            ));
        };
        let st = &mut *guard;
        while st.jobs.is_some() && (st.sent - st.next) < st.window as u64 {
            let item = st.source.bind(py).call_method0("__next__");
            let line = match item {
                Ok(obj) => line_text(&obj)?,
                Err(e) if e.is_instance_of::<pyo3::exceptions::PyStopIteration>(py) => {
                    st.jobs = None;
                    break;
                }
                Err(e) => return Err(e),
            };
            let sender = st.jobs.as_ref().expect("jobs open");
            if sender.send((st.sent, line)).is_err() {
                return Err(PyRuntimeError::new_err("the batch workers stopped"));
            }
            st.sent += 1;
        }
        if st.next == st.sent {
            self.cancel.store(true, Ordering::Relaxed);
            return Ok(None);
        }
        let answer = loop {
            if let Some(a) = st.early.remove(&st.next) {
                break a;
            }
            // `&mut`: the receiver is Send (not Sync) and moves to the detached closure
            let answers = &mut st.answers;
            match py.detach(move || answers.recv()) {
                Ok((i, a)) if i == st.next => break a,
                Ok((i, a)) => {
                    st.early.insert(i, a);
                }
                Err(_) => return Err(PyRuntimeError::new_err("the batch workers stopped")),
            }
        };
        st.next += 1;
        Ok(Some(answer))
    }
}

impl Drop for Batch {
    fn drop(&mut self) {
        // stop the computations in flight; the closed channels end the workers
        self.cancel.store(true, Ordering::Relaxed);
    }
}

/// A line of the input iterable: `str`, or `bytes` decoded like the CLI
/// does (invalid UTF-8 becomes U+FFFD, then a JSON error answer).
fn line_text(obj: &Bound<'_, PyAny>) -> PyResult<String> {
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(strip_newline(&s.to_cow()?).to_string());
    }
    if let Ok(b) = obj.cast::<PyBytes>() {
        return Ok(strip_newline(&String::from_utf8_lossy(b.as_bytes())).to_string());
    }
    Err(PyTypeError::new_err(format!(
        "batch lines must be str or bytes, got {}",
        obj.get_type().name()?
    )))
}

/// A worker: answers numbered lines until the job channel closes or the
/// consumer is gone, each line under `budget` (the batch's per-line budget,
/// carrying its cancellation flag), exactly as `quadsect batch` does.
fn worker(
    jobs: &Mutex<Receiver<(u64, String)>>,
    out: &Sender<(u64, String)>,
    budget: &Budget,
    echo: bool,
) {
    loop {
        let job = match jobs.lock() {
            Ok(rx) => rx.recv(),
            Err(_) => return,
        };
        let Ok((i, line)) = job else { return };
        let a = answer(&line, budget, echo);
        if out.send((i, a)).is_err() {
            return;
        }
    }
}
