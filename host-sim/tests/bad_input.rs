//! docs/bad-input.md against the code: every row's input, run through the `microtrace` command
//! and through the library, gives exactly the row's message and the row's error; and every
//! error the parser, the preparation and the decoders have appears in some row.

use std::collections::BTreeSet;
use std::path::Path;
use std::process::Command;

use microtrace::formats;
use microtrace::model::{SceneError, SceneErrorKind};
use microtrace::parser::{parse, parse_into_list};
use microtrace::pixel::FrameBuffer;
use microtrace::model::Primitive;
use microtrace::number::NumberKind;
use microtrace_sim::scene_file::{in_file, SceneFileError};
use microtrace_sim::heap::{Growing, HostPrepared};
use microtrace::with_number_kind;

#[allow(dead_code)]
mod common;

use common::{scratch, text};

/// Every scene error, by name. `SceneErrorKind` is `#[non_exhaustive]` (a new error is not a
/// breaking change for the crate's users), so a new variant reaches the last arm, which fails
/// the test naming it until it has a name here and a row in the table.
fn scene_variant(kind: &SceneErrorKind) -> &'static str {
    match kind {
        SceneErrorKind::InvalidUtf8 => "InvalidUtf8",
        SceneErrorKind::UnknownKeyword { .. } => "UnknownKeyword",
        SceneErrorKind::WrongArgumentCount { .. } => "WrongArgumentCount",
        SceneErrorKind::InvalidWord { .. } => "InvalidWord",
        SceneErrorKind::MalformedNumber { .. } => "MalformedNumber",
        SceneErrorKind::NumberNotFinite { .. } => "NumberNotFinite",
        SceneErrorKind::ExpectedInteger { .. } => "ExpectedInteger",
        SceneErrorKind::IntegerOutOfRange { .. } => "IntegerOutOfRange",
        SceneErrorKind::ValueOutOfRange { .. } => "ValueOutOfRange",
        SceneErrorKind::InvalidRectangle { .. } => "InvalidRectangle",
        SceneErrorKind::ZeroDirection => "ZeroDirection",
        SceneErrorKind::ObjectRequired { .. } => "ObjectRequired",
        SceneErrorKind::TooManyObjects { .. } => "TooManyObjects",
        SceneErrorKind::TooManyLights { .. } => "TooManyLights",
        SceneErrorKind::FeatureNotCompiled { .. } => "FeatureNotCompiled",
        SceneErrorKind::SingularTransform => "SingularTransform",
        SceneErrorKind::PrimitiveNotCompiled { .. } => "PrimitiveNotCompiled",
        SceneErrorKind::OutOfRangeForNumberType { .. } => "OutOfRangeForNumberType",
        SceneErrorKind::UnclosedSolid { .. } => "UnclosedSolid",
        SceneErrorKind::EndWithoutSolid => "EndWithoutSolid",
        SceneErrorKind::EmptySolid { .. } => "EmptySolid",
        SceneErrorKind::SolidTooComplex { .. } => "SolidTooComplex",
        SceneErrorKind::OperandRequired { .. } => "OperandRequired",
        SceneErrorKind::OpticsOnOperand { .. } => "OpticsOnOperand",
        SceneErrorKind::OpenSurfaceInSolid { .. } => "OpenSurfaceInSolid",
        SceneErrorKind::UnexpectedEnd { .. } => "UnexpectedEnd",
        SceneErrorKind::ViewRequired => "ViewRequired",
        other => panic!("{other:?}: a scene error with no name here and no row in docs/bad-input.md"),
    }
}

const SCENE_VARIANTS: [&str; 27] = [
    "InvalidUtf8",
    "UnknownKeyword",
    "WrongArgumentCount",
    "InvalidWord",
    "MalformedNumber",
    "NumberNotFinite",
    "ExpectedInteger",
    "IntegerOutOfRange",
    "ValueOutOfRange",
    "InvalidRectangle",
    "ZeroDirection",
    "ObjectRequired",
    "TooManyObjects",
    "TooManyLights",
    "FeatureNotCompiled",
    "SingularTransform",
    "PrimitiveNotCompiled",
    "OutOfRangeForNumberType",
    "UnclosedSolid",
    "EndWithoutSolid",
    "EmptySolid",
    "SolidTooComplex",
    "OperandRequired",
    "OpticsOnOperand",
    "OpenSurfaceInSolid",
    "UnexpectedEnd",
    "ViewRequired",
];

