//! `boltzone slab`: see the module docs of the solver it calls.

/// Arguments of `boltzone slab`.
#[derive(Debug, clap::Args)]
pub struct Args {}

/// Runs the command.
pub fn run(_args: Args) -> anyhow::Result<()> {
    anyhow::bail!("the 'slab' command is not built yet")
}
