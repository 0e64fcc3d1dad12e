//! The `quadsect` command line (see `quadsect --help`); everything it does
//! is in the library, the program only calls [`quadsect::cli::main`].

fn main() -> std::process::ExitCode {
    quadsect::cli::main()
}
