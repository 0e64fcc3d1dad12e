//! Compute budgets and the streaming batch, end to end through the binary:
//! the hostile inputs of issue 16 end within their time budget (plus a
//! small constant) with the documented answer, memory stays under the
//! limit, and `quadsect batch` streams, keeps order and ids, and ends
//! quietly on a closed pipe.

use quadsect::{Budget, Limit};
use serde_json::Value;
use std::io::{BufRead, BufReader, Read, Write};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// What a budgeted run may take beyond its time limit: unwinding, the
/// answer, process start-up and exit, on a loaded CI machine.
/// (Unoptimised builds are much slower between two checks.)
const SLACK: Duration = Duration::from_millis(if cfg!(debug_assertions) {
    20_000
} else {
    2_000
});

const E264: &str = "(x--2)^2/6+(y--5)^2/6+(z-0)^2/4-1";
const S264: &str = "-9/4*4*y*y+5*yz+6/3*z*z+-12/2*xx+3*yz^126+8/5*z+6/3";
/// 12 terms, degree 6667.
const ROOTS6667: &str = "x^6667-3x^5000+7x^4000-x^3333+5x^2000-2x^1000+x^500-9x^100+x^50-3x^10+x-1";

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_quadsect"))
}

/// The tests that time or measure a child process run one at a time, so
/// that their children do not compete for the cores with each other.
static ONE_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

fn serial() -> std::sync::MutexGuard<'static, ()> {
    ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner())
}

struct Run {
    status: i32,
    stdout: String,
    stderr: String,
    wall: Duration,
}

fn run(args: &[&str], stdin: Option<&str>) -> Run {
    let t0 = Instant::now();
    let mut child = bin()
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    {
        let mut input = child.stdin.take().unwrap();
        if let Some(s) = stdin {
            input.write_all(s.as_bytes()).unwrap();
        }
    }
    let out = child.wait_with_output().unwrap();
    Run {
        status: out.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        wall: t0.elapsed(),
    }
}

fn within(r: &Run, limit: Duration) {
    assert!(
        r.wall <= limit + SLACK,
        "took {:?} with a time limit of {:?}",
        r.wall,
        limit
    );
}

fn json(s: &str) -> Value {
    serde_json::from_str(s.trim()).unwrap_or_else(|e| panic!("not JSON ({e}): {s}"))
}

#[test]
fn the_264_byte_tangent_input_is_undecided_within_its_budget() {
    let _serial = serial();
    let r = run(
        &[
            "tangent",
            "--time-limit",
            "1",
            "--json",
            "--ellipsoid",
            E264,
            "--surface",
            S264,
        ],
        None,
    );
    within(&r, Duration::from_secs(1));
    assert_eq!(
        r.status, 3,
        "exit status 3 for an exhausted budget: {}",
        r.stderr
    );
    let v = json(&r.stdout);
    assert_eq!(v["verdict"], "undecided");
    assert_eq!(v["reason"]["kind"], "budget");
    let limit = v["reason"]["limit"].as_str().unwrap();
    assert!(["time", "size", "memory"].contains(&limit), "{v}");
    assert!(r.stderr.contains("budget exhausted"), "{}", r.stderr);
}

#[test]
fn a_huge_exact_coefficient_in_batch_is_undecided_within_its_budget() {
    let _serial = serial();
    let line = r#"{"id":"big","op":"tangent","ellipsoid":"x^2+y^2+z^2-1","surface":"x-5e-98709-90e-5083"}"#;
    let r = run(&["batch", "--time-limit", "1"], Some(&format!("{line}\n")));
    within(&r, Duration::from_secs(1));
    assert_eq!(r.status, 0, "{}", r.stderr);
    let v = json(&r.stdout);
    assert_eq!(v["id"], "big");
    assert_eq!(v["ok"], true);
    assert_eq!(v["result"]["verdict"], "undecided");
    assert_eq!(v["result"]["reason"]["kind"], "budget");
    assert_eq!(v["result"]["reason"]["limit"], "time");
    assert!(r.stdout.len() < 10_000, "no megabytes of output");
}

