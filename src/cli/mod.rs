//! The `quadsect` command line (feature `cli`): argument parsing, output
//! and the CLI-only jobs (the papers' examples, the benchmarks).

use crate::request::Request;
use crate::{Error, ErrorKind};
use clap::{Parser, Subcommand};
use std::io::{IsTerminal, Write};
use std::process::ExitCode;

pub mod alloc;
pub mod bench;
pub(crate) mod bench_cases;
mod bench_contact;
pub mod examples;
mod limits;

use limits::LimitArgs;

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
        /// Also write one SVG figure per paper example into DIR (created if
        /// missing): NAME.svg, named after the paper and the example.
        #[arg(long, value_name = "DIR")]
        figures: Option<std::path::PathBuf>,
    },
    /// Real roots of a univariate polynomial: counts and isolating intervals.
    Roots {
        /// The polynomial, e.g. "x^3 - 2x".
        #[arg(allow_hyphen_values = true)]
        expr: String,
        /// JSON output (the fields of docs/contract.md §5).
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
        /// JSON output (the fields of docs/contract.md §3).
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        limits: LimitArgs,
        /// Read every decimal literal as the nearest double (round to nearest,
        /// ties to even), i.e. the numbers a program reading them would use.
        #[arg(long)]
        float: bool,
        /// Compute the exact critical values: D(u), min and max (the default).
        #[arg(long, overrides_with = "no_values")]
        values: bool,
        /// The verdict and its certificate only: for deg S ≥ 3 in general
        /// position, D(u) and the exact min and max are not computed (min,
        /// max and judging_poly are null); S's sign at each real critical
        /// point is proven by an interval enclosure.
        #[arg(long, overrides_with = "values")]
        no_values: bool,
        /// Also draw the answer into FILE as SVG: E shaded by the sign of S,
        /// the curve S = 0 on E, the certificate's witness points.
        #[arg(long, value_name = "FILE")]
        svg: Option<std::path::PathBuf>,
        /// Also draw the answer into FILE as PNG (the SVG picture rendered).
        #[arg(long, value_name = "FILE")]
        png: Option<std::path::PathBuf>,
    },
    /// Two natural quadrics (sphere, cylinder, cone): class, conics, lines, points.
    Natural {
        /// First quadric: JSON or short syntax, e.g. "cone vertex=0,0,0 axis=1,0,0 tan2=1/3".
        a: String,
        /// Second quadric.
        b: String,
        /// JSON output (the fields of docs/contract.md §4).
        #[arg(long)]
        json: bool,
        #[command(flatten)]
        limits: LimitArgs,
        /// Compute the exact components (the default).
        #[arg(long, overrides_with = "no_components")]
        components: bool,
        /// Class and counts only, by the fast route (no components).
        #[arg(long, overrides_with = "components")]
        no_components: bool,
        /// Also referee the answer: the relative perturbation size `lo`
        /// within which every input provably has the same class and counts,
        /// and an exact nearby input at relative size `hi` whose answer
        /// differs (README, "Refereeing a floating-point kernel").
        #[arg(long)]
        referee: bool,
        /// Read every decimal literal as the nearest double (round to nearest,
        /// ties to even).
        #[arg(long)]
        float: bool,
        /// Also draw the answer into FILE as SVG: a 3D view of both surfaces
        /// and the components, and the axial plane when the axes are
        /// coplanar.
        #[arg(long, value_name = "FILE")]
        svg: Option<std::path::PathBuf>,
        /// Also draw the answer into FILE as PNG (the SVG picture rendered).
        #[arg(long, value_name = "FILE")]
        png: Option<std::path::PathBuf>,
    },
    /// Median timings of the kernel (resultants, isolation, Sturm), the tangent
    /// point method and the natural-quadric deciders.
    Bench {
        /// kernel, tangent, nonreduced (surfaces with a repeated factor),
        /// natural, figures (the examples' pictures, SVG and PNG), contact
        /// (ellipsoid pairs; --pairs takes a JSON-lines file of
        /// scripts/bench_contact.py) or all (all but contact).
        #[arg(default_value = "all")]
        suite: String,
        /// Kernel inputs (JSON; default: the copy shipped in the binary,
        /// benches/data/kernel_inputs.json).
        #[arg(long)]
        inputs: Option<String>,
        /// Natural-quadric pair file (default: the copy shipped in the
        /// binary, benches/data/natural_pairs.json).
        #[arg(long)]
        pairs: Option<String>,
        /// JSON output.
        #[arg(long)]
        json: bool,
        /// Instead of timing: write the critical systems of the tangent
        /// suite's general-position cases to DIR (msolve's input format,
        /// and cases.jsonl with E and S), for scripts/bench_msolve.py.
        #[arg(long, value_name = "DIR")]
        dump_systems: Option<std::path::PathBuf>,
    },
    /// Ellipsoid pairs (JSON lines, file or - for stdin): separated, touching or
    /// overlapping, exactly, with a certificate; one answer line per pair.
    #[command(after_help = ELLIPSOIDS_HELP)]
    Ellipsoids {
        /// Input file; standard input when absent or "-".
        file: Option<String>,
        /// Worker threads (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        /// Put each request line, verbatim, into its answer as "request".
        #[arg(long)]
        echo: bool,
        #[command(flatten)]
        limits: LimitArgs,
    },
    /// JSON lines in (file or - for stdin), one JSON answer line out per input line.
    #[command(after_help = BATCH_HELP)]
    Batch {
        /// Input file; standard input when absent or "-".
        file: Option<String>,
        /// Worker threads (default: all cores).
        #[arg(long, value_name = "N")]
        threads: Option<usize>,
        /// Put each request line, verbatim, into its answer as "request" (a
        /// JSON string), so that an answer can be checked on its own:
        /// `quadsect batch --echo F | python3 -m quadsect_check -`.
        #[arg(long)]
        echo: bool,
        #[command(flatten)]
        limits: LimitArgs,
    },
}

