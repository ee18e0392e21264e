//! `docs/scene-format.md`, the repository's reference of the `.mts` format, checked against the
//! parser so that it cannot drift from the code:
//! - every fenced block marked ```` ```mts ```` parses and prepares in `f64`;
//! - the statement tables (tables whose first header cell is `statement`) name only keywords
//!   the parser knows, and every one of the parser's 38 keywords (`Keyword::ALL` in
//!   core/src/parser/mod.rs) as a statement; a statement listed under "Object statements"
//!   needs an object, one listed elsewhere does not;
//! - every row of the errors table (header `input | message`) gives exactly that message;
//! - every relative link of the document points at a file or folder that exists.

use std::path::{Path, PathBuf};

use microtrace::model::{SceneError, SceneErrorKind};
use microtrace::parser::parse;
use microtrace::scene::Scene;

const CAPACITY: usize = 16;

/// The parser's keywords, in the order of `Keyword::ALL` (core/src/parser/mod.rs).
const KEYWORDS: [&str; 39] = [
    "viewport",
    "window",
    "viewplane",
    "perspective",
    "parallel",
    "light",
    "ambient",
    "background",
    "shadows",
    "dither",
    "group",
    "optimize",
    "cube",
    "sphere",
    "cylinder",
    "cone",
    "torus",
    "frustum",
    "triangle",
    "disc",
    "scale",
    "rotate",
    "translate",
    "colour",
    "ka",
    "kd",
    "ks",
    "pwr",
    "rnd",
    "cmy",
    "reflect",
    "transmit",
    "ior",
    "depth",
    "antialias",
    "end",
    "union",
    "intersection",
    "difference",
];

fn docs() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs")
}

fn document() -> String {
    let path = docs().join("scene-format.md");
    std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("cannot read {}: {error}", path.display()))
}

/// The ```` ```mts ```` blocks: (line of the opening fence, text).
fn mts_blocks(doc: &str) -> Vec<(usize, String)> {
    let mut blocks = Vec::new();
    let mut open: Option<(usize, String)> = None;
    for (index, line) in doc.lines().enumerate() {
        let fence = line.trim_start();
        match open.as_mut() {
            Some(_) if fence.starts_with("```") => blocks.extend(open.take()),
            Some((_, text)) => {
                text.push_str(line);
                text.push('\n');
            }
            None if fence == "```mts" => open = Some((index + 1, String::new())),
            None => {}
        }
    }
    assert!(open.is_none(), "an ```mts block is not closed");
    blocks
}

/// The cells of a table row, split at `|` not escaped as `\|` (escapes undone).
fn cells(row: &str) -> Vec<String> {
    let mut cells = Vec::new();
    let mut cell = String::new();
    let mut chars = row.trim().chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '\\' if chars.peek() == Some(&'|') => {
                cell.push('|');
                chars.next();
            }
            '|' => cells.push(std::mem::take(&mut cell).trim().to_string()),
            _ => cell.push(c),
        }
    }
    // The text before the first `|` is empty; after the last one there is nothing.
    cells.into_iter().skip(1).collect()
}

/// The rows (as cells) of every table whose first header cell is `header`, each with the
/// `## ` heading it stands under.
fn table_rows(doc: &str, header: &str) -> Vec<(String, Vec<String>)> {
    let mut rows = Vec::new();
    let mut heading = String::new();
    let mut in_table = false;
    let mut lines = doc.lines().peekable();
    while let Some(line) = lines.next() {
        if let Some(title) = line.strip_prefix("## ") {
            heading = title.to_string();
        }
        if !line.trim_start().starts_with('|') {
            in_table = false;
            continue;
        }
        if in_table {
            rows.push((heading.clone(), cells(line)));
        } else if cells(line).first().map(String::as_str) == Some(header) {
            in_table = true;
            lines.next(); // the `|---|` row
        }
    }
    rows
}

/// The backtick spans of a cell.
fn code_spans(cell: &str) -> impl Iterator<Item = &str> {
    cell.split('`').skip(1).step_by(2)
}

/// The statements of the statement tables: (heading, keyword, the form as written).
fn statements(doc: &str) -> Vec<(String, String, String)> {
    let mut found = Vec::new();
    for (heading, row) in table_rows(doc, "statement") {
        let first = row.first().cloned().unwrap_or_default();
        for span in code_spans(&first) {
            let keyword = span.split_whitespace().next().unwrap_or("").to_string();
            found.push((heading.clone(), keyword, span.to_string()));
        }
    }
    found
}

