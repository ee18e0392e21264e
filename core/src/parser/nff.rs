//! Eric Haines' Neutral File Format (NFF), the language of his Standard Procedural Databases
//! (SPD), read into the same scene model as `.mts` (docs/nff.md: every statement, and how each
//! maps onto MicroTrace's model where it cannot map exactly).
//!
//! NFF is a stream of whitespace-separated tokens: a statement's numbers may run over several
//! lines (`v`'s block, `p`'s vertices, `c`'s two ends), and `#` starts a comment to the end of
//! its line. Like [`super::parse`], reading never panics, allocates nothing and stops at the
//! first problem, naming its line.
//!
//! The model's camera always looks along −z from its eye, so the whole scene is moved into the
//! NFF camera's frame: eye at the origin, view plane z = −1, the window the field of view.

use crate::model::{Description, Light, LightSource, ObjectDescription, Palette, Primitive, Projection, Rgb4, SceneError, SceneErrorKind, Taper, Token, VertexNormals, Viewport, Window, MAX_LIGHTS};
use crate::storage::List;

use super::polygon::{self, MAX_POLYGON_VERTICES};

/// Reads an NFF scene (`.nff`) into a description whose objects live in `L`.
pub fn parse_into_list<L: List<ObjectDescription>>(text: &[u8]) -> Result<Description<L>, SceneError> {
    let mut scene = Description::default();
    let mut reader = Reader { tokens: Tokens { text, position: 0, line: 1 }, camera: None, material: Material::default(), groups: Groups::default(), lights: 0, background: [0.0; 3], light_lines: [0; MAX_LIGHTS] };
    let mut light_positions = [[0.0; 3]; MAX_LIGHTS];
    let mut light_weights = [0.0; MAX_LIGHTS];
    while let Some((keyword, line)) = reader.tokens.next()? {
        match keyword {
            "v" => reader.view(line, &mut scene)?,
            "b" => reader.background = reader.colour("b")?,
            "l" => {
                let position = reader.point("l")?;
                // An optional colour: its luminance weighs the light.
                let weight = if reader.tokens.peek_is_number() { luminance(reader.colour("l colour")?) } else { 1.0 };
                let index = reader.lights;
                let (Some(slot), Some(weight_slot), Some(line_slot)) = (light_positions.get_mut(index), light_weights.get_mut(index), reader.light_lines.get_mut(index)) else {
                    return Err(SceneError::new(line, SceneErrorKind::TooManyLights { capacity: MAX_LIGHTS }));
                };
                *slot = position;
                *weight_slot = weight;
                *line_slot = line;
                reader.lights += 1;
            }
            "f" => reader.fill(line)?,
            "s" => {
                let centre = reader.point("s centre")?;
                let radius = reader.number("s radius")?;
                let camera = reader.camera(line)?;
                let radius = radius.abs();
                let c = camera.point(centre);
                let object = reader.object(Primitive::Sphere, [[radius, 0.0, 0.0], [0.0, radius, 0.0], [0.0, 0.0, radius], c], line);
                push(&mut scene, object, line)?;
            }
            "c" => {
                let (base, base_radius) = (reader.point("c base")?, reader.number("c base radius")?);
                let (apex, apex_radius) = (reader.point("c apex")?, reader.number("c apex radius")?);
                let camera = reader.camera(line)?;
                // Negative radii (seen from inside only, in NFF) are taken as their size: the
                // frustum is seen from both sides.
                let (base_radius, apex_radius) = (base_radius.abs(), apex_radius.abs());
                // The narrow end at z = 0, the wide one (radius 1 in object space) at z = 1.
                let (narrow, wide, narrow_radius, wide_radius) =
                    if base_radius <= apex_radius { (base, apex, base_radius, apex_radius) } else { (apex, base, apex_radius, base_radius) };
                let axis = sub(camera.point(wide), camera.point(narrow));
                let length = libm::sqrt(dot(axis, axis));
                if !(length > 0.0 && wide_radius > 0.0) {
                    return Err(SceneError::new(line, SceneErrorKind::InvalidRectangle { what: "c", requirement: "a cone needs two different end points and a radius above 0" }));
                }
                let taper = Taper::from_f64(narrow_radius / wide_radius).unwrap_or(Taper::CYLINDER);
                let (u, v) = perpendiculars(axis.map(|c| c / length));
                let rows = [u.map(|c| c * wide_radius), v.map(|c| c * wide_radius), axis, camera.point(narrow)];
                let object = reader.object(Primitive::Frustum(taper), rows, line);
                push(&mut scene, object, line)?;
            }
            "p" | "pp" => reader.polygon(line, keyword == "pp", &mut scene)?,
            other => return Err(SceneError::new(line, SceneErrorKind::UnknownKeyword { keyword: Token::new(other), suggestion: None })),
        }
    }
    let camera = reader.camera(reader.tokens.line)?;
    // Every light, each 1/√n bright so that several lights neither darken nor saturate.
    let count = reader.lights.max(1);
    let share = 1.0 / libm::sqrt(count as f64);
    for (index, (position, weight)) in light_positions.iter().zip(light_weights).take(reader.lights).enumerate() {
        let light = Light::Point(camera.point(*position));
        let line = reader.light_lines.get(index).copied().unwrap_or(0);
        if index == 0 {
            scene.light = light;
            scene.light_intensity = share * weight;
            scene.lines.light = line;
        } else {
            let source = LightSource { light, intensity: share * weight, line };
            scene.more_lights.push(source).map_err(|_| SceneError::new(line, SceneErrorKind::TooManyLights { capacity: MAX_LIGHTS }))?;
        }
    }
    if reader.lights == 0 {
        // No light: one at the eye, as a viewer's lamp.
        scene.light = Light::Point([0.0; 3]);
    }
    let group = reader.groups.group_of(reader.background);
    let shade = libm::round(15.0 * reader.background.iter().copied().fold(0.0, f64::max)).clamp(0.0, 15.0) as u8;
    scene.background = 16 * group + shade;
    scene.palette = reader.groups.palette();
    Ok(scene)
}

