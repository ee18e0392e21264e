//! The counts of Table 4.2 (digest §9.1), plus the shadow-ray counts the thesis did not keep.
//! Times are measured by the caller (the core has no clock).

#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Statistics {
    /// Pixels in the viewport.
    pub pixels: u64,
    /// Pixels for which a primary ray was generated (below `pixels` only with Pixelbuffer).
    pub rays_traced: u64,
    /// Primary rays that hit an object.
    pub rays_intersected: u64,
    /// Primary ray–object tests (`testray` calls).
    pub ro_tests: u64,
    /// Primary tests that found a nearer hit than the best so far.
    pub ro_hits: u64,
    /// Shadow rays cast.
    pub shadow_rays: u64,
    /// Shadow ray–object tests.
    pub shadow_tests: u64,
}

impl Statistics {
    pub fn add(&mut self, other: &Statistics) {
        self.pixels += other.pixels;
        self.rays_traced += other.rays_traced;
        self.rays_intersected += other.rays_intersected;
        self.ro_tests += other.ro_tests;
        self.ro_hits += other.ro_hits;
        self.shadow_rays += other.shadow_rays;
        self.shadow_tests += other.shadow_tests;
    }
}
