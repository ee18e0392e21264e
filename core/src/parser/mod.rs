//! The `.mts` scene format (`docs/scene-format.md`): one statement per line mirroring the
//! thesis's user-interface calls, parsed into a [`SceneDescription`].
//!
//! [`parse`] takes raw bytes and never panics, allocates nothing, and runs in one pass over the
//! input (time linear in its length, whatever its lines look like). The first problem in
//! reading order is returned as a [`SceneError`] naming the 1-based line and the reason.
//!
//! # Choices where the format is silent
//!
//! - **Lines** end at `\n`; one `\r` right before it (or at the end of the input) is dropped,
//!   so `\r\n` files read the same. A UTF-8 byte-order mark at the very start is ignored. Line
//!   numbers count every `\n`, including those of blank and comment lines.
//! - **Comments**: everything from the first `#` to the end of the line is ignored unchecked
//!   (it may hold any bytes). The statement before it must be valid UTF-8; only spaces and
//!   tabs separate tokens (any other character, e.g. a stray `\r`, is part of a token).
//! - **Keywords** are lower case only (`Sphere`, `color` are unknown keywords).
//! - **Numbers** follow the grammar exactly: `[+|-] digits [. digits] [(e|E) [+|-] digits]`.
//!   So `.5`, `5.`, `inf`, `nan`, `0x10`, `1,5`, `1_000` are malformed. A well-formed number
//!   whose value overflows an `f64` (`1e400`) is out of range; one that underflows reads as 0.
//! - **Integers**: a number is an integer when its exact decimal value is whole, so `100`,
//!   `1e2`, `1.0` and `-0` are integers, and `1.5`, `1e-400` and `1.0000000000000000001` are
//!   not (the test is made on the digits, not on the rounded float).
//! - **Ranges**: viewport coordinates 0..=32767 with X1 <= X2 and Y1 <= Y2; window X1 < X2 and
//!   Y1 < Y2 with finite widths; `background` 0..=255; `colour` and a group's N, R, G, B
//!   0..=15. `ambient`, `ka`, `kd`, `ks` and `rnd` must be >= 0 (no upper bound); `pwr` must be
//!   0..=1e6 (powers are taken as integers); each of `cmy` must be 0..=1 (they are ratios).
//!   `viewplane`, `perspective`, `light point`, `translate` and `rotate` take any finite value.
//! - **Directions** (`parallel`, `light direction`) are rejected when their length is zero or
//!   cannot be computed in `f64` (as scene preparation would reject them), e.g.
//!   `parallel 0 0 0` or `parallel 1e-200 0 0`.
//! - **Transforms**: a `scale` with a zero factor is an error at that line. When an object ends
//!   (at the next primitive keyword or the end of the input) its `world_from_object` must be
//!   invertible with a finite inverse
//!   ([`Matrix4::affine_inverse`](crate::geometry::Matrix4::affine_inverse)); otherwise the error names
//!   the object's first line (the primitive keyword).
//! - **`optimize`** takes `all` or `none` on its own, or one or more of `pixelbuffer`,
//!   `extents`, `grid`, `sortlist` in any order (repeats allowed): those are on, the rest off.
//! - **Checks order** for one statement: unknown keyword, then "needs an object", then the
//!   argument count, then the arguments from left to right.
//! - Global statements may appear anywhere, also between objects; the last one wins.
//! - **Solids**: `union`, `intersection` and `difference` open a solid, `end` closes the innermost
//!   one; object statements change the most recent operand, or after `end` the solid (its
//!   leaves' transforms and the material of those that set none). A solid's checks (its leaves
//!   invertible, the walk's capacities) are made where it ends as an object: at the next object
//!   or the end of the input, naming the solid's first line (a leaf's own line when it is
//!   singular).

pub mod nff;
mod number;
mod polygon;
#[cfg(test)]
mod tests;


use crate::storage::List;
use crate::model::{ranges, IntegerRange, RealRange, SceneError, SceneErrorKind, Token};
use crate::model::{Antialias, Light, LightSource, Description, ObjectDescription, Optimizations, Primitive, Projection, Taper, Tube, SceneDescription, Viewport, Window, MAX_LIGHTS};
use crate::model::{enclosing_transform, Operation, SolidNode, SolidRange, MAX_SOLID_NODES};
use crate::model::Rgb4;

/// The most arguments any fixed-arity statement takes (`group N R G B up`).
const MAX_ARGS: usize = 5;

/// Parses a whole `.mts` scene. `MAX_OBJECTS` is the capacity; more objects is an error.
pub fn parse<const MAX_OBJECTS: usize>(text: &[u8]) -> Result<SceneDescription<MAX_OBJECTS>, SceneError> {
    parse_into_list(text)
}