/// The NFF reader's state: the view read so far, the current material, the colour groups.
struct Reader<'a> {
    tokens: Tokens<'a>,
    camera: Option<CameraFrame>,
    material: Material,
    groups: Groups,
    lights: usize,
    background: [f64; 3],
    light_lines: [u32; MAX_LIGHTS],
}

/// The current `f`: the colour's group and the chapter-5 material.
#[derive(Clone, Copy, Default)]
struct Material {
    group: u8,
    colour: [f64; 3],
    kd: f64,
    ks: f64,
    power: f64,
    transmit: f64,
    ior: f64,
}

impl<'a> Reader<'a> {
    /// The next token as a number (`what` names it in errors).
    fn number(&mut self, what: &'static str) -> Result<f64, SceneError> {
        let Some((token, line)) = self.tokens.next()? else {
            return Err(SceneError::new(self.tokens.line, SceneErrorKind::UnexpectedEnd { expected: what }));
        };
        match token.parse::<f64>() {
            Ok(value) if value.is_finite() => Ok(value),
            Ok(_) => Err(SceneError::new(line, SceneErrorKind::NumberNotFinite { what, token: Token::new(token) })),
            Err(_) => Err(SceneError::new(line, SceneErrorKind::MalformedNumber { what, token: Token::new(token) })),
        }
    }

    fn point(&mut self, what: &'static str) -> Result<[f64; 3], SceneError> {
        Ok([self.number(what)?, self.number(what)?, self.number(what)?])
    }

    /// Three numbers 0..=1 (values above 1 are kept to 1).
    fn colour(&mut self, what: &'static str) -> Result<[f64; 3], SceneError> {
        let line = self.tokens.line;
        let colour = self.point(what)?;
        if colour.iter().any(|c| *c < 0.0) {
            return Err(SceneError::new(line, SceneErrorKind::ValueOutOfRange { what, token: Token::new("a negative component"), range: "0 to 1 for each of red, green and blue" }));
        }
        Ok(colour.map(|c| c.min(1.0)))
    }

    /// The camera frame, which every object needs: NFF puts the view first.
    fn camera(&self, line: u32) -> Result<CameraFrame, SceneError> {
        self.camera.ok_or(SceneError::new(line, SceneErrorKind::ViewRequired))
    }

