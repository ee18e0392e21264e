//! The plan view (thesis figures 4.14b and 4.15b): each object's bounding volume seen from
//! above, on the x–z plane, with the eye and the rays through the window's left and right
//! edges. The volumes, the view and Sortlist's depth ranges all come from the core's
//! optimizations (`ObjectGeometry`, `Screen`, `sortlist::depth_bound`), not a copy of them.

use embedded_graphics::draw_target::DrawTargetExt;
use embedded_graphics::mono_font::ascii::FONT_6X10;
use embedded_graphics::mono_font::MonoTextStyle;
use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Circle, Line, PrimitiveStyle, Rectangle};
use embedded_graphics::text::{Baseline, Text};
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::number::Number;
use microtrace::optimize::bounding_volume::ObjectGeometry;
use microtrace::optimize::bounding_volume::View;
use microtrace::optimize::projection::Polygon;
use microtrace::optimize::{sortlist, window_corners};
use microtrace::config::Config;
use microtrace::storage::Index;
use microtrace::scene::Prepared;

use super::colours::object_colour;

/// The size of the plan's drawing area in the window.
pub const WIDTH: u32 = 256;
pub const HEIGHT: u32 = 232;

/// One object seen from above.
#[derive(Clone, Debug)]
pub struct PlanObject {
    /// The object's number in the scene (from 0).
    pub object: usize,
    /// The outline of its bounding volume from above: the convex hull of the (x, z) of the
    /// volume's 8 vertices.
    pub footprint: Vec<[f64; 2]>,
    /// Sortlist's range of the ray parameter `t` over the volume: the near bound it sorts by
    /// and the far bound; `None` when the core knows no bound.
    pub depth: Option<(f64, f64)>,
}

/// Where the primary rays come from, in (x, z).
#[derive(Clone, Copy, Debug)]
pub enum Rays {
    Perspective { eye: [f64; 2] },
    Parallel { direction: [f64; 2] },
}

#[derive(Clone, Debug)]
pub struct PlanView {
    pub objects: Vec<PlanObject>,
    /// The order Sortlist tests the objects in (by near bound); object order without a bound.
    pub order: Vec<usize>,
    pub rays: Rays,
    /// The (x, z) of the window's left and right edges on the view plane.
    pub window: [[f64; 2]; 2],
}

impl PlanView {
    /// The plan of a prepared scene, from the geometry the tracer renders (as the core's fill
    /// and extents take it).
    pub fn of<N: Number, C: Config<Number = N>>(scene: &Prepared<C>) -> Self {
        let screen = scene.acceleration.screen();
        let corners = window_corners(screen, &scene.camera);
        let objects: Vec<PlanObject> = scene
            .objects
            .iter()
            .enumerate()
            .map(|(object, description)| {
                let Some(geometry) = ObjectGeometry::new(description.primitive, &description.object_from_world) else {
                    return PlanObject { object, footprint: Vec::new(), depth: None };
                };
                let mut points = geometry.volume().map(|[x, _, z]| [x, z]);
                let footprint = Polygon::hull(&mut points).vertices().to_vec();
                // The near end as the render uses it (in the number type); the far end, which
                // nothing uses, from the f64 volume.
                let near = scene.acceleration.near_bound(object).map(Number::to_f64).or_else(|| sortlist::depth_bound(screen, &corners, &geometry));
                let far = sortlist::far_depth_bound(screen, &geometry);
                PlanObject { object, footprint, depth: near.zip(far) }
            })
            .collect();
        let order = if scene.acceleration.optimizations().sortlist {
            scene.acceleration.order().iter().map(|object| object.get()).collect()
        } else {
            let mut order: Vec<C::Index> = (0..objects.len()).map(C::Index::new).collect();
            let near = |index: usize| objects[index].depth.map_or(f64::NEG_INFINITY, |(near, _)| near);
            sortlist::sort_by_bound::<C, _>(&mut order, near);
            order.into_iter().map(|object| object.get()).collect()
        };
        let rays = match screen.view {
            View::Perspective { eye } => Rays::Perspective { eye: [eye[0], eye[2]] },
            View::Parallel { direction } => Rays::Parallel { direction: [direction[0], direction[2]] },
        };
        let window = [[corners[0][0], corners[0][2]], [corners[1][0], corners[1][2]]];
        Self { objects, order, rays, window }
    }
}

/// From (x, z) to the window: one scale for both axes, x to the right and z down the page
/// (seen from above with y up, so a viewer looking along −z looks up the page).
struct Mapping {
    low: [f64; 2],
    scale: f64,
    origin: Point,
}