#[test]
fn roots_of_degree_6667_is_a_budget_error_within_its_budget() {
    let _serial = serial();
    let r = run(&["roots", "--time-limit", "1", ROOTS6667], None);
    within(&r, Duration::from_secs(1));
    assert_eq!(r.status, 3);
    assert!(r.stdout.is_empty());
    assert!(r.stderr.contains("budget exhausted (time)"), "{}", r.stderr);
    // the same in batch: an error line of kind budget, in place
    let lines = format!(
        "{}\n{}\n",
        serde_json::json!({"id": 1, "op": "roots", "poly": ROOTS6667}),
        serde_json::json!({"id": 2, "op": "roots", "poly": "x^2-2"})
    );
    let r = run(&["batch", "--time-limit", "0.5"], Some(&lines));
    within(&r, Duration::from_millis(500));
    let out: Vec<Value> = r.stdout.lines().map(json).collect();
    assert_eq!(out.len(), 2);
    assert_eq!(out[0]["error"]["kind"], "budget");
    assert_eq!(out[0]["id"], 1);
    assert_eq!(out[1]["result"]["distinct_real"], 2);
}

/// `quadsect tangent --json` on the dense surface of degree `d` against a
/// fixed ellipsoid under a 2 s time limit, checked to end within it.
fn dense_within_two_seconds(d: u32) -> Run {
    let s = dense_degree(d);
    let r = run(
        &[
            "tangent",
            "--time-limit",
            "2",
            "--json",
            "--ellipsoid",
            "x^2+2y^2+3z^2-5",
            "--surface",
            &s,
        ],
        None,
    );
    within(&r, Duration::from_secs(2));
    r
}

/// A dense surface of degree `d` with pseudo-random coefficients in −9…9.
fn dense_degree(d: u32) -> String {
    let mut terms = Vec::new();
    let mut seed = 7u64;
    for i in 0..=d {
        for j in 0..=d - i {
            for k in 0..=d - i - j {
                seed = seed
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let c = (seed >> 33) % 19;
                terms.push(format!("{}*x^{i}*y^{j}*z^{k}", c as i64 - 9));
            }
        }
    }
    terms.join("+")
}

/// Dense degree 10 (no answer in minutes before the Poisson route of issue
/// 17, now about a second): within a 2 s budget the answer is either the
/// verdict or `undecided: budget` — never late.
#[test]
fn a_dense_degree_10_surface_ends_within_its_budget() {
    let _serial = serial();
    let r = dense_within_two_seconds(10);
    let v = json(&r.stdout);
    match r.status {
        0 => assert_ne!(v["verdict"], "undecided"),
        3 => assert_eq!(v["reason"]["kind"], "budget"),
        other => panic!("exit status {other}"),
    }
}

/// Dense degree 14 takes about 6 s to decide (degree 12, 2.3 s, came too
/// close to the 2 s limit once the value polynomials got faster): within
/// 2 s it must end `undecided: budget`, on time.
#[test]
fn a_dense_degree_14_surface_is_undecided_within_its_budget() {
    let _serial = serial();
    let r = dense_within_two_seconds(14);
    assert_eq!(r.status, 3);
    let v = json(&r.stdout);
    assert_eq!(v["verdict"], "undecided");
    assert_eq!(v["reason"]["kind"], "budget");
}

