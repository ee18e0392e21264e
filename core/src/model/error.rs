//! Errors of the scene format: a line number and a reason, with a `Display` that reads
//! `line 12: <reason>` (the host adds the file: `scene.mts:line 12: <reason>`). Scene preparation ([`crate::scene::Scene::prepare`]) reports its own
//! problems with the same type.

use core::fmt;

/// How many bytes of an offending token an error keeps (cut at a character boundary).
pub const TOKEN_EXCERPT_BYTES: usize = 20;

/// The start of an offending token, kept without an allocator: at most
/// [`TOKEN_EXCERPT_BYTES`] bytes, cut at a character boundary, with a flag saying whether
/// anything was cut off. `Display` shows it in backticks with control characters escaped and
/// `...` after a cut.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Token {
    text: heapless::String<TOKEN_EXCERPT_BYTES>,
    truncated: bool,
}

impl Token {
    /// Keeps the first characters of `text` that fit in [`TOKEN_EXCERPT_BYTES`] bytes.
    pub fn new(text: &str) -> Self {
        let mut kept = heapless::String::new();
        let mut truncated = false;
        for c in text.chars() {
            if kept.push(c).is_err() {
                truncated = true;
                break;
            }
        }
        Self { text: kept, truncated }
    }

    /// The kept characters (without the `...`).
    pub fn as_str(&self) -> &str {
        self.text.as_str()
    }

    /// Whether the token was longer than what is kept.
    pub fn is_truncated(&self) -> bool {
        self.truncated
    }
}

impl fmt::Display for Token {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("`")?;
        for c in self.text.chars() {
            write!(f, "{}", c.escape_debug())?;
        }
        if self.truncated {
            f.write_str("...")?;
        }
        f.write_str("`")
    }
}

/// A scene error: where (`line`, 1-based; 0 when the problem is not tied to a line) and what.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    pub line: u32,
    pub kind: SceneErrorKind,
}

impl SceneError {
    pub const fn new(line: u32, kind: SceneErrorKind) -> Self {
        Self { line, kind }
    }
}

