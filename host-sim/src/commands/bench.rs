//! `microtrace bench`: `--thesis` reproduces the thesis's Tables 4.3 and 4.4 (the
//! optimizations); `--numbers` reports speed against error for every number type.

use std::path::PathBuf;

#[path = "bench_numbers.rs"]
mod numbers;
#[path = "bench_thesis.rs"]
mod thesis;

#[derive(clap::Args, Clone, Debug)]
pub struct BenchArgs {
    /// Tables 4.3 and 4.4: both thesis scenes under the thesis's six configurations.
    #[arg(long)]
    pub thesis: bool,
    /// Speed against error for every number type.
    #[arg(long)]
    pub numbers: bool,
    /// Where the thesis scenes are.
    #[arg(long, default_value = "scenes")]
    pub scenes: PathBuf,
    /// Write the report (Markdown) here as well as to stdout (--numbers: default docs/numbers.md).
    #[arg(long, value_name = "FILE.md")]
    pub out: Option<PathBuf>,
    /// --numbers: write the speed-against-error plot here (default docs/images/numbers.png).
    #[arg(long, value_name = "FILE.png")]
    pub plot: Option<PathBuf>,
    /// --numbers: read Cortex-M instructions per pixel from this firmware report (default
    /// docs/firmware-report.json; a missing file leaves those columns empty).
    #[arg(long, value_name = "FILE.json")]
    pub firmware_report: Option<PathBuf>,
}

pub fn run(args: BenchArgs) -> anyhow::Result<()> {
    if !args.thesis && !args.numbers {
        anyhow::bail!("choose --thesis (optimizations, Tables 4.3 and 4.4) or --numbers (number types)");
    }
    if args.thesis && args.numbers && args.out.is_some() {
        anyhow::bail!("--out names one report: run --thesis and --numbers separately to write both");
    }
    if args.thesis {
        thesis::run(&args)?;
    }
    if args.numbers {
        numbers::run(&args)?;
    }
    Ok(())
}