impl Mapping {
    fn fit(points: impl Iterator<Item = [f64; 2]>, area: Rectangle) -> Self {
        let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for point in points.filter(|p| p[0].is_finite() && p[1].is_finite()) {
            for k in 0..2 {
                low[k] = low[k].min(point[k]);
                high[k] = high[k].max(point[k]);
            }
        }
        if low[0] > high[0] {
            (low, high) = ([0.0; 2], [1.0; 2]);
        }
        let margin = 6.0;
        let span = [(high[0] - low[0]).max(1e-9), (high[1] - low[1]).max(1e-9)];
        let scale = ((f64::from(area.size.width) - 2.0 * margin) / span[0]).min((f64::from(area.size.height) - 2.0 * margin) / span[1]);
        // Centre the drawing in the area.
        let used = [span[0] * scale, span[1] * scale];
        let origin = area.top_left
            + Point::new(((f64::from(area.size.width) - used[0]) / 2.0) as i32, ((f64::from(area.size.height) - used[1]) / 2.0) as i32);
        Self { low, scale, origin }
    }

    fn at(&self, point: [f64; 2]) -> Point {
        let x = (point[0] - self.low[0]) * self.scale;
        let z = (point[1] - self.low[1]) * self.scale;
        self.origin + Point::new(x.round().clamp(-1e5, 1e5) as i32, z.round().clamp(-1e5, 1e5) as i32)
    }
}

/// Draws the plan in `area`: a frame, the rays' wedge, the eye and every footprint.
pub fn draw(plan: &PlanView, target: &mut SimulatorDisplay<Rgb888>, area: Rectangle) {
    let _ = area.into_styled(PrimitiveStyle::with_stroke(Rgb888::new(90, 90, 90), 1)).draw(target);
    let footprints = plan.objects.iter().flat_map(|object| object.footprint.iter().copied());
    let eye = match plan.rays {
        Rays::Perspective { eye } => Some(eye),
        Rays::Parallel { .. } => None,
    };
    let mapping = Mapping::fit(footprints.chain(eye).chain(plan.window), area);
    let mut clipped = target.clipped(&area.offset(-1));
    draw_rays(plan, &mapping, &mut clipped, area);
    for object in &plan.objects {
        let colour = object_colour(object.object);
        let points = &object.footprint;
        for (i, &from) in points.iter().enumerate() {
            let to = points[(i + 1) % points.len()];
            let _ = Line::new(mapping.at(from), mapping.at(to)).into_styled(PrimitiveStyle::with_stroke(colour, 1)).draw(&mut clipped);
        }
    }
    let label = MonoTextStyle::new(&FONT_6X10, Rgb888::new(230, 230, 230));
    if let Some(eye) = eye {
        let at = mapping.at(eye);
        let _ = Circle::with_center(at, 5).into_styled(PrimitiveStyle::with_fill(Rgb888::WHITE)).draw(&mut clipped);
        let _ = Text::with_baseline("eye", at + Point::new(5, -4), label, Baseline::Top).draw(&mut clipped);
    }
    let axes = MonoTextStyle::new(&FONT_6X10, Rgb888::new(150, 150, 150));
    let corner = area.top_left + Point::new(3, area.size.height as i32 - 12);
    let _ = Text::with_baseline("x>  z v", corner, axes, Baseline::Top).draw(&mut clipped);
}

/// The rays through the window's left and right edges (from the eye, or along the parallel
/// direction), drawn to the edge of the plan.
fn draw_rays<D: DrawTarget<Color = Rgb888>>(plan: &PlanView, mapping: &Mapping, target: &mut D, area: Rectangle) {
    let reach = f64::from(area.size.width + area.size.height) / mapping.scale;
    let grey = PrimitiveStyle::with_stroke(Rgb888::new(110, 110, 110), 1);
    let window = plan.window;
    for edge in window {
        let (start, direction) = match plan.rays {
            Rays::Perspective { eye } => (eye, [edge[0] - eye[0], edge[1] - eye[1]]),
            Rays::Parallel { direction } => (edge, direction),
        };
        let length = direction[0].hypot(direction[1]);
        if !length.is_normal() {
            continue;
        }
        let end = [start[0] + direction[0] / length * reach, start[1] + direction[1] / length * reach];
        let _ = Line::new(mapping.at(start), mapping.at(end)).into_styled(grey).draw(target);
    }
    // The view plane's window itself.
    let _ = Line::new(mapping.at(window[0]), mapping.at(window[1])).into_styled(PrimitiveStyle::with_stroke(Rgb888::new(200, 200, 200), 1)).draw(target);
}

#[cfg(test)]
mod tests {
    use embedded_graphics::pixelcolor::Rgb888;
    use embedded_graphics::prelude::*;
    use embedded_graphics::primitives::Rectangle;
    use embedded_graphics_simulator::SimulatorDisplay;