/// `FormatErrorKind` is `#[non_exhaustive]`, so its list is by hand; the decoder tests in the
/// core construct each of them.
const FORMAT_VARIANTS: [&str; 12] = [
    "Empty",
    "UnknownId",
    "TruncatedHeader",
    "ReversedRange",
    "TruncatedPixels",
    "TrailingBytes",
    "NotARecord",
    "RowOrder",
    "TruncatedPacket",
    "PacketPastRow",
    "LutLength",
    "NotIndexed",
];

/// The name of a `Debug`-printed variant (`RowOrder { y: 1, .. }` -> `RowOrder`).
fn variant_name(debug: String) -> String {
    debug.chars().take_while(char::is_ascii_alphanumeric).collect()
}

#[derive(Debug)]
struct Row {
    error: String,
    place: String,
    input: Vec<u8>,
    message: String,
}

/// Splits a table line at the `|` that are not escaped as `\|`, and unescapes them.
fn cells(line: &str) -> Vec<String> {
    let mut cells = vec![String::new()];
    let mut chars = line.trim().trim_start_matches('|').chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                chars.next();
                cells.last_mut().unwrap().push('|');
            }
            '|' => cells.push(String::new()),
            c => cells.last_mut().unwrap().push(c),
        }
    }
    if cells.last().is_some_and(|cell| cell.trim().is_empty()) {
        cells.pop();
    }
    cells.into_iter().map(|cell| cell.trim().to_owned()).collect()
}

/// The input notation: `\n`, `\xHH`, `\\`, `{N:TEXT}`, and *(empty)*.
fn input_bytes(cell: &str) -> Vec<u8> {
    if cell == "*(empty)*" {
        return Vec::new();
    }
    let code = cell.strip_prefix('`').and_then(|c| c.strip_suffix('`')).unwrap_or_else(|| panic!("input {cell} is not in backticks"));
    unescape(code)
}

fn unescape(code: &str) -> Vec<u8> {
    let mut bytes = Vec::new();
    let mut rest = code;
    while let Some(c) = rest.chars().next() {
        if let Some(after) = rest.strip_prefix("\\n") {
            bytes.push(b'\n');
            rest = after;
        } else if let Some(after) = rest.strip_prefix("\\\\") {
            bytes.push(b'\\');
            rest = after;
        } else if let Some(after) = rest.strip_prefix("\\x") {
            bytes.push(u8::from_str_radix(&after[..2], 16).unwrap_or_else(|_| panic!("bad \\x escape in {code}")));
            rest = &after[2..];
        } else if let Some(after) = rest.strip_prefix('{') {
            let end = after.find('}').unwrap_or_else(|| panic!("unclosed {{ in {code}"));
            let (count, text) = after[..end].split_once(':').unwrap_or_else(|| panic!("{{N:TEXT}} expected in {code}"));
            let once = unescape(text);
            for _ in 0..count.parse::<usize>().unwrap() {
                bytes.extend_from_slice(&once);
            }
            rest = &after[end + 1..];
        } else {
            let mut buffer = [0; 4];
            bytes.extend_from_slice(c.encode_utf8(&mut buffer).as_bytes());
            rest = &rest[c.len_utf8()..];
        }
    }
    bytes
}

fn rows() -> Vec<Row> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/bad-input.md");
    let markdown = std::fs::read_to_string(&path).unwrap();
    let mut rows = Vec::new();
    let mut in_table = false;
    for line in markdown.lines() {
        if line.starts_with("| error | where | input | message |") {
            in_table = true;
            continue;
        }
        if !in_table || line.starts_with("|---") {
            continue;
        }
        if !line.starts_with('|') {
            break;
        }
        let cells = cells(line);
        assert_eq!(cells.len(), 4, "a row has 4 cells: {line}");
        rows.push(Row { error: cells[0].clone(), place: cells[1].clone(), input: input_bytes(&cells[2]), message: cells[3].clone() });
    }
    assert!(rows.len() > 30, "the table was not found or is cut short ({} rows)", rows.len());
    rows
}

