//! The layout's rules, checked on the source: each folder of `src/` imports only the folders below it
//! (`docs/architecture.md`), no module imports itself through others, the scene's modules import in one
//! direction, the extractors do not know each other, and the scene and the tables know nothing of wgpu.

use crate::common;
#[path = "architecture/imports.rs"]
mod imports;

use std::collections::BTreeMap;
use std::path::Path;

/// The folders of `src/`, lowest first; a folder may import its own and those before it. Modules at
/// the top of `src/` (the native tools, `lib.rs`, `main.rs`), `cli/` (the command line's commands), `web/` and `manifest/` (the elements'
/// descriptions, a native tool) may import any.
const LAYERS: &[&str] = &["scene", "device", "extract", "critical", "teach", "view", "draw", "renderer"];
const SHELLS: &[&str] = &["web", "manifest", "cli"];
/// The scene's modules, in the only order they may import each other.
const SCENE_ORDER: &[&str] =
    &["math", "number", "decimal", "checks", "sphere", "params", "motion", "json", "file"];

/// Every source file of the crate, relative to `src/`, with its code (line comments removed). The
/// GPU-free modules built in crates of their own are read where the crate re-exports them: the
/// scene's (`scene/src/`, whose `crate::` is `crate::scene::` here) as `scene/`, the core's
/// (`core/src/`) as the `extract/` files they are; a module file both crates have is read as one.
fn code() -> BTreeMap<String, String> {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut code = BTreeMap::new();
    for (dir, prefix) in [("src", ""), ("core/src", ""), ("scene/src", "scene/")] {
        let root = manifest.join(dir);
        for path in common::files_under(&root, "rs") {
            let text = std::fs::read_to_string(&path).unwrap();
            let lines: Vec<&str> = text.lines().map(|l| l.split("//").next().unwrap_or("")).collect();
            let mut file = path.strip_prefix(&root).unwrap().to_string_lossy().replace('\\', "/");
            let mut text = lines.join("\n");
            if prefix == "scene/" {
                file = if file == "lib.rs" { "mod.rs".to_string() } else { file };
                text = text.replace("crate::", "crate::scene::");
            }
            let entry: &mut String = code.entry(format!("{prefix}{file}")).or_default();
            entry.push_str(&text);
            entry.push('\n');
        }
    }
    code
}

/// The names that follow `prefix` in `code` (`crate::` → the top modules it names).
fn named_after<'a>(code: &'a str, prefix: &str) -> Vec<&'a str> {
    code.match_indices(prefix)
        .filter(|(at, _)| !code[..*at].ends_with(|c: char| c.is_alphanumeric() || c == '_' || c == ':'))
        .map(|(at, _)| {
            let rest = &code[at + prefix.len()..];
            let end =
                rest.find(|c: char| !(c.is_alphanumeric() || c == '_' || c == '{')).unwrap_or(rest.len());
            &rest[..end]
        })
        .collect()
}

fn layer_of(file: &str) -> Option<usize> {
    let top = file.split('/').next()?;
    LAYERS.iter().position(|&l| l == top)
}

#[test]
fn each_folder_imports_only_the_folders_below_it() {
    let manifest = Path::new(env!("CARGO_MANIFEST_DIR"));
    let folders =
        [manifest.join("src"), manifest.join("core/src")].map(|root| std::fs::read_dir(root).unwrap());
    for entry in folders.into_iter().flatten() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            let name = path.file_name().unwrap().to_string_lossy().to_string();
            assert!(
                LAYERS.contains(&name.as_str()) || SHELLS.contains(&name.as_str()),
                "src/{name}/ has no place among the layers: add it here and to docs/architecture.md"
            );
        }
    }
    let mut violations = Vec::new();
    for (file, code) in code() {
        let Some(own) = layer_of(&file) else { continue };
        for name in named_after(&code, "crate::") {
            if name.starts_with('{') {
                violations.push(format!("{file}: imports through the crate root (crate::{{…}})"));
                continue;
            }
            match LAYERS.iter().position(|&l| l == name) {
                Some(target) if target <= own => {}
                _ => violations.push(format!("{file} ({}) imports crate::{name}", LAYERS[own])),
            }
        }
    }
    assert!(violations.is_empty(), "imports against the layering:\n{}", violations.join("\n"));
}

