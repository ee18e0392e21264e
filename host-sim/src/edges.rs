//! The edge image (`microtrace render --edges`): Roth's second use of ray classification
//! (thesis §3.3; digest §10): for each pixel the first surface its primary ray meets, and a line
//! where it differs from the left or the upper neighbour's: a vertical line at x − ½ when it
//! differs from pixel (x − 1, y), a horizontal one at y − ½ when it differs from (x, y − 1),
//! drawn on the pixel itself. The background counts as a surface of its own; a solid's surfaces
//! are its operands' (a die's pips are edged apart from its faces).

use microtrace::model::SceneError;
use microtrace::number::{Number, NumberKind};
use microtrace::render::{nearest_hit, Statistics};
use microtrace::with_number_kind;

use crate::rendering::prepare_host;
use crate::scene_file::HostScene;

/// A surface: the object hit, and for a solid the operand (its leaf's place in the solid).
pub type Surface = (usize, u16);

/// The first surface of each pixel's primary ray (`None`: the background), rows top first.
pub fn first_surfaces(scene: &HostScene, number: NumberKind) -> Result<Vec<Option<Surface>>, SceneError> {
    with_number_kind!(number, N => first_surfaces_in::<N>(scene))
}

fn first_surfaces_in<N: Number>(scene: &HostScene) -> Result<Vec<Option<Surface>>, SceneError> {
    let prepared = prepare_host::<N>(scene)?;
    let (width, height) = (scene.viewport.width(), scene.viewport.height());
    let mut statistics = Statistics::default();
    let mut surfaces = Vec::with_capacity(usize::from(width) * usize::from(height));
    for row in 0..height {
        for column in 0..width {
            let pixel = prepared.camera.pixel(column, row);
            let surface = prepared.camera.primary_ray(pixel).and_then(|ray| nearest_hit(&prepared, &ray, pixel, &mut statistics)).map(|hit| (hit.object, hit.leaf));
            surfaces.push(surface);
        }
    }
    Ok(surfaces)
}

/// Which pixels are on an edge: their first surface differs from the left or the upper
/// neighbour's.
pub fn edges(surfaces: &[Option<Surface>], width: usize) -> Vec<bool> {
    (0..surfaces.len())
        .map(|index| {
            let (column, here) = (index % width.max(1), surfaces[index]);
            let left = column > 0 && surfaces[index - 1] != here;
            let up = index >= width && surfaces[index - width] != here;
            left || up
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_where_the_surface_changes_from_the_left_or_above() {
        // 4 x 3: object 0 in the two middle columns of the lower two rows.
        let o = Some((0, 0));
        let surfaces = [None, None, None, None, None, o, o, None, None, o, o, None];
        let lines: Vec<bool> = edges(&surfaces, 4);
        #[rustfmt::skip]
        let expected = [
            false, false, false, false,
            false, true,  true,  true,
            false, true,  false, true,
        ];
        assert_eq!(lines, expected);
        // Two operands of one solid are two surfaces.
        let surfaces = [Some((0, 0)), Some((0, 2)), Some((0, 2)), Some((1, 0))];
        assert_eq!(edges(&surfaces, 4), [false, true, false, true]);
    }
}
