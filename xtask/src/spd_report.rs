//! `cargo xtask firmware-report --spd`: Haines' SPD scenes at 128x64 on the Cortex-M4F
//! (mps2-an386, `f32` with the FPU, the board's 256 KB of flash and 64 KB of RAM), each with its
//! own `optimize` (issue 24): the small ones of `scenes/spd/` rendered under QEMU and set
//! against the host's render, and for every scene the chip cannot hold, the bytes of RAM it would
//! need (the firmware's own RAM check, in the target's layout: a scene of more objects than the
//! build bakes is compiled only to be sized, firmware/build.rs's `size_only`). Writes
//! `docs/spd-firmware.md`.

use std::io::Read as _;
use std::path::{Path, PathBuf};

use crate::firmware::{self, Board, FirmwareOptions};

/// The small SPD scenes shipped uncompressed.
const SMALL: [&str; 7] = ["balls1", "balls2", "jacks1", "lattice1", "rings1", "shells1", "tree3"];
/// The standard sizes (`scenes/spd/full/*.nff.gz`), and the ladders' rungs of more objects
/// than the blocker sets hold but fewer than the build bakes (a hierarchy in flash).
const FULL: [&str; 9] = ["tree-s6", "rings-s2", "balls", "gears", "mount", "rings", "teapot", "tetra", "tree"];
const BOARD: Board = Board::Mps2An386;
const NUMBER: &str = "f32";

/// One scene's outcome.
pub struct SpdRow {
    pub scene: String,
    pub objects: usize,
    pub outcome: Outcome,
}

pub enum Outcome {
    /// Rendered on the chip: its report's figures and the pixels that differ from the host's.
    Ran { frame_instructions: u64, instructions_per_pixel: u64, flash_bytes: u64, static_ram_bytes: u64, stack_peak_bytes: u64, differing_pixels: u64 },
    /// The build's RAM check: `needs N bytes of RAM (...), the mps2-an386 has 65,536`.
    DoesNotFit(String),
}

/// Runs every scene (printing progress) and writes `docs/spd-firmware.md`.
pub fn run() -> Result<Vec<SpdRow>, String> {
    let root = crate::repository_root();
    let work = crate::firmware_dir().join("target/report/spd");
    std::fs::create_dir_all(&work).map_err(|error| format!("{}: {error}", work.display()))?;
    let mut scenes: Vec<(String, PathBuf)> = SMALL.iter().map(|name| ((*name).to_owned(), root.join(format!("scenes/spd/{name}.nff")))).collect();
    for name in FULL {
        scenes.push((name.to_owned(), decompressed(&root.join(format!("scenes/spd/full/{name}.nff.gz")), &work.join(format!("{name}.nff")))?));
    }
    let mut rows = Vec::new();
    for (index, (name, path)) in scenes.iter().enumerate() {
        println!("[{}/{}] {name} {} {NUMBER} ...", index + 1, scenes.len(), BOARD.name());
        let objects = firmware::scene_objects(path)?;
        let options = FirmwareOptions::new(path, BOARD, NUMBER, work.join(name));
        let outcome = match firmware::run(&options) {
            Ok(result) => {
                let differing_pixels = crate::report::differing_from_host(&result, path, NUMBER, "scene").map_err(|error| format!("{name}: {error}"))?;
                let get = |key: &str| result.numbers.get(key).copied().ok_or_else(|| format!("{name}: the report lacks `{key}`"));
                Outcome::Ran {
                    frame_instructions: get("frame_instructions")?,
                    instructions_per_pixel: get("instructions_per_pixel")?,
                    flash_bytes: get("flash_bytes")?,
                    static_ram_bytes: get("static_ram_bytes")?,
                    stack_peak_bytes: get("stack_peak_bytes")?,
                    differing_pixels,
                }
            }
            Err(error) => match crate::report::does_not_fit(&error) {
                Some(reason) => Outcome::DoesNotFit(reason),
                None => return Err(format!("{name}: {error}")),
            },
        };
        match &outcome {
            Outcome::Ran { frame_instructions, differing_pixels, .. } => println!("    frame {frame_instructions} instructions, {differing_pixels} pixels differ from the host"),
            Outcome::DoesNotFit(reason) => println!("    does not fit: {reason}"),
        }
        rows.push(SpdRow { scene: name.clone(), objects, outcome });
    }
    let path = root.join("docs/spd-firmware.md");
    std::fs::write(&path, markdown(&rows)).map_err(|error| format!("{}: {error}", path.display()))?;
    println!("wrote {}", path.display());
    Ok(rows)
}

