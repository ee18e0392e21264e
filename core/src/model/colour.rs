//! Colours: an RGB-mode pixel, and the PGA look-up table: 256 entries of 4-bit red, green and blue, organised as 16 colour
//! groups of 16 shades; index = 16·group + shade (§4.2.4, figs 4.4–4.5; PGADPEND.C).

/// An RGB-mode pixel: 8 bits per channel.
pub type Rgb888 = [u8; 3];

/// One look-up-table entry: 4 bits per primary (0..=15).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Rgb4 {
    pub r: u8,
    pub g: u8,
    pub b: u8,
}

impl Rgb4 {
    pub const fn new(r: u8, g: u8, b: u8) -> Self {
        Self { r, g, b }
    }

    /// The 8-bit-per-channel colour (each 4-bit level times 17, so 15 gives 255).
    pub const fn to_rgb888(self) -> [u8; 3] {
        [self.r * 17, self.g * 17, self.b * 17]
    }

    /// The LUT-file word: bits 11..8 red, 7..4 green, 3..0 blue (§4.2.2, `savecolors`).
    pub const fn to_word(self) -> u16 {
        ((self.r as u16) << 8) | ((self.g as u16) << 4) | self.b as u16
    }

    /// Decodes a LUT-file word; bits 15..12 are ignored (`readcolors`).
    pub const fn from_word(word: u16) -> Self {
        Self::new(((word >> 8) & 0xF) as u8, ((word >> 4) & 0xF) as u8, (word & 0xF) as u8)
    }

    /// Grey level 0..=15 by integer Rec. 601 luma (299/587/114), rounded: how a 16-grey display
    /// shows this colour.
    pub const fn luminance(self) -> u8 {
        ((299 * self.r as u32 + 587 * self.g as u32 + 114 * self.b as u32 + 500) / 1000) as u8
    }
}

/// Two look-up-table entries and how much of the second a dithered area shows
/// ([`Palette::dithered_pair`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct DitherPair {
    pub near: u8,
    pub far: u8,
    /// The far entry's share, in sixteenths (0..=16).
    pub share: u8,
}

impl DitherPair {
    /// The entry a pixel shows, given its ordered-dither threshold (0..=15): the far one at
    /// `share` of the thresholds.
    pub fn at(self, threshold: u8) -> u8 {
        if self.share > threshold {
            self.far
        } else {
            self.near
        }
    }
}

/// The 256-entry look-up table.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Palette {
    pub entries: [Rgb4; 256],
}

impl Default for Palette {
    fn default() -> Self {
        Self::grey()
    }
}

impl Palette {
    /// Every group a grey ramp, shade i = (i, i, i): the scene format's default.
    pub fn grey() -> Self {
        Self { entries: core::array::from_fn(|index| { let i = (index % 16) as u8; Rgb4::new(i, i, i) }) }
    }

    pub fn entry(&self, index: u8) -> Rgb4 {
        self.entries[index as usize]
    }

    /// The entry nearest to an RGB colour (squared distance in 8-bit channels, ties to the
    /// lower index): how a PGA pixel mixed by the ray tree or antialiasing gets its index
    /// (scene format, chapter 5).
    pub fn nearest(&self, colour: [u8; 3]) -> u8 {
        let mut best = (u32::MAX, 0u8);
        for (index, entry) in (0..=255u8).zip(self.entries.iter()) {
            let distance: u32 = entry.to_rgb888().iter().zip(colour).map(|(a, b)| u32::from(a.abs_diff(b)).pow(2)).sum();
            if distance < best.0 {
                best = (distance, index);
            }
        }
        best.1
    }

    /// The two entries a mixed colour is dithered between (PGA mode's pixels that the ray tree or
    /// antialiasing mixed, scene format): the nearest entry, and the entry whose line from it
    /// passes nearest the colour, with the colour's place along that line in sixteenths. An
    /// ordered dither then shows the far entry at that share of the pixels, so an area of one
    /// mixed colour averages to it instead of banding at the nearest entry.
    pub fn dithered_pair(&self, colour: [u8; 3]) -> DitherPair {
        let near = self.nearest(colour);
        let [nr, ng, nb] = self.entry(near).to_rgb888().map(i32::from);
        let [cr, cg, cb] = colour.map(i32::from);
        let offset = (cr - nr, cg - ng, cb - nb);
        // Residuals in sixteenths: |16·(colour − near) − share·(far − near)|².
        let residual = |(dr, dg, db): (i32, i32, i32), share: i32| {
            let (er, eg, eb) = (16 * offset.0 - share * dr, 16 * offset.1 - share * dg, 16 * offset.2 - share * db);
            er * er + eg * eg + eb * eb
        };
        let mut best = DitherPair { near, far: near, share: 0 };
        let mut best_residual = residual((0, 0, 0), 0);
        for (index, entry) in (0..=255u8).zip(self.entries.iter()) {
            let [fr, fg, fb] = entry.to_rgb888().map(i32::from);
            let step = (fr - nr, fg - ng, fb - nb);
            let length = step.0 * step.0 + step.1 * step.1 + step.2 * step.2;
            let along = offset.0 * step.0 + offset.1 * step.1 + offset.2 * step.2;
            if along <= 0 {
                continue;
            }
            // `along > 0` needs a step, so `length > 0`; checked all the same (no panic path).
            let Some(share) = (16 * along + length / 2).checked_div(length) else { continue };
            let share = share.min(16);
            let candidate = residual(step, share);
            if candidate < best_residual {
                best = DitherPair { near, far: index, share: share as u8 };
                best_residual = candidate;
            }
        }
        best
    }

