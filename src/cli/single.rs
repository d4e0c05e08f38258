//! `boltzone single`: see the module docs of the solver it calls.

/// Arguments of `boltzone single`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Runs the command.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("the 'single' command is not built yet")
}
