//! The run's results as `key=value` lines of integers (and a few names), written to the host as
//! `report.txt`; xtask adds the ELF sizes and the instruction count and writes `report.json`.

use microtrace::render::Statistics;

use crate::decimal::Decimal;

pub struct Report {
    text: [u8; 1024],
    length: usize,
}

impl Report {
    pub fn new() -> Self {
        Self { text: [0; 1024], length: 0 }
    }

    pub fn name(&mut self, key: &str, value: &str) {
        self.line(key, value.as_bytes());
    }

    pub fn integer(&mut self, key: &str, value: u64) {
        self.line(key, Decimal::new(value).as_bytes());
    }

    pub fn statistics(&mut self, statistics: &Statistics) {
        self.integer("pixels", statistics.pixels);
        self.integer("rays_traced", statistics.rays_traced);
        self.integer("rays_intersected", statistics.rays_intersected);
        self.integer("ro_tests", statistics.ro_tests);
        self.integer("ro_hits", statistics.ro_hits);
        self.integer("shadow_rays", statistics.shadow_rays);
        self.integer("shadow_tests", statistics.shadow_tests);
        // The ray tree's (chapter 5); zero without one.
        self.integer("secondary_rays", statistics.secondary_rays_total());
        self.integer("secondary_tests", statistics.secondary_tests);
    }

    pub fn as_bytes(&self) -> &[u8] {
        self.text.get(..self.length).unwrap_or(&[])
    }

    /// Appends `key=value\n`; a line that does not fit is dropped whole (xtask then misses the
    /// key and says so).
    fn line(&mut self, key: &str, value: &[u8]) {
        let needed = key.len() + 1 + value.len() + 1;
        if self.length + needed > self.text.len() {
            return;
        }
        for part in [key.as_bytes(), b"=", value, b"\n"] {
            if let Some(slot) = self.text.get_mut(self.length..self.length + part.len()) {
                slot.copy_from_slice(part);
            }
            self.length += part.len();
        }
    }
}
