//! The 4x4 ordered-dither matrix of RTRACE.C (`dither4`), indexed `[x % 4][y % 4]` with screen
//! coordinates (y up).

pub const DITHER_4X4: [[u8; 4]; 4] = [[0, 8, 2, 10], [12, 4, 14, 6], [3, 11, 1, 9], [15, 7, 13, 5]];

pub fn dither_threshold(screen_x: u16, screen_y: u16) -> u8 {
    DITHER_4X4[(screen_x % 4) as usize][(screen_y % 4) as usize]
}
