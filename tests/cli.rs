//! The command line: `--no-components` (the fast route), `--components`,
//! hexadecimal input and `--float` on `natural` and `tangent`; the pair
//! rows of the natural benchmark through the library; the batch lines'
//! own limits and unknown fields.

use serde_json::Value;
use std::process::Command;

fn run(args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_quadsect"))
        .args(args)
        .output()
        .expect("the quadsect binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn json(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: {e}: {out}"))
}

const CYL: &str = "cylinder point=0,0,0 axis=1,0,0 radius2=1";
const CONE: &str = "cone vertex=0,0,2 axis=0,1,0 tan2=3";

#[test]
fn no_components_gives_the_same_class_and_counts_by_the_fast_route() {
    let full = json(&["natural", CYL, CONE, "--json"]);
    let fast = json(&["natural", CYL, CONE, "--json", "--no-components"]);
    for k in ["class", "conics", "lines", "points", "axes", "thm8"] {
        assert_eq!(full[k], fast[k], "{k}");
    }
    assert_eq!(fast["class"], "points");
    assert_eq!(fast["points"], 2);
    assert_eq!(fast["route"], "fast");
    assert!(fast.get("components").is_none());
    assert!(full["components"].as_array().is_some_and(|c| c.len() == 2));
    // --components is the default, and the later flag wins
    let explicit = json(&["natural", CYL, CONE, "--json", "--components"]);
    assert_eq!(explicit["components"], full["components"]);
    let last = json(&[
        "natural",
        CYL,
        CONE,
        "--json",
        "--no-components",
        "--components",
    ]);
    assert!(last.get("components").is_some());
    // human output
    let (code, out, _) = run(&["natural", CYL, CONE, "--no-components"]);
    assert_eq!(code, 0);
    assert!(
        out.starts_with("class     points  (0 conics, 0 lines, 2 points)"),
        "{out}"
    );
    assert!(out.contains("route     fast"), "{out}");
}

#[test]
fn hexadecimal_input_is_exact() {
    let dec = json(&["natural", CYL, CONE, "--json"]);
    let hex = json(&[
        "natural",
        "cylinder point=0x0p0,0,0 axis=0x1p0,0,0 radius2=0x1.0p0",
        "cone vertex=0,0,0x1p1 axis=0,0x.8p1,0 tan2=0x1.8p1",
        "--json",
    ]);
    for k in ["class", "conics", "lines", "points", "components"] {
        assert_eq!(dec[k], hex[k], "{k}");
    }
    // a malformed hex float is a bad-input error with its column
    let (code, _, err) = run(&["natural", "sphere center=0x1p,0,0 radius2=1", CYL]);
    assert_eq!(code, 2);
    assert!(
        err.contains("binary exponent") && err.contains("column 5"),
        "{err}"
    );
    let (code, _, err) = run(&["roots", "x^2 - 0x1.8p1"]);
    assert_eq!(code, 0, "{err}");
}

#[test]
fn float_mode_reads_decimals_as_doubles() {
    // exactly tangent spheres in decimal (0.1 + 0.1 = 0.2); as doubles the
    // distance 0.2 exceeds the sum of the radii √0.01: no intersection
    let a = "sphere center=0,0,0 radius2=0.01";
    let b = "sphere center=0.2,0,0 radius2=0.01";
    for comps in ["--components", "--no-components"] {
        let exact = json(&["natural", a, b, "--json", comps]);
        let float = json(&["natural", a, b, "--json", comps, "--float"]);
        assert_eq!(
            (exact["class"].as_str(), exact["points"].as_u64()),
            (Some("points"), Some(1))
        );
        assert_eq!(float["class"], "empty");
    }
    // the same with the double's exact value written in hex: identical
    let hex = json(&[
        "natural",
        "sphere center=0,0,0 radius2=0x1.47ae147ae147bp-7",
        "sphere center=0x1.999999999999ap-3,0,0 radius2=0x1.47ae147ae147bp-7",
        "--json",
    ]);
    assert_eq!(hex["class"], "empty");
    // tangent: x² + y² + z² = 0.01 touches the plane x = 0.1 exactly;
    // the doubles do not
    let e = "x^2+y^2+z^2-0.01";
    let s = "x-0.1";
    let exact = json(&["tangent", "--ellipsoid", e, "--surface", s, "--json"]);
    let float = json(&[
        "tangent",
        "--ellipsoid",
        e,
        "--surface",
        s,
        "--json",
        "--float",
    ]);
    assert_eq!(exact["verdict"], "touching");
    assert_eq!(float["verdict"], "separated");
    // out of the double range
    let (code, _, err) = run(&[
        "natural",
        "sphere center=1e400,0,0 radius2=1",
        CYL,
        "--float",
    ]);
    assert_eq!(code, 2);
    assert!(err.contains("out of the double range"), "{err}");
}

