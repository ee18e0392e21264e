//! The core's layers (docs/architecture.md, "Layers"): read from the sources, no module imports
//! a module of its own or a higher layer, and no two files import each other, directly or
//! round a circle. Test code (`tests.rs` files, `#[cfg(test)]` modules) is left out: a test
//! may reach anything.
//!
//! An import is a `use` (a `pub use` is a re-export, a door, not a dependency) or a path in
//! code (`crate::a::B`, `super::B`). A name is followed through re-exports to the file that
//! defines it, so `crate::render::Statistics` counts as an import of `render/statistics.rs`.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

fn repository() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The source with comments, string and character literals blanked and `#[cfg(test)]` items
/// cut out.
fn code_of(source: &str) -> String {
    let bytes = source.as_bytes();
    let mut out = String::with_capacity(source.len());
    let mut i = 0;
    while i < bytes.len() {
        let rest = &source[i..];
        if rest.starts_with("//") {
            i += rest.find('\n').unwrap_or(rest.len());
        } else if rest.starts_with("/*") {
            i += rest.find("*/").map_or(rest.len(), |end| end + 2);
        } else if rest.starts_with("r#\"") || rest.starts_with("r\"") {
            let hashes = rest[1..].chars().take_while(|&c| c == '#').count();
            let close = format!("\"{}", "#".repeat(hashes));
            let body = 2 + hashes;
            i += body + rest[body..].find(&close).map_or(rest.len() - body, |end| end + close.len());
            out.push_str("\"\"");
        } else if rest.starts_with('"') {
            let mut j = 1;
            while j < rest.len() && !rest[j..].starts_with('"') {
                j += if rest[j..].starts_with('\\') { 2 } else { rest[j..].chars().next().map_or(1, char::len_utf8) };
            }
            i += j + 1;
            out.push_str("\"\"");
        } else if rest.starts_with('\'') && (rest[1..].starts_with('\\') || rest[1..].chars().nth(1) == Some('\'')) {
            // A character literal (a lifetime has no closing quote after one character).
            let end = rest[2..].find('\'').map_or(rest.len(), |end| end + 3);
            i += end;
            out.push_str("' '");
        } else {
            let c = rest.chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
        }
    }
    cut_test_items(&out)
}

