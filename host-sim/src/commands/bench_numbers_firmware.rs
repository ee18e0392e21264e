//! Instructions per pixel and per frame on the Cortex-M boards, read from
//! `docs/firmware-report.json` (written by `cargo xtask firmware-report`: 128x64 frames,
//! preparation plus render, under QEMU; reports from before the frame was measured counted the
//! render alone).

use std::collections::BTreeMap;
use std::path::Path;

/// The board QEMU emulates for each core.
pub const CORTEX_M0_BOARD: &str = "microbit";
pub const CORTEX_M3_BOARD: &str = "lm3s6965evb";
pub const CORTEX_M4F_BOARD: &str = "mps2-an386";
pub const CORTEX_M33_BOARD: &str = "mps2-an505";

/// Which firmware builds a figure comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Build {
    /// The scene's own optimizations, as the host renders it: the figures in the tables.
    SceneOptimizations,
    /// Every optimization off: nearly all the work is arithmetic, so the ratios between number
    /// types show the types' own cost.
    OptimizationsOff,
}

/// Instructions per pixel and per frame keyed by (build, scene file stem, board, number type name).
#[derive(Debug, Default)]
pub struct FirmwareFigures {
    per_pixel: BTreeMap<(Build, String, String, String), u64>,
    per_frame: BTreeMap<(Build, String, String, String), PerFrame>,
}

/// A run's instructions per frame, and whether they are the frame's.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PerFrame {
    pub instructions: u64,
    /// `frame_instructions` (preparation plus render); false for the `instructions` of a report
    /// from before the frame was measured, which counted the render alone.
    pub whole_frame: bool,
}

impl FirmwareFigures {
    /// Reads `path`. A missing file gives no figures; an unreadable or malformed one is an
    /// error naming the file and the problem.
    pub fn read(path: &Path) -> Result<Self, String> {
        let text = match std::fs::read_to_string(path) {
            Ok(text) => text,
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => return Ok(Self::default()),
            Err(error) => return Err(format!("{}: {error}", path.display())),
        };
        Self::parse(&text).map_err(|problem| format!("{}: {problem}", path.display()))
    }

    /// Parses `{"runs": [{"scene", "board", "number", "instructions_per_pixel", ...}, ...]}`.
    /// The instructions per frame are `frame_instructions`, or `instructions` in a report that
    /// has no `frame_instructions`; a run with neither has no figure per frame.
    /// The scene may be given with or without its `.mts` extension. Runs at another size than
    /// 128x64 (when `width` and `height` say so) are left out, and so are builds with every
    /// primitive (`"primitives": "all"`, made to compare code size). `"optimizations": "none"`
    /// runs are [`Build::OptimizationsOff`]; runs with the scene's own (`"scene"`, or no such
    /// field) are [`Build::SceneOptimizations`]; runs with any other choice are left out.
    pub fn parse(text: &str) -> Result<Self, String> {
        let json: serde_json::Value = serde_json::from_str(text).map_err(|error| format!("not JSON: {error}"))?;
        let runs = json.get("runs").and_then(|runs| runs.as_array()).ok_or("no \"runs\" array")?;
        let mut figures = Self::default();
        for (position, run) in runs.iter().enumerate() {
            let text_field = |key: &str| {
                run.get(key).and_then(|value| value.as_str()).ok_or_else(|| format!("run {position} has no text \"{key}\""))
            };
            let scene = text_field("scene")?;
            let scene = scene.strip_suffix(".mts").unwrap_or(scene);
            let per_pixel = run
                .get("instructions_per_pixel")
                .and_then(|value| value.as_u64())
                .ok_or_else(|| format!("run {position} has no whole-number \"instructions_per_pixel\""))?;
            let size = (run.get("width").and_then(|w| w.as_u64()), run.get("height").and_then(|h| h.as_u64()));
            if matches!(size, (Some(width), Some(height)) if (width, height) != (128, 64)) {
                continue;
            }
            let optional_text = |key: &str| run.get(key).and_then(|value| value.as_str()).unwrap_or("scene");
            if optional_text("primitives") != "scene" {
                continue;
            }
            let build = match optional_text("optimizations") {
                "scene" => Build::SceneOptimizations,
                "none" => Build::OptimizationsOff,
                _ => continue,
            };
            let key = (build, scene.to_owned(), text_field("board")?.to_owned(), text_field("number")?.to_owned());
            let per_frame = ["frame_instructions", "instructions"].into_iter().find_map(|key| Some((key, run.get(key)?))).map(|(key, value)| {
                let instructions =
                    value.as_u64().ok_or_else(|| format!("run {position}: the instructions per frame (\"{key}\") are not a whole number"))?;
                Ok::<_, String>(PerFrame { instructions, whole_frame: key == "frame_instructions" })
            });
            if let Some(per_frame) = per_frame {
                figures.per_frame.insert(key.clone(), per_frame?);
            }
            figures.per_pixel.insert(key, per_pixel);
        }
        Ok(figures)
    }

    pub fn is_empty(&self) -> bool {
        self.per_pixel.is_empty()
    }

