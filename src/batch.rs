//! `quadsect batch`: JSON lines in, JSON lines out, one answer per input
//! line, in order, streamed: each answer is written as soon as it and the
//! lines before it are done ([`run_batch_with`]).  Lines run in parallel on
//! worker threads, each under its own compute budget; a bad line (or even
//! an internal failure, or an exhausted budget) yields its error line in
//! place and the batch goes on.

use crate::budget::{self, Budget};
use crate::error::{Error, ErrorKind};
use serde_json::{Map, Value, json};
use std::collections::BTreeMap;
use std::io::{BufRead, ErrorKind as IoErrorKind, Write};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Condvar, Mutex, mpsc};

/// Runs one operation given as a JSON object (`op` and its arguments)
/// within a compute budget: the same JSON as the CLI's `--json`.  When the
/// budget runs out, `tangent` and `natural` answer `undecided` with the
/// limit in `reason`, `roots` and `resultant` give an error of kind
/// `budget`.
///
/// The object's own `time_limit` (seconds) and `memory_limit` (MiB), when
/// present, tighten `budget` (never loosen it); a field that is not the
/// op's, `id`, `op` or a limit is an error of kind `bad-field`.
///
/// ```
/// use quadsect::Budget;
/// let line = r#"{"op":"roots","poly":"x^3000-3x^1001+1","time_limit":0}"#;
/// let obj = serde_json::from_str(line).unwrap();
/// let e = quadsect::batch::run_op_within(&obj, &Budget::default()).unwrap_err();
/// assert_eq!(e.kind().as_str(), "budget");
/// let typo = serde_json::from_str(r#"{"op":"roots","poly":"x","time_limt":1}"#).unwrap();
/// let e = quadsect::batch::run_op_within(&typo, &Budget::default()).unwrap_err();
/// assert_eq!(e.kind().as_str(), "bad-field");
/// assert!(e.message().starts_with(r#"unknown field "time_limt" for op "roots""#));
/// ```
pub fn run_op_within(obj: &Map<String, Value>, budget: &Budget) -> Result<Value, Error> {
    let (request, budget) = crate::request::Request::from_line(obj, budget)?;
    let svg = crate::request::Request::svg_wanted(obj)?;
    let answer = request.execute(&budget)?;
    let mut v = answer.to_json();
    if svg && let (Some(text), Value::Object(m)) = (answer.svg(), &mut v) {
        m.insert("svg".into(), Value::String(text));
    }
    Ok(v)
}

/// [`run_op_within`] under the default budget ([`Budget::default`]).
pub fn run_op(obj: &Map<String, Value>) -> Result<Value, Error> {
    run_op_within(obj, &Budget::default())
}

/// Answers one input line of the batch protocol under the default budget
/// ([`Budget::default`]; see [`answer_line_within`]): exactly one answer
/// object `{"id", "ok": true, "result"}` or `{"id", "ok": false, "error":
/// {"kind", "message"}}`, never a panic.
///
/// ```
/// let v = quadsect::batch::answer_line(r#"{"id":1,"op":"roots","poly":"x^2-2"}"#);
/// assert_eq!(v["result"]["distinct_real"], 2);
/// let bad = quadsect::batch::answer_line("oops");
/// assert_eq!((bad["ok"].as_bool(), bad["error"]["kind"].as_str()), (Some(false), Some("json")));
/// ```
pub fn answer_line(line: &str) -> Value {
    answer_line_within(line, &Budget::default())
}

/// Answers one input line within a compute budget (see [`run_op_within`]):
/// exactly one answer object, never a panic.
///
/// ```
/// use quadsect::Budget;
/// use std::time::Duration;
/// let none = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
/// let v = quadsect::batch::answer_line_within(r#"{"id":7,"op":"roots","poly":"x^3000-3x^1001+1"}"#, &none);
/// assert_eq!(v["error"]["kind"], "budget");
/// assert_eq!(v["id"], 7);
/// ```
pub fn answer_line_within(line: &str, budget: &Budget) -> Value {
    let (id, result) = answer_with(line, budget, run_op_within);
    match result {
        Ok(v) => {
            // built by hand: json! would serialize the result again (a
            // deep copy of the whole answer)
            let mut m = serde_json::Map::new();
            m.insert("id".into(), id);
            m.insert("ok".into(), Value::Bool(true));
            m.insert("result".into(), v);
            Value::Object(m)
        }
        Err(e) => error_line(id, &e),
    }
}

/// [`answer_line_within`] as compact JSON text (what `quadsect batch`
/// writes): the same answer, byte for byte `answer_line_within(…)
/// .to_string()`; a natural pair's answer is written straight into text,
/// without building a `Value` tree (about a third of the cost of a curve's
/// answer).
///
/// ```
/// use quadsect::Budget;
/// let line = r#"{"id":"c","op":"natural","a":"sphere 0 0 0 4","b":"cylinder 1 0 0 0 0 1 1"}"#;
/// let text = quadsect::batch::answer_line_text_within(line, &Budget::default());
/// assert_eq!(text, quadsect::batch::answer_line_within(line, &Budget::default()).to_string());
/// ```
pub fn answer_line_text_within(line: &str, budget: &Budget) -> String {
    answer_text(line, budget, false)
}

