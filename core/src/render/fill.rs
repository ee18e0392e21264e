//! Pixelbuffer's fill (§4.7.2, `initpga` and `rendervolume`): the marks that tell the image
//! loop which pixels no object can cover.

use core::ops::Range;

use crate::number::Number;
use crate::optimize::bounding_volume::ObjectGeometry;
use crate::optimize::extents::Extent;
use crate::optimize::pixelbuffer::hull_span;
use crate::optimize::projection::Projected;
use crate::pixel::PixelSink;
use crate::config::Config;
use crate::scene::Prepared;

/// Pixelbuffer's fill colour in PGA mode (the thesis's default `fillcolor`); the flood is its
/// complement, so the two always differ.
pub const PGA_FILL: u8 = 112;
/// PGA mode's flood: the fill's complement.
pub const PGA_FLOOD: u8 = PGA_FILL ^ 0xFF;
/// Pixelbuffer's fill colour in RGB mode; the flood is its complement.
pub const RGB_FILL: [u8; 3] = [112, 0, 255];
/// RGB mode's flood: the fill's complement.
pub const RGB_FLOOD: [u8; 3] = [RGB_FILL[0] ^ 0xFF, RGB_FILL[1] ^ 0xFF, RGB_FILL[2] ^ 0xFF];

/// Pixelbuffer's preprocess (`initpga` and `rendervolume`): flood the viewport, then fill
/// every object's extent octagon (its silhouette's rectangle cut by the two diagonal ranges,
/// computed when the scene was prepared), row span by row span, in integer arithmetic. With
/// the thesis's tuning, the thesis's fill: each 8-vertex volume projected and scan-converted. Public so a viewer can
/// record which pixels the fill marks (into a sink of its own, with its own two values).
pub fn fill_volumes<N, P, S, C: Config<Number = N>>(scene: &Prepared<C>, sink: &mut S, fill: P, flood: P)
where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
{
    fill_volumes_rows(scene, sink, fill, flood, 0..scene.acceleration.screen().height)
}

/// [`fill_volumes`] within the image rows `rows` only.
pub fn fill_volumes_rows<N, P, S, C: Config<Number = N>>(scene: &Prepared<C>, sink: &mut S, fill: P, flood: P, rows: Range<u16>)
where
    N: Number,
    P: Copy,
    S: PixelSink<P>,
{
    let screen = scene.acceleration.screen();
    let width = screen.width;
    let rows = rows.start..rows.end.min(screen.height);
    if rows.is_empty() {
        return;
    }
    for row in rows.clone() {
        sink.mark_row(0, row, width, flood);
    }
    let acceleration = &scene.acceleration;
    if acceleration.tuning().tight_silhouettes || !crate::optimize::SILHOUETTES {
        // Each object's extent octagon, prepared with the other optimizations: integer spans,
        // no projection per frame.
        for index in 0..scene.objects.len() {
            let Some(extent) = acceleration.extent(index) else { continue };
            // Rows outside the extent first: the streamed render fills one row at a time, and
            // most objects miss it.
            if extent.last_row < rows.start || extent.first_row >= rows.end {
                continue;
            }
            let stadium = acceleration.stadium(index);
            for row in rows.clone() {
                let Some(span) = extent.row_span(row, screen.height) else { continue };
                // Narrowed by the silhouette's stadium: a thin oblique rod fills a band along it.
                let span = match stadium {
                    Some(stadium) => match stadium.block(span, (row, row)) {
                        Some((columns, _)) => columns,
                        None => continue,
                    },
                    None => span,
                };
                sink.mark_row(span.0, row, span.1 - span.0 + 1, fill);
            }
        }
        return;
    }
    // The thesis's fill: each object's 8-vertex volume projected and scan-converted.
    for object in scene.objects.iter() {
        let projected = match ObjectGeometry::new(object.primitive, &object.object_from_world) {
            Some(geometry) => screen.project_object(&geometry, false),
            None => Projected::Whole,
        };
        let points = match projected {
            Projected::Points(points) => points,
            Projected::Invisible => continue,
            Projected::Whole => {
                // No projection (the eye in or at the volume, or rays along the view plane): all.
                for row in rows.clone() {
                    sink.mark_row(0, row, width, fill);
                }
                continue;
            }
        };
        let extent = Extent::of(screen, &projected);
        if extent.is_empty() {
            continue;
        }
        for row in extent.first_row.max(rows.start)..=extent.last_row.min(rows.end - 1) {
            if let Some((first, last)) = hull_span(&points, row, width) {
                sink.mark_row(first, row, last - first + 1, fill);
            }
        }
    }
}