#[test]
fn pair_rows_of_the_benchmark() {
    let dir = std::env::temp_dir().join(format!("quadsect-pairs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("pairs.json");
    std::fs::write(
        &path,
        r#"{"description": "test", "pairs": [
          {"name": "p1", "group": "g", "a": {"kind": "cylinder", "point": ["0","0","0"], "axis": ["1","0","0"], "radius2": "1"},
           "b": {"kind": "cone", "vertex": ["0","0","2"], "axis": ["0","1","0"], "tan2": "3"},
           "expect": {"class": "points", "conics": 0, "lines": 0, "points": 2}},
          {"name": "p2", "group": "g", "a": {"kind": "sphere", "center": ["0","0","0"], "radius2": "1"},
           "b": {"kind": "sphere", "center": ["0x1p0","0","0"], "radius2": "1"},
           "expect": {"class": "empty", "conics": 0, "lines": 0, "points": 0}}]}"#,
    )
    .unwrap();
    let mut rows = Vec::new();
    quadsect::cli::bench::pairs_suite(Some(path.to_str().unwrap()), &mut rows).unwrap();
    let j = quadsect::cli::bench::to_json(&rows);
    let rows = j.as_array().unwrap();
    // two pairs, the group (class and counts), the group (whole answer),
    // the input kind (whole answer)
    assert_eq!(rows.len(), 5);
    assert_eq!(rows[0]["suite"], "natural-pair");
    assert_eq!(rows[0]["group"], "g");
    assert_eq!(rows[0]["agrees"], true);
    // p2 is a circle, not empty: the row says it disagrees with expect
    assert_eq!(rows[1]["agrees"], false);
    assert_eq!(rows[2]["suite"], "natural-group");
    assert_eq!(rows[2]["agree"], 1);
    assert!(rows[2]["max_s"].as_f64().unwrap() >= rows[2]["median_s"].as_f64().unwrap());
    assert_eq!(rows[3]["suite"], "natural-whole-group");
    assert_eq!(rows[4]["suite"], "natural-whole-kind");
    assert!(rows[0]["whole_s"].as_f64().unwrap() > 0.0);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn batch_accepts_components_and_float_fields() {
    let line = r#"{"id":1,"op":"natural","a":"sphere center=0,0,0 radius2=0.01","b":"sphere center=0.2,0,0 radius2=0.01","components":false}"#;
    let v = quadsect::batch::answer_line(line);
    assert_eq!(v["result"]["class"], "points");
    assert_eq!(v["result"]["route"], "fast");
    let line = r#"{"id":2,"op":"natural","a":"sphere center=0,0,0 radius2=0.01","b":"sphere center=0.2,0,0 radius2=0.01","float":true}"#;
    let v = quadsect::batch::answer_line(line);
    assert_eq!(v["result"]["class"], "empty");
    assert!(v["result"]["components"].is_array());
    let line =
        r#"{"id":3,"op":"tangent","ellipsoid":"x^2+y^2+z^2-0.01","surface":"x-0.1","float":true}"#;
    assert_eq!(
        quadsect::batch::answer_line(line)["result"]["verdict"],
        "separated"
    );
    let line = r#"{"id":4,"op":"natural","a":"sphere center=0,0,0 radius2=1","b":"sphere center=1,0,0 radius2=1","float":1}"#;
    assert_eq!(quadsect::batch::answer_line(line)["ok"], false);
}

/// 12 terms of degree up to 6667: seconds of work.
const SLOW_ROOTS: &str =
    "x^6667-3x^5000+7x^4000-x^3333+5x^2000-2x^1000+x^500-9x^100+x^50-3x^10+x-1";

#[test]
fn batch_lines_may_tighten_their_limits_and_unknown_fields_are_errors() {
    use serde_json::json;
    let lines = [
        // tightens --time-limit: a budget error at once, not after 0.3 s
        json!({"id": "tight", "op": "roots", "poly": SLOW_ROOTS, "time_limit": 0.001}).to_string(),
        // cannot loosen it: 0.3 s still applies
        json!({"id": "loose", "op": "roots", "poly": SLOW_ROOTS, "time_limit": 3600}).to_string(),
        json!({"id": "neg", "op": "roots", "poly": "x^2-2", "time_limit": -1}).to_string(),
        json!({"id": "word", "op": "roots", "poly": "x^2-2", "memory_limit": "lots"}).to_string(),
        json!({"id": "typo", "op": "roots", "poly": "x^2-2", "time_limt": 0.001}).to_string(),
        json!({"id": "ok", "op": "roots", "poly": "x^2-2", "time_limit": null, "memory_limit": 64})
            .to_string(),
        "not json".to_string(),
    ];
    let path = std::env::temp_dir().join(format!("quadsect-limits-{}.jsonl", std::process::id()));
    std::fs::write(&path, lines.join("\n") + "\n").unwrap();
    let t0 = std::time::Instant::now();
    let (code, out, err) = run(&["batch", "--time-limit", "0.3", path.to_str().unwrap()]);
    let took = t0.elapsed();
    std::fs::remove_file(&path).ok();
    // bad lines are answers: the batch itself succeeds
    assert_eq!(code, 0, "{err}");
    let answers: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(answers.len(), lines.len(), "one answer per line: {out}");
    let ids: Vec<Value> = answers.iter().map(|a| a["id"].clone()).collect();
    let expected = ["tight", "loose", "neg", "word", "typo", "ok"].map(|s| json!(s));
    assert_eq!(ids[..6], expected, "in input order");
    assert_eq!(ids[6], Value::Null);
    let kind = |i: usize| answers[i]["error"]["kind"].as_str().unwrap_or("none");
    let message = |i: usize| answers[i]["error"]["message"].as_str().unwrap_or("");
    assert_eq!(kind(0), "budget");
    assert!(
        message(0).contains("time limit of 0.001 s"),
        "{}",
        message(0)
    );
    assert_eq!(kind(1), "budget");
    assert!(message(1).contains("time limit of 0.3 s"), "{}", message(1));
    assert_eq!(kind(2), "bad-field");
    assert!(
        message(2).starts_with("field \"time_limit\" must be a number of seconds"),
        "{}",
        message(2)
    );
    assert!(message(2).contains("got -1"), "{}", message(2));
    assert_eq!(kind(3), "bad-field");
    assert!(
        message(3).starts_with("field \"memory_limit\" must be a number of MiB"),
        "{}",
        message(3)
    );
    assert_eq!(kind(4), "bad-field");
    assert_eq!(
        message(4),
        "unknown field \"time_limt\" for op \"roots\" (expected: id, op, poly, time_limit, memory_limit)"
    );
    assert_eq!(answers[5]["ok"], true);
    assert_eq!(answers[5]["result"]["distinct_real"], 2);
    assert_eq!(kind(6), "json");
    // the slow lines ran 0.001 s and 0.3 s, not seconds
    assert!(took < std::time::Duration::from_secs(5), "{took:?}");
    // the protocol is in the help
    let (code, help, _) = run(&["batch", "--help"]);
    assert_eq!(code, 0);
    for word in [
        "time_limit",
        "memory_limit",
        "bad-field",
        "never loosen",
        "Exit status",
    ] {
        assert!(help.contains(word), "{word}: {help}");
    }
}

/// `--svg` and `--png` on `natural` and `tangent`, `examples --figures`,
/// the batch field `"svg"`, and a picture that cannot be written.
#[test]
fn pictures_from_the_command_line_and_the_batch() {
    let dir = std::env::temp_dir().join(format!("quadsect-pictures-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let (svg, png) = (dir.join("n.svg"), dir.join("n.png"));
    let (code, out, err) = run(&[
        "natural",
        CYL,
        CONE,
        "--svg",
        svg.to_str().unwrap(),
        "--png",
        png.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(out.starts_with("class     points"), "{out}");
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("class points"));
    assert_eq!(&std::fs::read(&png).unwrap()[1..4], b"PNG");
    let t = dir.join("t.svg");
    let (code, _, err) = run(&[
        "tangent",
        "--ellipsoid",
        "x^2+y^2+z^2-25",
        "--surface",
        "x - 5",
        "--svg",
        t.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{err}");
    assert!(
        std::fs::read_to_string(&t)
            .unwrap()
            .contains("verdict: touching")
    );
    // a directory that cannot be written: an I/O error, exit status 2
    let (code, _, err) = run(&["natural", CYL, CONE, "--svg", "/nonexistent/dir/x.svg"]);
    assert_eq!(code, 2);
    assert!(err.contains("cannot write /nonexistent/dir/x.svg"), "{err}");
    // one figure per paper example
    let figs = dir.join("figures");
    let (code, _, err) = run(&["examples", "--figures", figs.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let n = std::fs::read_dir(&figs).unwrap().count();
    assert!(n >= 25, "{n} figures");
    // batch: "svg": true adds the picture; a non-boolean is a bad field
    let lines = format!(
        "{}\n{}\n{}\n",
        r#"{"id":1,"op":"natural","a":"sphere center=0,0,0 radius2=4","b":"sphere center=3,0,0 radius2=4","svg":true}"#,
        r#"{"id":2,"op":"tangent","ellipsoid":"x^2+y^2+z^2-25","surface":"x-6","svg":true}"#,
        r#"{"id":3,"op":"natural","a":"sphere center=0,0,0 radius2=4","b":"sphere center=3,0,0 radius2=4","svg":"yes"}"#,
    );
    let input = dir.join("lines.jsonl");
    std::fs::write(&input, lines).unwrap();
    let (code, out, err) = run(&["batch", "--threads", "1", input.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let answers: Vec<Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert!(
        answers[0]["result"]["svg"]
            .as_str()
            .unwrap()
            .contains("class conics")
    );
    assert!(
        answers[1]["result"]["svg"]
            .as_str()
            .unwrap()
            .contains("verdict: separated")
    );
    assert_eq!(answers[2]["error"]["kind"], "bad-field");
    std::fs::remove_dir_all(&dir).unwrap();
}