/// [`answer_line_text_within`] with the request line itself in the answer
/// (`quadsect batch --echo`): `{"id", "request", "ok", …}`, where
/// `request` is the input line, verbatim, as a JSON string — so that an
/// answer can be checked against the input it answers without the input
/// file (the checker `quadsect_check` rebuilds the surfaces from it).
///
/// ```
/// use quadsect::Budget;
/// let line = r#"{"id":1,"op":"roots","poly":"x^2 - 2"}"#;
/// let text = quadsect::batch::answer_line_text_echoed(line, &Budget::default());
/// let v: serde_json::Value = serde_json::from_str(&text).unwrap();
/// assert_eq!(v["request"], line);
/// assert!(text.starts_with(r#"{"id":1,"request":"#));
/// let bad = quadsect::batch::answer_line_text_echoed("oops", &Budget::default());
/// let v: serde_json::Value = serde_json::from_str(&bad).unwrap();
/// assert_eq!((v["request"].as_str(), v["ok"].as_bool()), (Some("oops"), Some(false)));
/// ```
pub fn answer_line_text_echoed(line: &str, budget: &Budget) -> String {
    answer_text(line, budget, true)
}

/// The answer text, with `"request"` (the line as a JSON string) after the
/// `id` when `echo`.
fn answer_text(line: &str, budget: &Budget, echo: bool) -> String {
    let (id, result) = answer_with(line, budget, run_op_text_within);
    match result {
        Ok(text) => {
            let id = id.to_string();
            // a JSON string literal of the line (a str always serializes)
            let request = echo.then(|| serde_json::to_string(line).unwrap_or_default());
            let extra = request.as_ref().map_or(0, |r| r.len() + 12);
            let mut out = String::with_capacity(text.len() + id.len() + extra + 32);
            out.push_str("{\"id\":");
            out.push_str(&id);
            if let Some(r) = &request {
                out.push_str(",\"request\":");
                out.push_str(r);
            }
            out.push_str(",\"ok\":true,\"result\":");
            out.push_str(&text);
            out.push('}');
            out
        }
        Err(e) => {
            let mut v = error_line(id, &e);
            if echo {
                v = with_request(v, line);
            }
            v.to_string()
        }
    }
}

/// `answer` with `"request": line` inserted after its `id`.
fn with_request(answer: Value, line: &str) -> Value {
    let Value::Object(m) = answer else {
        return answer;
    };
    let mut out = Map::new();
    for (k, v) in m {
        let is_id = k == "id";
        out.insert(k, v);
        if is_id {
            out.insert("request".into(), Value::String(line.to_string()));
        }
    }
    Value::Object(out)
}

/// [`run_op_within`] as compact JSON text.
fn run_op_text_within(obj: &Map<String, Value>, budget: &Budget) -> Result<String, Error> {
    let (request, budget) = crate::request::Request::from_line(obj, budget)?;
    let svg = crate::request::Request::svg_wanted(obj)?;
    let answer = request.execute(&budget)?;
    let mut text = answer.to_json_text();
    if svg
        && let Some(picture) = answer.svg()
        && text.ends_with('}')
    {
        // the picture as the answer object's last member
        text.pop();
        text.push_str(",\"svg\":");
        text.push_str(&Value::String(picture).to_string());
        text.push('}');
    }
    Ok(text)
}

/// The line's `id` and its answer: the line parsed as a JSON object and
/// run, an exhausted budget or a panic caught as an error.
fn answer_with<T>(
    line: &str,
    budget: &Budget,
    run: fn(&Map<String, Value>, &Budget) -> Result<T, Error>,
) -> (Value, Result<T, Error>) {
    let parsed: Result<Value, _> = serde_json::from_str(line);
    match parsed {
        Err(e) => (
            Value::Null,
            Err(Error::new(
                ErrorKind::Json,
                if line.trim().is_empty() {
                    "empty line (expected a JSON object)".to_string()
                } else {
                    format!("invalid JSON: {e}")
                },
            )),
        ),
        Ok(Value::Object(obj)) => {
            let id = obj.get("id").cloned().unwrap_or(Value::Null);
            // `run` catches an exhausted budget itself; a payload reaching
            // this point is a panic (an internal failure)
            let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| run(&obj, budget)))
                .unwrap_or_else(|p| match p.downcast::<budget::Exhausted>() {
                    Ok(e) => Err(Error::from(*e)),
                    Err(p) => Err(Error::internal(panic_message(&p))),
                });
            (id, r)
        }
        Ok(_) => (
            Value::Null,
            Err(Error::new(
                ErrorKind::Json,
                "each line must be a JSON object",
            )),
        ),
    }
}