/// The library's message and error name for a scene row.
fn scene_library(row: &Row) -> (String, String) {
    if row.place == "parse nff" {
        let error = microtrace::parser::nff::parse_into_list::<Growing<_>>(&row.input).expect_err(&format!("{row:?} parses"));
        let name = scene_variant(&error.kind).to_owned();
        return (SceneFileError { path: "scene.nff".into(), error }.to_string(), name);
    }
    let description = parse_into_list::<Growing<_>>(&row.input);
    if row.place == "parse" {
        let error = description.expect_err(&format!("{row:?} parses"));
        let name = scene_variant(&error.kind).to_owned();
        return (SceneFileError { path: "scene.mts".into(), error }.to_string(), name);
    }
    let description = Box::new(description.unwrap_or_else(|error| panic!("{row:?} does not parse: {error}")));
    let number = row.place.strip_prefix("prepare ").unwrap();
    let number = NumberKind::from_name(number).unwrap();
    let prepared = with_number_kind!(number, N => HostPrepared::<N>::prepare(&*description).map(|_| ()));
    let error = prepared.expect_err(&format!("{row:?} prepares"));
    let name = scene_variant(&error.kind).to_owned();
    let message = format!("{:#}", in_file(Path::new("scene.mts"), anyhow::Error::new(error)));
    (message, name)
}

/// What `microtrace` prints for the row (run in a scratch directory, so the files are named as
/// in the table).
fn command_message(row: &Row, directory: &Path) -> String {
    let run = |arguments: &[&str]| {
        let output = Command::new(env!("CARGO_BIN_EXE_microtrace")).args(arguments).current_dir(directory).output().unwrap();
        assert_eq!(output.status.code(), Some(1), "{row:?}: {}", text(&output.stderr));
        assert!(!directory.join("out.png").exists(), "{row:?} wrote an image");
        let stderr = text(&output.stderr);
        stderr.strip_prefix("microtrace: ").and_then(|s| s.strip_suffix('\n')).unwrap_or_else(|| panic!("{row:?}: {stderr:?}")).to_owned()
    };
    match row.place.as_str() {
        "parse" => {
            std::fs::write(directory.join("scene.mts"), &row.input).unwrap();
            run(&["render", "scene.mts", "--out", "out.png"])
        }
        "parse nff" => {
            std::fs::write(directory.join("scene.nff"), &row.input).unwrap();
            run(&["render", "scene.nff", "--out", "out.png"])
        }
        place if place.starts_with("prepare ") => {
            std::fs::write(directory.join("scene.mts"), &row.input).unwrap();
            run(&["render", "scene.mts", "--number", &place["prepare ".len()..], "--out", "out.png"])
        }
        "decode" => {
            std::fs::write(directory.join("image.bin"), &row.input).unwrap();
            run(&["decode", "image.bin", "--out", "out.png"])
        }
        "lut" => {
            std::fs::write(directory.join("image.ff"), b"\xFF\x00\x00\x00\x00\x00\x00\x00\x00\x07").unwrap();
            std::fs::write(directory.join("table.lut"), &row.input).unwrap();
            run(&["decode", "image.ff", "--lut", "table.lut", "--out", "out.png"])
        }
        other => panic!("{row:?}: unknown place {other}"),
    }
}