/// Whether a file of this name is NFF (`.nff`, any case), read by [`nff::parse_into_list`].
pub fn is_nff(name: &str) -> bool {
    name.len() >= 4 && name.get(name.len() - 4..).is_some_and(|end| end.eq_ignore_ascii_case(".nff"))
}

/// The one door from a scene file's name and bytes to its description: NFF when the name
/// says so ([`is_nff`]), the `.mts` format otherwise. (A host decompresses `.nff.gz` first.)
pub fn parse_file<L: List<ObjectDescription>>(name: &str, text: &[u8]) -> Result<Description<L>, SceneError> {
    if is_nff(name) {
        nff::parse_into_list(text)
    } else {
        parse_into_list(text)
    }
}

/// [`parse`] into any list of objects (a host's grows as the file does); more objects than
/// the list holds ([`List::CAPACITY`]) is an error.
pub fn parse_into_list<L: List<ObjectDescription>>(text: &[u8]) -> Result<Description<L>, SceneError> {
    let mut scene = Description::default();
    parse_into(text, &mut scene)?;
    Ok(scene)
}

/// The body of [`parse`], writing into a description the caller owns (so the large
/// description is not moved around on the stack more than once).
fn parse_into<L: List<ObjectDescription>>(text: &[u8], scene: &mut Description<L>) -> Result<(), SceneError> {
    let text = text.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(text);
    let mut line: u32 = 0;
    let mut solids = SolidsBeingWritten::default();
    for raw in text.split(|&b| b == b'\n') {
        line = line.saturating_add(1);
        let raw = raw.strip_suffix(b"\r").unwrap_or(raw);
        let code = raw.split(|&b| b == b'#').next().unwrap_or(&[]);
        let code = core::str::from_utf8(code).map_err(|_| SceneError::new(line, SceneErrorKind::InvalidUtf8))?;
        statement(code, line, scene, &mut solids)?;
    }
    if let Some(open) = solids.open.last() {
        return Err(SceneError::new(open.line, SceneErrorKind::UnclosedSolid { keyword: open.operation.name() }));
    }
    finish_object(scene, &solids)
}

/// The most solids open inside one another while a scene is read.
const MAX_NESTING: usize = 16;
/// No material statement has reached the leaf yet (see [`SolidsBeingWritten::material_depth`]).
const NO_MATERIAL: u8 = u8::MAX;

/// The parser's place among the solids (`union` … `end`): which are open, and what the object
/// statements change.
struct SolidsBeingWritten {
    /// The solids opened and not yet closed, outermost first.
    open: heapless::Vec<OpenSolid, MAX_NESTING>,
    /// What `scale`, `colour`, … change.
    target: Target,
    /// For each node of `Description::solids`, the nesting depth of what set the leaf's material:
    /// the leaf itself or an enclosing solid (0: the outermost). A solid's material statement
    /// reaches only the leaves no deeper node set, so an operand keeps its own.
    material_depth: [u8; MAX_SOLID_NODES],
}

impl Default for SolidsBeingWritten {
    fn default() -> Self {
        Self { open: heapless::Vec::new(), target: Target::Object, material_depth: [NO_MATERIAL; MAX_SOLID_NODES] }
    }
}

struct OpenSolid {
    operation: Operation,
    line: u32,
    /// Operands started so far.
    operands: u16,
    /// Its first node in `Description::solids` (its nodes are written after it opens).
    first: usize,
}

#[derive(Clone, Copy)]
enum Target {
    /// The most recent object of the scene's list (none yet: an error).
    Object,
    /// A solid was opened and no operand has started yet (an error).
    NoOperand,
    /// The nodes of `Description::solids` from `first` to the end: an operand (a primitive or a
    /// closed solid) or a whole solid, at nesting `depth` (0: a solid of the scene's list).
    Nodes { first: usize, depth: u8 },
}

/// Splits a statement into its tokens.
fn tokens(code: &str) -> impl Iterator<Item = &str> {
    code.split([' ', '\t']).filter(|token| !token.is_empty())
}

/// The check at the end of each object: its transform must be invertible. A solid's end is where
/// its leaves' transforms are final: each must be invertible, the tree must fit the walk's
/// capacities, and the object becomes the box that encloses the solid (§3.3.6).
fn finish_object<L: List<ObjectDescription>>(scene: &mut Description<L>, solids: &SolidsBeingWritten) -> Result<(), SceneError> {
    let Some(object) = scene.objects.last_mut() else { return Ok(()) };
    let Primitive::Solid(range) = object.primitive else {
        return match object.world_from_object.affine_inverse() {
            None => Err(SceneError::new(object.line, SceneErrorKind::SingularTransform)),
            Some(_) => Ok(()),
        };
    };
    if !matches!(solids.target, Target::Nodes { depth: 0, .. }) {
        // Still open: the end of the input reports it.
        return Ok(());
    }
    let nodes = scene.solids.get(range.nodes()).unwrap_or(&[]);
    object.world_from_object = enclosing_transform(nodes, object.line)?;
    Ok(())
}

