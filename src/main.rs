//! The `quadsect` command line: argument parsing and dispatch only.

mod cli_alloc;
mod cli_limits;

use clap::{Parser, Subcommand};
use cli_limits::LimitArgs;
use quadsect::budget::{self, Exhausted};
use quadsect::{Error, ErrorKind};
use std::io::{IsTerminal, Write};
use std::process::ExitCode;

#[global_allocator]
static ALLOC: cli_alloc::Counting = cli_alloc::Counting;

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
        #[command(flatten)]
        limits: LimitArgs,
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
        #[command(flatten)]
        limits: LimitArgs,
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
        #[command(flatten)]
        limits: LimitArgs,
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
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// Median timings (kernel on ../shared/bench/inputs.json, tangent, natural).
    Bench {
        /// kernel, tangent, natural or all.
        #[arg(default_value = "all")]
        suite: String,
        /// The shared benchmark inputs.
        #[arg(long, default_value = "../shared/bench/inputs.json")]
        inputs: String,
        /// JSON output.
        #[arg(long)]
        json: bool,
    },
    /// JSON lines in (file or - for stdin), one JSON answer line out per input line.
    Batch {
        /// Input file; standard input when absent or "-".
        file: Option<String>,
        /// Worker threads (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        #[command(flatten)]
        limits: LimitArgs,
    },
}

/// The JSON or the human form (only the one asked for is built).
fn render(
    json: bool,
    v: impl FnOnce() -> serde_json::Value,
    human: impl FnOnce() -> String,
) -> String {
    if json { format!("{}\n", v()) } else { human() }
}

/// Prints the JSON or the human form (only the one asked for is built).
fn emit(json: bool, v: impl FnOnce() -> serde_json::Value, human: impl FnOnce() -> String) {
    print_text(&render(json, v, human));
}

fn print_text(text: &str) {
    let _ = std::io::stdout().lock().write_all(text.as_bytes());
}

/// Computes and formats an answer within the budget of `limits` and prints
/// it.  When the budget runs out, `exhausted` gives the text of the answer
/// for that case (`None`: there is none, the error alone is reported); the
/// command then fails with the budget error (exit status 3).
fn within(
    limits: &LimitArgs,
    compute: impl FnOnce() -> Result<String, Error>,
    exhausted: impl FnOnce(&Exhausted) -> Option<String>,
) -> Result<(), Error> {
    match budget::run(&limits.budget(), compute) {
        Ok(text) => {
            print_text(&text?);
            Ok(())
        }
        Err(e) => {
            if let Some(text) = exhausted(&e) {
                print_text(&text);
            }
            Err(e.into())
        }
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
        Command::Roots { expr, json, limits } => within(
            &limits,
            || {
                let r = quadsect::ops::roots(&expr)?;
                Ok(render(
                    json,
                    || quadsect::report::roots_json(&r),
                    || quadsect::report::roots_human(&r),
                ))
            },
            |_| None,
        )?,
        Command::Resultant {
            f,
            g,
            var,
            json,
            limits,
        } => within(
            &limits,
            || {
                let r = quadsect::ops::resultant(&f, &g, &var)?;
                Ok(render(
                    json,
                    || quadsect::report::resultant_json(&r),
                    || quadsect::report::resultant_human(&r),
                ))
            },
            |_| None,
        )?,
        Command::Tangent {
            ellipsoid,
            surface,
            json,
            limits,
        } => within(
            &limits,
            || {
                let r = quadsect::tangent::decide_str(&ellipsoid, &surface)?;
                Ok(render(
                    json,
                    || quadsect::report::tangent_json(&r),
                    || quadsect::report::tangent_human(&r),
                ))
            },
            |e| {
                let zero = quadsect::poly::QMPoly::zero;
                let r =
                    quadsect::tangent::TangentReport::budget_exhausted(zero(), zero(), e.clone());
                Some(render(
                    json,
                    || quadsect::report::tangent_json(&r),
                    || quadsect::report::tangent_human(&r),
                ))
            },
        )?,
        Command::Natural { a, b, json, limits } => {
            let qa = quadsect::natural::parse_natural(&a).map_err(|e| e.context("in A"))?;
            let qb = quadsect::natural::parse_natural(&b).map_err(|e| e.context("in B"))?;
            within(
                &limits,
                || {
                    let r = quadsect::natural::classify(&qa, &qb)?;
                    Ok(render(
                        json,
                        || quadsect::report::natural_json(&r),
                        || quadsect::report::natural_human(&r),
                    ))
                },
                |e| {
                    let r = quadsect::natural::result::NaturalReport::budget_exhausted(
                        &qa,
                        &qb,
                        e.clone(),
                    );
                    Some(render(
                        json,
                        || quadsect::report::natural_json(&r),
                        || quadsect::report::natural_human(&r),
                    ))
                },
            )?
        }
        Command::Bench {
            suite,
            inputs,
            json,
        } => {
            let rows = quadsect::bench::run(&suite, &inputs)?;
            emit(
                json,
                || quadsect::bench::to_json(&rows),
                || quadsect::bench::to_markdown(&rows),
            );
        }
        Command::Batch {
            file,
            threads,
            limits,
        } => {
            let mut opts = quadsect::batch::BatchOptions {
                budget: limits.budget(),
                progress: std::io::stderr().is_terminal(),
                ..Default::default()
            };
            if let Some(n) = threads {
                opts.threads = n.max(1);
                opts.lookahead = quadsect::batch::DEFAULT_LOOKAHEAD * opts.threads;
            }
            let out = std::io::BufWriter::new(std::io::stdout().lock());
            let res = match file.as_deref() {
                None | Some("-") => quadsect::batch::run_batch_with(
                    std::io::BufReader::new(std::io::stdin()),
                    out,
                    &opts,
                ),
                Some(path) => {
                    let f = std::fs::File::open(path).map_err(|e| {
                        Error::new(ErrorKind::Io, format!("cannot open batch file {path}: {e}"))
                    })?;
                    opts.input_bytes = f.metadata().ok().filter(|m| m.is_file()).map(|m| m.len());
                    quadsect::batch::run_batch_with(std::io::BufReader::new(f), out, &opts)
                }
            };
            // a closed output pipe ends the run quietly (exit status 0)
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
    budget::set_memory_probe(cli_alloc::thread_net_bytes);
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
