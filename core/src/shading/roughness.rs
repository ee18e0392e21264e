//! Roughness noise (§4.2.4, table 4.1 `rnd`). The thesis drew it from `rand()`, once per shaded
//! pixel in tracing order, so the noise depended on which pixels were traced before. Here it is
//! a hash of the pixel's screen position: the same pixel gets the same noise in any order, on
//! any tiling, with any optimization.

/// A value in 0..=32767 (the range of the thesis's `rand()`) for a screen position.
pub fn roughness_sample(screen_x: u16, screen_y: u16) -> u16 {
    // "lowbias32" integer hash (Chris Wellons): good avalanche from two multiplies.
    let mut h = (u32::from(screen_y) << 16) | u32::from(screen_x);
    h ^= h >> 16;
    h = h.wrapping_mul(0x7feb_352d);
    h ^= h >> 15;
    h = h.wrapping_mul(0x846c_a68b);
    h ^= h >> 16;
    (h & 0x7fff) as u16
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn samples_cover_the_range_evenly() {
        let mut buckets = [0u32; 8];
        for y in 0..64 {
            for x in 0..128 {
                buckets[(roughness_sample(x, y) >> 12) as usize] += 1;
            }
        }
        // 8192 samples, 1024 expected per bucket.
        assert!(buckets.iter().all(|&count| (900..1150).contains(&count)), "{buckets:?}");
    }
}
