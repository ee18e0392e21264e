//! The thesis scenes, prepared small, for the view's unit tests.

use std::path::Path;


use crate::scene_file::{self, HostScene};
use crate::heap::HostPrepared;

/// `scenes/NAME.mts` fitted to 132x120: the description and the scene prepared in `f64`.
pub fn prepared(name: &str) -> (Box<HostScene>, Box<HostPrepared<f64>>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes").join(format!("{name}.mts"));
    let mut description = scene_file::load(&path).expect("thesis scene loads");
    description.fit_to_size(132, 120);
    let scene = Box::new(HostPrepared::prepare(&*description).expect("thesis scene prepares"));
    (description, scene)
}
