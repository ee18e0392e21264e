//! `microtrace volume SCENE.mts [--size N]`: each top-level object's volume by ray casting, the
//! third use of Roth's ray classification (thesis §3.3; digest §10: in a parallel view the volume
//! is Σ H·V·(t₂ − t₁ + t₄ − t₃ + …)·|d|). Parallel rays along −z through the centres of an N x N
//! grid over the object's box; each ray's spans inside the object (`csg::leaf_spans`, in its
//! object space: an affine map keeps the ray's parameter, so span lengths are world lengths
//! along a unit direction; for a solid, its operands' spans combined up its tree,
//! `csg::solid_spans`) times the cell's area, summed.
//!
//! The error the pixel size implies: the sum over the cells of the cell's area times half the
//! largest change of the depth inside the object to a neighbouring cell's (the depth along a
//! cell is not constant, and the middle ray stands for it). An estimate of the discretisation
//! error, not a proof: the tests check that the true volumes of the unit primitives lie within
//! it and that it shrinks as N grows.

use std::path::PathBuf;

use anyhow::Context;
use microtrace::geometry::{AffineTransform, Ray, Vector3};
use microtrace::csg::{solid_spans, Span};
use microtrace::model::{ObjectDescription, PreparedSolidNode, Primitive};
use microtrace::optimize::bounding_volume::unit_volume;

use crate::rendering::prepare_host;
use crate::scene_file;

#[derive(clap::Args, Clone, Debug)]
pub struct VolumeArgs {
    /// The scene.
    pub scene: PathBuf,
    /// Rays across each object's box: N x N (default 256).
    #[arg(long, value_name = "N", default_value_t = 256, value_parser = clap::value_parser!(u32).range(1..=8192))]
    pub size: u32,
}

/// An object's volume by ray casting and the error the grid implies.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Volume {
    pub volume: f64,
    pub error: f64,
}

pub fn run(args: VolumeArgs) -> anyhow::Result<()> {
    let scene = scene_file::load(&args.scene)?;
    if scene.objects.is_empty() {
        anyhow::bail!("{}: the scene has no objects", args.scene.display());
    }
    // Solids' operands as the render has them (in f64).
    let prepared = prepare_host::<f64>(&scene).map_err(|error| scene_file::in_file(&args.scene, error.into()))?;
    for (index, object) in scene.objects.iter().enumerate() {
        let volume = object_volume(object, prepared.solid(object.primitive), args.size).with_context(|| format!("{}:line {}: the object's volume", args.scene.display(), object.line))?;
        println!(
            "object {} ({}, line {}): volume {:.6e} ± {:.2e} ({} x {} rays)",
            index + 1,
            object.primitive.name(),
            object.line,
            volume.volume,
            volume.error,
            args.size,
            args.size
        );
    }
    Ok(())
}

/// The volume of one object in world units, by `size` x `size` parallel rays along −z; a solid's
/// `nodes` are its operands prepared in `f64` (empty for a primitive).
pub fn object_volume(object: &ObjectDescription, nodes: &[PreparedSolidNode<f64>], size: u32) -> anyhow::Result<Volume> {
    let corners = unit_volume(object.primitive).map(|corner| object.world_from_object.transform_point(corner));
    let low = [0, 1, 2].map(|axis| corners.iter().map(|c| c[axis]).fold(f64::INFINITY, f64::min));
    let high = [0, 1, 2].map(|axis| corners.iter().map(|c| c[axis]).fold(f64::NEG_INFINITY, f64::max));
    let inverse = object.world_from_object.affine_inverse().context("the transform cannot be inverted")?;
    let object_from_world = AffineTransform::<f64>::from_matrix(&inverse);
    let n = size as usize;
    let (width, height) = ((high[0] - low[0]) / f64::from(size), (high[1] - low[1]) / f64::from(size));
    let start_z = high[2] + 1.0;
    // The depth inside the object along each cell's middle ray.
    let mut depths = vec![0.0f64; n * n];
    for row in 0..n {
        for column in 0..n {
            let x = low[0] + (column as f64 + 0.5) * width;
            let y = low[1] + (row as f64 + 0.5) * height;
            let world = Ray { origin: Vector3::new(x, y, start_z), direction: Vector3::new(0.0, 0.0, -1.0) };
            let depth = |spans: &[Span<f64>]| spans.iter().map(|span| span.exit.t - span.enter.t).sum();
            depths[row * n + column] = match object.primitive {
                Primitive::Solid(_) => solid_spans::<_, crate::heap::Growing<PreparedSolidNode<f64>>, _>(nodes, &world, |_| false, &mut 0, depth).context("the solid's spans overflow their capacity")?,
                primitive => depth(
                    microtrace::csg::leaf_spans(primitive, &object_from_world.ray(&world), 0)
                        .map_err(|overflow| anyhow::anyhow!("more than {} spans along a ray", overflow.capacity))?
                        .as_slice(),
                ),
            };
        }
    }
    let area = width * height;
    let volume = depths.iter().sum::<f64>() * area;
    let mut error = 0.0;
    for row in 0..n {
        for column in 0..n {
            let here = depths[row * n + column];
            let mut change: f64 = 0.0;
            for (dr, dc) in [(0i64, 1i64), (0, -1), (1, 0), (-1, 0)] {
                let (r, c) = (row as i64 + dr, column as i64 + dc);
                // Beyond the grid the object is absent.
                let there = if r < 0 || c < 0 || r >= n as i64 || c >= n as i64 { 0.0 } else { depths[r as usize * n + c as usize] };
                change = change.max((here - there).abs());
            }
            error += area * change / 2.0;
        }
    }
    Ok(Volume { volume, error })
}

