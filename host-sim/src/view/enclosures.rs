//! The overlay's enclosure trees (thesis §3.3.6, fig 3.6): for each solid, the screen box of
//! every node of its tree, as `model::for_each_node_box` combines the boxes (∪ the union, ∩
//! the overlap, − the left operand's): the operations' boxes drawn solid, the operands' dotted,
//! in the solid's colour. The solid's own box is the one the optimizations use.

use embedded_graphics::pixelcolor::Rgb888;
use embedded_graphics::prelude::*;
use embedded_graphics::primitives::{Primitive as _, PrimitiveStyle, Rectangle};
use embedded_graphics_simulator::SimulatorDisplay;
use microtrace::camera::Camera;
use microtrace::model::{for_each_node_box, Primitive};
use microtrace::number::Number;
use microtrace::optimize::projection::Screen;

use super::colours::object_colour;
use crate::scene_file::HostScene;

/// One node's box on the screen, in image pixels (columns and rows, first and last).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeBox {
    /// The solid's number in the scene, for its colour.
    pub object: usize,
    /// An operand (a primitive), not an operation.
    pub leaf: bool,
    pub columns: (i32, i32),
    pub rows: (i32, i32),
}

/// The boxes of every solid's nodes seen by `camera`, in its samples (`step` samples a pixel
/// side with antialiasing); a node partly behind the eye is left out.
pub fn enclosure_trees<N: Number>(scene: &HostScene, camera: &Camera<N>, step: u16) -> Vec<NodeBox> {
    let screen = Screen::new(camera);
    let step = f64::from(step.max(1));
    // Boxes reaching past the image are drawn to just outside it.
    let (width, height) = (f64::from(camera.width()) / step, f64::from(camera.height()) / step);
    let mut boxes = Vec::new();
    for (object, description) in scene.objects.iter().enumerate() {
        let Primitive::Solid(range) = description.primitive else { continue };
        let Some(nodes) = scene.solids.get(range.nodes()) else { continue };
        for_each_node_box(nodes, |leaf, [low, high]| {
            let corners = (0..8).map(|corner: usize| std::array::from_fn(|axis| if corner >> axis & 1 == 0 { low[axis] } else { high[axis] }));
            let projected: Option<Vec<[f64; 2]>> = corners.map(|corner| screen.project(corner).map(|point| screen.to_image(point))).collect();
            let Some(points) = projected else { return };
            let (mut first, mut last) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
            for point in &points {
                for axis in 0..2 {
                    first[axis] = first[axis].min(point[axis] / step);
                    last[axis] = last[axis].max(point[axis] / step);
                }
            }
            let pixel = |value: f64, size: f64| value.round().clamp(-1.0, size) as i32;
            boxes.push(NodeBox {
                object,
                leaf,
                columns: (pixel(first[0], width), pixel(last[0], width)),
                rows: (pixel(first[1], height), pixel(last[1], height)),
            });
        });
    }
    boxes
}

/// Draws the boxes: operations solid, operands dotted.
pub fn draw(boxes: &[NodeBox], target: &mut SimulatorDisplay<Rgb888>) {
    for node in boxes {
        let colour = object_colour(node.object);
        let (left, right, top, bottom) = (node.columns.0, node.columns.1, node.rows.0, node.rows.1);
        if node.leaf {
            let horizontal = (left..=right).step_by(3).flat_map(|x| [Point::new(x, top), Point::new(x, bottom)]);
            let vertical = (top..=bottom).step_by(3).flat_map(|y| [Point::new(left, y), Point::new(right, y)]);
            let _ = target.draw_iter(horizontal.chain(vertical).map(|point| Pixel(point, colour)));
        } else {
            let size = Size::new((right - left + 1).max(1) as u32, (bottom - top + 1).max(1) as u32);
            let _ = Rectangle::new(Point::new(left, top), size).into_styled(PrimitiveStyle::with_stroke(colour, 1)).draw(target);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rendering::prepare_host;

    /// The die's tree: a box for each of its 15 nodes; the whole solid's (a difference: its
    /// left operand's, the rounded cube) inside the screen extent the optimizations use, the
    /// pips' boxes inside it.
    #[test]
    fn every_node_of_a_solid_has_its_box_and_the_tree_nests() {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes/csg/die.mts");
        let scene = crate::scene_file::load(&path).unwrap();
        let prepared = prepare_host::<f64>(&scene).unwrap();
        let boxes = enclosure_trees(&scene, &prepared.camera, 1);
        let Primitive::Solid(range) = scene.objects[1].primitive else { panic!("the die is the second object") };
        assert_eq!(boxes.len(), usize::from(range.count));
        assert_eq!(boxes.iter().filter(|node| node.leaf).count(), 8);
        let root = *boxes.last().unwrap();
        assert!(!root.leaf && root.object == 1);
        let extent = prepared.acceleration.extent(1).unwrap();
        assert!(i32::from(extent.first_column) <= root.columns.0 + 1 && root.columns.1 <= i32::from(extent.last_column) + 1, "{root:?} against {extent:?}");
        assert!(i32::from(extent.first_row) <= root.rows.0 + 1 && root.rows.1 <= i32::from(extent.last_row) + 1, "{root:?} against {extent:?}");
        for pip in &boxes[boxes.len() - 8..boxes.len() - 1] {
            if pip.leaf {
                assert!(pip.columns.0 >= root.columns.0 - 1 && pip.columns.1 <= root.columns.1 + 1, "{pip:?} outside {root:?}");
            }
        }
    }
}