/// What the parser (then, if it parses, preparation in `f64`) says about `scene`.
fn outcome(scene: &str) -> Result<(), SceneError> {
    let description = parse::<CAPACITY>(scene.as_bytes())?;
    Scene::<f64, CAPACITY>::prepare(&description).map(|_| ())
}

#[test]
fn every_mts_block_parses() {
    let doc = document();
    let blocks = mts_blocks(&doc);
    assert!(blocks.len() >= 2, "expected the document's example scenes, found {} ```mts blocks", blocks.len());
    for (line, text) in &blocks {
        let description = parse::<CAPACITY>(text.as_bytes())
            .unwrap_or_else(|error| panic!("the ```mts block at docs/scene-format.md line {line} does not parse: {error}"));
        let prepared = Scene::<f64, CAPACITY>::prepare(&description).map(|_| ());
        if let Err(error) = prepared {
            panic!("the ```mts block at docs/scene-format.md line {line} parses but does not prepare: {error}");
        }
    }
}

#[test]
fn the_fixed_keyword_list_is_the_parsers() {
    for keyword in KEYWORDS {
        let result = parse::<CAPACITY>(format!("sphere\n{keyword}\n").as_bytes());
        assert!(
            !matches!(&result, Err(SceneError { kind: SceneErrorKind::UnknownKeyword { .. }, .. })),
            "`{keyword}` is in the test's list but the parser does not know it"
        );
    }
    // The check can fail: a near miss and a capitalised keyword are unknown.
    for word in ["spheer", "Sphere", "color"] {
        let result = parse::<CAPACITY>(format!("sphere\n{word}\n").as_bytes());
        assert!(matches!(result, Err(SceneError { kind: SceneErrorKind::UnknownKeyword { .. }, .. })), "{word}: {result:?}");
    }
}

#[test]
fn the_statement_tables_list_exactly_the_parsers_keywords() {
    let doc = document();
    let statements = statements(&doc);
    assert!(!statements.is_empty(), "no statement tables found");
    for (heading, keyword, form) in &statements {
        let alone = parse::<CAPACITY>(keyword.as_bytes());
        assert!(
            !matches!(&alone, Err(SceneError { kind: SceneErrorKind::UnknownKeyword { .. }, .. })),
            "the table under \"{heading}\" lists `{form}`, but the parser does not know `{keyword}`"
        );
        assert!(KEYWORDS.contains(&keyword.as_str()), "`{keyword}` (under \"{heading}\") is missing from the test's list");
        let needs_object = matches!(&alone, Err(SceneError { kind: SceneErrorKind::ObjectRequired { .. }, .. }));
        let in_object_section = heading.starts_with("Object statements");
        assert_eq!(
            needs_object, in_object_section,
            "`{keyword}` is listed under \"{heading}\", but it {} an object",
            if needs_object { "needs" } else { "does not need" }
        );
    }
    for keyword in KEYWORDS {
        assert!(
            statements.iter().any(|(_, listed, _)| listed == keyword),
            "the parser's keyword `{keyword}` is not a statement in any table of docs/scene-format.md"
        );
        assert!(
            doc.contains(&format!("`{keyword}`")) || doc.contains(&format!("`{keyword} ")),
            "`{keyword}` does not appear in backticks"
        );
    }
}

#[test]
fn the_errors_table_quotes_the_codes_messages() {
    let doc = document();
    let rows = table_rows(&doc, "input");
    assert!(rows.len() >= 10, "expected the errors table, found {} rows", rows.len());
    for (_, row) in rows {
        let [input, message] = [0, 1].map(|index| row.get(index).cloned().unwrap_or_default());
        let scene = code_spans(&input).next().unwrap_or_else(|| panic!("input not in backticks: {input}")).replace("\\n", "\n");
        let error = outcome(&scene).err().unwrap_or_else(|| panic!("`{input}` gives no error"));
        assert_eq!(error.to_string(), message, "the message of {input}");
    }
}

#[test]
fn relative_links_exist() {
    let doc = document();
    let mut checked = 0;
    for piece in doc.split("](").skip(1) {
        let target = piece.split(')').next().unwrap_or("");
        let target = target.split('#').next().unwrap_or("");
        if target.is_empty() || target.contains("://") {
            continue;
        }
        assert!(docs().join(target).exists(), "docs/scene-format.md links to {target}, which does not exist");
        checked += 1;
    }
    assert!(checked > 0);
}
