//! `cargo xtask <task>`: see `usage()`.

use std::path::PathBuf;
use std::time::Duration;

use xtask::firmware::{self, Board, Fault, FirmwareOptions, Primitives};
use xtask::report::ReportFilter;

fn usage() -> &'static str {
    "usage:
  cargo xtask firmware [--scene FILE] [--board lm3s6965evb|mps2-an386|microbit|mps2-an505|lm3s811evb|netduinoplus2] [--number f64|f32|fixed|fixed16|f32-micromath|soft32]
                       [--opt scene|all|none|pixelbuffer,extents,grid,sortlist] [--out DIR]
                       [--timeout SECONDS] [--stack-reserve BYTES] [--size WxH] [--progressive] [--framebuffer]
                       [--provoke panic|hard-fault|unexpected-interrupt|stack-overflow]
      Builds the firmware for the scene (default scenes/snooker.mts), runs it under QEMU and
      leaves framebuffer.bin, oled.png (lm3s6965evb) and report.json in DIR
      (default firmware/target/run/BOARD-SCENE-NUMBER). --provoke builds the fault test, which
      does that before preparing the scene: the run fails with the firmware's message.
      --stack-reserve: the stack the build's RAM check keeps free (default: 4 KB plus the
                       render's shadow tables per object (with a hierarchy in flash,
                       preparation's tables), at least 12288; on the 8 KB
                       lm3s811evb 1.5 KB plus the tables, at least 2560, 3072 with its
                       OLED; firmware/src/ram.rs).
      --size: the render's size (default 128x64; the lm3s811evb's OLED is 96x16).
      --progressive renders coarse to fine (8x8 blocks, then 4x4, 2x2, every pixel): the same
      image, the rays of each pass reported. --framebuffer builds the framebuffer render (the
      picture in an 8 KB RAM framebuffer) instead of the streamed one (rows sent as they are done).
  cargo xtask firmware-example
      Builds (does not run) the real-board examples in firmware/examples/
      (Raspberry Pi Pico + SSD1306, Raspberry Pi Pico + ST7789).
  cargo xtask firmware-report [--scene snooker|lattice] [--board B] [--number N] [--opt scene|none]
                              [--primitives scene|all]
      Runs both thesis scenes at 128x64 in every number type on both boards (and all-primitives
      builds), writes the table into docs/firmware-report.md and docs/firmware-report.json (several minutes).
      With any of the options, runs only what they keep and writes the partial report to
      firmware/target/report/partial/ (docs/ is left alone).
  cargo xtask firmware-report --spd
      Haines' SPD scenes at 128x64 on the mps2-an386 in f32: the small ones rendered, and the RAM
      each scene the board cannot hold would need; writes docs/spd-firmware.md."
}

fn main() {
    let arguments: Vec<String> = std::env::args().skip(1).collect();
    let result = match arguments.first().map(String::as_str) {
        Some("firmware") => firmware_task(&arguments[1..]),
        Some("firmware-report") if arguments.get(1).map(String::as_str) == Some("--spd") && arguments.len() == 2 => {
            xtask::spd_report::run().map(|rows| println!("{} scenes", rows.len()))
        }
        Some("firmware-report") => {
            report_filter(&arguments[1..]).and_then(|filter| xtask::report::run(&filter)).map(|runs| println!("{} runs", runs.len()))
        }
        Some("firmware-example") => xtask::example::build_all().map(|paths| {
            for path in paths {
                println!("built {} and {}", path.display(), xtask::example::uf2_path(&path).display());
            }
        }),
        _ => Err(usage().to_owned()),
    };
    if let Err(message) = result {
        eprintln!("xtask: {message}");
        std::process::exit(1);
    }
}