/// The format's statements, each written once: its keyword, its arguments (fewest, most;
/// `None`: no limit), its usage, and whether it changes the most recent object. The primitives'
/// keywords come from [`Primitive`] (each takes no argument and starts an object).
macro_rules! keywords {
    ($($variant:ident $name:literal ($fewest:literal, $most:expr) $usage:literal $changes_object:literal;)*) => {
        #[derive(Clone, Copy, Debug, PartialEq, Eq)]
        enum Keyword {
            $($variant,)*
            Primitive(Primitive),
            /// `union`, `intersection`, `difference`: opens a solid.
            Solid(Operation),
        }

        impl Keyword {
            /// The statements' keywords (the primitives' and solids' are theirs).
            const NAMES: &'static [&'static str] = &[$($name,)*];

            fn from_token(token: &str) -> Option<Self> {
                match token {
                    $($name => Some(Keyword::$variant),)*
                    _ => Primitive::ALL
                        .into_iter()
                        .find(|primitive| primitive.name() == token)
                        .map(Keyword::Primitive)
                        .or_else(|| Operation::ALL.into_iter().find(|operation| operation.name() == token).map(Keyword::Solid)),
                }
            }

            fn name(self) -> &'static str {
                match self {
                    $(Keyword::$variant => $name,)*
                    Keyword::Primitive(primitive) => primitive.name(),
                    Keyword::Solid(operation) => operation.name(),
                }
            }

            /// (fewest arguments, most arguments (`None`: no limit), usage).
            fn arity(self) -> (u8, Option<u8>, &'static str) {
                match self {
                    $(Keyword::$variant => ($fewest, $most, $usage),)*
                    Keyword::Primitive(Primitive::Torus(_)) => (1, Some(1), "torus R"),
                    Keyword::Primitive(Primitive::Frustum(_)) => (1, Some(1), "frustum R"),
                    Keyword::Primitive(primitive) => (0, Some(0), primitive.name()),
                    Keyword::Solid(operation) => (0, Some(0), operation.name()),
                }
            }

            /// Whether the statement changes the most recent object.
            fn needs_object(self) -> bool {
                match self {
                    $(Keyword::$variant => $changes_object,)*
                    Keyword::Primitive(_) | Keyword::Solid(_) => false,
                }
            }
        }
    };
}

keywords! {
    Viewport "viewport" (4, Some(4)) "viewport X1 X2 Y1 Y2" false;
    Window "window" (4, Some(4)) "window X1 X2 Y1 Y2" false;
    Viewplane "viewplane" (1, Some(1)) "viewplane D" false;
    Perspective "perspective" (3, Some(3)) "perspective X Y Z" false;
    Parallel "parallel" (3, Some(3)) "parallel DX DY DZ" false;
    Light "light" (4, Some(5)) "light point X Y Z [I] | light direction DX DY DZ [I]" false;
    Ambient "ambient" (1, Some(1)) "ambient A" false;
    Background "background" (1, Some(1)) "background C" false;
    Shadows "shadows" (1, Some(1)) "shadows on|off" false;
    Dither "dither" (1, Some(1)) "dither on|off" false;
    Group "group" (5, Some(5)) "group N R G B up|down" false;
    Optimize "optimize" (1, None) "optimize all|none|pixelbuffer extents grid sortlist" false;
    Scale "scale" (3, Some(3)) "scale SX SY SZ" true;
    Rotate "rotate" (2, Some(2)) "rotate x|y|z DEG" true;
    Translate "translate" (3, Some(3)) "translate TX TY TZ" true;
    Colour "colour" (1, Some(1)) "colour N" true;
    Ka "ka" (1, Some(1)) "ka V" true;
    Kd "kd" (1, Some(1)) "kd V" true;
    Ks "ks" (1, Some(1)) "ks V" true;
    Pwr "pwr" (1, Some(1)) "pwr V" true;
    Rnd "rnd" (1, Some(1)) "rnd V" true;
    Cmy "cmy" (3, Some(3)) "cmy C M Y" true;
    Reflect "reflect" (1, Some(1)) "reflect R" true;
    Transmit "transmit" (1, Some(1)) "transmit T" true;
    Ior "ior" (1, Some(1)) "ior N" true;
    Depth "depth" (1, Some(1)) "depth N" false;
    Antialias "antialias" (1, Some(2)) "antialias off | antialias T [L]" false;
    End "end" (0, Some(0)) "end" false;
}

