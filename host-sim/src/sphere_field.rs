//! A generated scene of any number of spheres, for measuring how the tracer scales with the
//! objects (`microtrace bench --scale`, docs/scale.md): a square field of spheres on a floor,
//! seen from above one edge in perspective, lit by a point light with shadows, every
//! optimization on. The radii and colours come from a fixed pseudo-random sequence, so a
//! count always gives the same scene.

use std::fmt::Write;

/// The `.mts` text of a field of `count` spheres rendered at `width` x `height`.
pub fn sphere_field(count: usize, width: u16, height: u16) -> String {
    // `side` x `side` places, 2 units apart, the last row partly filled; x across, z away
    // from the viewer (z from 0 down to -2·side), y up.
    let side = (count as f64).sqrt().ceil().max(1.0);
    let eye = [0.0, 0.9 * side, 0.9 * side];
    let view_plane = eye[2] - side / 2.0;
    // The window: the field's corners (and the spheres' tops) projected onto the view plane.
    let project = |x: f64, y: f64, z: f64| {
        let t = (eye[2] - view_plane) / (eye[2] - z);
        [eye[0] + (x - eye[0]) * t, eye[1] + (y - eye[1]) * t]
    };
    let mut low = [f64::INFINITY; 2];
    let mut high = [f64::NEG_INFINITY; 2];
    for (x, z) in [(-side, 0.0), (side, 0.0), (-side, -2.0 * side), (side, -2.0 * side)] {
        for y in [0.0, 2.0] {
            let [u, v] = project(x, y, z);
            low = [low[0].min(u), low[1].min(v)];
            high = [high[0].max(u), high[1].max(v)];
        }
    }
    // The window's shape follows the viewport's, so the spheres stay round.
    let aspect = f64::from(width.max(1)) / f64::from(height.max(1));
    let (mut half_width, mut half_height) = ((high[0] - low[0]) / 2.0, (high[1] - low[1]) / 2.0);
    if half_width / half_height < aspect {
        half_width = half_height * aspect;
    } else {
        half_height = half_width / aspect;
    }
    let centre = [(low[0] + high[0]) / 2.0, (low[1] + high[1]) / 2.0];
    let mut text = String::with_capacity(80 * count + 1024);
    let _ = writeln!(text, "# {count} spheres on a floor (microtrace_sim::sphere_field): the scale test of docs/scale.md");
    let _ = writeln!(text, "viewport 0 {} 0 {}", width.max(1) - 1, height.max(1) - 1);
    let _ = writeln!(
        text,
        "window {:.4} {:.4} {:.4} {:.4}",
        centre[0] - half_width * 1.02,
        centre[0] + half_width * 1.02,
        centre[1] - half_height * 1.02,
        centre[1] + half_height * 1.02
    );
    let _ = writeln!(text, "viewplane {view_plane:.4}");
    let _ = writeln!(text, "perspective {:.4} {:.4} {:.4}", eye[0], eye[1], eye[2]);
    let _ = writeln!(text, "light point {:.4} {:.4} {:.4}", side * 0.6, side * 2.0, side * 0.4);
    let _ = writeln!(text, "shadows on\noptimize all\nbackground 0");
    for (group, (r, g, b)) in [(1, (15, 2, 2)), (2, (15, 13, 1)), (3, (2, 12, 4)), (4, (3, 6, 15)), (5, (15, 8, 11)), (6, (13, 13, 13))] {
        let _ = writeln!(text, "group {group} {r} {g} {b} up");
    }
    let mut state: u32 = 0x2545_F491;
    let mut next = || {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state
    };
    let side = side as usize;
    for index in 0..count {
        let (row, column) = (index / side, index % side);
        let radius = 0.35 + f64::from(next() % 1000) / 1000.0 * 0.6;
        let x = -(side as f64) + 1.0 + 2.0 * column as f64;
        let z = -1.0 - 2.0 * row as f64;
        let _ = writeln!(text, "sphere\n  scale {radius:.3} {radius:.3} {radius:.3}\n  translate {x} {radius:.3} {z}\n  colour {}", 1 + next() % 6);
    }
    text
}

#[cfg(test)]
mod tests {
    use super::sphere_field;

    #[test]
    fn the_field_parses_with_every_sphere() {
        for count in [1, 2, 10, 1_000] {
            let text = sphere_field(count, 64, 48);
            let scene = microtrace::parser::parse_into_list::<crate::heap::Growing<_>>(text.as_bytes()).unwrap();
            assert_eq!(scene.objects.len(), count);
            assert_eq!(scene.viewport.width(), 64);
        }
    }
}