/// Why a scene was rejected.
#[derive(Clone, Debug, PartialEq)]
#[non_exhaustive]
pub enum SceneErrorKind {
    /// The statement part of the line (before any `#`) is not valid UTF-8.
    InvalidUtf8,
    /// The first word of a statement is not a keyword of the format; `suggestion`, the keyword
    /// within an edit or two of it, if there is one.
    UnknownKeyword { keyword: Token, suggestion: Option<&'static str> },
    /// A statement has the wrong number of arguments: it takes from `fewest` to `most` (no
    /// limit when `None`); `usage` shows the statement's form.
    WrongArgumentCount { keyword: &'static str, fewest: u8, most: Option<u8>, found: usize, usage: &'static str },
    /// A word argument (`on`/`off`, an axis, a light type, ...) is not one of the allowed words.
    InvalidWord { keyword: &'static str, word: Token, expected: &'static str },
    /// A number argument does not follow the format's grammar
    /// (optional sign, digits, optional `.digits`, optional exponent).
    MalformedNumber { what: &'static str, token: Token },
    /// A well-formed number too large for a 64-bit float (e.g. `1e400`).
    NumberNotFinite { what: &'static str, token: Token },
    /// An integer argument has a fractional part.
    ExpectedInteger { what: &'static str, token: Token },
    /// An integer argument lies outside its range.
    IntegerOutOfRange { what: &'static str, token: Token, min: i32, max: i32 },
    /// A real argument lies outside its range (`range` reads e.g. "at least 0", "0 to 1").
    ValueOutOfRange { what: &'static str, token: Token, range: &'static str },
    /// The corners of a viewport or window are in the wrong order (or the window is too
    /// large); `requirement` says what must hold.
    InvalidRectangle { what: &'static str, requirement: &'static str },
    /// A direction (parallel projection, directional light) is the zero vector, or its length
    /// cannot be computed (underflows to zero or overflows).
    ZeroDirection,
    /// An object statement (`scale`, `colour`, ...) before the first primitive keyword.
    ObjectRequired { keyword: &'static str },
    /// More objects than the build's capacity.
    TooManyObjects { capacity: usize },
    /// More `light` statements than a scene may hold.
    TooManyLights { capacity: usize },
    /// The scene uses a feature (reflection, refraction, more lights, antialiasing) that this
    /// build leaves out (scene preparation); `statement` names what asked for it.
    FeatureNotCompiled { feature: &'static str, statement: &'static str },
    /// An object's transform cannot be inverted: a `scale` with a zero factor (the line is the
    /// `scale` statement's) or a transform that became singular or non-finite (the line is
    /// the object's first line).
    SingularTransform,
    /// The scene uses a primitive that this build leaves out (scene preparation).
    PrimitiveNotCompiled { primitive: &'static str },
    /// A scene value does not fit the number type the scene is prepared in (scene
    /// preparation): `what` reached `value` in magnitude, beyond `limit`, the documented range
    /// of the type called `number`. The error's line is the object's first line, or the line of
    /// the `window`, `viewplane`, `perspective` or `light` statement that set the value (0 for
    /// a default).
    OutOfRangeForNumberType { what: &'static str, number: &'static str, value: f64, limit: f64 },
    /// A solid (`union`, `intersection`, `difference`) is never closed with `end`; the line is
    /// the one that opened it.
    UnclosedSolid { keyword: &'static str },
    /// `end` with no solid open.
    EndWithoutSolid,
    /// `end` closes a solid with no operand; `opened` is the line that opened it.
    EmptySolid { keyword: &'static str, opened: u32 },
    /// A solid needs more of something than the format holds: `what`, how many it `needs`, the
    /// `capacity` (the line is the solid's first).
    SolidTooComplex { what: &'static str, needs: usize, capacity: usize },
    /// An object statement right after a solid opens, before its first operand.
    OperandRequired { keyword: &'static str },
    /// `reflect`, `transmit` or `ior` on an operand of a solid: they are the whole solid's.
    OpticsOnOperand { keyword: &'static str },
    /// An open surface (a frustum, a triangle) as an operand of a solid, which needs an inside.
    OpenSurfaceInSolid { primitive: &'static str },
    /// The file ends inside a statement that needs more (an NFF `p` short of its vertices).
    UnexpectedEnd { expected: &'static str },
    /// An NFF object before the view (`v`), or an NFF scene without one.
    ViewRequired,
}

impl fmt::Display for SceneErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::InvalidUtf8 => f.write_str("the statement is not valid UTF-8 text"),
            Self::UnknownKeyword { keyword, suggestion: None } => write!(f, "unknown keyword {keyword}"),
            Self::UnknownKeyword { keyword, suggestion: Some(suggestion) } => write!(f, "unknown keyword {keyword} (did you mean `{suggestion}`?)"),
            Self::WrongArgumentCount { keyword, fewest, most, found, usage } => {
                f.write_str("`")?;
                f.write_str(keyword)?;
                f.write_str("` takes ")?;
                match (fewest, most) {
                    (0, Some(0)) => f.write_str("no arguments")?,
                    (1, Some(1)) => f.write_str("1 argument")?,
                    (n, Some(m)) if n == m => write!(f, "{n} arguments")?,
                    (n, Some(m)) => write!(f, "{n} or {m} arguments")?,
                    (1, None) => f.write_str("at least 1 argument")?,
                    (n, None) => write!(f, "at least {n} arguments")?,
                }
                write!(f, " (`{usage}`), found {found}")
            }
            Self::InvalidWord { keyword, word, expected } => {
                write!(f, "`{keyword}`: invalid word {word}, expected {expected}")
            }
            Self::MalformedNumber { what, token } => write!(
                f,
                "{what}: malformed number {token} (expected an optional sign, digits, an optional \
                 fraction and an optional exponent, e.g. -1.5 or 2e-3)"
            ),
            Self::NumberNotFinite { what, token } => {
                write!(f, "{what}: number {token} is out of range (too large for a 64-bit float)")
            }
            Self::ExpectedInteger { what, token } => write!(f, "{what}: expected an integer, found {token}"),
            Self::IntegerOutOfRange { what, token, min, max } => {
                write!(f, "{what}: {token} is out of range (must be an integer from {min} to {max})")
            }
            Self::ValueOutOfRange { what, token, range } => write!(f, "{what}: {token} is out of range (must be {range})"),
            Self::InvalidRectangle { what, requirement } => write!(f, "{what}: {requirement}"),
            Self::ZeroDirection => f.write_str(
                "the direction is the zero vector (or too small or too large for its length to be computed)",
            ),
            Self::ObjectRequired { keyword } => {
                write!(f, "`{keyword}` changes the most recent object, but no object has started yet (start one with ")?;
                // Every primitive's keyword, from the one list of them.
                let names = super::Primitive::ALL.map(super::Primitive::name);
                for (index, name) in names.iter().enumerate() {
                    let separator = match index {
                        0 => "",
                        _ if index + 1 == names.len() => " or ",
                        _ => ", ",
                    };
                    write!(f, "{separator}{name}")?;
                }
                f.write_str(", or a solid: union, intersection or difference)")
            }
            Self::TooManyObjects { capacity } => {
                write!(f, "too many objects: this build holds at most {capacity}")
            }
            Self::TooManyLights { capacity } => write!(f, "too many lights: a scene holds at most {capacity}"),
            Self::FeatureNotCompiled { feature, statement } => {
                write!(f, "`{statement}` needs the `{feature}` feature, which this build leaves out")
            }
            Self::SingularTransform => f.write_str("singular transform: the object's transform cannot be inverted"),
            Self::PrimitiveNotCompiled { primitive } => write!(f, "{primitive} is not compiled into this build"),
            Self::OutOfRangeForNumberType { what, number, value, limit } => {
                write!(f, "{what} reaches ")?;
                write_magnitude(f, *value)?;
                write!(f, ", too large for the number type `{number}`, whose documented range for scene values is ±")?;
                write_magnitude(f, *limit)?;
                f.write_str(" (see docs/hard-cases.md)")
            }
            Self::UnclosedSolid { keyword } => write!(f, "the `{keyword}` opened here is never closed with `end`"),
            Self::EndWithoutSolid => f.write_str("`end` with no solid open (open one with union, intersection or difference)"),
            Self::EmptySolid { keyword, opened } => write!(f, "`end` closes the `{keyword}` of line {opened}, which has no operand (a solid needs at least one object)"),
            Self::SolidTooComplex { what, needs, capacity } => {
                write!(f, "the solid needs {needs} {what}, more than the {capacity} the format holds (model::solid)")
            }
            Self::OperandRequired { keyword } => write!(
                f,
                "`{keyword}` changes the most recent object, but the solid just opened has no operand yet (start one with a primitive or a solid)"
            ),
            Self::OpticsOnOperand { keyword } => write!(
                f,
                "`{keyword}` on an operand of a solid: reflection and refraction are the whole solid's (write it after the outermost `end`)"
            ),
            Self::OpenSurfaceInSolid { primitive } => write!(
                f,
                "a {primitive} is an open surface, with no inside: it cannot be an operand of a solid (use a closed primitive: cube, sphere, cylinder, cone or torus)"
            ),
            Self::UnexpectedEnd { expected } => write!(f, "the file ends where {expected} should follow"),
            Self::ViewRequired => f.write_str("NFF needs the view (`v` with from, at, up and angle) before the first object"),
        }
    }
}

/// A magnitude as plain digits up to a billion, in exponent form above (or when not finite).
fn write_magnitude(f: &mut fmt::Formatter<'_>, value: f64) -> fmt::Result {
    if value.abs() < 1e9 {
        write!(f, "{value}")
    } else {
        write!(f, "{value:e}")
    }
}

impl fmt::Display for SceneError {
    /// `line N: reason`, or the reason alone when the error is tied to no line (line 0). A host
    /// that read the scene from a file puts `FILE:` in front (`FILE:line N: reason`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line != 0 {
            write!(f, "line {}: ", self.line)?;
        }
        write!(f, "{}", self.kind)
    }
}

impl core::error::Error for SceneError {}