/// One statement's arguments, with the helpers that read them and build errors.
struct Statement<'a> {
    line: u32,
    keyword: Keyword,
    args: [&'a str; MAX_ARGS],
}

impl<'a> Statement<'a> {
    fn error(&self, kind: SceneErrorKind) -> SceneError {
        SceneError::new(self.line, kind)
    }

    fn arg(&self, index: usize) -> &'a str {
        self.args.get(index).copied().unwrap_or("")
    }

    /// A number argument, its parts and its value.
    fn decimal(&self, index: usize, what: &'static str) -> Result<(number::Decimal<'a>, f64), SceneError> {
        let token = self.arg(index);
        let decimal = number::split(token)
            .ok_or_else(|| self.error(SceneErrorKind::MalformedNumber { what, token: Token::new(token) }))?;
        match token.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok((decimal, value)),
            // The grammar is a subset of what `parse` accepts, so only overflow lands here.
            _ => Err(self.error(SceneErrorKind::NumberNotFinite { what, token: Token::new(token) })),
        }
    }

    fn real(&self, index: usize, what: &'static str) -> Result<f64, SceneError> {
        self.decimal(index, what).map(|(_, value)| value)
    }

    /// A real in `low..=high`; `range` describes it for the error.
    fn bounded(&self, index: usize, what: &'static str, low: f64, high: f64, range: &'static str) -> Result<f64, SceneError> {
        let value = self.real(index, what)?;
        if (low..=high).contains(&value) {
            Ok(value)
        } else {
            Err(self.error(SceneErrorKind::ValueOutOfRange { what, token: Token::new(self.arg(index)), range }))
        }
    }

    /// A real in one of the format's ranges (`model::ranges`, which `Description::validate`
    /// checks too).
    fn ranged(&self, index: usize, range: RealRange) -> Result<f64, SceneError> {
        self.bounded(index, range.what, range.low, range.high, range.range)
    }

    /// An integer in one of the format's ranges.
    fn integer_in(&self, index: usize, range: IntegerRange) -> Result<i32, SceneError> {
        self.integer(index, range.what, range.min, range.max)
    }

    /// An integer in `min..=max`.
    fn integer(&self, index: usize, what: &'static str, min: i32, max: i32) -> Result<i32, SceneError> {
        let (decimal, value) = self.decimal(index, what)?;
        let token = || Token::new(self.arg(index));
        if !decimal.is_integral() {
            return Err(self.error(SceneErrorKind::ExpectedInteger { what, token: token() }));
        }
        if !(f64::from(min)..=f64::from(max)).contains(&value) {
            return Err(self.error(SceneErrorKind::IntegerOutOfRange { what, token: token(), min, max }));
        }
        // In range and whole, so the (saturating) conversion is exact.
        Ok(value as i32)
    }

    /// A 4-bit level 0..=15.
    fn nibble(&self, index: usize, what: &'static str) -> Result<u8, SceneError> {
        self.integer(index, what, 0, 15).map(|value| value as u8)
    }

    fn vector(&self, first: usize, what: [&'static str; 3]) -> Result<[f64; 3], SceneError> {
        Ok([self.real(first, what[0])?, self.real(first + 1, what[1])?, self.real(first + 2, what[2])?])
    }

    /// A vector whose length can be normalised, as scene preparation needs.
    fn direction(&self, first: usize, what: [&'static str; 3]) -> Result<[f64; 3], SceneError> {
        let direction = self.vector(first, what)?;
        let length = libm::sqrt(direction.iter().map(|c| c * c).sum::<f64>());
        if length == 0.0 || !length.is_finite() {
            return Err(self.error(SceneErrorKind::ZeroDirection));
        }
        Ok(direction)
    }

    /// The position in `words` of the word argument, or an error listing them.
    fn word(&self, index: usize, words: &[&str], expected: &'static str) -> Result<usize, SceneError> {
        let token = self.arg(index);
        words.iter().position(|word| *word == token).ok_or_else(|| {
            self.error(SceneErrorKind::InvalidWord { keyword: self.keyword.name(), word: Token::new(token), expected })
        })
    }

    fn on_off(&self) -> Result<bool, SceneError> {
        self.word(0, &["off", "on"], "`on` or `off`").map(|index| index == 1)
    }
}

const OPTIMIZE_EXPECTED: &str = "`all` or `none` on its own, or any of `pixelbuffer`, `extents`, `grid`, `sortlist`";

/// The keyword `token` was most likely meant to be: one within an edit of it, or two for a word
/// of six letters or more, ignoring case; `None` when none is that close (`bogus` is two edits
/// from `torus`, and no typo of it).
fn nearest_keyword(token: &str) -> Option<&'static str> {
    let allowed = if token.chars().count() < 6 { 1 } else { 2 };
    let names = Keyword::NAMES.iter().copied().chain(Primitive::ALL.iter().map(|primitive| primitive.name())).chain(Operation::ALL.iter().map(|operation| operation.name()));
    names.map(|name| (edit_distance(token, name), name)).filter(|(distance, _)| *distance <= allowed).min_by_key(|(distance, _)| *distance).map(|(_, name)| name)
}