    /// `v`: from, at, up, angle, hither, resolution, each a word and its numbers (in any order;
    /// `yon` is read and ignored).
    fn view(&mut self, line: u32, scene: &mut Description<impl List<ObjectDescription>>) -> Result<(), SceneError> {
        let (mut from, mut at, mut up, mut angle, mut resolution) = (None, None, None, None, None);
        let mut seen = 0;
        while seen < 6 {
            let Some((word, word_line)) = self.tokens.peek()? else { break };
            match word {
                "from" | "at" | "up" => {
                    self.tokens.next()?;
                    let value = Some(self.point(match word { "from" => "v from", "at" => "v at", _ => "v up" })?);
                    match word {
                        "from" => from = value,
                        "at" => at = value,
                        _ => up = value,
                    }
                }
                "angle" => {
                    self.tokens.next()?;
                    let value = self.number("v angle")?;
                    if !(value > 0.0 && value < 180.0) {
                        return Err(SceneError::new(word_line, SceneErrorKind::ValueOutOfRange { what: "v angle", token: Token::new("the angle"), range: "between 0 and 180 degrees" }));
                    }
                    angle = Some(value);
                }
                "hither" | "yon" => {
                    self.tokens.next()?;
                    self.number("v hither")?;
                }
                "resolution" => {
                    self.tokens.next()?;
                    let (width, height) = (self.number("v resolution")?, self.number("v resolution")?);
                    let side = |value: f64| ((1.0..=8192.0).contains(&value) && libm::trunc(value) == value).then_some(value as u16);
                    let (Some(width), Some(height)) = (side(width), side(height)) else {
                        return Err(SceneError::new(word_line, SceneErrorKind::ValueOutOfRange { what: "v resolution", token: Token::new("the resolution"), range: "whole numbers of pixels from 1 to 8192" }));
                    };
                    resolution = Some((width, height));
                }
                _ => break,
            }
            seen += 1;
        }
        let missing = |what: &'static str| SceneError::new(line, SceneErrorKind::UnexpectedEnd { expected: what });
        let from = from.ok_or(missing("`from` of the view"))?;
        let at = at.ok_or(missing("`at` of the view"))?;
        let up = up.ok_or(missing("`up` of the view"))?;
        let angle = angle.ok_or(missing("`angle` of the view"))?;
        let (width, height) = resolution.unwrap_or((512, 512));
        let camera = CameraFrame::new(from, at, up).ok_or(SceneError::new(line, SceneErrorKind::ZeroDirection))?;
        self.camera = Some(camera);
        // The first and last pixels' centres lie on the window's edges (the thesis's mapping and
        // NFF's definition of the angle); square pixels.
        let half = libm::tan(angle.to_radians() / 2.0);
        let half_x = if height > 1 { half * f64::from(width - 1) / f64::from(height - 1) } else { half };
        scene.viewport = Viewport { x1: 0, x2: width - 1, y1: 0, y2: height - 1 };
        scene.window = Window { x1: -half_x, x2: half_x, y1: -half, y2: half };
        scene.view_plane = -1.0;
        scene.projection = Projection::Perspective { eye: [0.0; 3] };
        scene.ambient = 0.1;
        scene.shadows = true;
        scene.lines.window = line;
        scene.lines.view_plane = line;
        scene.lines.projection = line;
        Ok(())
    }

    /// `f r g b Kd Ks Shine T index`.
    fn fill(&mut self, line: u32) -> Result<(), SceneError> {
        let colour = self.colour("f colour")?;
        let mut next = |what| self.number(what);
        let (kd, ks, power, transmit, ior) = (next("f Kd")?, next("f Ks")?, next("f Shine")?, next("f T")?, next("f index of refraction")?);
        let bad = |what: &'static str, range: &'static str| SceneError::new(line, SceneErrorKind::ValueOutOfRange { what, token: Token::new("the value"), range });
        // Every number read is finite.
        if kd < 0.0 || ks < 0.0 {
            return Err(bad("f Kd, Ks", "at least 0"));
        }
        if power < 0.0 {
            return Err(bad("f Shine", "at least 0"));
        }
        if !(0.0..=1.0).contains(&transmit) {
            return Err(bad("f T", "0 to 1"));
        }
        // The SPD writes an index of 0 for opaque surfaces: a glass needs a real one.
        let ior = if transmit > 0.0 || ior != 0.0 { ior } else { 1.0 };
        if !(0.1..=10.0).contains(&ior) {
            return Err(bad("f index of refraction", "0.1 to 10 (0 for an opaque surface)"));
        }
        self.material = Material { group: self.groups.group_of(colour), colour, kd, ks, power: power.min(1e6), transmit, ior };
        Ok(())
    }

    /// An object of the current material whose transform has the rows given (row-vector
    /// convention: the images of x, y, z and the origin).
    fn object(&self, primitive: Primitive, rows: [[f64; 3]; 4], line: u32) -> ObjectDescription {
        let mut object = ObjectDescription::new(primitive, line);
        for (row, values) in object.world_from_object.rows.iter_mut().zip(rows) {
            row[..3].copy_from_slice(&values);
        }
        let m = &self.material;
        object.material.colour = m.group;
        object.material.ka = 1.0;
        object.material.kd = m.kd;
        object.material.ks = m.ks;
        object.material.pwr = m.power;
        object.material.rnd = 0.0;
        object.material.cmy = m.colour.map(|c| 1.0 - c);
        // NFF's Ks is the mirror's share as well as the highlight's.
        object.material.reflect = m.ks.min(1.0);
        object.material.transmit = m.transmit;
        object.material.ior = m.ior;
        object
    }

