//! TODO
// TEMPORARY lead-engineer stub until the parser lands.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneError { pub line: u32, pub kind: SceneErrorKind }
#[derive(Debug, Clone, PartialEq)]
pub enum SceneErrorKind { PrimitiveNotCompiled { primitive: &'static str }, SingularTransform, TooManyObjects { capacity: usize }, ZeroDirection }
impl core::fmt::Display for SceneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result { write!(f, "line {}: {:?}", self.line, self.kind) }
}
pub fn parse<const M: usize>(_text: &[u8]) -> Result<crate::scene::SceneDescription<M>, SceneError> {
    Err(SceneError { line: 0, kind: SceneErrorKind::ZeroDirection })
}
