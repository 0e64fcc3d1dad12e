//! `cargo bench`: the same suites as `quadsect bench` (no criterion: the
//! protocol is the one of the team's FLINT/PARI timing script, medians of
//! repeated samples, so our numbers and FLINT/PARI's are comparable).
//!
//! ```sh
//! cargo bench                 # all suites
//! cargo bench -- kernel       # one suite
//! ```

fn main() {
    let suite = std::env::args()
        .skip(1)
        .find(|a| ["kernel", "tangent", "natural", "all"].contains(&a.as_str()))
        .unwrap_or_else(|| "all".to_string());
    let inputs = std::env::var("QUADSECT_BENCH_INPUTS").ok();
    match quadsect::cli::bench::run(&suite, inputs.as_deref(), None) {
        Ok(rows) => print!("{}", quadsect::cli::bench::to_markdown(&rows)),
        Err(e) => {
            eprintln!("bench: {e}");
            std::process::exit(2);
        }
    }
}