#[test]
fn every_row_of_the_bad_input_table_gives_its_message_and_every_error_has_a_row() {
    let directory = scratch("bad-input");
    let mut scene_seen = BTreeSet::new();
    let mut format_seen = BTreeSet::new();
    let mut failures = Vec::new();
    for row in rows() {
        let (message, name) = match row.place.as_str() {
            "parse" | "parse nff" => scene_library(&row),
            place if place.starts_with("prepare ") => scene_library(&row),
            "decode" => match formats::inspect(&row.input) {
                Err(error) => (format!("cannot decode image.bin: {error}"), variant_name(format!("{:?}", error.kind))),
                Ok(_) => {
                    let error = microtrace_sim::files::decode_image_file(&write(&directory, "library.bin", &row.input), None)
                        .expect_err(&format!("{row:?} decodes"));
                    (format!("cannot decode image.bin: {error}"), "host".to_owned())
                }
            },
            "lut" => {
                let error = formats::lut::decode_lut(&row.input).expect_err(&format!("{row:?} is a LUT"));
                (format!("cannot read look-up table table.lut: {error}"), variant_name(format!("{:?}", error.kind)))
            }
            "library" if row.error == "TooManyObjects" => {
                // The host's lists grow; a build of fixed capacity (here 512) gives the error.
                assert!(parse_into_list::<Growing<_>>(&row.input).is_ok());
                let error = parse::<512>(&row.input).expect_err(&format!("{row:?} fits 512 objects"));
                (error.to_string(), scene_variant(&error.kind).to_owned())
            }
            "library" if row.error == "PrimitiveNotCompiled" => {
                // Every primitive is compiled into the host, so the input parses and prepares;
                // the error is the one a build without the primitive gives for it.
                let description = parse_into_list::<Growing<_>>(&row.input).unwrap();
                let object = &description.objects[0];
                assert!(Primitive::ALL.iter().all(|p| p.is_compiled()));
                let error = SceneError::new(object.line, SceneErrorKind::PrimitiveNotCompiled { primitive: object.primitive.name() });
                (error.to_string(), scene_variant(&error.kind).to_owned())
            }
            "library" if row.error == "FeatureNotCompiled" => {
                // The host has the ray tree, so the input parses and prepares; the error is the
                // one a build without the `ray-tree` feature gives for it.
                let description = parse_into_list::<Growing<_>>(&row.input).unwrap();
                let object = &description.objects[0];
                assert!(object.material.reflect > 0.0);
                assert!(HostPrepared::<f64>::prepare(&description).is_ok());
                let error = SceneError::new(object.line, SceneErrorKind::FeatureNotCompiled { feature: "ray-tree", statement: "reflect" });
                (error.to_string(), scene_variant(&error.kind).to_owned())
            }
            "library" => {
                let mut pixels = [0u8; 16];
                let error = formats::decode_indices_into(&row.input, &mut FrameBuffer::new(&mut pixels, 4, 4).unwrap())
                    .expect_err(&format!("{row:?} decodes as indices"));
                (error.to_string(), variant_name(format!("{:?}", error.kind)))
            }
            other => panic!("{row:?}: unknown place {other}"),
        };
        if message != row.message {
            failures.push(format!("{} {} {:?}:\n  table: {}\n  code:  {message}", row.error, row.place, text(&row.input), row.message));
        }
        if name != row.error {
            failures.push(format!("{:?} gives {name}, the table says {}", text(&row.input), row.error));
        }
        if row.place != "library" {
            let printed = command_message(&row, &directory);
            if printed != row.message {
                failures.push(format!("{} {}: the command prints\n  {printed}\n  the table says\n  {}", row.error, row.place, row.message));
            }
        }
        if SCENE_VARIANTS.contains(&name.as_str()) && !row.place.starts_with("decode") && row.place != "lut" {
            scene_seen.insert(name);
        } else {
            format_seen.insert(name);
        }
    }
    assert!(failures.is_empty(), "docs/bad-input.md differs from the code:\n{}", failures.join("\n"));
    for variant in SCENE_VARIANTS {
        assert!(scene_seen.contains(variant), "SceneErrorKind::{variant} has no row in docs/bad-input.md");
    }
    for variant in FORMAT_VARIANTS {
        assert!(format_seen.contains(variant), "FormatErrorKind::{variant} has no row in docs/bad-input.md");
    }
}

fn write(directory: &Path, name: &str, bytes: &[u8]) -> std::path::PathBuf {
    let path = directory.join(name);
    std::fs::write(&path, bytes).unwrap();
    path
}
