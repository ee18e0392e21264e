//! How far an indexed image is from a reference render of the same scene: the measures of
//! `bench --numbers` (docs/numbers.md defines each one).
//!
//! A palette index is `group << 4 | shade`: the high nibble picks one of 16 colour groups, the
//! low nibble one of 16 shades in it.

use microtrace::model::Palette;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImageDifference {
    pub pixels: usize,
    /// Pixels whose palette index differs from the reference's.
    pub differing: usize,
    /// Differing pixels in another colour group than the reference's (another object, or
    /// object against background): not counted in `largest_shade_step`.
    pub group_changes: usize,
    /// The largest |shade − reference shade| over the pixels in the same colour group.
    pub largest_shade_step: u8,
    /// Differing pixels whose index also differs from every one of their neighbours (eight
    /// inside the image, five on an edge, three in a corner) in the image's own pixels.
    pub speckles: usize,
    /// Peak signal-to-noise ratio in dB of the RGB image (indices through the palette, 8-bit
    /// channels) against the reference's RGB image; infinite when the two are identical.
    pub psnr_db: f64,
}

impl ImageDifference {
    /// Compares `image` with `reference`, both `width` x `height` palette indices, rows top
    /// first. Errors name the mismatch when the sizes disagree.
    pub fn measure(reference: &[u8], image: &[u8], width: usize, height: usize, palette: &Palette) -> Result<Self, String> {
        let pixels = width * height;
        if reference.len() != pixels || image.len() != pixels {
            return Err(format!(
                "cannot compare images of {} and {} pixels as {width} x {height}",
                reference.len(),
                image.len()
            ));
        }
        let mut difference =
            ImageDifference { pixels, differing: 0, group_changes: 0, largest_shade_step: 0, speckles: 0, psnr_db: f64::INFINITY };
        let mut squared_error_sum = 0u64;
        for row in 0..height {
            for column in 0..width {
                let at = row * width + column;
                let (expected, found) = (reference[at], image[at]);
                if expected == found {
                    continue;
                }
                difference.differing += 1;
                if expected >> 4 == found >> 4 {
                    difference.largest_shade_step = difference.largest_shade_step.max((expected & 15).abs_diff(found & 15));
                } else {
                    difference.group_changes += 1;
                }
                if is_isolated(image, width, height, row, column) {
                    difference.speckles += 1;
                }
                let (expected_rgb, found_rgb) = (palette.entry(expected).to_rgb888(), palette.entry(found).to_rgb888());
                squared_error_sum +=
                    expected_rgb.iter().zip(found_rgb).map(|(a, b)| u64::from(a.abs_diff(b)).pow(2)).sum::<u64>();
            }
        }
        if squared_error_sum > 0 {
            let mean_squared_error = squared_error_sum as f64 / (3 * pixels) as f64;
            difference.psnr_db = 10.0 * (255.0f64 * 255.0 / mean_squared_error).log10();
        }
        Ok(difference)
    }

    pub fn percent_differing(&self) -> f64 {
        percent(self.differing, self.pixels)
    }

    pub fn percent_identical(&self) -> f64 {
        100.0 - self.percent_differing()
    }
}

pub fn percent(part: usize, whole: usize) -> f64 {
    if whole == 0 { 0.0 } else { 100.0 * part as f64 / whole as f64 }
}

/// Whether the pixel at (`row`, `column`) differs from all its neighbours in `image`. A pixel
/// with no neighbours (a 1 x 1 image) is not isolated.
fn is_isolated(image: &[u8], width: usize, height: usize, row: usize, column: usize) -> bool {
    let value = image[row * width + column];
    let mut neighbours = 0;
    for neighbour_row in row.saturating_sub(1)..=(row + 1).min(height - 1) {
        for neighbour_column in column.saturating_sub(1)..=(column + 1).min(width - 1) {
            if (neighbour_row, neighbour_column) == (row, column) {
                continue;
            }
            if image[neighbour_row * width + neighbour_column] == value {
                return false;
            }
            neighbours += 1;
        }
    }
    neighbours > 0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every group a grey ramp: shade i is (i, i, i), 17·i in 8 bits.
    fn grey_palette() -> Palette {
        Palette::grey()
    }

    #[test]
    fn identical_images_have_no_difference_and_infinite_psnr() {
        let image = [0x12u8; 12];
        let difference = ImageDifference::measure(&image, &image, 4, 3, &grey_palette()).unwrap();
        assert_eq!((difference.differing, difference.speckles, difference.largest_shade_step), (0, 0, 0));
        assert!(difference.psnr_db.is_infinite());
    }

    #[test]
    fn one_odd_pixel_is_a_speckle_and_its_shade_step_and_psnr_are_measured() {
        let reference = [0x14u8; 9];
        let mut image = reference;
        image[4] = 0x17; // three shades up, in the middle of a 3 x 3 image
        let difference = ImageDifference::measure(&reference, &image, 3, 3, &grey_palette()).unwrap();
        assert_eq!(difference.differing, 1);
        assert_eq!(difference.largest_shade_step, 3);
        assert_eq!(difference.group_changes, 0);
        assert_eq!(difference.speckles, 1);
        // Each channel is off by 3 × 17 = 51 in one pixel of nine: MSE = 51² / 9.
        let expected = 10.0 * (255.0f64.powi(2) / (51.0f64.powi(2) / 9.0)).log10();
        assert!((difference.psnr_db - expected).abs() < 1e-9, "{}", difference.psnr_db);
    }

    #[test]
    fn a_shifted_edge_is_not_speckled_and_a_group_change_is_counted_apart() {
        // Reference: left column group 1, the rest group 2. Image: the edge moved one column.
        let reference = [0x10, 0x20, 0x20, 0x10, 0x20, 0x20, 0x10, 0x20, 0x20];
        let image = [0x10, 0x10, 0x20, 0x10, 0x10, 0x20, 0x10, 0x10, 0x20];
        let difference = ImageDifference::measure(&reference, &image, 3, 3, &grey_palette()).unwrap();
        assert_eq!(difference.differing, 3);
        assert_eq!(difference.group_changes, 3);
        assert_eq!(difference.largest_shade_step, 0);
        assert_eq!(difference.speckles, 0);
    }

    #[test]
    fn mismatched_sizes_are_an_error_not_a_panic() {
        let error = ImageDifference::measure(&[0; 4], &[0; 5], 2, 2, &grey_palette()).unwrap_err();
        assert!(error.contains("4 and 5 pixels"), "{error}");
    }
}