#[test]
fn the_scene_modules_import_in_one_direction() {
    let rank = |name: &str| SCENE_ORDER.iter().position(|&m| m == name);
    let mut violations = Vec::new();
    for (file, code) in code() {
        let Some(rest) = file.strip_prefix("scene/") else { continue };
        let module = rest.split(['/', '.']).next().unwrap();
        let Some(own) = rank(module) else { continue };
        // `super::` from scene/x.rs or scene/params/mod.rs names a scene module; from deeper files
        // (scene/params/table.rs) it names their own module.
        let depth = rest.matches('/').count();
        let mut named: Vec<&str> = named_after(&code, "crate::scene::");
        if depth == 0 || rest.ends_with("/mod.rs") {
            named.extend(named_after(&code, "super::"));
        }
        for name in named {
            if let Some(target) = rank(name)
                && target > own
            {
                violations.push(format!("{file} ({module}) imports {name}, which comes after it"));
            }
        }
    }
    assert!(violations.is_empty(), "the scene's modules import in a loop:\n{}", violations.join("\n"));
}

#[test]
fn extractors_do_not_know_each_other_and_the_scene_knows_no_gpu() {
    for (file, code) in code() {
        if file.starts_with("extract/cpu/") {
            assert!(named_after(&code, "gpu::").is_empty(), "{file} names the GPU extractor");
        }
        if file.starts_with("extract/gpu/") {
            assert!(named_after(&code, "cpu::").is_empty(), "{file} names the CPU extractor");
        }
        let plain = file.starts_with("scene/")
            || ["extract/tables.rs", "extract/reference.rs", "extract/mesh.rs", "extract/cpu/mesher.rs"]
                .contains(&file.as_str());
        if plain {
            assert!(!code.contains("wgpu"), "{file} uses wgpu");
        }
    }
}

#[test]
fn the_view_knows_no_gpu() {
    for (file, code) in code() {
        if file.starts_with("view/") {
            assert!(!code.contains("wgpu"), "{file} uses wgpu");
        }
    }
}

#[test]
fn the_architecture_page_names_every_folder() {
    let page = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/architecture.md"))
        .expect("docs/architecture.md");
    for folder in LAYERS.iter().chain(SHELLS) {
        // The scene is a crate of its own (`scene/src/`).
        let named = page.contains(&format!("src/{folder}/")) || page.contains(&format!("{folder}/src/"));
        assert!(named, "docs/architecture.md does not name src/{folder}/");
    }
    for folder in ["shaders/extract/", "shaders/draw/", "shaders/draw/views/"] {
        assert!(page.contains(folder), "docs/architecture.md does not name {folder}");
    }
}

#[test]
fn the_rust_modules_import_without_cycles() {
    let cycles = imports::cycles(&imports::import_graph(&code()));
    let named: Vec<String> = cycles.iter().map(|cycle| cycle.join(" → ")).collect();
    assert!(named.is_empty(), "modules of src/ that import themselves through others:\n{}", named.join("\n"));
}

#[test]
fn the_import_graph_reads_use_trees_and_paths_and_names_a_cycle() {
    let files = |list: &[(&str, &str)]| -> BTreeMap<String, String> {
        list.iter().map(|(file, code)| (file.to_string(), code.to_string())).collect()
    };
    let layout = [
        ("lib.rs", "pub mod a;\npub mod b;"),
        ("a/mod.rs", "mod x;\nmod y;\npub use x::T;\nfn f() { y::g(); }"),
        ("a/x.rs", "use super::T;\nuse crate::{b::{self, c::U as V}};\nmod tests { use super::*; }"),
        ("a/y.rs", "pub fn g() {}"),
        ("b/mod.rs", "pub mod c;"),
        ("b/c.rs", "pub struct U;\nfn h() -> super::super::a::y::G { G }"),
    ];
    let graph = imports::import_graph(&files(&layout));
    let edges = |file: &str| graph[file].iter().cloned().collect::<Vec<_>>();
    assert_eq!(edges("a/mod.rs"), ["a/x.rs", "a/y.rs"], "a parent's imports of its files count");
    assert_eq!(edges("a/x.rs"), ["b/c.rs", "b/mod.rs"], "nor its parent nor itself");
    assert_eq!(edges("b/c.rs"), ["a/y.rs"]);
    assert!(imports::cycles(&graph).is_empty());

    let mut looped = layout.to_vec();
    looped[3] = ("a/y.rs", "use crate::b::c::U;");
    let cycles = imports::cycles(&imports::import_graph(&files(&looped)));
    assert_eq!(cycles, [["a/y.rs", "b/c.rs", "a/y.rs"]]);
}