    /// `p n` and n vertices, or `pp n` and n vertices each with its normal: split into
    /// triangles (`polygon::triangulate`).
    fn polygon(&mut self, line: u32, patch: bool, scene: &mut Description<impl List<ObjectDescription>>) -> Result<(), SceneError> {
        let what = if patch { "pp vertex count" } else { "p vertex count" };
        let count = self.number(what)?;
        if !((3.0..=MAX_POLYGON_VERTICES as f64).contains(&count) && libm::trunc(count) == count) {
            return Err(SceneError::new(line, SceneErrorKind::IntegerOutOfRange { what, token: Token::new("the count"), min: 3, max: MAX_POLYGON_VERTICES as i32 }));
        }
        let camera = self.camera(line)?;
        let mut points: heapless::Vec<[f64; 3], MAX_POLYGON_VERTICES> = heapless::Vec::new();
        let mut normals: heapless::Vec<[f64; 3], MAX_POLYGON_VERTICES> = heapless::Vec::new();
        for _ in 0..count as usize {
            let vertex = self.point(if patch { "pp vertex" } else { "p vertex" })?;
            let _ = points.push(camera.point(vertex));
            if patch {
                let normal = self.point("pp normal")?;
                let _ = normals.push(camera.vector(normal));
            }
        }
        polygon::triangulate(&points, |[a, b, c]| {
            let (Some(&p0), Some(&p1), Some(&p2)) = (points.get(a), points.get(b), points.get(c)) else { return Ok(()) };
            let (e1, e2) = (sub(p1, p0), sub(p2, p0));
            let normal = cross(e1, e2);
            let area = libm::sqrt(dot(normal, normal));
            // The third axis, the plane's normal, as long as the triangle is wide: a transform
            // no worse conditioned than the triangle itself.
            let third = libm::sqrt(area);
            if !(area > 0.0 && third > 0.0 && area.is_finite()) {
                return Ok(());
            }
            let e3 = normal.map(|c| c / area * third);
            // A patch's corner normals carried into object space (n ↦ (e₁·n, e₂·n, e₃·n), the
            // inverse of how the tracer carries an object's normal out); a patch whose normals
            // are all zero is a flat triangle.
            let corners = match (normals.get(a), normals.get(b), normals.get(c)) {
                (Some(&n0), Some(&n1), Some(&n2)) => VertexNormals::from_f64([n0, n1, n2].map(|n| [dot(e1, n), dot(e2, n), dot(e3, n)])),
                _ => None,
            };
            #[cfg(feature = "triangle")]
            let primitive = corners.map_or(Primitive::Triangle, Primitive::Patch);
            // Without the triangle's code a patch is refused at preparation as a triangle is.
            #[cfg(not(feature = "triangle"))]
            let primitive = corners.map_or(Primitive::Triangle, |_| Primitive::Triangle);
            let object = self.object(primitive, [e1, e2, e3, p0], line);
            if object.world_from_object.affine_inverse().is_none() {
                return Ok(());
            }
            push(scene, object, line)
        })
    }
}

fn push<L: List<ObjectDescription>>(scene: &mut Description<L>, object: ObjectDescription, line: u32) -> Result<(), SceneError> {
    if object.world_from_object.affine_inverse().is_none() {
        return Err(SceneError::new(line, SceneErrorKind::SingularTransform));
    }
    scene.objects.push(object).map_err(|_| SceneError::new(line, SceneErrorKind::TooManyObjects { capacity: L::CAPACITY }))
}

/// Rec. 601 luma of a colour 0..=1.
fn luminance(colour: [f64; 3]) -> f64 {
    0.299 * colour[0] + 0.587 * colour[1] + 0.114 * colour[2]
}

/// The NFF camera's frame: a point's place seen from the eye, x right, y up, z back.
#[derive(Clone, Copy)]
struct CameraFrame {
    eye: [f64; 3],
    rows: [[f64; 3]; 3],
}

