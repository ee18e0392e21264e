//! One colour per object, shared by the screen extents, the plan view and the depth ranges, so
//! an object can be followed from one to the others.

use embedded_graphics::pixelcolor::Rgb888;

/// A bright colour for object `object`: hues a golden-ratio turn apart, so neighbours in the
/// object list differ strongly and no two of the first few hundred objects coincide.
pub fn object_colour(object: usize) -> Rgb888 {
    const GOLDEN_TURN: f64 = 0.618_033_988_749_895;
    let hue = (object as f64 * GOLDEN_TURN).fract() * 6.0;
    // Saturation 0.8 and value 1: readable on black and on the image.
    let (low, high) = (0.2, 1.0);
    let rising = low + (high - low) * hue.fract();
    let falling = high - (high - low) * hue.fract();
    let (red, green, blue) = match hue as u32 {
        0 => (high, rising, low),
        1 => (falling, high, low),
        2 => (low, high, rising),
        3 => (low, falling, high),
        4 => (rising, low, high),
        _ => (high, low, falling),
    };
    let byte = |channel: f64| (channel * 255.0).round() as u8;
    Rgb888::new(byte(red), byte(green), byte(blue))
}

#[cfg(test)]
mod tests {
    use super::object_colour;

    #[test]
    fn the_first_objects_have_distinct_colours() {
        let colours: Vec<_> = (0..128).map(object_colour).collect();
        for (i, a) in colours.iter().enumerate() {
            assert!(colours[i + 1..].iter().all(|b| b != a), "object {i} shares its colour");
        }
    }
}