/// Levenshtein's distance between `a` and `b`, case ignored: insertions, deletions and
/// substitutions (a keyword is at most [`KEYWORD_LETTERS`] letters; longer words are far).
fn edit_distance(a: &str, b: &str) -> usize {
    let mut previous = [0usize; KEYWORD_LETTERS + 1];
    let mut current = [0usize; KEYWORD_LETTERS + 1];
    let mut letters = ['\0'; KEYWORD_LETTERS];
    let mut count = 0;
    for c in b.chars() {
        let Some(slot) = letters.get_mut(count) else { return usize::MAX };
        *slot = c.to_ascii_lowercase();
        count += 1;
    }
    let b = letters.get(..count).unwrap_or(&[]);
    if a.chars().count() > KEYWORD_LETTERS + 2 {
        return usize::MAX;
    }
    for (j, slot) in previous.iter_mut().enumerate().take(b.len() + 1) {
        *slot = j;
    }
    for (i, x) in a.chars().map(|c| c.to_ascii_lowercase()).enumerate() {
        current[0] = i + 1;
        for (j, y) in b.iter().enumerate() {
            // j < b.len() <= KEYWORD_LETTERS, so j + 1 is within both rows.
            let (Some(&diagonal), Some(&above), Some(&left)) = (previous.get(j), previous.get(j + 1), current.get(j)) else { break };
            if let Some(slot) = current.get_mut(j + 1) {
                *slot = (diagonal + usize::from(x != *y)).min(above + 1).min(left + 1);
            }
        }
        previous = current;
    }
    previous.get(b.len()).copied().unwrap_or(usize::MAX)
}

/// The longest keyword's letters (`intersection`) with room.
const KEYWORD_LETTERS: usize = 16;

