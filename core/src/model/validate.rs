//! What a scene's values must be, in one place: the ranges the `.mts` parser checks each
//! statement's arguments against, and [`Description::validate`], which checks a description
//! however it was made (parsed, or built in code) against the same ranges with the same
//! messages (a value built in code has no line: its error's line is the object's, or 0).
//! Scene preparation calls it first, so a description built in code cannot reach the tracer
//! with a colour group of 200, a reflectance of 5 or a NaN (docs/scene-format.md).

use core::fmt::Write;

use super::{Description, Light, Material, ObjectDescription, Projection, SceneError, SceneErrorKind, SolidNode, Token, MAX_DEPTH};

/// A real argument's range: `low..=high`, described as `range` in the error.
#[derive(Clone, Copy, Debug)]
pub(crate) struct RealRange {
    pub what: &'static str,
    pub low: f64,
    pub high: f64,
    pub range: &'static str,
}

impl RealRange {
    const fn at_least_zero(what: &'static str) -> Self {
        Self { what, low: 0.0, high: f64::INFINITY, range: "at least 0" }
    }

    const fn unit(what: &'static str) -> Self {
        Self { what, low: 0.0, high: 1.0, range: "from 0 to 1" }
    }

    /// Whether `value` lies in the range (a NaN never does).
    pub fn holds(&self, value: f64) -> bool {
        (self.low..=self.high).contains(&value)
    }

    fn check(&self, line: u32, value: f64) -> Result<(), SceneError> {
        if self.holds(value) {
            Ok(())
        } else {
            Err(SceneError::new(line, SceneErrorKind::ValueOutOfRange { what: self.what, token: value_token(value), range: self.range }))
        }
    }
}

/// An integer argument's range: `min..=max`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct IntegerRange {
    pub what: &'static str,
    pub min: i32,
    pub max: i32,
}

impl IntegerRange {
    fn check(&self, line: u32, value: i32) -> Result<(), SceneError> {
        if (self.min..=self.max).contains(&value) {
            Ok(())
        } else {
            Err(SceneError::new(line, SceneErrorKind::IntegerOutOfRange { what: self.what, token: value_token(f64::from(value)), min: self.min, max: self.max }))
        }
    }
}

pub(crate) const KA: RealRange = RealRange::at_least_zero("ka");
pub(crate) const KD: RealRange = RealRange::at_least_zero("kd");
pub(crate) const KS: RealRange = RealRange::at_least_zero("ks");
pub(crate) const RND: RealRange = RealRange::at_least_zero("rnd");
pub(crate) const PWR: RealRange = RealRange { what: "pwr", low: 0.0, high: 1.0e6, range: "from 0 to 1000000" };
pub(crate) const CMY: [RealRange; 3] = [RealRange::unit("cmy C"), RealRange::unit("cmy M"), RealRange::unit("cmy Y")];
pub(crate) const REFLECT: RealRange = RealRange::unit("reflect");
pub(crate) const TRANSMIT: RealRange = RealRange::unit("transmit");
pub(crate) const IOR: RealRange = RealRange { what: "ior", low: 0.1, high: 10.0, range: "from 0.1 to 10" };
pub(crate) const AMBIENT: RealRange = RealRange::at_least_zero("ambient");
pub(crate) const LIGHT_INTENSITY: RealRange = RealRange::at_least_zero("light I");
pub(crate) const ANTIALIAS_THRESHOLD: RealRange = RealRange::unit("antialias T");
pub(crate) const COLOUR: IntegerRange = IntegerRange { what: "colour", min: 0, max: 15 };
pub(crate) const DEPTH: IntegerRange = IntegerRange { what: "depth", min: 1, max: MAX_DEPTH as i32 };
pub(crate) const ANTIALIAS_LEVELS: IntegerRange = IntegerRange { what: "antialias L", min: 1, max: 4 };
/// A viewport's corners (`viewport X1 X2 Y1 Y2`).
pub(crate) const VIEWPORT: [IntegerRange; 4] = [
    IntegerRange { what: "viewport X1", min: 0, max: 32767 },
    IntegerRange { what: "viewport X2", min: 0, max: 32767 },
    IntegerRange { what: "viewport Y1", min: 0, max: 32767 },
    IntegerRange { what: "viewport Y2", min: 0, max: 32767 },
];
/// A look-up table cell's levels (`group N R G B`).
pub(crate) const LEVEL: IntegerRange = IntegerRange { what: "group R, G or B", min: 0, max: 15 };

/// `value` as the error shows it (the parser shows the token as written).
fn value_token(value: f64) -> Token {
    let mut text: heapless::String<{ super::TOKEN_EXCERPT_BYTES }> = heapless::String::new();
    // A value too long for the excerpt is cut, as a long token is.
    let _ = write!(text, "{value}");
    Token::new(&text)
}