/// `{"id", "ok": false, "error": {"kind", "message"}}`.
fn error_line(id: Value, e: &Error) -> Value {
    json!({"id": id, "ok": false, "error": {"kind": e.kind().as_str(), "message": e.message()}})
}

/// Best-effort text of a panic payload.
pub fn panic_message(p: &Box<dyn std::any::Any + Send>) -> String {
    if let Some(s) = p.downcast_ref::<&str>() {
        s.to_string()
    } else if let Some(s) = p.downcast_ref::<String>() {
        s.clone()
    } else {
        "unknown panic".to_string()
    }
}

/// How [`run_batch_with`] runs.
#[derive(Clone, Debug)]
pub struct BatchOptions {
    /// Worker threads (at least 1).
    pub threads: usize,
    /// Most lines read but not yet written: a slow line delays the lines
    /// after it by at most this many (at least 1).
    pub lookahead: usize,
    /// The compute budget of each line.
    pub budget: Budget,
    /// Show progress on stderr (lines done, lines/s).
    pub progress: bool,
    /// The input's size in bytes when known (a regular file): the progress
    /// display then shows a bar and the time left.
    pub input_bytes: Option<u64>,
    /// Put each request line, verbatim, into its answer as `"request"`
    /// ([`answer_line_text_echoed`]; `quadsect batch --echo`).
    pub echo: bool,
}

impl Default for BatchOptions {
    /// All cores, a look-ahead of [`DEFAULT_LOOKAHEAD`] lines per thread,
    /// the default budget per line, no progress display.
    fn default() -> Self {
        let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
        BatchOptions {
            threads,
            lookahead: DEFAULT_LOOKAHEAD * threads,
            budget: Budget::default(),
            progress: false,
            input_bytes: None,
            echo: false,
        }
    }
}

/// How long written answers may wait for the next one before they are
/// flushed, while other lines are in flight.
const FLUSH_DELAY: std::time::Duration = std::time::Duration::from_millis(1);

/// A worker hands its answers over when it holds this many, when no line
/// is waiting for it, or when the first it holds is [`HOLD_TIME`] old.
pub const HOLD_LINES: usize = 8;
/// See [`HOLD_LINES`].
pub const HOLD_TIME: std::time::Duration = std::time::Duration::from_millis(1);

/// Look-ahead per worker thread (lines) of [`BatchOptions::default`].
pub const DEFAULT_LOOKAHEAD: usize = 64;

/// What a batch run did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BatchSummary {
    /// Answer lines written.
    pub lines: usize,
    /// The output was closed early (a broken pipe, as `quadsect batch F |
    /// head -1` does): the run stopped there.
    pub output_closed: bool,
}

/// Reads JSON lines from `input` and writes one answer line per input line
/// to `out`, in order, in parallel on all cores, each line under the
/// default budget.  `progress` shows progress on stderr.  Returns the
/// number of lines (see [`run_batch_with`]).
pub fn run_batch(
    input: impl BufRead + Send + 'static,
    out: impl Write,
    progress: bool,
) -> std::io::Result<usize> {
    let opts = BatchOptions {
        progress,
        ..BatchOptions::default()
    };
    run_batch_with(input, out, &opts).map(|s| s.lines)
}

/// A line read, waiting for its answer: its index, text and size in bytes.
type Job = (usize, String, u64);

/// The lines read but not yet written, shared by the reader (who waits
/// while there are `lookahead` of them) and the writer.
struct Window {
    state: Mutex<WindowState>,
    changed: Condvar,
    /// Lines handed to the workers (after their text was read): the
    /// writer flushes at once when every one of them is written.
    queued: AtomicUsize,
}

struct WindowState {
    read: usize,
    written: usize,
    stop: bool,
    /// The reader waits for the window to open.
    waiting: bool,
}

impl Window {
    /// Blocks until one more line may be read; `false` when the run stops.
    fn admit(&self, lookahead: usize) -> bool {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        while !st.stop && st.read - st.written >= lookahead {
            st.waiting = true;
            st = self.changed.wait(st).unwrap_or_else(|e| e.into_inner());
        }
        st.waiting = false;
        if st.stop {
            return false;
        }
        st.read += 1;
        true
    }

    /// Records `n` lines written; wakes a waiting reader once the window
    /// is half open (it then reads half a window without sleeping, not one
    /// line per wake-up).
    fn set_written(&self, n: usize, lookahead: usize) {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        st.written = n;
        if st.waiting && st.read - st.written <= lookahead / 2 {
            self.changed.notify_all();
        }
    }

    fn stop(&self) {
        let mut st = self.state.lock().unwrap_or_else(|e| e.into_inner());
        st.stop = true;
        self.changed.notify_all();
    }
}

/// Stops the reader and cancels the running lines when the run ends.
struct StopOnDrop {
    window: Arc<Window>,
    cancel: Arc<AtomicBool>,
}