/// Parses one statement (comment already removed) into the scene.
fn statement<L: List<ObjectDescription>>(
    code: &str,
    line: u32,
    scene: &mut Description<L>,
    solids: &mut SolidsBeingWritten,
) -> Result<(), SceneError> {
    let mut words = tokens(code);
    let Some(first) = words.next() else {
        return Ok(());
    };
    let keyword = Keyword::from_token(first)
        .ok_or_else(|| SceneError::new(line, SceneErrorKind::UnknownKeyword { keyword: Token::new(first), suggestion: nearest_keyword(first) }))?;
    if keyword.needs_object() && scene.objects.is_empty() {
        return Err(SceneError::new(line, SceneErrorKind::ObjectRequired { keyword: keyword.name() }));
    }
    let mut args = [""; MAX_ARGS];
    let mut found: usize = 0;
    for word in words {
        if let Some(slot) = args.get_mut(found) {
            *slot = word;
        }
        found = found.saturating_add(1);
    }
    let (fewest, most, usage) = keyword.arity();
    let count_ok = found >= usize::from(fewest) && most.is_none_or(|most| found <= usize::from(most));
    if !count_ok {
        return Err(SceneError::new(line, SceneErrorKind::WrongArgumentCount { keyword: keyword.name(), fewest, most, found, usage }));
    }
    let s = Statement { line, keyword, args };
    match keyword {
        Keyword::Viewport => {
            let [x1_range, x2_range, y1_range, y2_range] = ranges::VIEWPORT;
            let x1 = s.integer_in(0, x1_range)?;
            let x2 = s.integer_in(1, x2_range)?;
            let y1 = s.integer_in(2, y1_range)?;
            let y2 = s.integer_in(3, y2_range)?;
            if x1 > x2 {
                return Err(s.error(SceneErrorKind::InvalidRectangle { what: "viewport", requirement: "X1 must not be greater than X2" }));
            }
            if y1 > y2 {
                return Err(s.error(SceneErrorKind::InvalidRectangle { what: "viewport", requirement: "Y1 must not be greater than Y2" }));
            }
            scene.viewport = Viewport { x1: x1 as u16, x2: x2 as u16, y1: y1 as u16, y2: y2 as u16 };
        }
        Keyword::Window => {
            let x1 = s.real(0, "window X1")?;
            let x2 = s.real(1, "window X2")?;
            let y1 = s.real(2, "window Y1")?;
            let y2 = s.real(3, "window Y2")?;
            if x1 >= x2 {
                return Err(s.error(SceneErrorKind::InvalidRectangle { what: "window", requirement: "X1 must be less than X2" }));
            }
            if y1 >= y2 {
                return Err(s.error(SceneErrorKind::InvalidRectangle { what: "window", requirement: "Y1 must be less than Y2" }));
            }
            if !(x2 - x1).is_finite() || !(y2 - y1).is_finite() {
                return Err(s.error(SceneErrorKind::InvalidRectangle {
                    what: "window",
                    requirement: "too large: X2 - X1 and Y2 - Y1 must be finite",
                }));
            }
            scene.window = Window { x1, x2, y1, y2 };
            scene.lines.window = line;
        }
        Keyword::Viewplane => {
            scene.view_plane = s.real(0, "viewplane D")?;
            scene.lines.view_plane = line;
        }
        Keyword::Perspective => {
            scene.projection = Projection::Perspective { eye: s.vector(0, ["perspective X", "perspective Y", "perspective Z"])? };
            scene.lines.projection = line;
        }
        Keyword::Parallel => {
            scene.projection =
                Projection::Parallel { direction: s.direction(0, ["parallel DX", "parallel DY", "parallel DZ"])? };
            scene.lines.projection = line;
        }
        Keyword::Light => {
            let light = match s.word(0, &["point", "direction"], "`point` or `direction`")? {
                0 => Light::Point(s.vector(1, ["light point X", "light point Y", "light point Z"])?),
                _ => Light::Direction(s.direction(1, ["light direction DX", "light direction DY", "light direction DZ"])?),
            };
            let intensity = if found == 5 { s.ranged(4, ranges::LIGHT_INTENSITY)? } else { 1.0 };
            // The first statement replaces the default light; each later one adds a light.
            if scene.lines.light == 0 {
                scene.light = light;
                scene.light_intensity = intensity;
                scene.lines.light = line;
            } else {
                scene
                    .more_lights
                    .push(LightSource { light, intensity, line })
                    .map_err(|_| s.error(SceneErrorKind::TooManyLights { capacity: MAX_LIGHTS }))?;
            }
        }
        Keyword::Depth => scene.depth = s.integer_in(0, ranges::DEPTH)? as u8,
        Keyword::Antialias => {
            scene.antialias = if found == 1 && s.arg(0) == "off" {
                None
            } else {
                let threshold = s.ranged(0, ranges::ANTIALIAS_THRESHOLD)?;
                let levels = if found == 2 { s.integer_in(1, ranges::ANTIALIAS_LEVELS)? as u8 } else { 2 };
                Some(Antialias { threshold, levels })
            };
            scene.lines.antialias = line;
        }
        Keyword::Ambient => scene.ambient = s.ranged(0, ranges::AMBIENT)?,
        Keyword::Background => scene.background = s.integer(0, "background", 0, 255)? as u8,
        Keyword::Shadows => scene.shadows = s.on_off()?,
        Keyword::Dither => scene.dither = s.on_off()?,
        Keyword::Group => {
            let group = s.nibble(0, "group N")?;
            let cell = Rgb4::new(s.nibble(1, "group R")?, s.nibble(2, "group G")?, s.nibble(3, "group B")?);
            match s.word(4, &["up", "down"], "`up` or `down`")? {
                0 => scene.palette.set_group_up(group, cell),
                _ => scene.palette.set_group_down(group, cell),
            }
        }
        Keyword::Optimize => scene.optimizations = optimize(code, line)?,
        Keyword::Primitive(primitive) => {
            let primitive = match primitive {
                Primitive::Torus(_) => Primitive::Torus(tube(&s)?),
                Primitive::Frustum(_) => Primitive::Frustum(taper(&s)?),
                other => other,
            };
            if !solids.open.is_empty() && !primitive.is_closed() {
                return Err(s.error(SceneErrorKind::OpenSurfaceInSolid { primitive: primitive.name() }));
            }
            if solids.open.is_empty() {
                finish_object(scene, solids)?;
                scene
                    .objects
                    .push(ObjectDescription::new(primitive, line))
                    .map_err(|_| s.error(SceneErrorKind::TooManyObjects { capacity: L::CAPACITY }))?;
                solids.target = Target::Object;
            } else {
                start_operand(&s, scene, solids)?;
                let first = scene.solids.len();
                push_node(&s, scene, SolidNode::Leaf(ObjectDescription::new(primitive, line)))?;
                solids.target = Target::Nodes { first, depth: solids.open.len() as u8 };
            }
        }
        Keyword::Solid(operation) => {
            if solids.open.is_empty() {
                finish_object(scene, solids)?;
                let range = SolidRange { first: scene.solids.len() as u16, count: 0 };
                scene
                    .objects
                    .push(ObjectDescription::new(Primitive::Solid(range), line))
                    .map_err(|_| s.error(SceneErrorKind::TooManyObjects { capacity: L::CAPACITY }))?;
            } else {
                start_operand(&s, scene, solids)?;
            }
            solids
                .open
                .push(OpenSolid { operation, line, operands: 0, first: scene.solids.len() })
                .map_err(|_| s.error(SceneErrorKind::SolidTooComplex { what: "solids open inside one another", needs: MAX_NESTING + 1, capacity: MAX_NESTING }))?;
            solids.target = Target::NoOperand;
        }
        Keyword::End => {
            let closed = solids.open.pop().ok_or(s.error(SceneErrorKind::EndWithoutSolid))?;
            if closed.operands == 0 {
                return Err(s.error(SceneErrorKind::EmptySolid { keyword: closed.operation.name(), opened: closed.line }));
            }
            if closed.operands >= 2 {
                push_node(&s, scene, SolidNode::Combine { operation: closed.operation, line: closed.line })?;
            }
            let first = closed.first;
            let depth = solids.open.len() as u8;
            solids.target = Target::Nodes { first, depth };
            if solids.open.is_empty() {
                if let Some(object) = scene.objects.last_mut() {
                    if let Primitive::Solid(range) = &mut object.primitive {
                        range.count = (scene.solids.len() - usize::from(range.first)) as u16;
                    }
                }
            }
        }
        Keyword::Scale
        | Keyword::Rotate
        | Keyword::Translate
        | Keyword::Colour
        | Keyword::Ka
        | Keyword::Kd
        | Keyword::Ks
        | Keyword::Pwr
        | Keyword::Rnd
        | Keyword::Cmy
        | Keyword::Reflect
        | Keyword::Transmit
        | Keyword::Ior => match solids.target {
            Target::Object => object_statement(&s, scene)?,
            Target::NoOperand => return Err(s.error(SceneErrorKind::OperandRequired { keyword: s.keyword.name() })),
            Target::Nodes { first, depth } => solid_statement(&s, scene, solids, first, depth)?,
        },
    }
    Ok(())
}

