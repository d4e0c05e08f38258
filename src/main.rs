//! The `boltzone` command-line tool. Run `boltzone --help` for the commands; exit codes are
//! listed in `cli/exit.rs` (0 converged, 1 failure, 2 bad input, 3 not converged).

mod cli;

use clap::Parser;

fn main() -> std::process::ExitCode {
    let args = cli::Cli::parse();
    match cli::run(args) {
        Ok(status) => std::process::ExitCode::from(status.code()),
        Err(e) => {
            eprintln!("error: {e:#}");
            std::process::ExitCode::from(cli::exit::code_of(&e))
        }
    }
}