impl Drop for StopOnDrop {
    fn drop(&mut self) {
        self.cancel.store(true, Ordering::Relaxed);
        self.window.stop();
    }
}

/// Reads the lines of `input` lazily (one more only when the look-ahead
/// allows it) and queues them; returns the first read error.
fn read_lines(
    mut input: impl BufRead,
    jobs: mpsc::Sender<Job>,
    window: &Window,
    lookahead: usize,
) -> std::io::Result<()> {
    let mut buf = Vec::new();
    let mut i = 0;
    loop {
        if !window.admit(lookahead) {
            return Ok(());
        }
        buf.clear();
        let n = input.read_until(b'\n', &mut buf)?;
        if n == 0 {
            return Ok(());
        }
        if buf.last() == Some(&b'\n') {
            buf.pop();
            if buf.last() == Some(&b'\r') {
                buf.pop();
            }
        }
        // invalid UTF-8 becomes U+FFFD and then a JSON error line: never lost
        let line = String::from_utf8_lossy(&buf).into_owned();
        if jobs.send((i, line, n as u64)).is_err() {
            return Ok(());
        }
        i += 1;
        window.queued.store(i, Ordering::Release);
    }
}

/// Without the `cli` feature there is no progress display.
#[cfg(not(feature = "cli"))]
struct NoBar;

#[cfg(not(feature = "cli"))]
impl NoBar {
    fn set_message(&self, _: String) {}
    fn set_position(&self, _: u64) {}
    fn finish_and_clear(self) {}
}

#[cfg(not(feature = "cli"))]
fn progress_bar(_: &BatchOptions) -> Option<NoBar> {
    None
}

/// The progress display on stderr: lines done and lines/s, with a bar and
/// the time left when the input size is known.
#[cfg(feature = "cli")]
fn progress_bar(opts: &BatchOptions) -> Option<indicatif::ProgressBar> {
    if !opts.progress {
        return None;
    }
    let (bar, template) = match opts.input_bytes {
        Some(total) => (
            indicatif::ProgressBar::new(total),
            "{bar:30} {percent:>3}%  {msg}  {elapsed} (eta {eta})",
        ),
        None => (
            indicatif::ProgressBar::new_spinner(),
            "{spinner} {msg}  {elapsed}",
        ),
    };
    bar.set_style(
        indicatif::ProgressStyle::with_template(template)
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_spinner()),
    );
    // redrawn on a timer: updates between two draws are not lost, and the
    // display moves while a slow line holds the others back
    bar.enable_steady_tick(std::time::Duration::from_millis(200));
    Some(bar)
}