/// A new operand of the innermost open solid: the operand before it is complete, so a chain
/// of more than two operands combines it now (`A op B op C` is `(A op B) op C`).
fn start_operand<L: List<ObjectDescription>>(s: &Statement<'_>, scene: &mut Description<L>, solids: &mut SolidsBeingWritten) -> Result<(), SceneError> {
    let Some(open) = solids.open.last_mut() else { return Ok(()) };
    open.operands = open.operands.saturating_add(1);
    let (operation, line, operands) = (open.operation, open.line, open.operands);
    if operands >= 3 {
        push_node(s, scene, SolidNode::Combine { operation, line })?;
    }
    Ok(())
}

/// Appends a node to the scene's solids.
fn push_node<L>(s: &Statement<'_>, scene: &mut Description<L>, node: SolidNode) -> Result<(), SceneError> {
    scene.solids.push(node).map_err(|_| s.error(SceneErrorKind::SolidTooComplex { what: "primitives and operations in the scene's solids", needs: MAX_SOLID_NODES + 1, capacity: MAX_SOLID_NODES }))
}

/// An object statement for an operand or a solid: the nodes from `first` on. A transform
/// composes on top of each leaf's own; a material statement reaches the leaves that no deeper
/// operand gave a material of its own (POV-Ray's rule), and, for a solid of the scene's list
/// (`depth` 0), the object's material too. Reflection and refraction are the whole solid's
/// (the ray tree's optics are per object): an operand may not set them.
fn solid_statement<L: List<ObjectDescription>>(
    s: &Statement<'_>,
    scene: &mut Description<L>,
    solids: &mut SolidsBeingWritten,
    first: usize,
    depth: u8,
) -> Result<(), SceneError> {
    let optics = matches!(s.keyword, Keyword::Reflect | Keyword::Transmit | Keyword::Ior);
    if optics && depth > 0 {
        return Err(s.error(SceneErrorKind::OpticsOnOperand { keyword: s.keyword.name() }));
    }
    let transform = matches!(s.keyword, Keyword::Scale | Keyword::Rotate | Keyword::Translate);
    if depth == 0 {
        // The solid's own object: its material (the ray tree's optics, and what its operands
        // inherit); its transform is the enclosure's, made at its end.
        object_statement(s, scene)?;
    }
    let object_material = scene.objects.last().map(|object| object.material);
    for (index, node) in scene.solids.iter_mut().enumerate().skip(first) {
        let SolidNode::Leaf(leaf) = node else { continue };
        if transform {
            apply(s, leaf)?;
            continue;
        }
        let Some(owner) = solids.material_depth.get_mut(index) else { continue };
        if *owner != NO_MATERIAL && *owner > depth {
            continue;
        }
        *owner = depth;
        match (depth, object_material) {
            (0, Some(material)) => leaf.material = material,
            _ => apply(s, leaf)?,
        }
    }
    Ok(())
}

