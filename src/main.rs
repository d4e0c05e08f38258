//! The `boltzone` command-line tool. Run `boltzone --help` for the commands; exit codes are
//! listed in `cli/exit.rs` (0 converged, 1 failure, 2 bad input, 3 not converged).
//!
//! # Accuracy
//!
//! No numerics: `tests/cli/` (the contract, its fuzz, the README's commands, regressions).
//!
//! # Cost
//!
//! None.

mod cli;

use clap::Parser;

fn main() -> std::process::ExitCode {
    // A closed pipe (`boltzone table1 | head`) ends the program quietly, as it ends any Unix
    // filter, instead of a panic in println!.
    #[cfg(unix)]
    // SAFETY: restores the default disposition of one signal before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
    let args = cli::Cli::parse();
    match cli::run(args) {
        Ok(status) => std::process::ExitCode::from(status.code()),
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::from(cli::exit::code_of(&e))
        }
    }
}
