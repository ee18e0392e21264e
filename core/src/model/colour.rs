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

    /// The same luma on an 8-bit scale (0..=255, the channels times 17), rounded: the grey an
    /// error-diffused 1-bit display reproduces (`pixel::ErrorDiffusion`).
    pub const fn luma8(self) -> u8 {
        ((17 * (299 * self.r as u32 + 587 * self.g as u32 + 114 * self.b as u32) + 500) / 1000) as u8
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

    /// The entry a mixed colour shows at a pixel whose ordered-dither threshold is `threshold`
    /// (0..=15) (PGA mode's pixels mixed by the ray tree or antialiasing, scene format): the
    /// colour dithered between its nearest entry and the one of its next nearest distinct
    /// colours whose line from the nearest passes nearest it, the second entry at the colour's
    /// share along that line, in sixteenths. Over a 4x4 block the entries average to the colour
    /// instead of banding at the nearest entry; one pass over the table, as the nearest entry
    /// alone takes.
    pub fn dithered(&self, colour: [u8; 3], threshold: u8) -> u8 {
        const KEPT: usize = 4;
        let [cr, cg, cb] = colour.map(i32::from);
        // The KEPT nearest distinct colours, nearest first: (distance², index, rgb).
        let mut nearest: [(i32, u8, [i32; 3]); KEPT] = [(i32::MAX, 0, [0; 3]); KEPT];
        for (index, entry) in (0..=255u8).zip(self.entries.iter()) {
            let rgb = entry.to_rgb888().map(i32::from);
            let distance = (rgb[0] - cr).pow(2) + (rgb[1] - cg).pow(2) + (rgb[2] - cb).pow(2);
            let Some(last) = nearest.last() else { break };
            // Strictly nearer only: ties keep the lower index, as `nearest` does.
            // (Component by component: an array's `==` is a `memcmp` call on the chip.)
            let same = |kept: &[i32; 3]| kept[0] == rgb[0] && kept[1] == rgb[1] && kept[2] == rgb[2];
            if distance >= last.0 || nearest.iter().any(|kept| same(&kept.2) && kept.0 != i32::MAX) {
                continue;
            }
            let mut slot = KEPT - 1;
            while slot > 0 && nearest.get(slot - 1).is_some_and(|before| before.0 > distance) {
                nearest.swap(slot, slot - 1);
                slot -= 1;
            }
            if let Some(place) = nearest.get_mut(slot) {
                *place = (distance, index, rgb);
            }
        }
        let [(_, near, [nr, ng, nb]), others @ ..] = nearest;
        let offset = (cr - nr, cg - ng, cb - nb);
        // Residuals in sixteenths: |16·(colour − near) − share·(far − near)|².
        let residual = |(dr, dg, db): (i32, i32, i32), share: i32| {
            let (er, eg, eb) = (16 * offset.0 - share * dr, 16 * offset.1 - share * dg, 16 * offset.2 - share * db);
            er * er + eg * eg + eb * eb
        };
        let (mut far, mut share, mut best) = (near, 0, residual((0, 0, 0), 0));
        for (distance, index, [fr, fg, fb]) in others {
            let step = (fr - nr, fg - ng, fb - nb);
            let length = step.0 * step.0 + step.1 * step.1 + step.2 * step.2;
            let along = offset.0 * step.0 + offset.1 * step.1 + offset.2 * step.2;
            if distance == i32::MAX || along <= 0 {
                continue;
            }
            let Some(candidate_share) = (16 * along + length / 2).checked_div(length) else { continue };
            let candidate_share = candidate_share.min(16);
            let candidate = residual(step, candidate_share);
            if candidate < best {
                (far, share, best) = (index, candidate_share, candidate);
            }
        }
        if share > i32::from(threshold) {
            far
        } else {
            near
        }
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
    fn a_dithered_colour_averages_to_it_where_the_nearest_entry_bands() {
        let palette = Palette::grey();
        let mut worst_nearest: f64 = 0.0;
        for level in 0..=255u8 {
            let mean = (0..16u8).map(|threshold| f64::from(palette.entry(palette.dithered([level; 3], threshold)).to_rgb888()[0])).sum::<f64>() / 16.0;
            // Grey levels are 17 apart; the dither averages to within a sixteenth of a step and
            // the rounding of the shifts.
            assert!((mean - f64::from(level)).abs() <= 1.6, "level {level}: averages {mean}");
            worst_nearest = worst_nearest.max((f64::from(palette.entry(palette.nearest([level; 3])).to_rgb888()[0]) - f64::from(level)).abs());
        }
        assert!(worst_nearest >= 8.0, "the nearest entry alone is up to half a step off: {worst_nearest}");
        // A colour on an entry is that entry wherever the threshold.
        assert!((0..16).all(|threshold| palette.dithered([102; 3], threshold) == palette.nearest([102; 3])));
    }

    #[test]
    fn lut_word_round_trips() {
        let c = Rgb4::new(10, 4, 15);
        assert_eq!(c.to_word(), 0x0A4F);
        assert_eq!(Rgb4::from_word(0xFA4F), c);
    }
}
