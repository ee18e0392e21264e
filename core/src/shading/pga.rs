//! PGA mode (`pgashade`, digest §6.3): a shade 0..15 within the object's colour group.
//!
//! `intensity = 15·(ks·spec + kd·diff + ka·Ia) + rnd·noise`, clamped to [0, 14.9], then either
//! rounded or dithered; index = 16·group + shade.

use super::{dither_threshold, roughness_sample};
use crate::light::Lighting;
use crate::camera::PixelPosition;
use crate::number::Number;
use crate::model::PreparedMaterial;

/// Constants the shading needs in the number type, converted once per scene.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShadingConstants<N> {
    pub fifteen: N,
    pub brightest: N,
    pub half: N,
    pub noise_step: N,
    pub ambient: N,
    pub full_rgb: N,
    pub brightest_rgb: N,
}

impl<N: Number> ShadingConstants<N> {
    /// Every byte zero: the value before preparation.
    pub const UNSET: Self = Self { fifteen: N::ZEROED, brightest: N::ZEROED, half: N::ZEROED, noise_step: N::ZEROED, ambient: N::ZEROED, full_rgb: N::ZEROED, brightest_rgb: N::ZEROED };

    pub fn new(ambient: f64) -> Self {
        Self {
            fifteen: N::from_i32(15),
            brightest: N::from_f64(14.9),
            half: N::from_f64(0.5),
            noise_step: N::from_f64(1.0 / 32768.0),
            ambient: N::from_f64(ambient),
            full_rgb: N::from_i32(255),
            brightest_rgb: N::from_f64(254.9),
        }
    }

    /// Rounds or dithers an intensity in [0, `top`] to an integer level (§6.3–6.4). Every
    /// value rounded is at least zero, where [`Number::to_i32_monotone`] is the floor.
    pub fn quantize(&self, intensity: N, top: N, dither: bool, pixel: PixelPosition) -> i32 {
        let clamped = intensity.max(N::ZERO).min(top);
        if dither {
            let whole = clamped.to_i32_monotone();
            let fraction = clamped - N::from_i32(whole);
            let step = (self.fifteen * fraction + self.half).to_i32_monotone();
            whole + i32::from(step > i32::from(dither_threshold(pixel.screen_x, pixel.screen_y)))
        } else {
            (clamped + self.half).to_i32_monotone()
        }
    }
}

pub fn pga_index<N: Number>(
    material: &PreparedMaterial<N>,
    light: Lighting<N>,
    constants: &ShadingConstants<N>,
    dither: bool,
    pixel: PixelPosition,
) -> u8 {
    let reflected = material.ks * light.specular + material.kd * light.diffuse + material.ka * constants.ambient;
    let noise = material.rnd * (N::from_i32(i32::from(roughness_sample(pixel.screen_x, pixel.screen_y))) * constants.noise_step);
    let intensity = constants.fifteen * reflected + noise;
    let shade = constants.quantize(intensity, constants.brightest, dither, pixel).clamp(0, 15) as u8;
    material.colour * 16 + shade
}