/// Removes each `#[cfg(test)]` item: up to its `;` or its balanced `{ }`.
fn cut_test_items(code: &str) -> String {
    let mut out = String::new();
    let mut rest = code;
    while let Some(start) = rest.find("#[cfg(test)]") {
        out.push_str(&rest[..start]);
        let after = &rest[start..];
        let semicolon = after.find(';').unwrap_or(after.len());
        let brace = after.find('{').unwrap_or(after.len());
        if semicolon < brace {
            rest = &after[(semicolon + 1).min(after.len())..];
            continue;
        }
        let mut depth = 0usize;
        let mut end = after.len();
        for (offset, c) in after.char_indices().skip(brace) {
            match c {
                '{' => depth += 1,
                '}' => {
                    depth -= 1;
                    if depth == 0 {
                        end = offset + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// One source file of the core: its module path (`["render", "image"]`), its code.
struct File {
    path: String,
    module: Vec<String>,
    code: String,
}

fn core_files() -> Vec<File> {
    let root = repository().join("core/src");
    let mut files = Vec::new();
    let mut folders = vec![root.clone()];
    while let Some(folder) = folders.pop() {
        for entry in std::fs::read_dir(&folder).expect("core/src is readable") {
            let path = entry.expect("a directory entry").path();
            if path.is_dir() {
                folders.push(path);
                continue;
            }
            let relative = path.strip_prefix(&root).expect("below core/src").to_string_lossy().replace('\\', "/");
            if !relative.ends_with(".rs") || relative.ends_with("tests.rs") {
                continue;
            }
            let mut module: Vec<String> = relative.trim_end_matches(".rs").split('/').map(str::to_owned).collect();
            if matches!(module.last().map(String::as_str), Some("mod" | "lib")) {
                module.pop();
            }
            let source = std::fs::read_to_string(&path).expect("a source file is readable");
            files.push(File { path: relative, module, code: code_of(&source) });
        }
    }
    files.sort_by(|a, b| a.path.cmp(&b.path));
    files
}

fn is_identifier(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Every `use` tree of the code with whether it is a re-export, as flat paths (`a::{b, c::d}`
/// gives `a::b` and `a::c::d`; `a::b as c` gives `a::b`).
fn use_paths(code: &str) -> Vec<(bool, Vec<String>)> {
    let mut found = Vec::new();
    let mut from = 0;
    while let Some(at) = code[from..].find("use ").map(|at| at + from) {
        from = at + 4;
        let before = code[..at].trim_end();
        if code[..at].chars().last().is_some_and(is_identifier) {
            continue;
        }
        let at_statement_start = before.is_empty() || before.ends_with([';', '{', '}', ']']) || before.ends_with("pub") || before.ends_with(')');
        if !at_statement_start {
            continue;
        }
        let reexport = before.ends_with("pub") || (before.ends_with(')') && before.rfind("pub(").is_some_and(|open| before[open..].find(')') == Some(before.len() - open - 1)));
        let Some(end) = code[from..].find(';') else { break };
        // Whitespace folded to single spaces, then dropped but for the one of `x as y`.
        let folded = code[from..from + end].split_whitespace().collect::<Vec<_>>().join(" ");
        let tree = folded.replace(" as ", "\u{0}").replace(' ', "").replace('\u{0}', " as ");
        for path in expand(&tree) {
            found.push((reexport, path));
        }
    }
    found
}

fn expand(tree: &str) -> Vec<Vec<String>> {
    let mut paths = Vec::new();
    expand_into(Vec::new(), tree, &mut paths);
    paths
}

fn expand_into(prefix: Vec<String>, tree: &str, paths: &mut Vec<Vec<String>>) {
    if let Some(open) = tree.find('{') {
        let mut base = prefix;
        base.extend(tree[..open].split("::").filter(|s| !s.is_empty()).map(str::to_owned));
        let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
        let mut depth = 0;
        let mut start = 0;
        for (offset, c) in inner.char_indices() {
            match c {
                '{' => depth += 1,
                '}' => depth -= 1,
                ',' if depth == 0 => {
                    expand_into(base.clone(), &inner[start..offset], paths);
                    start = offset + 1;
                }
                _ => {}
            }
        }
        if start < inner.len() {
            expand_into(base, &inner[start..], paths);
        }
        return;
    }
    let mut path = prefix;
    let tree = tree.split(" as ").next().unwrap_or(tree);
    path.extend(tree.split("::").filter(|s| !s.is_empty() && *s != "*" && *s != "self").map(str::to_owned));
    if !path.is_empty() {
        paths.push(path);
    }
}

/// The code without its `use` statements.
fn without_uses(code: &str) -> String {
    let mut kept = String::new();
    let mut rest = code;
    while let Some(at) = rest.find("use ") {
        let boundary = at == 0 || !rest[..at].chars().last().is_some_and(is_identifier);
        let end = rest[at..].find(';').map_or(rest.len(), |end| at + end + 1);
        if boundary {
            kept.push_str(&rest[..at]);
        } else {
            kept.push_str(&rest[..end]);
        }
        rest = &rest[end..];
    }
    kept.push_str(rest);
    kept
}

/// Paths written in code (not in `use`): `crate::a::b` and `super::a`.
fn code_paths(code: &str) -> Vec<Vec<String>> {
    let without_uses = without_uses(code);
    let mut paths = Vec::new();
    for root in ["crate::", "super::"] {
        let mut from = 0;
        while let Some(at) = without_uses[from..].find(root).map(|at| at + from) {
            from = at + root.len();
            if without_uses[..at].chars().last().is_some_and(|c| is_identifier(c) || c == ':') {
                continue;
            }
            let tail: String = without_uses[at..].chars().take_while(|&c| is_identifier(c) || c == ':').collect();
            paths.push(tail.split("::").filter(|s| !s.is_empty()).map(str::to_owned).collect());
        }
    }
    paths
}

struct Crate {
    files: Vec<File>,
    by_module: BTreeMap<Vec<String>, usize>,
}

impl Crate {
    /// Whether the file defines an item of this name (at any depth: an associated item is not
    /// imported by path, so a false match only makes the import point at the right file).
    fn defines(&self, file: usize, name: &str) -> bool {
        let code = &self.files[file].code;
        ["struct ", "enum ", "trait ", "fn ", "const ", "static ", "type ", "mod ", "macro_rules! "].iter().any(|keyword| {
            let pattern = format!("{keyword}{name}");
            code.match_indices(&pattern).any(|(at, _)| {
                let before_ok = !code[..at].chars().last().is_some_and(is_identifier);
                let after_ok = !code[at + pattern.len()..].chars().next().is_some_and(is_identifier);
                before_ok && after_ok
            })
        })
    }

    /// The file that defines `name` as seen from module `module`: its own, or through its
    /// re-exports (named or glob).
    fn item_file(&self, module: &[String], name: &str, depth: usize) -> Option<usize> {
        let file = *self.by_module.get(module)?;
        if let Some(child) = self.by_module.get(&[module, &[name.to_owned()]].concat()) {
            return Some(*child);
        }
        if self.defines(file, name) || depth > 8 {
            return Some(file);
        }
        for (reexport, path) in use_paths(&self.files[file].code) {
            if !reexport {
                continue;
            }
            let last = path.last().map(String::as_str);
            let glob = self.is_glob(file, &path);
            if last == Some(name) || glob {
                let mut full = path.clone();
                if glob {
                    full.push(name.to_owned());
                }
                if let Some(found) = self.resolve(module, &full, depth + 1) {
                    if found != file && (!glob || self.defines(found, name)) {
                        return Some(found);
                    }
                }
            }
        }
        Some(file)
    }

    fn is_glob(&self, file: usize, path: &[String]) -> bool {
        let joined = path.join("::");
        self.files[file].code.contains(&format!("{joined}::*"))
    }

    /// The file a path written in module `from` leads to (`None`: outside the crate).
    fn resolve(&self, from: &[String], path: &[String], depth: usize) -> Option<usize> {
        let first = path.first()?.as_str();
        let (mut module, rest): (Vec<String>, &[String]) = match first {
            "crate" => (Vec::new(), &path[1..]),
            "self" => (from.to_vec(), &path[1..]),
            "super" => {
                let mut module = from.to_vec();
                let mut rest = path;
                while rest.first().map(String::as_str) == Some("super") {
                    module.pop();
                    rest = &rest[1..];
                }
                (module, rest)
            }
            child if self.by_module.contains_key(&[from, &[child.to_owned()]].concat()) => (from.to_vec(), path),
            _ => return None,
        };
        let mut rest = rest;
        while let Some(segment) = rest.first() {
            let deeper = [module.as_slice(), std::slice::from_ref(segment)].concat();
            if !self.by_module.contains_key(&deeper) {
                break;
            }
            module = deeper;
            rest = &rest[1..];
        }
        match rest.first() {
            Some(name) => self.item_file(&module, name, depth),
            None => self.by_module.get(&module).copied(),
        }
    }

    /// Paths in code that start at one of the file's own submodules (`child::item`).
    fn child_paths(&self, file: &File) -> Vec<Vec<String>> {
        let children: Vec<&str> = self
            .by_module
            .keys()
            .filter(|module| module.len() == file.module.len() + 1 && module.starts_with(&file.module))
            .filter_map(|module| module.last().map(String::as_str))
            .collect();
        let code = without_uses(&file.code);
        let mut paths = Vec::new();
        for child in children {
            let pattern = format!("{child}::");
            for (at, _) in code.match_indices(&pattern) {
                let before = code[..at].chars().last();
                if before.is_some_and(|c| is_identifier(c) || c == ':') {
                    continue;
                }
                let tail: String = code[at..].chars().take_while(|&c| is_identifier(c) || c == ':').collect();
                paths.push(tail.split("::").filter(|s| !s.is_empty()).map(str::to_owned).collect());
            }
        }
        paths
    }

    /// Each file's imports (indices of other files).
    fn imports(&self) -> Vec<BTreeSet<usize>> {
        self.files
            .iter()
            .enumerate()
            .map(|(index, file)| {
                let uses = use_paths(&file.code).into_iter().filter(|(reexport, _)| !reexport).map(|(_, path)| path);
                uses.chain(code_paths(&file.code))
                    .chain(self.child_paths(file))
                    .filter_map(|path| self.resolve(&file.module, &path, 0))
                    .filter(|&target| target != index)
                    .collect()
            })
            .collect()
    }
}

fn core_crate() -> Crate {
    let files = core_files();
    let by_module = files.iter().enumerate().map(|(index, file)| (file.module.clone(), index)).collect();
    Crate { files, by_module }
}

/// The layers docs/architecture.md declares: its table under "## Layers", one row a layer,
/// lowest first, each naming its modules in backticks.
fn declared_layers() -> BTreeMap<String, usize> {
    let path = repository().join("docs/architecture.md");
    let doc = std::fs::read_to_string(&path).unwrap_or_else(|error| panic!("cannot read {}: {error}", path.display()));
    let section = doc.split("\n## Layers").nth(1).expect("docs/architecture.md has a \"## Layers\" section");
    let section = section.split("\n## ").next().unwrap_or(section);
    let mut layers = BTreeMap::new();
    for line in section.lines().filter(|line| line.starts_with('|')) {
        let cells: Vec<&str> = line.trim_matches('|').split('|').map(str::trim).collect();
        let Some(Ok(layer)) = cells.first().map(|cell| cell.parse::<usize>()) else { continue };
        let modules = cells.get(1).copied().unwrap_or("");
        for module in modules.split('`').skip(1).step_by(2) {
            layers.insert(module.to_owned(), layer);
        }
    }
    assert!(!layers.is_empty(), "docs/architecture.md's layer table names no module");
    layers
}

fn top_module(file: &File) -> Option<&str> {
    file.module.first().map(String::as_str)
}

#[test]
fn every_module_is_in_a_declared_layer() {
    let layers = declared_layers();
    let krate = core_crate();
    let modules: BTreeSet<&str> = krate.files.iter().filter_map(top_module).collect();
    for module in &modules {
        assert!(layers.contains_key(*module), "core/src/{module} is in no layer of docs/architecture.md");
    }
    for declared in layers.keys() {
        assert!(modules.contains(declared.as_str()), "docs/architecture.md declares `{declared}`, which core/src does not have");
    }
}

#[test]
fn no_module_imports_its_own_layer_or_above() {
    let layers = declared_layers();
    let krate = core_crate();
    let mut wrong = Vec::new();
    for (index, targets) in krate.imports().iter().enumerate() {
        let file = &krate.files[index];
        let Some(from) = top_module(file) else { continue };
        for &target in targets {
            let Some(to) = top_module(&krate.files[target]) else { continue };
            if from == to {
                continue;
            }
            let (Some(&low), Some(&high)) = (layers.get(to), layers.get(from)) else { continue };
            if low >= high {
                wrong.push(format!("{} (layer {high}) imports {} (layer {low})", file.path, krate.files[target].path));
            }
        }
    }
    assert!(wrong.is_empty(), "imports against the layer order of docs/architecture.md:\n{}", wrong.join("\n"));
}

#[test]
fn no_import_cycle_between_files() {
    let krate = core_crate();
    let imports = krate.imports();
    // Tarjan's strongly connected components: any with more than one file is a cycle.
    struct State<'a> {
        imports: &'a [BTreeSet<usize>],
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on_stack: Vec<bool>,
        next: usize,
        cycles: Vec<Vec<usize>>,
    }
    fn visit(state: &mut State<'_>, v: usize) {
        state.index[v] = Some(state.next);
        state.low[v] = state.next;
        state.next += 1;
        state.stack.push(v);
        state.on_stack[v] = true;
        for &w in state.imports[v].iter() {
            match state.index[w] {
                None => {
                    visit(state, w);
                    state.low[v] = state.low[v].min(state.low[w]);
                }
                Some(index) if state.on_stack[w] => state.low[v] = state.low[v].min(index),
                Some(_) => {}
            }
        }
        if Some(state.low[v]) == state.index[v] {
            let mut component = Vec::new();
            while let Some(w) = state.stack.pop() {
                state.on_stack[w] = false;
                component.push(w);
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                state.cycles.push(component);
            }
        }
    }
    let count = krate.files.len();
    let mut state = State { imports: &imports, index: vec![None; count], low: vec![0; count], stack: Vec::new(), on_stack: vec![false; count], next: 0, cycles: Vec::new() };
    for v in 0..count {
        if state.index[v].is_none() {
            visit(&mut state, v);
        }
    }
    let described: Vec<String> = state
        .cycles
        .iter()
        .map(|cycle| cycle.iter().map(|&file| krate.files[file].path.as_str()).collect::<Vec<_>>().join(", "))
        .collect();
    assert!(described.is_empty(), "files that import each other (round a circle):\n{}", described.join("\n"));
}

/// The reader itself: it must see the imports it is meant to judge, or the tests above pass
/// on nothing.
#[test]
fn the_reader_finds_imports_through_reexports() {
    let krate = core_crate();
    let imports = krate.imports();
    let file = |path: &str| krate.files.iter().position(|file| file.path == path).unwrap_or_else(|| panic!("no core/src/{path}"));
    for (from, expected) in [
        ("render/walk.rs", ["render/coverage.rs", "render/statistics.rs", "scene/prepared.rs", "pixel/mod.rs"]),
        ("render/order.rs", ["render/walk.rs", "render/antialias.rs", "render/statistics.rs", "config.rs"]),
    ] {
        for expected in expected {
            assert!(imports[file(from)].contains(&file(expected)), "{from} should import {expected}");
        }
    }
    let total: usize = imports.iter().map(BTreeSet::len).sum();
    assert!(total > 150, "only {total} imports found in the core");
    let code = code_of("// use crate::x;\nuse crate::a::{b, c::{d as e}};\n#[cfg(test)]\nmod tests { use crate::f; }\nfn g() { crate::h::i(); }\n");
    assert_eq!(use_paths(&code), vec![(false, vec!["crate".into(), "a".into(), "b".into()]), (false, vec!["crate".into(), "a".into(), "c".into(), "d".into()])]);
    assert_eq!(code_paths(&code), vec![vec!["crate".to_owned(), "h".into(), "i".into()]]);
}
