//! Surface constants (table 4.1): as written, and in the render's number type.

/// Surface constants of one object (table 4.1), defaults from `getobject`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Colour group 0..15 (`clr`).
    pub colour: u8,
    pub ka: f64,
    pub kd: f64,
    pub ks: f64,
    /// Specular exponent.
    pub pwr: f64,
    /// Roughness: noise of up to `rnd` shade steps.
    pub rnd: f64,
    /// Cyan, magenta, yellow reflection ratios (RGB mode).
    pub cmy: [f64; 3],
    /// Reflection coefficient kr, 0..1 (chapter 5, `reflect`): the share of the reflected ray's
    /// colour added to the local shade.
    pub reflect: f64,
    /// Transmission coefficient kt, 0..1 (`transmit`): the share of the refracted ray's colour,
    /// and the share of a light that a shadow ray through the object passes.
    pub transmit: f64,
    /// Refractive index of the inside (`ior`), 0.1..10.
    pub ior: f64,
}

impl Default for Material {
    fn default() -> Self {
        Self { colour: 0, ka: 1.0, kd: 0.4, ks: 0.6, pwr: 20.0, rnd: 0.8, cmy: [0.3; 3], reflect: 0.0, transmit: 0.0, ior: 1.0 }
    }
}

impl Material {
    /// Whether rays leave this surface for more than the light (a mirror or a glass).
    pub fn spawns_rays(&self) -> bool {
        self.reflect > 0.0 || self.transmit > 0.0
    }
}


/// An object's surface constants in the number type.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PreparedMaterial<N> {
    pub colour: u8,
    pub ka: N,
    pub kd: N,
    pub ks: N,
    pub rnd: N,
    /// The specular exponent rounded to an integer.
    pub power: u32,
    /// RGB mode: the fraction of red, green and blue reflected, `1 − cmy`.
    pub reflectance: [N; 3],
}
