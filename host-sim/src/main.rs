//! `microtrace`: render MicroTrace scenes on the desktop, read the thesis's image files back,
//! benchmark, and watch the tracer work in a simulator window (`view`, which runs the program
//! `microtrace-view` so that this one does not link SDL2: see `microtrace_sim::window_binary`).

use microtrace_sim::commands;

use clap::{Parser, Subcommand};

/// Counts the heap's bytes for `bench --scale` (two relaxed atomics an allocation).
#[global_allocator]
static ALLOCATOR: microtrace_sim::allocation::Counting = microtrace_sim::allocation::Counting;

#[derive(Parser)]
#[command(name = "microtrace", version, about = "MicroTrace: the 1989 microcomputer ray tracer, re-created")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Render a .mts scene to a PNG and/or the thesis's file formats.
    Render(commands::render::RenderArgs),
    /// Read a PGA (compressed or not) or RGB image file back into a PNG.
    Decode(commands::decode::DecodeArgs),
    /// Measure the optimizations and the number types.
    Bench(commands::bench::BenchArgs),
    /// Open the simulator window and watch a scene render.
    View(commands::view::ViewArgs),
    /// Each object's volume by ray casting in a parallel view (thesis §3.3), with its error.
    Volume(commands::volume::VolumeArgs),
}

fn main() {
    let cli = Cli::parse();
    microtrace_sim::files::remove_temporaries_on_interrupt();
    let result = match cli.command {
        Command::Render(args) => commands::render::run(args),
        Command::Decode(args) => commands::decode::run(args),
        Command::Bench(args) => commands::bench::run(args),
        Command::Volume(args) => commands::volume::run(args),
        // The arguments were checked above; `microtrace-view` takes what followed `view`.
        Command::View(_) => microtrace_sim::window_binary::run_view(env!("MICROTRACE_BUILD_ID"), std::env::args_os().skip(2)),
    };
    if let Err(error) = result {
        eprintln!("microtrace: {error:#}");
        std::process::exit(1);
    }
}
