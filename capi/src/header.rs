//! The header check: the committed `include/quadsect.h` must equal what
//! cbindgen makes from this crate with `cbindgen.toml` (run by `cargo test
//! -p quadsect-capi`, hence by CI).  `QS_WRITE_HEADER=1 cargo test -p
//! quadsect-capi header` rewrites the header instead.

use std::path::Path;

/// The header cbindgen generates now from `capi/src` and `cbindgen.toml`.
fn fresh_header(dir: &Path) -> Vec<u8> {
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml"))
        .unwrap_or_else(|e| panic!("capi/cbindgen.toml: {e}"));
    let bindings = cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .unwrap_or_else(|e| panic!("cbindgen failed on capi/src: {e}"));
    let mut out = Vec::new();
    bindings.write(&mut out);
    out
}

/// The first line where `a` and `b` differ (1-based), with both versions.
fn first_difference(a: &str, b: &str) -> String {
    let (mut la, mut lb) = (a.lines(), b.lines());
    for n in 1.. {
        match (la.next(), lb.next()) {
            (Some(x), Some(y)) if x == y => continue,
            (None, None) => break,
            (x, y) => {
                return format!(
                    "line {n}:\n  committed: {}\n  fresh:     {}",
                    x.unwrap_or("<end of file>"),
                    y.unwrap_or("<end of file>")
                );
            }
        }
    }
    "no line differs (line endings?)".to_string()
}

#[test]
fn the_committed_header_equals_a_fresh_cbindgen_generation() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let path = dir.join("include/quadsect.h");
    let fresh = fresh_header(dir);
    if std::env::var_os("QS_WRITE_HEADER").is_some() {
        std::fs::write(&path, &fresh).expect("write capi/include/quadsect.h");
        return;
    }
    let committed = std::fs::read(&path).expect("read capi/include/quadsect.h");
    if committed != fresh {
        panic!(
            "capi/include/quadsect.h is stale: regenerate it with \
             `QS_WRITE_HEADER=1 cargo test --release -p quadsect-capi header` and commit it; \
             first difference at {}",
            first_difference(
                &String::from_utf8_lossy(&committed),
                &String::from_utf8_lossy(&fresh)
            )
        );
    }
}

#[test]
fn first_difference_names_the_line() {
    assert_eq!(
        first_difference("a\nb\nc", "a\nx\nc"),
        "line 2:\n  committed: b\n  fresh:     x"
    );
    assert!(first_difference("a", "a\nb").contains("<end of file>"));
}
