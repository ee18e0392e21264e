//! `microtrace-view SCENE.mts [OPTIONS]`: the simulator window, what `microtrace view` runs (the
//! one program of the two that links SDL2; see `microtrace_sim::window_binary`). It takes the
//! options of `microtrace view`.

use clap::Parser;
use microtrace_sim::commands::view::{self, ViewArgs};

#[derive(Parser)]
#[command(name = "microtrace view", version, about = "Open the simulator window and watch a scene render.")]
struct Cli {
    #[command(flatten)]
    args: ViewArgs,
}

fn main() {
    let cli = Cli::parse();
    microtrace_sim::files::remove_temporaries_on_interrupt();
    let result = microtrace_sim::window_binary::check_parent_build(env!("MICROTRACE_BUILD_ID")).and_then(|()| view::run(cli.args));
    if let Err(error) = result {
        eprintln!("microtrace: {error:#}");
        std::process::exit(1);
    }
}
