//! The thesis scenes, prepared small, for the view's unit tests.

use std::path::Path;

use microtrace::scene::Scene;

use crate::scene_file::{self, HostScene, HOST_MAX_OBJECTS};

/// `scenes/NAME.mts` fitted to 132x120: the description and the scene prepared in `f64`.
pub fn prepared(name: &str) -> (Box<HostScene>, Box<Scene<f64, HOST_MAX_OBJECTS>>) {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../scenes").join(format!("{name}.mts"));
    let mut description = scene_file::load(&path).expect("thesis scene loads");
    description.fit_to_size(132, 120);
    let scene = Box::new(Scene::prepare(&*description).expect("thesis scene prepares"));
    (description, scene)
}