#[cfg(test)]
mod tests {
    use super::*;
    use microtrace::geometry::Matrix4;
    use microtrace::model::{Primitive, Tube};

    fn object(primitive: Primitive, scale: [f64; 3]) -> ObjectDescription {
        let mut object = ObjectDescription::new(primitive, 1);
        let mut m = Matrix4::IDENTITY;
        m.scale(scale);
        m.rotate(0, 30.0);
        m.rotate(1, 20.0);
        m.translate([5.0, -3.0, 2.0]);
        object.world_from_object = m;
        object
    }

    /// The analytic volume lies within the estimate, and both the error and the estimate shrink
    /// as the grid grows (`what` names the object in a failure; `nodes`: a solid's).
    fn converges_with(what: &str, object: &ObjectDescription, nodes: &[PreparedSolidNode<f64>], exact: f64) {
        let coarse = object_volume(object, nodes, 64).unwrap();
        let fine = object_volume(object, nodes, 256).unwrap();
        for (n, v) in [(64, coarse), (256, fine)] {
            assert!((v.volume - exact).abs() <= v.error, "{what} at {n}: {} ± {} against {exact}", v.volume, v.error);
        }
        assert!(fine.error < coarse.error / 2.0, "{what}: ± {} at 64, ± {} at 256", coarse.error, fine.error);
        assert!((fine.volume - exact).abs() < exact * 0.01, "{what}: {} against {exact}", fine.volume);
    }

    fn converges(primitive: Primitive, scale: [f64; 3], exact: f64) {
        converges_with(&format!("{primitive:?}"), &object(primitive, scale), &[], exact);
    }

    #[test]
    fn the_unit_primitives_volumes_converge() {
        use std::f64::consts::PI;
        converges(Primitive::Cube, [2.0, 3.0, 4.0], 24.0);
        converges(Primitive::Sphere, [2.0, 2.0, 2.0], 4.0 / 3.0 * PI * 8.0);
        converges(Primitive::Cylinder, [1.5, 1.5, 2.0], PI * 1.5 * 1.5 * 2.0);
        converges(Primitive::Cone, [1.0, 1.0, 3.0], PI * 3.0 / 3.0);
        // A torus: 2π² R r², scaled by 2 in every direction (8 times the volume).
        converges(Primitive::Torus(Tube::QUARTER), [2.0, 2.0, 2.0], 2.0 * PI * PI * 0.0625 * 8.0);
    }

    /// A solid's volume, as its scene describes it, converges like a primitive's.
    fn solid_converges(text: &str, exact: f64) {
        let scene: crate::scene_file::HostScene = microtrace::parser::parse_into_list(text.as_bytes()).unwrap();
        let prepared = prepare_host::<f64>(&scene).unwrap();
        let object = &scene.objects[0];
        converges_with(text, object, prepared.solid(object.primitive), exact);
    }

    #[test]
    fn solids_volumes_converge() {
        use std::f64::consts::PI;
        // A lens: two unit spheres one apart, π(4r + d)(2r − d)²/12, turned so no axis helps.
        solid_converges("intersection\n sphere\n sphere\n  translate 0 0 1\nend\n rotate x 30\n rotate y 20\n", 5.0 * PI / 12.0);
        // A cube of 2 drilled through by a cylinder of radius 0.5: 8 − π/2.
        solid_converges("difference\n cube\n  scale 2 2 2\n cylinder\n  scale 0.5 0.5 4\n  translate 1 1 -1\nend\n rotate x 25\n", 8.0 - PI / 2.0);
        // A union counts the overlap once: two unit cubes overlapping by half, 1.5.
        solid_converges("union\n cube\n cube\n  translate 0.5 0 0\nend\n rotate z 10\n", 1.5);
    }
}