/// The peak resident set of a child process, polled from /proc until it
/// exits (VmHWM is itself a peak, so a late reading sees earlier peaks),
/// its exit status and its standard output.
#[cfg(target_os = "linux")]
fn peak_rss_kib(args: &[&str]) -> (u64, i32, String) {
    let mut child = bin()
        .args(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let reader = std::thread::spawn(move || {
        let mut s = String::new();
        stdout.read_to_string(&mut s).unwrap();
        s
    });
    let path = format!("/proc/{}/status", child.id());
    let mut peak = 0u64;
    loop {
        if let Ok(s) = std::fs::read_to_string(&path) {
            for l in s.lines() {
                if let Some(v) = l.strip_prefix("VmHWM:") {
                    let kib: u64 = v.trim().trim_end_matches("kB").trim().parse().unwrap_or(0);
                    peak = peak.max(kib);
                }
            }
        }
        if let Some(st) = child.try_wait().unwrap() {
            return (peak, st.code().unwrap_or(-1), reader.join().unwrap());
        }
        std::thread::sleep(Duration::from_millis(2));
    }
}

/// What the process holds besides the memory an operation allocates: the
/// program itself and the allocator's slack.
#[cfg(target_os = "linux")]
const RSS_SLACK_KIB: u64 = 16 * 1024;

/// `quadsect tangent --json` under a memory limit of `mib` MiB: its peak
/// resident set stays under the limit (plus the program itself), the
/// budget runs out (exit status 3), and the answer says why.
#[cfg(target_os = "linux")]
fn tangent_under_memory_limit(mib: u64, e: &str, s: &str) -> Value {
    let m = mib.to_string();
    let (kib, status, out) = peak_rss_kib(&[
        "tangent",
        "--json",
        "--memory-limit",
        &m,
        "--time-limit",
        "20",
        "--ellipsoid",
        e,
        "--surface",
        s,
    ]);
    assert_eq!(status, 3);
    assert!(kib > 0, "the child's memory was read");
    assert!(
        kib < mib * 1024 + RSS_SLACK_KIB,
        "peak RSS {kib} KiB over the {mib} MiB limit"
    );
    let v = json(&out);
    assert_eq!(v["verdict"], "undecided");
    assert_eq!(v["reason"]["kind"], "budget");
    v
}

#[cfg(target_os = "linux")]
#[test]
fn the_264_byte_input_stays_under_the_memory_limit() {
    let _serial = serial();
    // without limits it grew to 3.3 GB; with the default size estimates
    // and a 256 MiB limit it is refused before the large matrices exist,
    // and with 100 MiB the allocator's count stops it
    for mib in [256, 100] {
        let v = tangent_under_memory_limit(mib, E264, S264);
        let limit = v["reason"]["limit"].as_str().unwrap();
        assert!(["size", "memory"].contains(&limit), "{v}");
    }
}

#[cfg(target_os = "linux")]
#[test]
fn a_dense_degree_12_surface_stays_under_the_memory_limit() {
    let _serial = serial();
    let s = dense_degree(12);
    // the Gröbner bases modulo primes and the lifted polynomials grow past
    // 8 MiB; the allocator's count stops them.  (Since the CRT keeps word
    // digits and D(u)'s roots are isolated without Descartes' rule, the
    // computation fits in 16 MiB and the answer comes in about 3 s; its JSON,
    // which repeats D(u) for every critical value, then takes 45 MB.)
    tangent_under_memory_limit(8, "x^2+2y^2+3z^2-5", &s);
}

#[test]
fn batch_streams_answer_before_the_next_line() {
    let _serial = serial();
    let mut child = bin()
        .args(["batch"])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .spawn()
        .unwrap();
    let mut input = child.stdin.take().unwrap();
    let mut output = BufReader::new(child.stdout.take().unwrap());
    for i in 0..3 {
        writeln!(input, r#"{{"id":{i},"op":"roots","poly":"x^2-{}"}}"#, i + 2).unwrap();
        input.flush().unwrap();
        // the answer comes while the input is still open
        let mut line = String::new();
        output.read_line(&mut line).unwrap();
        let v = json(&line);
        assert_eq!(v["id"], i);
        assert_eq!(v["result"]["distinct_real"], 2);
    }
    drop(input);
    let mut rest = String::new();
    output.read_to_string(&mut rest).unwrap();
    assert!(rest.is_empty());
    assert!(child.wait().unwrap().success());
}

#[test]
fn batch_keeps_order_and_ids_with_slow_and_fast_lines() {
    let _serial = serial();
    let mut lines = String::new();
    let mut expect = Vec::new();
    for i in 0..24 {
        let line = if i % 6 == 1 {
            expect.push("budget");
            serde_json::json!({"id": format!("slow{i}"), "op": "roots", "poly": ROOTS6667})
        } else if i % 6 == 4 {
            expect.push("bad");
            serde_json::json!({"id": format!("bad{i}"), "op": "roots", "poly": "x y"})
        } else {
            expect.push("fast");
            serde_json::json!({"id": format!("fast{i}"), "op": "roots", "poly": format!("x^2-{}", i + 2)})
        };
        lines.push_str(&line.to_string());
        lines.push('\n');
    }
    lines.push_str("not json\n");
    let r = run(
        &["batch", "--threads", "2", "--time-limit", "0.3"],
        Some(&lines),
    );
    assert_eq!(r.status, 0, "{}", r.stderr);
    let out: Vec<Value> = r.stdout.lines().map(json).collect();
    assert_eq!(out.len(), 25, "one answer per line");
    for (i, (v, kind)) in out.iter().zip(&expect).enumerate() {
        let id = v["id"].as_str().unwrap();
        assert!(
            id.ends_with(&i.to_string()) && id.starts_with(kind.replace("budget", "slow").as_str()),
            "line {i}: {v}"
        );
        match *kind {
            "fast" => assert_eq!(v["result"]["distinct_real"], 2),
            "budget" => assert_eq!(v["error"]["kind"], "budget"),
            _ => assert_eq!(v["error"]["kind"], "not-univariate"),
        }
    }
    assert_eq!(out[24]["error"]["kind"], "json");
    // 4 slow lines of 0.3 s on 2 threads overlap with the fast ones
    within(&r, Duration::from_millis(1200));
}

#[test]
fn batch_into_a_closed_pipe_ends_quietly() {
    let _serial = serial();
    let dir = std::env::temp_dir().join(format!("quadsect-epipe-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("lines.jsonl");
    let mut text = String::new();
    for i in 0..20_000 {
        text.push_str(&format!(
            "{{\"id\":{i},\"op\":\"roots\",\"poly\":\"x^3-{i}\"}}\n"
        ));
    }
    std::fs::write(&file, text).unwrap();
    // `quadsect batch F | head -1`
    let mut child = bin()
        .arg("batch")
        .arg(&file)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut out = BufReader::new(child.stdout.take().unwrap());
    let mut first = String::new();
    out.read_line(&mut first).unwrap();
    assert_eq!(json(&first)["id"], 0);
    drop(out);
    let res = child.wait_with_output().unwrap();
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(res.status.code(), Some(0));
    assert!(
        res.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
}

#[test]
fn library_answers_under_a_budget() {
    use quadsect::tangent::Undecided;
    use quadsect::{Class, ClassifyOptions, ErrorKind, Natural, Polynomial, Var};
    use quadsect::{TangentOptions, Verdict};
    let none = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
    // tangent: undecided with the limit
    let e: quadsect::Ellipsoid = "x^2+y^2+z^2-25".parse().unwrap();
    let s: Polynomial = "(x-9)^2/9+y^2/4+z^2/16-1".parse().unwrap();
    let r = quadsect::decide_with(&e, &s, &TangentOptions::with_budget(none.clone())).unwrap();
    assert_eq!(r.verdict(), Verdict::Undecided);
    match r.undecided() {
        Some(Undecided::Budget(x)) => assert_eq!(x.limit(), Limit::Time),
        other => panic!("expected the budget, got {other:?}"),
    }
    let v = serde_json::to_value(&r).unwrap();
    assert_eq!(v["reason"]["limit"], "time");
    // the same without a budget: the verdict
    let r = quadsect::decide(&e, &s).unwrap();
    assert_eq!(r.verdict(), Verdict::Separated);
    assert!(r.undecided().is_none());
    // natural: class undecided
    let a: Natural = "cylinder point=0,0,0 axis=1,0,0 radius2=1".parse().unwrap();
    let b: Natural = "cone vertex=0,1,0 axis=0,1,0 tan2=1".parse().unwrap();
    let n = quadsect::classify_with(&a, &b, &ClassifyOptions::with_budget(none.clone())).unwrap();
    assert_eq!(n.class(), Class::Undecided);
    assert_eq!(n.exhausted().unwrap().limit(), Limit::Time);
    let v = serde_json::to_value(&n).unwrap();
    assert_eq!(v["class"], "undecided");
    assert_eq!(v["reason"]["kind"], "budget");
    assert_eq!(v["conics"], Value::Null);
    let n = quadsect::classify_with(&a, &b, &ClassifyOptions::default()).unwrap();
    assert_eq!(n.class(), Class::Curve);
    // bad input stays an error, not a budget answer
    assert!("sphere radius2=-1".parse::<Natural>().is_err());
    // resultant: an error of kind budget
    let f: Polynomial = "x^9+y^7-1".parse().unwrap();
    let g: Polynomial = "x^8-y^5+x".parse().unwrap();
    let err = quadsect::resultant_with(&f, &g, Var::X, &none).unwrap_err();
    assert_eq!(err.kind(), ErrorKind::Budget);
    assert_eq!(err.exit_code(), 3);
}

#[test]
fn batch_lines_report_budget_not_internal() {
    let none = Budget::unlimited().with_time_limit(Some(Duration::ZERO));
    let line = r#"{"id":3,"op":"tangent","ellipsoid":"x^2+y^2+z^2-25","surface":"x^3+y*z-1"}"#;
    let v = quadsect::batch::answer_line_within(line, &none);
    assert_eq!(v["ok"], true);
    assert_eq!(v["result"]["verdict"], "undecided");
    assert_eq!(v["result"]["reason"]["kind"], "budget");
    let line = r#"{"id":4,"op":"resultant","f":"x^9+y^7-1","g":"x^8-y^5+x","var":"x"}"#;
    let v = quadsect::batch::answer_line_within(line, &none);
    assert_eq!(v["error"]["kind"], "budget");
    // without a budget the same line answers
    let v = quadsect::batch::answer_line(line);
    assert_eq!(v["ok"], true);
}

/// A singular S (∇S = 0 at points of E: a non-radical critical ideal) goes
/// to the exact route, whose Gröbner basis over Q grows numbers of
/// hundreds of thousands of bits; the gcds and products of its content
/// steps read the clock per term (they once ran 1.1 s past a 6 s limit).
#[test]
fn a_singular_sextic_ends_within_its_budget() {
    let _serial = serial();
    let r = run(
        &[
            "tangent",
            "--time-limit",
            "6",
            "--json",
            "--ellipsoid",
            "3x^2+y^2+2z^2+x*y-4",
            "--surface",
            "x^3*y^3+z^6-x*y+1",
        ],
        None,
    );
    // a tighter slack than SLACK: the overshoot grew with the numbers
    // (1.1 s here, 2.2 s at a 60 s limit), start-up is milliseconds
    let tight = Duration::from_millis(if cfg!(debug_assertions) { 20_000 } else { 600 });
    assert!(
        r.wall <= Duration::from_secs(6) + tight,
        "took {:?}",
        r.wall
    );
    let v = json(&r.stdout);
    match r.status {
        0 => assert_eq!(v["verdict"], "intersecting", "{v}"),
        3 => assert_eq!(v["reason"]["kind"], "budget", "{v}"),
        s => panic!("exit status {s}: {}", r.stderr),
    }
}
