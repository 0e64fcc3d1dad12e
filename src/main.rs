//! The `quadsect` command line: argument parsing and dispatch only.

use clap::{Parser, Subcommand};
use quadsect::{Error, ErrorKind};
use std::io::{IsTerminal, Write};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "quadsect",
    version,
    about = "Exact decisions on how two surfaces meet: ellipsoid vs algebraic surface, and natural quadrics",
    long_about = None
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Reproduce the papers' examples side by side with what they printed.
    Examples {
        /// Machine-readable output.
        #[arg(long)]
        json: bool,
    },
    /// Real roots of a univariate polynomial: counts and isolating intervals.
    Roots {
        /// The polynomial, e.g. "x^3 - 2x".
        #[arg(allow_hyphen_values = true)]
        expr: String,
        /// JSON output (SPEC §5).
        #[arg(long)]
        json: bool,
    },
    /// The resultant of two polynomials with respect to a variable.
    Resultant {
        /// First polynomial.
        #[arg(allow_hyphen_values = true)]
        f: String,
        /// Second polynomial.
        #[arg(allow_hyphen_values = true)]
        g: String,
        /// Variable to eliminate (x, y, z or u).
        #[arg(long)]
        var: String,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// Ellipsoid vs algebraic surface: intersect, touch or separated (exact, with certificate).
    Tangent {
        /// The ellipsoid E, e.g. "x^2+y^2+z^2-25".
        #[arg(long, allow_hyphen_values = true)]
        ellipsoid: String,
        /// The surface S, e.g. "(x-9)^2/9+y^2/4+z^2/16-1".
        #[arg(long, allow_hyphen_values = true)]
        surface: String,
        /// JSON output (SPEC §3).
        #[arg(long)]
        json: bool,
        /// Read every number literal as the nearest double (round to nearest, ties to even).
        #[arg(long)]
        float: bool,
    },
    /// Two natural quadrics (sphere, cylinder, cone): class, conics, lines, points.
    Natural {
        /// First quadric: JSON or short syntax, e.g. "cone vertex=0,0,0 axis=1,0,0 tan2=1/3".
        a: String,
        /// Second quadric.
        b: String,
        /// JSON output (SPEC §4).
        #[arg(long)]
        json: bool,
        /// Compute the exact components (the default).
        #[arg(long, overrides_with = "no_components")]
        components: bool,
        /// Class and counts only, by the fast route (no components).
        #[arg(long, overrides_with = "components")]
        no_components: bool,
        /// Read every number literal as the nearest double (round to nearest, ties to even).
        #[arg(long)]
        float: bool,
    },
    /// Median timings (kernel on ../shared/bench/inputs.json, tangent, natural).
    Bench {
        /// kernel, tangent, natural or all.
        #[arg(default_value = "all")]
        suite: String,
        /// The shared benchmark inputs.
        #[arg(long, default_value = "../shared/bench/inputs.json")]
        inputs: String,
        /// The natural-quadric pair file (default: benches/data/natural_pairs.json
        /// of the crate the binary was built from, else of the current directory).
        #[arg(long)]
        pairs: Option<String>,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// JSON lines in (file or - for stdin), one JSON answer line out per input line.
    Batch {
        /// Input file; standard input when absent or "-".
        file: Option<String>,
    },
}

/// Prints the JSON or the human form (only the one asked for is built).
fn emit(json: bool, v: impl FnOnce() -> serde_json::Value, human: impl FnOnce() -> String) {
    let mut out = std::io::stdout().lock();
    let _ = if json {
        writeln!(out, "{}", v())
    } else {
        write!(out, "{}", human())
    };
}

fn number_mode(float: bool) -> quadsect::number::NumberMode {
    if float {
        quadsect::number::NumberMode::Float
    } else {
        quadsect::number::NumberMode::Exact
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Examples { json } => {
            let r = quadsect::examples::run_all();
            emit(
                json,
                || quadsect::examples::to_json(&r),
                || quadsect::examples::to_human(&r),
            );
        }
        Command::Roots { expr, json } => {
            let r = quadsect::ops::roots(&expr)?;
            emit(
                json,
                || quadsect::report::roots_json(&r),
                || quadsect::report::roots_human(&r),
            );
        }
        Command::Resultant { f, g, var, json } => {
            let r = quadsect::ops::resultant(&f, &g, &var)?;
            emit(
                json,
                || quadsect::report::resultant_json(&r),
                || quadsect::report::resultant_human(&r),
            );
        }
        Command::Tangent {
            ellipsoid,
            surface,
            json,
            float,
        } => {
            let r = quadsect::tangent::decide_str_in(&ellipsoid, &surface, number_mode(float))?;
            emit(
                json,
                || quadsect::report::tangent_json(&r),
                || quadsect::report::tangent_human(&r),
            );
        }
        Command::Natural {
            a,
            b,
            json,
            components: _,
            no_components,
            float,
        } => {
            let mode = number_mode(float);
            let qa = quadsect::natural::types::parse_natural_in(&a, mode)
                .map_err(|e| e.context("in A"))?;
            let qb = quadsect::natural::types::parse_natural_in(&b, mode)
                .map_err(|e| e.context("in B"))?;
            if no_components {
                let opts = quadsect::natural::ClassifyOptions { components: false };
                let r = quadsect::natural::classify_with(&qa, &qb, &opts)?;
                emit(
                    json,
                    || quadsect::report::natural_counts_json(&r),
                    || quadsect::report::natural_counts_human(&r),
                );
            } else {
                let r = quadsect::natural::classify(&qa, &qb)?;
                emit(
                    json,
                    || quadsect::report::natural_json(&r),
                    || quadsect::report::natural_human(&r),
                );
            }
        }
        Command::Bench {
            suite,
            inputs,
            pairs,
            json,
        } => {
            let pairs = pairs.or_else(quadsect::bench::default_pairs_path);
            if pairs.is_none() && (suite == "natural" || suite == "all") {
                eprintln!(
                    "note: no pair file (benches/data/natural_pairs.json): the natural-pair rows are left out"
                );
            }
            let rows = quadsect::bench::run_with(&suite, &inputs, pairs.as_deref())?;
            emit(
                json,
                || quadsect::bench::to_json(&rows),
                || quadsect::bench::to_markdown(&rows),
            );
        }
        Command::Batch { file } => {
            let progress = std::io::stderr().is_terminal();
            let out = std::io::BufWriter::new(std::io::stdout().lock());
            let res = match file.as_deref() {
                None | Some("-") => {
                    quadsect::batch::run_batch(std::io::stdin().lock(), out, progress)
                }
                Some(path) => {
                    let f = std::fs::File::open(path).map_err(|e| {
                        Error::new(ErrorKind::Io, format!("cannot open batch file {path}: {e}"))
                    })?;
                    quadsect::batch::run_batch(std::io::BufReader::new(f), out, progress)
                }
            };
            res.map_err(|e| Error::new(ErrorKind::Io, format!("batch I/O error: {e}")))?;
        }
    }
    Ok(())
}

fn main() -> ExitCode {
    // panics are internal failures: report them in one line, exit status 1
    std::panic::set_hook(Box::new(|info| {
        eprintln!("internal error: {info}");
    }));
    let cli = Cli::parse();
    match std::panic::catch_unwind(|| run(cli)) {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
        Err(_) => ExitCode::from(1),
    }
}