fn report_filter(arguments: &[String]) -> Result<ReportFilter, String> {
    let mut filter = ReportFilter::default();
    let mut rest = arguments.iter();
    while let Some(flag) = rest.next() {
        let mut value = || rest.next().cloned().ok_or_else(|| format!("{flag} needs a value\n{}", usage()));
        match flag.as_str() {
            "--scene" => filter.scene = Some(value()?),
            "--board" => {
                let name = value()?;
                filter.board = Some(Board::from_name(&name).ok_or_else(|| format!("unknown board `{name}` (lm3s6965evb, mps2-an386, microbit, mps2-an505 or lm3s811evb)"))?);
            }
            "--number" => filter.number = Some(value()?),
            "--opt" => filter.optimizations = Some(value()?),
            "--primitives" => {
                filter.primitives = Some(match value()?.as_str() {
                    "scene" => Primitives::Scene,
                    "all" => Primitives::All,
                    other => return Err(format!("--primitives {other}: scene or all")),
                })
            }
            other => return Err(format!("unknown argument `{other}`\n{}", usage())),
        }
    }
    Ok(filter)
}

fn firmware_task(arguments: &[String]) -> Result<(), String> {
    let root = xtask::repository_root();
    let mut scene = root.join("scenes/snooker.mts");
    let mut board = Board::Lm3s6965evb;
    let mut number = "f32".to_owned();
    let mut optimizations = "scene".to_owned();
    let mut out: Option<PathBuf> = None;
    let mut timeout = Duration::from_secs(300);
    let mut provoke = None;
    let mut stack_reserve = None;
    let mut progressive = false;
    let mut framebuffer = false;
    let mut size = None;
    let mut rest = arguments.iter();
    while let Some(flag) = rest.next() {
        let mut value = || rest.next().cloned().ok_or_else(|| format!("{flag} needs a value\n{}", usage()));
        match flag.as_str() {
            "--scene" => scene = PathBuf::from(value()?),
            "--board" => {
                let name = value()?;
                board = Board::from_name(&name).ok_or_else(|| format!("unknown board `{name}` (lm3s6965evb, mps2-an386, microbit, mps2-an505 or lm3s811evb)"))?;
            }
            "--number" => number = value()?,
            "--opt" => optimizations = value()?,
            "--out" => out = Some(PathBuf::from(value()?)),
            "--progressive" => progressive = true,
            "--framebuffer" => framebuffer = true,
            "--timeout" => {
                let seconds = value()?;
                timeout = Duration::from_secs(seconds.parse().map_err(|_| format!("--timeout {seconds}: not a number of seconds"))?);
            }
            "--size" => {
                let text = value()?;
                let parsed = text.split_once('x').and_then(|(width, height)| Some((width.parse::<u16>().ok()?, height.parse::<u16>().ok()?)));
                size = Some(parsed.filter(|(width, height)| *width > 0 && *height > 0).ok_or_else(|| format!("--size {text}: expected WIDTHxHEIGHT, e.g. 96x16"))?);
            }
            "--stack-reserve" => {
                let bytes = value()?;
                stack_reserve = Some(bytes.parse().map_err(|_| format!("--stack-reserve {bytes}: not a number of bytes"))?);
            }
            "--provoke" => {
                let name = value()?;
                provoke = Some(Fault::from_name(&name).ok_or_else(|| format!("--provoke {name}: panic, hard-fault, unexpected-interrupt or stack-overflow"))?);
            }
            "-h" | "--help" => {
                println!("{}", usage());
                return Ok(());
            }
            other => return Err(format!("unknown argument `{other}`\n{}", usage())),
        }
    }
    let out = out.unwrap_or_else(|| {
        let stem = scene.file_stem().map(|stem| stem.to_string_lossy().into_owned()).unwrap_or_default();
        xtask::firmware_dir().join("target/run").join(format!("{}-{stem}-{number}", board.name()))
    });
    let mut options = FirmwareOptions::new(scene, board, &number, out);
    options.optimizations = optimizations;
    options.timeout = timeout;
    options.provoke = provoke;
    options.stack_reserve = stack_reserve;
    options.progressive = progressive;
    options.framebuffer = framebuffer;
    options.size = size.unwrap_or(options.size);
    let run = firmware::run(&options)?;
    println!("{}", firmware::summary(&run, &options));
    Ok(())
}
