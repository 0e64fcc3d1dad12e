//! The `quadsect` command line (see `quadsect --help`); everything it does
//! is in the library, the program only installs the counting allocator
//! (the memory probe of the compute budgets; a library never sets a global
//! allocator) and calls [`quadsect::cli::main`].

#[global_allocator]
static ALLOC: quadsect::cli::alloc::Counting = quadsect::cli::alloc::Counting;

fn main() -> std::process::ExitCode {
    quadsect::cli::main()
}
