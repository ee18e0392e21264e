//! `microtrace bench`: `--thesis` reproduces the thesis's Tables 4.3 and 4.4 (the
//! optimizations); `--numbers` reports speed against error for every number type; `--scale`
//! how memory and time grow with the objects; `--spd` Haines' SPD scenes at their standard sizes.

use std::path::PathBuf;

#[path = "bench_numbers.rs"]
mod numbers;
#[path = "bench_scale.rs"]
mod scale;
#[path = "bench_spd.rs"]
mod spd;
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
    /// Memory and time against the number of objects: generated fields of spheres.
    #[arg(long)]
    pub scale: bool,
    /// Haines' SPD scenes (scenes/spd/full) at their standard sizes: times, tests per ray, rays
    /// a second, memory, and the growth along the size ladders.
    #[arg(long)]
    pub spd: bool,
    /// --spd: only these scenes (comma-separated: balls, gears, mount, rings, teapot, tetra,
    /// tree, and the ladders' balls-s1..s3, rings-s1..s3, tree-s6..s8).
    #[arg(long, value_delimiter = ',')]
    pub spd_scenes: Vec<String>,
    /// --spd: the image size (the SPD's rules: 512x512).
    #[arg(long, value_parser = crate::scene_file::parse_size, default_value = "512x512")]
    pub spd_size: (u16, u16),
    /// --scale: the sphere counts, comma-separated.
    #[arg(long, value_delimiter = ',', default_value = "1000,10000,100000")]
    pub counts: Vec<usize>,
    /// --scale: the image size.
    #[arg(long, value_parser = crate::scene_file::parse_size, default_value = "320x240")]
    pub size: (u16, u16),
    /// --scale, --spd: the number type.
    #[arg(long, default_value = "f32")]
    pub number: String,
    /// --scale: also write each generated scene here, as spheres-COUNT.mts (to render or view).
    #[arg(long, value_name = "DIR")]
    pub scenes_out: Option<PathBuf>,
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
    let chosen = [args.thesis, args.numbers, args.scale, args.spd].iter().filter(|on| **on).count();
    if chosen == 0 {
        anyhow::bail!("choose --thesis (optimizations, Tables 4.3 and 4.4), --numbers (number types), --scale (memory and time against the objects) or --spd (Haines' SPD scenes)");
    }
    if chosen > 1 && args.out.is_some() {
        anyhow::bail!("--out names one report: run --thesis, --numbers, --scale and --spd separately to write each");
    }
    if args.thesis {
        thesis::run(&args)?;
    }
    if args.numbers {
        numbers::run(&args)?;
    }
    if args.scale {
        scale::run(&args)?;
    }
    if args.spd {
        spd::run(&args)?;
    }
    Ok(())
}