fn finite(line: u32, what: &'static str, values: &[f64]) -> Result<(), SceneError> {
    match values.iter().find(|value| !value.is_finite()) {
        Some(value) => Err(SceneError::new(line, SceneErrorKind::NumberNotFinite { what, token: value_token(*value) })),
        None => Ok(()),
    }
}

/// A direction whose length can be normalised (as the parser's `parallel` and `light
/// direction` require).
fn direction(line: u32, what: &'static str, vector: [f64; 3]) -> Result<(), SceneError> {
    finite(line, what, &vector)?;
    let length = libm::sqrt(vector.iter().map(|c| c * c).sum::<f64>());
    if length == 0.0 || !length.is_finite() {
        return Err(SceneError::new(line, SceneErrorKind::ZeroDirection));
    }
    Ok(())
}

fn light(line: u32, light: &Light, intensity: f64) -> Result<(), SceneError> {
    match light {
        Light::Point(position) => finite(line, "light point", position)?,
        Light::Direction(towards) => direction(line, "light direction", *towards)?,
    }
    LIGHT_INTENSITY.check(line, intensity)
}

fn material(line: u32, material: &Material) -> Result<(), SceneError> {
    COLOUR.check(line, i32::from(material.colour))?;
    for (range, value) in [(KA, material.ka), (KD, material.kd), (KS, material.ks), (PWR, material.pwr), (RND, material.rnd), (REFLECT, material.reflect), (TRANSMIT, material.transmit), (IOR, material.ior)] {
        range.check(line, value)?;
    }
    for (range, value) in CMY.iter().zip(material.cmy) {
        range.check(line, value)?;
    }
    Ok(())
}

impl ObjectDescription {
    /// Checks its material against the format's ranges and its transform for non-finite
    /// entries ([`Description::validate`] does this for every object and solid operand).
    pub fn validate(&self) -> Result<(), SceneError> {
        material(self.line, &self.material)?;
        if self.world_from_object.rows.iter().flatten().any(|entry| !entry.is_finite()) {
            return Err(SceneError::new(self.line, SceneErrorKind::SingularTransform));
        }
        Ok(())
    }
}

impl<L: core::ops::Deref<Target = [ObjectDescription]>> Description<L> {
    /// Checks every value against the ranges the scene format gives it (docs/scene-format.md),
    /// with the parser's messages: what a description built in code must hold before it is
    /// prepared (preparation calls this first). A parsed description always passes.
    pub fn validate(&self) -> Result<(), SceneError> {
        let v = self.viewport;
        for (range, corner) in VIEWPORT.iter().zip([v.x1, v.x2, v.y1, v.y2]) {
            range.check(0, i32::from(corner))?;
        }
        let rectangle = |requirement| Err(SceneError::new(0, SceneErrorKind::InvalidRectangle { what: "viewport", requirement }));
        if v.x1 > v.x2 {
            return rectangle("X1 must not be greater than X2");
        }
        if v.y1 > v.y2 {
            return rectangle("Y1 must not be greater than Y2");
        }
        let w = self.window;
        let line = self.lines.window;
        finite(line, "window", &[w.x1, w.x2, w.y1, w.y2])?;
        let rectangle = |requirement| Err(SceneError::new(line, SceneErrorKind::InvalidRectangle { what: "window", requirement }));
        // Finite by now, so `>=` is the negation of `<`.
        if w.x1 >= w.x2 {
            return rectangle("X1 must be less than X2");
        }
        if w.y1 >= w.y2 {
            return rectangle("Y1 must be less than Y2");
        }
        if !(w.x2 - w.x1).is_finite() || !(w.y2 - w.y1).is_finite() {
            return rectangle("too large: X2 - X1 and Y2 - Y1 must be finite");
        }
        finite(self.lines.view_plane, "viewplane D", &[self.view_plane])?;
        match self.projection {
            Projection::Perspective { eye } => finite(self.lines.projection, "perspective", &eye)?,
            Projection::Parallel { direction: towards } => direction(self.lines.projection, "parallel", towards)?,
        }
        light(self.lines.light, &self.light, self.light_intensity)?;
        for source in &self.more_lights {
            light(source.line, &source.light, source.intensity)?;
        }
        DEPTH.check(0, i32::from(self.depth))?;
        if let Some(antialias) = self.antialias {
            ANTIALIAS_THRESHOLD.check(self.lines.antialias, antialias.threshold)?;
            ANTIALIAS_LEVELS.check(self.lines.antialias, i32::from(antialias.levels))?;
        }
        AMBIENT.check(0, self.ambient)?;
        for cell in self.palette.entries.iter() {
            for level in [cell.r, cell.g, cell.b] {
                LEVEL.check(0, i32::from(level))?;
            }
        }
        for description in self.objects.iter() {
            description.validate()?;
        }
        for node in &self.solids {
            if let SolidNode::Leaf(leaf) = node {
                leaf.validate()?;
            }
        }
        Ok(())
    }
}