    /// `generatergbup(group, r, g, b)`: shade i = round(i·(r,g,b)/max(r,g,b)), walking from
    /// black through the cell so that the largest channel reaches 15 at shade 15.
    /// The thesis did nothing for (0,0,0); we make the group black.
    pub fn set_group_up(&mut self, group: u8, cell: Rgb4) {
        let largest = cell.r.max(cell.g).max(cell.b) as f64;
        for shade in 0..16u8 {
            let level = |channel: u8| {
                if largest == 0.0 { 0 } else { (shade as f64 * (channel as f64 / largest) + 0.5) as u8 }
            };
            self.entries[(group as usize & 15) * 16 + shade as usize] = Rgb4::new(level(cell.r), level(cell.g), level(cell.b));
        }
    }

    /// The `down` palette as the scene format defines it (the thesis's intent, digest §11 B8
    /// reading (b)): shade 15 is white and the line from white passes through the cell,
    /// shade i = 15 − round((15 − i)·d) with d = (15 − r, 15 − g, 15 − b) / max.
    /// A white cell gives an all-white group.
    pub fn set_group_down(&mut self, group: u8, cell: Rgb4) {
        let complement = [15 - cell.r.min(15), 15 - cell.g.min(15), 15 - cell.b.min(15)];
        let largest = complement.iter().copied().max().unwrap_or(0) as f64;
        for shade in 0..16u8 {
            let level = |channel: u8| {
                if largest == 0.0 {
                    15
                } else {
                    15 - ((15 - shade) as f64 * (channel as f64 / largest) + 0.5) as u8
                }
            };
            self.entries[(group as usize & 15) * 16 + shade as usize] =
                Rgb4::new(level(complement[0]), level(complement[1]), level(complement[2]));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn up_group_walks_from_black_to_the_cell_scaled_to_15() {
        let mut palette = Palette::grey();
        palette.set_group_up(1, Rgb4::new(15, 1, 1));
        assert_eq!(palette.entry(16), Rgb4::new(0, 0, 0));
        assert_eq!(palette.entry(31), Rgb4::new(15, 1, 1));
        assert_eq!(palette.entry(16 + 8), Rgb4::new(8, 1, 1)); // 8/15 rounds to 1
    }

    #[test]
    fn down_group_is_white_at_15_and_passes_through_the_cell() {
        let mut palette = Palette::grey();
        palette.set_group_down(2, Rgb4::new(3, 9, 15));
        assert_eq!(palette.entry(47), Rgb4::new(15, 15, 15));
        // max complement is 12 (red), so shade 15 - 12 = 3 is the cell itself.
        assert_eq!(palette.entry(32 + 3), Rgb4::new(3, 9, 15));
    }

    #[test]
    fn a_dithered_pair_averages_to_the_colour_where_the_nearest_entry_bands() {
        let palette = Palette::grey();
        for level in 0..=255u8 {
            let pair = palette.dithered_pair([level; 3]);
            let mean = (0..16u8).map(|threshold| f64::from(palette.entry(pair.at(threshold)).to_rgb888()[0])).sum::<f64>() / 16.0;
            // Grey levels are 17 apart: sixteenths of that step, rounded.
            assert!((mean - f64::from(level)).abs() <= 17.0 / 32.0 + 1e-9, "level {level}: {pair:?} averages {mean}");
            assert_eq!(pair.near, palette.nearest([level; 3]));
        }
        // A colour on an entry is that entry everywhere.
        let exact = palette.dithered_pair([102; 3]);
        assert!((0..16).all(|threshold| exact.at(threshold) == exact.near));
        // A mix of red and green, with a red and a green group among greys: the dithered area
        // comes nearer the mix than its nearest entry.
        let mut two = Palette::grey();
        two.set_group_up(1, Rgb4::new(15, 0, 0));
        two.set_group_up(2, Rgb4::new(0, 15, 0));
        let mix = [128u8, 127, 0];
        let pair = two.dithered_pair(mix);
        let distance = |colour: [f64; 3]| (0..3).map(|c| (colour[c] - f64::from(mix[c])).powi(2)).sum::<f64>().sqrt();
        let mean = (0..16u8).fold([0.0; 3], |sum, threshold| {
            let rgb = two.entry(pair.at(threshold)).to_rgb888();
            [0, 1, 2].map(|c| sum[c] + f64::from(rgb[c]) / 16.0)
        });
        let nearest = two.entry(pair.near).to_rgb888().map(f64::from);
        assert!(distance(mean) < distance(nearest) - 10.0, "{pair:?}: mean {mean:?}, nearest {nearest:?}");
    }

    #[test]
    fn lut_word_round_trips() {
        let c = Rgb4::new(10, 4, 15);
        assert_eq!(c.to_word(), 0x0A4F);
        assert_eq!(Rgb4::from_word(0xFA4F), c);
    }
}
