//! TODO
// TEMPORARY lead-engineer stub until the parser lands.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError { pub line: u32, pub kind: SceneErrorKind }
#[derive(Debug, Clone, PartialEq)]
pub enum SceneErrorKind { PrimitiveNotCompiled { primitive: &'static str }, SingularTransform, TooManyObjects { capacity: usize }, ZeroDirection }
