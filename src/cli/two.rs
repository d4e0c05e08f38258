//! `boltzone two`: see the module docs of the solver it calls.

/// Arguments of `boltzone two`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Runs the command.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("the 'two' command is not built yet")
}