/// `torus R`: the tube's radius, a ring torus's (0 < R < 1), to the nearest 2⁻¹⁵ (`Tube`).
fn tube(s: &Statement) -> Result<Tube, SceneError> {
    let radius = s.real(0, "torus")?;
    Tube::from_f64(radius).ok_or_else(|| {
        s.error(SceneErrorKind::ValueOutOfRange { what: "torus", token: Token::new(s.arg(0)), range: "between 0 and 1, a ring torus's tube radius" })
    })
}

/// `frustum R`: the radius at z = 0 (0 ≤ R ≤ 1), to the nearest 2⁻¹⁵ (`Taper`).
fn taper(s: &Statement) -> Result<Taper, SceneError> {
    let radius = s.real(0, "frustum")?;
    Taper::from_f64(radius).ok_or_else(|| {
        s.error(SceneErrorKind::ValueOutOfRange { what: "frustum", token: Token::new(s.arg(0)), range: "from 0 to 1, the radius at z = 0 of a frustum whose radius at z = 1 is 1" })
    })
}

/// `optimize ...`: the argument count is already checked to be at least 1.
fn optimize(code: &str, line: u32) -> Result<Optimizations, SceneError> {
    let invalid = |word: &str| {
        SceneError::new(line, SceneErrorKind::InvalidWord { keyword: "optimize", word: Token::new(word), expected: OPTIMIZE_EXPECTED })
    };
    let mut words = tokens(code).skip(1);
    let first = words.next().unwrap_or("");
    if first == "all" || first == "none" {
        // `all` and `none` stand alone.
        return match words.next() {
            Some(extra) => Err(invalid(extra)),
            None if first == "all" => Ok(Optimizations::ALL),
            None => Ok(Optimizations::NONE),
        };
    }
    let mut chosen = Optimizations::NONE;
    for word in core::iter::once(first).chain(words) {
        match word {
            "pixelbuffer" => chosen.pixelbuffer = true,
            "extents" => chosen.extents = true,
            "grid" => chosen.grid = true,
            "sortlist" => chosen.sortlist = true,
            _ => return Err(invalid(word)),
        }
    }
    Ok(chosen)
}

/// A statement that changes the most recent object.
fn object_statement<L: List<ObjectDescription>>(
    s: &Statement<'_>,
    scene: &mut Description<L>,
) -> Result<(), SceneError> {
    let object = scene
        .objects
        .last_mut()
        .ok_or_else(|| s.error(SceneErrorKind::ObjectRequired { keyword: s.keyword.name() }))?;
    apply(s, object)
}

/// An object statement applied to one object description.
fn apply(s: &Statement<'_>, object: &mut ObjectDescription) -> Result<(), SceneError> {
    let material = &mut object.material;
    match s.keyword {
        Keyword::Scale => {
            let factors = s.vector(0, ["scale SX", "scale SY", "scale SZ"])?;
            if factors.contains(&0.0) {
                return Err(s.error(SceneErrorKind::SingularTransform));
            }
            object.world_from_object.scale(factors);
        }
        Keyword::Rotate => {
            let axis = s.word(0, &["x", "y", "z"], "an axis `x`, `y` or `z`")?;
            let degrees = s.real(1, "rotate DEG")?;
            object.world_from_object.rotate(axis, degrees);
        }
        Keyword::Translate => object.world_from_object.translate(s.vector(0, ["translate TX", "translate TY", "translate TZ"])?),
        Keyword::Colour => material.colour = s.integer_in(0, ranges::COLOUR)? as u8,
        Keyword::Ka => material.ka = s.ranged(0, ranges::KA)?,
        Keyword::Kd => material.kd = s.ranged(0, ranges::KD)?,
        Keyword::Ks => material.ks = s.ranged(0, ranges::KS)?,
        Keyword::Pwr => material.pwr = s.ranged(0, ranges::PWR)?,
        Keyword::Rnd => material.rnd = s.ranged(0, ranges::RND)?,
        Keyword::Cmy => {
            material.cmy = [
                s.ranged(0, ranges::CMY[0])?,
                s.ranged(1, ranges::CMY[1])?,
                s.ranged(2, ranges::CMY[2])?,
            ];
        }
        Keyword::Reflect => material.reflect = s.ranged(0, ranges::REFLECT)?,
        Keyword::Transmit => material.transmit = s.ranged(0, ranges::TRANSMIT)?,
        Keyword::Ior => material.ior = s.ranged(0, ranges::IOR)?,
        _ => {}
    }
    Ok(())
}
