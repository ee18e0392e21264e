//! `microtrace view`: not written yet.

use std::path::PathBuf;

#[derive(clap::Args)]
pub struct ViewArgs {
    /// The scene to show.
    pub scene: PathBuf,
}

pub fn run(_args: ViewArgs) -> anyhow::Result<()> {
    anyhow::bail!("view is not implemented yet; use `microtrace render SCENE --out IMAGE.png`")
}
