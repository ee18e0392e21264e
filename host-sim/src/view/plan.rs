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
use microtrace::optimize::projection::{Polygon, View};
use microtrace::optimize::{sortlist, window_corners};
use microtrace::scene::Scene;

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
    pub order: Vec<u16>,
    pub rays: Rays,
    /// The (x, z) of the window's left and right edges on the view plane.
    pub window: [[f64; 2]; 2],
}

impl PlanView {
    /// The plan of a prepared scene, from the geometry the tracer renders (as the core's fill
    /// and extents take it).
    pub fn of<N: Number, const MAX_OBJECTS: usize>(scene: &Scene<N, MAX_OBJECTS>) -> Self {
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
                let near = sortlist::depth_bound(screen, &corners, &geometry);
                let far = sortlist::far_depth_bound(screen, &geometry);
                PlanObject { object, footprint, depth: near.zip(far) }
            })
            .collect();
        let order = if scene.acceleration.optimizations().sortlist {
            scene.acceleration.order().to_vec()
        } else {
            let mut order: Vec<u16> = (0..objects.len() as u16).collect();
            let near = |index: usize| objects[index].depth.map_or(f64::NEG_INFINITY, |(near, _)| near);
            sortlist::sort_by_bound(&mut order, near);
            order
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