/// Reads JSON lines from `input` and writes one answer line per input line
/// to `out`, in input order, streaming:
///
/// * each answer is written as soon as it and every earlier line are done,
///   and flushed at once when no other line is in flight (else within
///   1 ms); while more lines are queued a worker hands its answers over
///   up to [`HOLD_LINES`] at a time (the first waits at most
///   [`HOLD_TIME`] or one more line's time);
/// * the lines are answered by `opts.threads` workers, each under its own
///   `opts.budget`; at most `opts.lookahead` lines are read ahead of the
///   last one written, so a slow line delays only the lines after it, and
///   only up to the look-ahead;
/// * the input is read lazily: a client that waits for the answer to line
///   i before it sends line i+1 gets it;
/// * a bad line yields its error line in place (nothing is lost);
/// * a closed output (broken pipe) ends the run quietly:
///   [`BatchSummary::output_closed`], not an error.
///
/// The reader and the workers are detached threads (so that a reader
/// blocked on an open but silent input cannot keep the run alive after the
/// output closed); they end on their own once the run is over.
pub fn run_batch_with(
    input: impl BufRead + Send + 'static,
    mut out: impl Write,
    opts: &BatchOptions,
) -> std::io::Result<BatchSummary> {
    let threads = opts.threads.max(1);
    let lookahead = opts.lookahead.max(1);
    let cancel = Arc::new(AtomicBool::new(false));
    let budget = opts.budget.clone().with_cancel_flag(cancel.clone());
    let window = Arc::new(Window {
        state: Mutex::new(WindowState {
            read: 0,
            written: 0,
            stop: false,
            waiting: false,
        }),
        changed: Condvar::new(),
        queued: AtomicUsize::new(0),
    });
    // however the run ends, the reader stops and the lines still running
    // are cancelled
    let _stop = StopOnDrop {
        window: window.clone(),
        cancel: cancel.clone(),
    };
    let (job_tx, job_rx) = mpsc::channel::<Job>();
    let (ans_tx, ans_rx) = mpsc::channel::<Vec<Job>>();
    let reader = {
        let window = window.clone();
        std::thread::spawn(move || read_lines(input, job_tx, &window, lookahead))
    };
    let job_rx = Arc::new(Mutex::new(job_rx));
    for _ in 0..threads {
        let (jobs, answers, budget) = (job_rx.clone(), ans_tx.clone(), budget.clone());
        let echo = opts.echo;
        std::thread::spawn(move || {
            // answers go to the writer a few at a time (one wake-up of the
            // writer per handful of lines, not per line: the futex calls
            // and context switches were an eighth of a run's CPU time);
            // what is held goes at once when no line is waiting, so a
            // held answer waits at most HOLD_TIME or the next line's time
            let mut held: Vec<Job> = Vec::new();
            let mut since = std::time::Instant::now();
            loop {
                // a worker never waits while it holds answers (the writer may
                // be waiting for them): the queue counts as empty while the
                // other worker waits on it
                let next = match jobs.try_lock() {
                    Ok(rx) => rx.try_recv(),
                    Err(std::sync::TryLockError::WouldBlock) => Err(mpsc::TryRecvError::Empty),
                    Err(std::sync::TryLockError::Poisoned(e)) => e.into_inner().try_recv(),
                };
                let job = match next {
                    Ok(job) => job,
                    Err(mpsc::TryRecvError::Disconnected) => break,
                    Err(mpsc::TryRecvError::Empty) => {
                        if !held.is_empty() && answers.send(std::mem::take(&mut held)).is_err() {
                            return;
                        }
                        match jobs.lock().unwrap_or_else(|e| e.into_inner()).recv() {
                            Ok(job) => job,
                            Err(_) => break,
                        }
                    }
                };
                let (i, line, bytes) = job;
                let answer = answer_text(&line, &budget, echo);
                if held.is_empty() {
                    since = std::time::Instant::now();
                }
                held.push((i, answer, bytes));
                if (held.len() >= HOLD_LINES || since.elapsed() >= HOLD_TIME)
                    && answers.send(std::mem::take(&mut held)).is_err()
                {
                    return;
                }
            }
            if !held.is_empty() {
                let _ = answers.send(held);
            }
        });
    }
    drop(ans_tx);
    let bar = progress_bar(opts);
    let started = std::time::Instant::now();
    let mut pending: BTreeMap<usize, (String, u64)> = BTreeMap::new();
    let (mut written, mut bytes_done) = (0usize, 0u64);
    let mut closed = false;
    // the workers hang up when the reader is done and every line answered;
    // written answers are flushed as soon as no other line is in flight,
    // else when none has come for FLUSH_DELAY (one write for many lines)
    let mut unflushed = false;
    'run: loop {
        let next = if unflushed {
            match ans_rx.recv_timeout(FLUSH_DELAY) {
                Ok(job) => Some(job),
                Err(mpsc::RecvTimeoutError::Timeout) => None,
                Err(mpsc::RecvTimeoutError::Disconnected) => break,
            }
        } else {
            match ans_rx.recv() {
                Ok(job) => Some(job),
                Err(_) => break,
            }
        };
        if let Some(batch) = next {
            for (i, answer, bytes) in batch {
                pending.insert(i, (answer, bytes));
            }
            loop {
                while let Some((answer, bytes)) = pending.remove(&written) {
                    if let Err(e) = writeln!(out, "{answer}") {
                        if e.kind() == IoErrorKind::BrokenPipe {
                            closed = true;
                            break 'run;
                        }
                        return Err(e);
                    }
                    written += 1;
                    bytes_done += bytes;
                    unflushed = true;
                }
                // more answers already done: write them before flushing
                match ans_rx.try_recv() {
                    Ok(batch) => {
                        for (i, answer, bytes) in batch {
                            pending.insert(i, (answer, bytes));
                        }
                    }
                    Err(_) => break,
                }
            }
            window.set_written(written, lookahead);
            if written < window.queued.load(Ordering::Acquire) {
                // lines in flight: their answers come soon
                continue;
            }
        }
        if unflushed {
            if let Err(e) = out.flush() {
                if e.kind() == IoErrorKind::BrokenPipe {
                    closed = true;
                    break;
                }
                return Err(e);
            }
            unflushed = false;
        }
        if let Some(b) = &bar {
            let rate = written as f64 / started.elapsed().as_secs_f64().max(1e-9);
            b.set_message(format!("{written} lines  {rate:.1} lines/s"));
            if opts.input_bytes.is_some() {
                b.set_position(bytes_done);
            }
        }
    }
    if unflushed && !closed {
        match out.flush() {
            Err(e) if e.kind() == IoErrorKind::BrokenPipe => closed = true,
            Err(e) => return Err(e),
            Ok(()) => {}
        }
    }
    if let Some(b) = bar {
        b.finish_and_clear();
    }
    if closed {
        return Ok(BatchSummary {
            lines: written,
            output_closed: true,
        });
    }
    // every line read has been answered: the reader has finished
    match reader.join() {
        Ok(r) => r?,
        Err(_) => return Err(std::io::Error::other("the batch reader failed")),
    }
    Ok(BatchSummary {
        lines: written,
        output_closed: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Cursor;

    fn lines(n: usize) -> String {
        (0..n)
            .map(|i| {
                format!(
                    "{{\"id\":{i},\"op\":\"roots\",\"poly\":\"x^2-{}\"}}\n",
                    i + 2
                )
            })
            .collect()
    }

    fn opts(threads: usize, lookahead: usize) -> BatchOptions {
        BatchOptions {
            threads,
            lookahead,
            budget: Budget::default(),
            progress: false,
            input_bytes: None,
            echo: false,
        }
    }

    #[test]
    fn echo_puts_each_line_verbatim_after_the_id_and_changes_nothing_else() {
        let input = "{\"id\":\"a\", \"op\":\"roots\",\"poly\":\"x^2-2\"}\r\nnot json\n{\"op\":\"roots\",\"poly\":\"x\",\"bogus\":1}\n";
        let run = |echo: bool| {
            let mut out = Vec::new();
            let o = BatchOptions { echo, ..opts(2, 4) };
            run_batch_with(Cursor::new(input.to_string()), &mut out, &o).unwrap();
            String::from_utf8(out).unwrap()
        };
        let (plain, echoed) = (run(false), run(true));
        let requests = [
            "{\"id\":\"a\", \"op\":\"roots\",\"poly\":\"x^2-2\"}",
            "not json",
            "{\"op\":\"roots\",\"poly\":\"x\",\"bogus\":1}",
        ];
        for ((p, e), r) in plain.lines().zip(echoed.lines()).zip(requests) {
            let (mut pv, mut ev): (Map<String, Value>, Map<String, Value>) = (
                serde_json::from_str(p).unwrap(),
                serde_json::from_str(e).unwrap(),
            );
            assert_eq!(ev.keys().take(2).collect::<Vec<_>>(), ["id", "request"]);
            assert_eq!(ev.remove("request"), Some(Value::String(r.into())));
            assert_eq!(ev, pv, "{e}");
            assert!(pv.remove("request").is_none());
        }
        assert_eq!(echoed.lines().count(), 3);
    }

    #[test]
    fn answers_in_input_order_whatever_the_threads_and_look_ahead() {
        for (threads, lookahead) in [(1, 1), (2, 1), (3, 2), (4, 64)] {
            let mut out = Vec::new();
            let input = Cursor::new(lines(50).into_bytes());
            let s = run_batch_with(input, &mut out, &opts(threads, lookahead)).unwrap();
            assert_eq!(
                s,
                BatchSummary {
                    lines: 50,
                    output_closed: false
                }
            );
            let text = String::from_utf8(out).unwrap();
            for (i, l) in text.lines().enumerate() {
                let v: Value = serde_json::from_str(l).unwrap();
                assert_eq!(v["id"], i, "threads {threads}, look-ahead {lookahead}");
                assert_eq!(v["result"]["distinct_real"], 2);
            }
        }
    }

    /// A writer whose reader goes away after `keep` lines.
    struct ClosesAfter {
        keep: usize,
        lines: usize,
    }

    impl Write for ClosesAfter {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            if self.lines >= self.keep {
                return Err(std::io::Error::from(IoErrorKind::BrokenPipe));
            }
            self.lines += buf.iter().filter(|&&b| b == b'\n').count();
            Ok(buf.len())
        }
        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_closed_output_ends_the_run_quietly() {
        let input = Cursor::new(lines(500).into_bytes());
        let out = ClosesAfter { keep: 3, lines: 0 };
        let s = run_batch_with(input, out, &opts(2, 8)).unwrap();
        assert!(s.output_closed);
        assert!(s.lines >= 3 && s.lines < 500, "{s:?}");
    }

    /// Input that fails after its first bytes.
    struct FailsAfter(Cursor<Vec<u8>>);

    impl std::io::Read for FailsAfter {
        fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
            match self.0.read(buf)? {
                0 => Err(std::io::Error::other("disk on fire")),
                n => Ok(n),
            }
        }
    }

    #[test]
    fn a_read_error_comes_after_the_answers_to_the_lines_before_it() {
        let input = std::io::BufReader::new(FailsAfter(Cursor::new(lines(5).into_bytes())));
        let mut out = Vec::new();
        let e = run_batch_with(input, &mut out, &opts(2, 4)).unwrap_err();
        assert!(e.to_string().contains("disk on fire"));
        assert_eq!(String::from_utf8(out).unwrap().lines().count(), 5);
    }

    /// 12 terms of degree up to 6667: seconds of work.
    const SLOW_ROOTS: &str =
        "x^6667-3x^5000+7x^4000-x^3333+5x^2000-2x^1000+x^500-9x^100+x^50-3x^10+x-1";

    fn answer(line: Value, budget: &Budget) -> Value {
        answer_line_within(&line.to_string(), budget)
    }

    #[test]
    fn a_line_time_limit_tightens_the_budget() {
        let t0 = std::time::Instant::now();
        let v = answer(
            json!({"id": 1, "op": "roots", "poly": SLOW_ROOTS, "time_limit": 0.001}),
            &Budget::default(),
        );
        assert!(t0.elapsed() < std::time::Duration::from_secs(5), "{v}");
        assert_eq!((v["id"].clone(), v["ok"].clone()), (json!(1), json!(false)));
        assert_eq!(v["error"]["kind"], "budget", "{v}");
        assert!(
            v["error"]["message"]
                .as_str()
                .unwrap()
                .contains("time limit of 0.001 s"),
            "{v}"
        );
        // tangent and natural answer undecided, with the limit
        let v = answer(
            json!({"id": 2, "op": "natural", "a": "cylinder point=0,0,0 axis=1,0,0 radius2=1",
                   "b": "cone vertex=0,1,0 axis=0,1,0 tan2=1", "time_limit": 0}),
            &Budget::default(),
        );
        assert_eq!(v["result"]["class"], "undecided", "{v}");
        assert_eq!(v["result"]["reason"]["limit"], "time");
        let v = answer(
            json!({"id": 3, "op": "tangent", "ellipsoid": "x^2+y^2+z^2-1", "surface": "x*y*z-1/9",
                   "time_limit": 0}),
            &Budget::default(),
        );
        assert_eq!(v["result"]["verdict"], "undecided", "{v}");
        // a line without limits of its own, or with a loose one, is unaffected
        for limit in [json!(null), json!("none"), json!(3600), json!(1e300)] {
            let v = answer(
                json!({"id": 4, "op": "roots", "poly": "x^2-2", "time_limit": limit}),
                &Budget::default(),
            );
            assert_eq!(v["result"]["distinct_real"], 2, "{limit}: {v}");
        }
    }

    #[test]
    fn a_line_limit_never_loosens_the_budget() {
        let no_time = Budget::default().with_time_limit(Some(std::time::Duration::ZERO));
        for limit in [
            json!(3600),
            json!(1e300),
            json!(null),
            json!("none"),
            json!("NONE"),
        ] {
            let v = answer(
                json!({"id": 1, "op": "roots", "poly": "x^2-2", "time_limit": limit}),
                &no_time,
            );
            assert_eq!(v["error"]["kind"], "budget", "{limit}: {v}");
        }
        // memory: the parser's products of (x+1)^64 (cancelled by its
        // negative) are estimated at more than 0.001 MiB
        let line = |m: Value| json!({"id": 2, "op": "roots", "poly": "(x+1)^64 - (x+1)^64 + x^2 - 2", "memory_limit": m});
        let v = answer(line(json!(0.001)), &Budget::default());
        assert_eq!(v["error"]["kind"], "budget", "{v}");
        assert!(
            v["error"]["message"]
                .as_str()
                .unwrap()
                .contains("the memory limit is 0.001 MiB"),
            "{v}"
        );
        assert_eq!(answer(line(json!(null)), &Budget::default())["ok"], true);
        assert_eq!(answer(line(json!(1)), &Budget::default())["ok"], true);
        let tiny = Budget::default().with_memory_limit(Some(1000));
        for m in [json!(4096), json!(null), json!("none")] {
            assert_eq!(answer(line(m), &tiny)["error"]["kind"], "budget");
        }
    }

    #[test]
    fn bad_limit_values_are_bad_fields_named() {
        for field in ["time_limit", "memory_limit"] {
            for value in [
                json!(-1),
                json!(-0.5),
                json!("NaN"),
                json!("inf"),
                json!("0.5"),
                json!(""),
                json!(true),
                json!([1]),
                json!({"s": 1}),
            ] {
                let mut line = json!({"id": 9, "op": "roots", "poly": "x^2-2"});
                line[field] = value.clone();
                let v = answer(line, &Budget::default());
                assert_eq!(v["id"], 9);
                assert_eq!(v["error"]["kind"], "bad-field", "{field}={value}: {v}");
                let m = v["error"]["message"].as_str().unwrap();
                assert!(
                    m.starts_with(&format!("field \"{field}\" must be a number of")),
                    "{m}"
                );
                assert!(m.contains(&format!("got {value}")), "{m}");
            }
        }
        // zero is a limit (no time at all), not an error
        let v = answer(
            json!({"id": 1, "op": "roots", "poly": "x^2-2", "time_limit": 0, "memory_limit": 0.0}),
            &Budget::default(),
        );
        assert_eq!(v["error"]["kind"], "budget", "{v}");
    }

    #[test]
    fn unknown_fields_are_bad_fields_named() {
        let v = answer(
            json!({"id": 5, "op": "roots", "poly": "x^2-2", "time_limt": 0.001}),
            &Budget::default(),
        );
        assert_eq!(v["id"], 5);
        assert_eq!(v["error"]["kind"], "bad-field");
        assert_eq!(
            v["error"]["message"],
            r#"unknown field "time_limt" for op "roots" (expected: id, op, poly, time_limit, memory_limit)"#
        );
        // another op's field is unknown too; the first unknown one is named
        let v = answer(
            json!({"op": "resultant", "f": "x", "g": "y", "var": "x", "poly": "x", "zz": 1}),
            &Budget::default(),
        );
        assert_eq!(
            v["error"]["message"],
            r#"unknown field "poly" for op "resultant" (expected: id, op, f, g, var, time_limit, memory_limit)"#
        );
        // a misspelt required field is named (not only the missing one)
        let v = answer(json!({"op": "roots", "pol": "x"}), &Budget::default());
        assert_eq!(v["error"]["kind"], "bad-field");
        assert!(
            v["error"]["message"]
                .as_str()
                .unwrap()
                .starts_with(r#"unknown field "pol""#)
        );
        // an unknown op is still unknown-op
        let v = answer(json!({"op": "frobnicate", "x": 1}), &Budget::default());
        assert_eq!(v["error"]["kind"], "unknown-op");
    }

    #[test]
    fn every_known_field_of_every_op_is_accepted() {
        let lines = [
            json!({"id": 1, "op": "tangent", "ellipsoid": "x^2+y^2+z^2-1", "surface": "x-2",
                   "values": false, "float": true, "svg": true, "time_limit": 5, "memory_limit": 256}),
            json!({"id": 2, "op": "natural", "a": "sphere center=0,0,0 radius2=1",
                   "b": {"kind": "sphere", "center": ["3", "0", "0"], "radius2": "1"},
                   "components": false, "referee": true, "float": false, "svg": false, "time_limit": 5, "memory_limit": 256}),
            json!({"id": 3, "op": "roots", "poly": "x^2-2", "time_limit": 5, "memory_limit": 256}),
            json!({"id": 4, "op": "resultant", "f": "x^2+y^2-1", "g": "x-y", "var": "x",
                   "time_limit": 5, "memory_limit": 256}),
            json!({"id": 5, "op": "ellipsoid-contact", "a": "x^2+y^2+z^2-1",
                   "b": {"center": [2, 0, 0], "semi_axes": ["1", 1, 1],
                         "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
                   "time_limit": 5, "memory_limit": 256}),
        ];
        assert_eq!(lines.len(), crate::request::OPS.len());
        for line in lines {
            let v = answer(line.clone(), &Budget::default());
            assert_eq!(v["ok"], true, "{line}: {v}");
            // the picture exactly when asked for
            assert_eq!(
                v["result"].get("svg").is_some(),
                line["svg"] == true,
                "{line}"
            );
            let op = line["op"].as_str().unwrap();
            let (_, fields) = crate::request::OPS.iter().find(|(n, _)| *n == op).unwrap();
            for f in *fields {
                assert!(line.get(*f).is_some(), "the test line of {op} lacks {f}");
            }
        }
    }

    #[test]
    fn lines_with_limits_and_bad_fields_are_answered_in_order() {
        let lines = [
            json!({"id": 0, "op": "roots", "poly": SLOW_ROOTS, "time_limit": 0.001}),
            json!({"id": 1, "op": "roots", "poly": "x^2-2", "time_limit": 2}),
            json!({"id": 2, "op": "roots", "poly": "x^2-2", "time_limit": -2}),
            json!({"id": 3, "op": "roots", "poly": "x^2-2", "timelimit": 2}),
            json!({"id": 4, "op": "roots", "poly": "x^2-3"}),
        ];
        let text: String = lines.iter().map(|l| format!("{l}\n")).collect();
        let mut out = Vec::new();
        let s = run_batch_with(Cursor::new(text.into_bytes()), &mut out, &opts(2, 4)).unwrap();
        assert_eq!(s.lines, 5);
        let got: Vec<Value> = String::from_utf8(out)
            .unwrap()
            .lines()
            .map(|l| serde_json::from_str(l).unwrap())
            .collect();
        let kinds: Vec<&str> = got
            .iter()
            .map(|v| v["error"]["kind"].as_str().unwrap_or("ok"))
            .collect();
        assert_eq!(kinds, ["budget", "ok", "bad-field", "bad-field", "ok"]);
        for (i, v) in got.iter().enumerate() {
            assert_eq!(v["id"], i);
        }
    }

    #[test]
    fn an_exhausted_budget_is_not_an_internal_error() {
        let none = Budget::unlimited().with_time_limit(Some(std::time::Duration::ZERO));
        let v = answer_line_within(
            r#"{"id":1,"op":"natural","a":"cylinder point=0,0,0 axis=1,0,0 radius2=1","b":"cone vertex=0,1,0 axis=0,1,0 tan2=1"}"#,
            &none,
        );
        assert_eq!(v["ok"], true);
        assert_eq!(v["result"]["class"], "undecided");
        assert_eq!(v["result"]["reason"]["limit"], "time");
    }
}
