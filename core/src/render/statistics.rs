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
    /// The ray tree (chapter 5): secondary rays traced in each generation after the primary
    /// (index 0: the rays spawned at primary hits).
    pub secondary_rays: [u64; 7],
    /// Secondary ray–object tests (after the bounding spheres).
    pub secondary_tests: u64,
    /// The primitives tested inside solids, by rays of every kind (a solid's test counts once
    /// above, however many of its operands it tests; circumstance classification skips some).
    pub solid_leaf_tests: u64,
}

impl Statistics {
    /// Secondary rays of every generation.
    pub fn secondary_rays_total(&self) -> u64 {
        self.secondary_rays.iter().sum()
    }
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
        for (mine, theirs) in self.secondary_rays.iter_mut().zip(other.secondary_rays) {
            *mine += theirs;
        }
        self.secondary_tests += other.secondary_tests;
        self.solid_leaf_tests += other.solid_leaf_tests;
    }
}
