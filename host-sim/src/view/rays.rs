//! The chapter-5 settings the keys cycle: the ray tree's depth (`T`) and the adaptive
//! antialiasing (`A`), and how the panel states them with the rays they cost.

use microtrace::render::Statistics;
use microtrace::model::{Antialias, MAX_DEPTH};

/// The antialiasing threshold `A` uses when the scene has no `antialias` statement.
pub const DEFAULT_THRESHOLD: f64 = 0.1;
/// The most subdivision levels the scene format allows (`antialias T [L]`, L in 1..=4).
pub const MAX_LEVELS: u8 = 4;

/// The depth after `depth`: 1, 2, ..., [`MAX_DEPTH`], then 1 again (anything out of range
/// starts over at 1).
pub fn next_depth(depth: u8) -> u8 {
    if (1..MAX_DEPTH).contains(&depth) { depth + 1 } else { 1 }
}

/// The antialiasing after `current`: off, then levels 1 to [`MAX_LEVELS`] at `threshold`, then
/// off again.
pub fn next_antialias(current: Option<Antialias>, threshold: f64) -> Option<Antialias> {
    match current {
        None => Some(Antialias { threshold, levels: 1 }),
        Some(antialias) if antialias.levels >= MAX_LEVELS => None,
        Some(antialias) => Some(Antialias { threshold, levels: antialias.levels + 1 }),
    }
}

/// The antialiasing setting as the panel and stderr show it.
pub fn antialias_label(antialias: Option<Antialias>) -> String {
    match antialias {
        None => "antialias off".to_owned(),
        Some(Antialias { threshold, levels }) => format!("antialias L{levels} threshold {threshold:.2}"),
    }
}

/// Rays per pixel: every ray that left the eye (with antialiasing, one per sample corner) over
/// the image's pixels; 0 for an empty image.
pub fn rays_per_pixel(statistics: &Statistics, pixels: u64) -> f64 {
    if pixels == 0 { 0.0 } else { statistics.rays_traced as f64 / pixels as f64 }
}

/// The panel's lines about the rays: depth and antialiasing, rays per pixel, and the secondary
/// rays (their total and tests per ray, then the count of each generation) when there are any.
/// Always [`LINES`] lines, so the panel keeps its height.
pub fn lines(depth: u8, antialias: Option<Antialias>, statistics: &Statistics, pixels: u64) -> [String; LINES] {
    let secondary = statistics.secondary_rays_total();
    let (total, generations) = if secondary == 0 {
        ("no secondary rays".to_owned(), String::new())
    } else {
        let tests = statistics.secondary_tests as f64 / secondary as f64;
        let counts: Vec<String> = statistics.secondary_rays.iter().take_while(|count| **count > 0).map(u64::to_string).collect();
        (format!("secondary rays {secondary}, {tests:.2} tests/ray"), format!("  by generation {}", counts.join("/")))
    };
    [
        format!("depth {depth}  {}", antialias_label(antialias)),
        format!("rays per pixel {:.2} ({} rays)", rays_per_pixel(statistics, pixels), statistics.rays_traced),
        total,
        generations,
    ]
    .map(fit)
}

/// Characters of the panel's font across the panel.
const COLUMNS: usize = super::panel::WIDTH as usize / 6;

/// `line`, cut to the panel's width with a `~` where it was cut (the full figures are in the
/// statistics on stderr).
fn fit(line: String) -> String {
    if line.chars().count() <= COLUMNS { line } else { line.chars().take(COLUMNS - 1).chain(['~']).collect() }
}

/// How many lines [`lines`] returns.
pub const LINES: usize = 4;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn depth_cycles_from_one_to_eight_and_back() {
        let mut depth = 1;
        let mut seen = vec![depth];
        for _ in 0..MAX_DEPTH {
            depth = next_depth(depth);
            seen.push(depth);
        }
        assert_eq!(seen, [1, 2, 3, 4, 5, 6, 7, 8, 1]);
        assert_eq!(next_depth(0), 1);
        assert_eq!(next_depth(200), 1);
    }

    #[test]
    fn antialiasing_cycles_off_then_each_level_then_off_at_the_threshold_given() {
        let mut current = None;
        let mut seen = Vec::new();
        for _ in 0..6 {
            current = next_antialias(current, 0.06);
            seen.push(current.map(|a| a.levels));
            assert!(current.is_none_or(|a| a.threshold == 0.06));
        }
        assert_eq!(seen, [Some(1), Some(2), Some(3), Some(4), None, Some(1)]);
        // From the scene's own level (lattice-antialiased: L2) up, and a level the format
        // rejects ends the cycle rather than going beyond.
        assert_eq!(next_antialias(Some(Antialias { threshold: 0.06, levels: 2 }), 0.06).map(|a| a.levels), Some(3));
        assert_eq!(next_antialias(Some(Antialias { threshold: 0.06, levels: 9 }), 0.06), None);
    }

    #[test]
    fn the_panel_states_depth_antialiasing_rays_per_pixel_and_secondary_rays() {
        let mut statistics = Statistics { rays_traced: 5640, ..Statistics::default() };
        let shown = lines(4, Some(Antialias { threshold: 0.06, levels: 2 }), &statistics, 1000);
        assert_eq!(shown[0], "depth 4  antialias L2 threshold 0.06");
        assert_eq!(shown[1], "rays per pixel 5.64 (5640 rays)");
        assert_eq!(shown[2], "no secondary rays");
        assert_eq!(shown[3], "");
        statistics.secondary_rays[..3].copy_from_slice(&[60, 30, 10]);
        statistics.secondary_tests = 250;
        let shown = lines(1, None, &statistics, 0);
        assert_eq!(shown[0], "depth 1  antialias off");
        assert_eq!(shown[1], "rays per pixel 0.00 (5640 rays)");
        assert_eq!(shown[2], "secondary rays 100, 2.50 tests/ray");
        assert_eq!(shown[3], "  by generation 60/30/10");
    }

    #[test]
    fn every_line_fits_the_panel() {
        // A 4096x4096 image at level 4 and depth 8: the figures fit; the seven generations'
        // counts are cut.
        let statistics = Statistics { rays_traced: 4_858_000_000, secondary_rays: [999_999_999; 7], secondary_tests: 90_000_000_000, ..Statistics::default() };
        let shown = lines(8, Some(Antialias { threshold: 0.25, levels: 4 }), &statistics, 4096 * 4096);
        for line in &shown {
            assert!(line.chars().count() * 6 <= super::super::panel::WIDTH as usize, "{line:?} is wider than the panel");
        }
        assert_eq!(shown[1], "rays per pixel 289.56 (4858000000 rays)");
        assert_eq!(shown[2], "secondary rays 6999999993, 12.86 tests/ray");
        assert!(shown[3].starts_with("  by generation 999999999/") && shown[3].ends_with('~'), "{}", shown[3]);
    }
}
