//! Loading a `.mts` file with errors that name the file and line, and the command-line
//! overrides every command shares.

use std::fmt;
use std::path::{Path, PathBuf};

use anyhow::Context;
use microtrace::model::SceneError;
use microtrace::model::{Description, ObjectDescription, Optimizations};

use crate::heap::Growing;

/// A scene as written, its objects on the heap: as many as memory holds (the firmware's are
/// sized to its scene).
pub type HostScene = Description<Growing<ObjectDescription>>;

/// A scene error with the file it is in: `FILE:line N: reason` (or `FILE: reason` for an error
/// tied to no line), the one format of every parse and preparation error the command prints.
/// The scene error stays typed, so callers can still tell its kind.
#[derive(Debug)]
pub struct SceneFileError {
    pub path: PathBuf,
    pub error: SceneError,
}

impl fmt::Display for SceneFileError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.error.line == 0 {
            write!(f, "{}: {}", self.path.display(), self.error)
        } else {
            write!(f, "{}:{}", self.path.display(), self.error)
        }
    }
}

impl std::error::Error for SceneFileError {}

/// Names `path` in `error` when it is a bare [`SceneError`] (from preparing the scene read from
/// `path`); any other error is returned as it is.
pub fn in_file(path: &Path, error: anyhow::Error) -> anyhow::Error {
    match error.downcast::<SceneError>() {
        Ok(error) => SceneFileError { path: path.to_owned(), error }.into(),
        Err(other) => other,
    }
}

/// Reads a scene: `.mts` (docs/scene-format.md), or Haines' NFF (`.nff`, and `.nff.gz`
/// compressed; docs/nff.md).
pub fn load(path: &Path) -> anyhow::Result<Box<HostScene>> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read scene {}", path.display()))?;
    let name = path.file_name().map(|name| name.to_string_lossy().to_ascii_lowercase()).unwrap_or_default();
    let parsed = match name.strip_suffix(".gz") {
        Some(inner) if microtrace::parser::is_nff(inner) => {
            let mut text = Vec::new();
            std::io::Read::read_to_end(&mut flate2::read::MultiGzDecoder::new(&bytes[..]), &mut text)
                .with_context(|| format!("{}: not a readable gzip file", path.display()))?;
            microtrace::parser::parse_file(inner, &text)
        }
        _ => microtrace::parser::parse_file(&name, &bytes),
    };
    match parsed {
        Ok(scene) => Ok(Box::new(scene)),
        Err(error) => Err(SceneFileError { path: path.to_owned(), error }.into()),
    }
}

/// Prints on stderr what may make `scene`'s picture other than meant
/// (`microtrace::scene::SceneWarning`: no light statement, the eye or a light inside an object),
/// each as `FILE:line N: warning: ...` (the line of the object or light it names), or
/// `FILE: warning: ...`. Not errors: the render goes on.
pub fn warn(path: &Path, scene: &HostScene) {
    use microtrace::scene::SceneWarning;
    scene.warnings(|warning| {
        let line = match warning {
            SceneWarning::EyeInsideObject { object } => object,
            SceneWarning::LightInsideObject { light, .. } => light,
            _ => 0,
        };
        if line == 0 {
            eprintln!("{}: warning: {warning}", path.display());
        } else {
            eprintln!("{}:line {line}: warning: {warning}", path.display());
        }
    });
}

/// The number type, the mode and the overrides of a scene's statements that `render` and `view`
/// share (clap's `flatten`).
#[derive(clap::Args, Clone, Debug)]
pub struct SceneOptions {
    /// The number type to trace in.
    #[arg(long, value_parser = crate::number_type::number_kind_parser(), default_value = "f64")]
    pub number: microtrace::number::NumberKind,
    /// PGA palette mode or 24-bit RGB mode.
    #[arg(long, value_enum, default_value = "pga")]
    pub mode: crate::rendering::Mode,
    /// Replace the viewport by W x H pixels; the scene's window stays in view, with square pixels.
    #[arg(long, value_name = "WxH", value_parser = parse_size)]
    pub size: Option<(u16, u16)>,
    /// Override the scene's `optimize` statement: all, none, or a list like extents,grid.
    #[arg(long, value_name = "LIST", value_parser = parse_optimizations)]
    pub opt: Option<Optimizations>,
    /// Override the scene's `shadows` statement.
    #[arg(long, value_name = "on|off", value_parser = parse_switch)]
    pub shadows: Option<bool>,
    /// Override the scene's `dither` statement.
    #[arg(long, value_name = "on|off", value_parser = parse_switch)]
    pub dither: Option<bool>,
}

impl SceneOptions {
    /// The overrides applied to `scene`: its size (the window widened to keep pixels square),
    /// its `optimize`, `shadows` and `dither`.
    pub fn apply(&self, scene: &mut HostScene) {
        if let Some((width, height)) = self.size {
            scene.fit_to_size(width, height);
        }
        if let Some(optimizations) = self.opt {
            scene.optimizations = optimizations;
        }
        if let Some(shadows) = self.shadows {
            scene.shadows = shadows;
        }
        if let Some(dither) = self.dither {
            scene.dither = dither;
        }
    }
}

/// Parses `WxH`.
pub fn parse_size(text: &str) -> Result<(u16, u16), String> {
    let (width, height) = text.split_once(['x', 'X']).ok_or_else(|| format!("expected WxH, got `{text}`"))?;
    let parse = |part: &str| match part.trim().parse::<u16>() {
        Ok(value) if (1..=8192).contains(&value) => Ok(value),
        _ => Err(format!("size `{text}`: each side must be a whole number from 1 to 8192")),
    };
    Ok((parse(width)?, parse(height)?))
}

/// Parses `all`, `none`, or a comma-separated list of pixelbuffer, extents, grid, sortlist.
pub fn parse_optimizations(text: &str) -> Result<Optimizations, String> {
    Optimizations::from_list(text)
        .map_err(|other| format!("unknown optimization `{other}`: use all, none, or any of pixelbuffer,extents,grid,sortlist"))
}

/// Parses `on` / `off`.
pub fn parse_switch(text: &str) -> Result<bool, String> {
    match text {
        "on" => Ok(true),
        "off" => Ok(false),
        _ => Err(format!("expected on or off, got `{text}`")),
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    /// `.nff.gz` is read through gzip, `.nff` as it is: the same scene.
    #[test]
    fn compressed_and_plain_nff_read_the_same() {
        let scenes = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/spd");
        let compressed = super::load(&scenes.join("full/balls-s1.nff.gz")).unwrap();
        let plain = super::load(&scenes.join("balls1.nff")).unwrap();
        // 10 spheres and the ground square as two triangles.
        assert_eq!(compressed.objects.len(), 12);
        assert_eq!(compressed.objects.len(), plain.objects.len());
        assert_eq!(compressed.more_lights.len(), 2);
        // Any other name is read as `.mts`.
        let error = super::load(&scenes.join("README.md")).unwrap_err().to_string();
        assert!(error.contains("README.md:line ") && error.contains(": unknown keyword"), "{error}");
    }
}