/// `gz` decompressed to `to` (QEMU's build script reads plain NFF).
pub fn decompressed(gz: &Path, to: &Path) -> Result<PathBuf, String> {
    let file = std::fs::File::open(gz).map_err(|error| format!("{}: {error}", gz.display()))?;
    let mut text = Vec::new();
    flate2::read::GzDecoder::new(file).read_to_end(&mut text).map_err(|error| format!("{}: {error}", gz.display()))?;
    std::fs::write(to, text).map_err(|error| format!("{}: {error}", to.display()))?;
    Ok(to.to_path_buf())
}

/// The table: what ran, with its figures, and what needs more RAM than the board has.
pub fn markdown(rows: &[SpdRow]) -> String {
    let mut text = String::from(
        "<!-- written by `cargo xtask firmware-report --spd`; do not edit by hand -->\n\
         # Haines' SPD scenes on the Cortex-M4F\n\n\
         Each SPD scene at 128x64 on QEMU's mps2-an386 (Cortex-M4F, `f32` with the FPU), with the\n\
         board's budget of 256 KB of flash and 64 KB of RAM and the scene's own `optimize`: the small\n\
         scenes of `scenes/spd/` rendered (frame instructions as the firmware report counts them; `host`:\n\
         `=` when the picture is the host's byte for byte), and for a scene the board cannot hold, the\n\
         RAM the build's check says it needs (firmware/src/ram.rs). A scene the build bakes (up\n\
         to 512 objects) has its objects, screen grid, shadow tables and per-object tables of the view\n\
         made at build time and kept in flash (a scene of more than 128 objects a hierarchy of boxes\n\
         instead of shadow tables: docs/optimizations.md); in RAM it keeps only what the ray tree needs\n\
         per object (its optics, bounding spheres and space grid, for a scene that reflects). A scene\n\
         of more than 512 objects is sized, not baked (firmware/build.rs, `microtrace::bake::bake_sizes`),\n\
         as a bake would keep it: its tables in flash, in RAM what the ray tree needs and the stack\n\
         the shadow tables take per object where a render builds them.\n\n\
         | scene | objects | on the chip | frame instructions | instructions per pixel | flash bytes | static RAM bytes | peak stack bytes | host |\n\
         |---|---:|---|---:|---:|---:|---:|---:|---|\n",
    );
    for row in rows {
        text += &match &row.outcome {
            Outcome::Ran { frame_instructions, instructions_per_pixel, flash_bytes, static_ram_bytes, stack_peak_bytes, differing_pixels } => format!(
                "| {} | {} | runs | {} | {} | {} | {} | {} | {} |\n",
                row.scene,
                crate::report::thousands(row.objects as u64),
                crate::report::thousands(*frame_instructions),
                crate::report::thousands(*instructions_per_pixel),
                crate::report::thousands(*flash_bytes),
                crate::report::thousands(*static_ram_bytes),
                crate::report::thousands(*stack_peak_bytes),
                if *differing_pixels == 0 { "=".to_owned() } else { format!("{differing_pixels} differ") }
            ),
            Outcome::DoesNotFit(reason) => format!("| {} | {} | {reason} | | | | | | |\n", row.scene, crate::report::thousands(row.objects as u64)),
        };
    }
    text
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_scene_that_ran_has_its_figures_and_one_that_does_not_fit_what_it_needs() {
        let rows = [
            SpdRow { scene: "tree3".into(), objects: 32, outcome: Outcome::Ran { frame_instructions: 57_785_276, instructions_per_pixel: 7_053, flash_bytes: 41_432, static_ram_bytes: 10_808, stack_peak_bytes: 16_536, differing_pixels: 0 } },
            SpdRow { scene: "balls1".into(), objects: 12, outcome: Outcome::Ran { frame_instructions: 1, instructions_per_pixel: 1, flash_bytes: 1, static_ram_bytes: 1, stack_peak_bytes: 1, differing_pixels: 3 } },
            SpdRow { scene: "tree".into(), objects: 8192, outcome: Outcome::DoesNotFit("needs 6,526,072 bytes of RAM (...), the mps2-an386 has 65,536".into()) },
        ];
        let text = markdown(&rows);
        assert!(text.contains("| tree3 | 32 | runs | 57,785,276 | 7,053 | 41,432 | 10,808 | 16,536 | = |\n"), "{text}");
        assert!(text.contains("| balls1 | 12 | runs | 1 | 1 | 1 | 1 | 1 | 3 differ |\n"), "{text}");
        assert!(text.contains("| tree | 8,192 | needs 6,526,072 bytes of RAM (...), the mps2-an386 has 65,536 | | | | | | |\n"), "{text}");
    }
}