    use super::super::colours::object_colour;
    use super::super::test_scenes::prepared;
    use super::{draw, PlanView, Rays};

    fn inside(polygon: &[[f64; 2]], point: [f64; 2]) -> bool {
        let cross = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]) * (point[1] - a[1]) - (b[1] - a[1]) * (point[0] - a[0]);
        let signs: Vec<f64> = (0..polygon.len()).map(|i| cross(polygon[i], polygon[(i + 1) % polygon.len()])).collect();
        signs.iter().all(|s| *s >= 0.0) || signs.iter().all(|s| *s <= 0.0)
    }

    /// Each snooker ball's footprint is its bounding box from above (a square around its
    /// centre, as wide as the ball), and its depth range holds the ball's nearest and farthest
    /// points from the eye; Sortlist's order is by near bound.
    #[test]
    fn snooker_footprints_and_depth_ranges_bound_the_balls() {
        let (description, scene) = prepared("snooker");
        let plan = PlanView::of(&*scene);
        assert_eq!(plan.objects.len(), 21);
        let Rays::Perspective { eye } = plan.rays else { panic!("snooker is a perspective view") };
        assert_eq!(eye, [0.0, 1380.0]);
        for (object, description) in plan.objects.iter().zip(&description.objects) {
            let rows = &description.world_from_object.rows;
            let centre = [rows[3][0], rows[3][1], rows[3][2]];
            let radius = (rows[0][0] * rows[0][0] + rows[0][1] * rows[0][1] + rows[0][2] * rows[0][2]).sqrt();
            assert_eq!(object.footprint.len(), 4, "object {}: a box seen from above", object.object);
            assert!(inside(&object.footprint, [centre[0], centre[2]]), "object {}", object.object);
            let xs = object.footprint.iter().map(|p| p[0]);
            let width = xs.clone().fold(f64::NEG_INFINITY, f64::max) - xs.fold(f64::INFINITY, f64::min);
            assert!((width - 2.0 * radius).abs() < 1e-6 * radius, "object {}: footprint {width} wide", object.object);
            let eye3 = [0.0, 220.0, 1380.0];
            let distance = (0..3).map(|k| (centre[k] - eye3[k]).powi(2)).sum::<f64>().sqrt();
            let (near, far) = object.depth.expect("a depth range");
            assert!(near <= distance - radius && far >= distance + radius, "object {}: {near}..{far} vs {distance}±{radius}", object.object);
            assert!(near > distance - radius - 2e-3 * distance && far < distance + 2.0 * radius, "object {}: range too loose: {near}..{far} vs {distance}±{radius}", object.object);
        }
        let nears: Vec<f64> = plan.order.iter().map(|&o| plan.objects[o].depth.unwrap().0).collect();
        assert!(nears.windows(2).all(|pair| pair[0] <= pair[1]), "Sortlist order by near bound: {nears:?}");
    }

    /// Every object of the lattice shows in the plan in its own colour (unless a later object
    /// has the same footprint: the three tiers lie exactly above each other, as the thesis
    /// notes for figure 4.15b), and nothing is drawn outside the plan's area.
    #[test]
    fn the_plan_draws_every_object_within_its_area() {
        let (_, scene) = prepared("lattice");
        let plan = PlanView::of(&*scene);
        let mut display = SimulatorDisplay::<Rgb888>::new(Size::new(300, 260));
        let area = Rectangle::new(Point::new(20, 10), Size::new(super::WIDTH, super::HEIGHT));
        draw(&plan, &mut display, area);
        let lit = |point: Point| display.get_pixel(point) != Rgb888::BLACK;
        let outside = display.bounding_box().points().filter(|p| !area.contains(*p)).filter(|p| lit(*p)).count();
        assert_eq!(outside, 0, "pixels drawn outside the plan's area");
        let same = |a: &[[f64; 2]], b: &[[f64; 2]]| a.len() == b.len() && a.iter().zip(b).all(|(p, q)| (p[0] - q[0]).abs() + (p[1] - q[1]).abs() < 1e-6);
        let mut seen = 0;
        for (object, drawn) in plan.objects.iter().enumerate() {
            if plan.objects[object + 1..].iter().any(|later| same(&later.footprint, &drawn.footprint)) {
                continue;
            }
            let colour = object_colour(object);
            assert!(area.points().any(|p| display.get_pixel(p) == colour), "object {object}'s colour is not in the plan");
            seen += 1;
        }
        // 9 spheres and 9 rods along y seen from above, 3 rods each along x and along z.
        assert_eq!(seen, 24, "objects with a footprint of their own");
    }
}