    /// The figure of the ordinary build (the scene's own optimizations).
    pub fn instructions_per_pixel(&self, scene: &str, board: &str, number: &str) -> Option<u64> {
        self.instructions_per_pixel_of(Build::SceneOptimizations, scene, board, number)
    }

    pub fn instructions_per_pixel_of(&self, build: Build, scene: &str, board: &str, number: &str) -> Option<u64> {
        self.per_pixel.get(&(build, scene.to_owned(), board.to_owned(), number.to_owned())).copied()
    }

    /// The instructions of one 128x64 frame of the ordinary build (the scene's own optimizations).
    pub fn instructions_per_frame(&self, scene: &str, board: &str, number: &str) -> Option<PerFrame> {
        self.per_frame.get(&(Build::SceneOptimizations, scene.to_owned(), board.to_owned(), number.to_owned())).copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_runs_by_scene_board_and_number() {
        let figures = FirmwareFigures::parse(
            r#"{"runs":[{"scene":"snooker","board":"lm3s6965evb","number":"f32","instructions_per_pixel":900,"pixels":8192},
                        {"scene":"lattice.mts","board":"mps2-an386","number":"fixed","instructions_per_pixel":450}]}"#,
        )
        .unwrap();
        assert_eq!(figures.instructions_per_pixel("snooker", CORTEX_M3_BOARD, "f32"), Some(900));
        assert_eq!(figures.instructions_per_pixel("lattice", CORTEX_M4F_BOARD, "fixed"), Some(450));
        assert_eq!(figures.instructions_per_pixel("snooker", CORTEX_M4F_BOARD, "f32"), None);
    }

    #[test]
    fn builds_are_told_apart_and_other_sizes_and_all_primitive_builds_left_out() {
        let figures = FirmwareFigures::parse(
            r#"{"runs":[{"scene":"snooker","board":"lm3s6965evb","number":"f32","primitives":"all","optimizations":"scene","instructions_per_pixel":5448},
                        {"scene":"snooker","board":"lm3s6965evb","number":"f32","primitives":"scene","optimizations":"scene","instructions_per_pixel":5432},
                        {"scene":"snooker","board":"lm3s6965evb","number":"f32","primitives":"scene","optimizations":"none","instructions_per_pixel":84250},
                        {"scene":"snooker","board":"lm3s6965evb","number":"f32","optimizations":"grid","instructions_per_pixel":7},
                        {"scene":"lattice","board":"lm3s6965evb","number":"f32","width":466,"height":480,"instructions_per_pixel":1}]}"#,
        )
        .unwrap();
        assert_eq!(figures.instructions_per_pixel("snooker", CORTEX_M3_BOARD, "f32"), Some(5432));
        assert_eq!(figures.instructions_per_pixel_of(Build::OptimizationsOff, "snooker", CORTEX_M3_BOARD, "f32"), Some(84250));
        assert_eq!(figures.instructions_per_pixel("lattice", CORTEX_M3_BOARD, "f32"), None);
    }

    #[test]
    fn the_frame_comes_from_frame_instructions_or_else_instructions() {
        let figures = FirmwareFigures::parse(
            r#"{"runs":[{"scene":"snooker","board":"mps2-an386","number":"f32","instructions":35882729,"frame_instructions":35882729,
                         "prepare_instructions":22777349,"render_instructions":13105380,"instructions_per_pixel":4380},
                        {"scene":"snooker","board":"lm3s6965evb","number":"f32","instructions":36840130,"instructions_per_pixel":4497},
                        {"scene":"lattice","board":"lm3s6965evb","number":"f32","instructions_per_pixel":15236}]}"#,
        )
        .unwrap();
        assert_eq!(figures.instructions_per_frame("snooker", CORTEX_M4F_BOARD, "f32"), Some(PerFrame { instructions: 35882729, whole_frame: true }));
        assert_eq!(figures.instructions_per_frame("snooker", CORTEX_M3_BOARD, "f32"), Some(PerFrame { instructions: 36840130, whole_frame: false }));
        assert_eq!(figures.instructions_per_frame("lattice", CORTEX_M3_BOARD, "f32"), None);
        assert_eq!(figures.instructions_per_pixel("lattice", CORTEX_M3_BOARD, "f32"), Some(15236));
        let error = FirmwareFigures::parse(r#"{"runs":[{"scene":"a","board":"b","number":"f32","instructions_per_pixel":1,"frame_instructions":"many"}]}"#)
            .unwrap_err();
        assert!(error.contains("per frame"), "{error}");
    }

    #[test]
    fn malformed_reports_name_the_problem() {
        assert!(FirmwareFigures::parse("{").unwrap_err().contains("not JSON"));
        assert!(FirmwareFigures::parse("{}").unwrap_err().contains("\"runs\""));
        let error = FirmwareFigures::parse(r#"{"runs":[{"scene":"a","board":"b","number":"f32"}]}"#).unwrap_err();
        assert!(error.contains("instructions_per_pixel"), "{error}");
    }
}