/// The batch protocol in brief, after `quadsect batch --help` (the full
/// contract: docs/contract.md §5).
const BATCH_HELP: &str = "\
Protocol: each input line is a JSON object {\"id\": …, \"op\": …, fields…}; each answer
line is {\"id\": …, \"ok\": true, \"result\": {…}} or {\"id\": …, \"ok\": false,
\"error\": {\"kind\": …, \"message\": …}}, in input order.

Ops and their fields:
  tangent     ellipsoid, surface; optional values (false: the verdict only), float
  natural     a, b (short syntax or JSON object); optional components, float
  ellipsoid-contact  a, b (see quadsect ellipsoids --help)
  roots       poly
  resultant   f, g, var
Fields of every line (all optional):
  id            any JSON value, copied into the answer
  time_limit    seconds (a number >= 0), or null or \"none\": no limit of the line's own
  memory_limit  MiB (a number >= 0), or null or \"none\": no limit of the line's own
A line's limit is the smaller of its own and --time-limit / --memory-limit: a line can
tighten the limits, never loosen them. Any other field, or a bad limit, is an error line
of kind \"bad-field\" naming the field.

With --echo each answer also has \"request\": the input line, verbatim, as a JSON string
(right after \"id\"), which the independent checker reads (python3 -m quadsect_check).

Exit status: 0 when every line was answered, whatever the answers (bad lines, exhausted
budgets and internal failures are error lines); 2 when the input cannot be read.";

/// `quadsect ellipsoids --help`, after the options.
const ELLIPSOIDS_HELP: &str = "\
Each line: {\"id\": …, \"a\": E, \"b\": E} (\"op\": \"ellipsoid-contact\" is implied; the lines
of `quadsect batch` with that op are read as they are). E is
  {\"center\": [x, y, z], \"semi_axes\": [r1, r2, r3], \"rotation\": [[…], […], […]]}
— the ellipsoid { c + R·diag(r)·u : |u| <= 1 } for any invertible matrix R (rows); JSON
numbers are the doubles they denote, strings exact numbers (\"1/3\", \"0.1\") — or a
quadric polynomial string such as \"x^2 + y^2/4 + z^2 - 1\".
Answer: {\"id\", \"ok\": true, \"result\": {\"contact\": \"separated\"|\"touching\"|\"overlapping\",
\"kind\", \"route\", \"certificate\"}} (docs/contract.md, \"Ellipsoid contact\").";

/// The lines of `quadsect ellipsoids`: a JSON object without `op` gets
/// `"op": "ellipsoid-contact"` in front of its fields (the rest verbatim).
fn with_contact_op(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + text.len() / 8);
    for line in text.lines() {
        let t = line.trim_start();
        let lacks_op = t.starts_with('{')
            && matches!(serde_json::from_str::<serde_json::Value>(t),
                Ok(serde_json::Value::Object(ref o)) if !o.contains_key("op"));
        if lacks_op {
            let rest = t[1..].trim_start();
            out.push_str("{\"op\":\"ellipsoid-contact\"");
            if !rest.starts_with('}') {
                out.push(',');
            }
            out.push_str(rest);
        } else {
            out.push_str(line);
        }
        out.push('\n');
    }
    out
}

/// Prints the JSON or the human form (only the one asked for is built).
/// The JSON is serialized straight into a buffered standard output (no
/// intermediate copy: a tangent answer's certificate can be megabytes).
fn emit<T: serde::Serialize>(json: bool, v: impl FnOnce() -> T, human: impl FnOnce() -> String) {
    if json {
        let mut out = std::io::BufWriter::new(std::io::stdout().lock());
        if serde_json::to_writer(&mut out, &v()).is_ok() {
            let _ = writeln!(out);
        }
        let _ = out.flush();
    } else {
        let _ = write!(std::io::stdout().lock(), "{}", human());
    }
}

fn number_mode(float: bool) -> crate::number::NumberMode {
    if float {
        crate::number::NumberMode::Float
    } else {
        crate::number::NumberMode::Exact
    }
}

/// Runs one request of the dispatch table under the budget of `limits`
/// and prints its answer.  When the budget ran out, the `undecided`
/// answer (tangent, natural) is printed and the command fails with the
/// budget error (exit status 3); for roots and resultant the error alone
/// is reported.
fn answer(
    json: bool,
    limits: &LimitArgs,
    request: Request,
    pictures: [Option<std::path::PathBuf>; 2],
) -> Result<(), Error> {
    let a = request.execute(&limits.budget())?;
    let [svg, png] = pictures;
    if svg.is_some() || png.is_some() {
        let text = a.svg().unwrap_or_default();
        if let Some(path) = svg {
            write_file(&path, text.as_bytes())?;
        }
        if let Some(path) = png {
            write_file(&path, &crate::svg_to_png(&text)?)?;
        }
    }
    emit(json, || &a, || a.to_string());
    match a.exhausted() {
        Some(e) => Err(e.clone().into()),
        None => Ok(()),
    }
}

/// Writes a file, with the path in the error.
fn write_file(path: &std::path::Path, bytes: &[u8]) -> Result<(), Error> {
    std::fs::write(path, bytes).map_err(|e| {
        Error::new(
            ErrorKind::Io,
            format!("cannot write {}: {e}", path.display()),
        )
    })
}

fn run(cli: Cli) -> Result<(), Error> {
    match cli.command {
        Command::Examples { json, figures } => {
            let r = examples::run_all();
            if let Some(dir) = figures {
                std::fs::create_dir_all(&dir).map_err(|e| {
                    Error::new(
                        ErrorKind::Io,
                        format!("cannot create {}: {e}", dir.display()),
                    )
                })?;
                for (name, svg) in examples::figures(&r) {
                    write_file(&dir.join(format!("{name}.svg")), svg.as_bytes())?;
                }
            }
            emit(json, || examples::to_json(&r), || examples::to_human(&r));
        }
        Command::Roots { expr, json, limits } => {
            answer(json, &limits, Request::Roots { poly: expr }, [None, None])?
        }
        Command::Resultant {
            f,
            g,
            var,
            json,
            limits,
        } => answer(
            json,
            &limits,
            Request::Resultant { f, g, var },
            [None, None],
        )?,
        Command::Tangent {
            ellipsoid,
            surface,
            json,
            float,
            limits,
            values: _,
            no_values,
            svg,
            png,
        } => answer(
            json,
            &limits,
            Request::Tangent {
                ellipsoid,
                surface,
                mode: number_mode(float),
                values: !no_values,
            },
            [svg, png],
        )?,
        Command::Natural {
            a,
            b,
            json,
            components: _,
            no_components,
            referee,
            float,
            limits,
            svg,
            png,
        } => {
            let mode = number_mode(float);
            let parse = |t: &str, what: &str| {
                crate::natural::types::parse_natural_in(t, mode).map_err(|e| e.context(what))
            };
            let (a, b) = (parse(&a, "in A")?, parse(&b, "in B")?);
            answer(
                json,
                &limits,
                Request::Natural {
                    a,
                    b,
                    components: !no_components,
                    referee,
                },
                [svg, png],
            )?
        }
        Command::Bench {
            dump_systems: Some(dir),
            ..
        } => {
            let n = bench_cases::dump_systems(&dir).map_err(|e| {
                Error::new(
                    ErrorKind::Io,
                    format!("cannot write the systems to {}: {e}", dir.display()),
                )
            })?;
            println!("{n} critical systems written to {}", dir.display());
        }
        Command::Bench {
            suite,
            inputs,
            pairs,
            json,
            dump_systems: None,
        } => {
            let rows = bench::run(&suite, inputs.as_deref(), pairs.as_deref())?;
            emit(json, || bench::to_json(&rows), || bench::to_markdown(&rows));
        }
        Command::Ellipsoids {
            file,
            threads,
            echo,
            limits,
        } => {
            let text = match file.as_deref() {
                None | Some("-") => std::io::read_to_string(std::io::stdin()),
                Some(path) => std::fs::read_to_string(path),
            }
            .map_err(|e| Error::new(ErrorKind::Io, format!("cannot read the pairs: {e}")))?;
            let mut opts = crate::batch::BatchOptions {
                budget: limits.budget(),
                progress: std::io::stderr().is_terminal(),
                echo,
                ..Default::default()
            };
            if let Some(n) = threads {
                opts.threads = n.max(1);
                opts.lookahead = crate::batch::DEFAULT_LOOKAHEAD * opts.threads;
            }
            let input = std::io::Cursor::new(with_contact_op(&text).into_bytes());
            let out = std::io::BufWriter::new(std::io::stdout().lock());
            crate::batch::run_batch_with(input, out, &opts)
                .map_err(|e| Error::new(ErrorKind::Io, format!("I/O error: {e}")))?;
        }
        Command::Batch {
            file,
            threads,
            echo,
            limits,
        } => {
            let mut opts = crate::batch::BatchOptions {
                budget: limits.budget(),
                progress: std::io::stderr().is_terminal(),
                echo,
                ..Default::default()
            };
            if let Some(n) = threads {
                opts.threads = n.max(1);
                opts.lookahead = crate::batch::DEFAULT_LOOKAHEAD * opts.threads;
            }
            let out = std::io::BufWriter::new(std::io::stdout().lock());
            let res = match file.as_deref() {
                None | Some("-") => crate::batch::run_batch_with(
                    std::io::BufReader::new(std::io::stdin()),
                    out,
                    &opts,
                ),
                Some(path) => {
                    let f = std::fs::File::open(path).map_err(|e| {
                        Error::new(ErrorKind::Io, format!("cannot open batch file {path}: {e}"))
                    })?;
                    opts.input_bytes = f.metadata().ok().filter(|m| m.is_file()).map(|m| m.len());
                    crate::batch::run_batch_with(std::io::BufReader::new(f), out, &opts)
                }
            };
            // a closed output pipe ends the run quietly (exit status 0)
            res.map_err(|e| Error::new(ErrorKind::Io, format!("batch I/O error: {e}")))?;
        }
    }
    Ok(())
}

/// Runs the command line: parses the arguments, runs the command, prints
/// its answer, and returns the exit status (0 success, 2 bad input, 3
/// budget exhausted, 1 internal failure).
pub fn main() -> ExitCode {
    // panics are internal failures: report them in one line, exit status 1
    std::panic::set_hook(Box::new(|info| {
        eprintln!("internal error: {info}");
    }));
    crate::budget::set_memory_probe(alloc::thread_net_bytes);
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
