//! Lights as written: the thesis's one light (§4.2.4) and chapter 5's further lights.

/// A light's position or direction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Light {
    /// A point light at this position.
    Point([f64; 3]),
    /// A directional light; the vector points toward the light (never zero).
    Direction([f64; 3]),
}

/// How many lights a scene may have (chapter 5: each `light` statement adds one; Haines' SPD
/// scenes have up to 7). A build's own tables hold its scene's (`Config::OtherLights`).
pub const MAX_LIGHTS: usize = 8;

/// A light beyond the first, with its intensity and the line that set it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightSource {
    pub light: Light,
    pub intensity: f64,
    pub line: u32,
}