impl CameraFrame {
    /// `None` when `at` is the eye or `up` is along the view.
    fn new(from: [f64; 3], at: [f64; 3], up: [f64; 3]) -> Option<Self> {
        let forward = normalised(sub(at, from))?;
        let right = normalised(cross(forward, up))?;
        let true_up = cross(right, forward);
        Some(Self { eye: from, rows: [right, true_up, forward.map(|c| -c)] })
    }

    fn vector(&self, v: [f64; 3]) -> [f64; 3] {
        self.rows.map(|row| dot(row, v))
    }

    fn point(&self, p: [f64; 3]) -> [f64; 3] {
        self.vector(sub(p, self.eye))
    }
}

/// The colour groups of the look-up table: one per distinct colour (in 4-bit cells), 16 at
/// most; a 17th colour takes the nearest group's.
#[derive(Default)]
struct Groups {
    cells: heapless::Vec<Rgb4, 16>,
}

impl Groups {
    fn group_of(&mut self, colour: [f64; 3]) -> u8 {
        let level = |c: f64| libm::round(15.0 * c).clamp(0.0, 15.0) as u8;
        let cell = Rgb4::new(level(colour[0]), level(colour[1]), level(colour[2]));
        if let Some(index) = self.cells.iter().position(|known| *known == cell) {
            return index as u8;
        }
        if self.cells.push(cell).is_ok() {
            return (self.cells.len() - 1) as u8;
        }
        let distance = |known: &Rgb4| {
            let d = |a: u8, b: u8| i32::from(a) - i32::from(b);
            d(known.r, cell.r).pow(2) + d(known.g, cell.g).pow(2) + d(known.b, cell.b).pow(2)
        };
        self.cells.iter().enumerate().min_by_key(|(_, known)| distance(known)).map(|(index, _)| index as u8).unwrap_or(0)
    }

    /// Each group a ramp from black up to its colour (`group N R G B up`).
    fn palette(&self) -> Palette {
        let mut palette = Palette::grey();
        for (group, cell) in self.cells.iter().enumerate() {
            palette.set_group_up(group as u8, *cell);
        }
        palette
    }
}

/// Whitespace-separated tokens with their lines; `#` to the end of a line is a comment.
struct Tokens<'a> {
    text: &'a [u8],
    position: usize,
    line: u32,
}

impl<'a> Tokens<'a> {
    fn skip_space(&mut self) {
        while let Some(&byte) = self.text.get(self.position) {
            match byte {
                b'\n' => self.line = self.line.saturating_add(1),
                b' ' | b'\t' | b'\r' | b'\x0c' | b'\x0b' => {}
                b'#' => {
                    while self.text.get(self.position).is_some_and(|b| *b != b'\n') {
                        self.position += 1;
                    }
                    continue;
                }
                _ => return,
            }
            self.position += 1;
        }
    }

    fn next(&mut self) -> Result<Option<(&'a str, u32)>, SceneError> {
        self.skip_space();
        let start = self.position;
        while self.text.get(self.position).is_some_and(|b| !b.is_ascii_whitespace() && *b != b'#') {
            self.position += 1;
        }
        let bytes = self.text.get(start..self.position).unwrap_or(&[]);
        if bytes.is_empty() {
            return Ok(None);
        }
        let token = core::str::from_utf8(bytes).map_err(|_| SceneError::new(self.line, SceneErrorKind::InvalidUtf8))?;
        Ok(Some((token, self.line)))
    }

    fn peek(&mut self) -> Result<Option<(&'a str, u32)>, SceneError> {
        let (position, line) = (self.position, self.line);
        let token = self.next();
        (self.position, self.line) = (position, line);
        token
    }

    /// Whether the next token starts like a number (a statement's keyword never does).
    fn peek_is_number(&mut self) -> bool {
        matches!(self.peek(), Ok(Some((token, _))) if token.bytes().next().is_some_and(|b| b.is_ascii_digit() || b == b'-' || b == b'+' || b == b'.'))
    }
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
}

fn normalised(v: [f64; 3]) -> Option<[f64; 3]> {
    let length = libm::sqrt(dot(v, v));
    (length > 0.0 && length.is_finite()).then(|| v.map(|c| c / length))
}

/// Two unit vectors perpendicular to the unit `axis` and to each other, (u, v, axis) right-handed.
fn perpendiculars(axis: [f64; 3]) -> ([f64; 3], [f64; 3]) {
    let helper = if axis[0].abs() < 0.6 { [1.0, 0.0, 0.0] } else { [0.0, 1.0, 0.0] };
    let u = normalised(cross(helper, axis)).unwrap_or([1.0, 0.0, 0.0]);
    (u, cross(axis, u))
}

#[cfg(test)]
mod tests;
