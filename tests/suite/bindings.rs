//! The shaders' bindings, checked on the source: across every file of `shaders/`, one number in a group
//! means one variable, and each variable's number is the constant of its name in
//! `src/device/bindings.rs`, which the Rust side binds with.

use crate::common;

use metaballs::device::bindings::ALL;
use std::collections::BTreeMap;
use std::path::Path;

/// A `@group(g) @binding(n) var… name` declaration and the file it is in.
#[derive(Debug)]
struct Declaration {
    file: String,
    group: u32,
    binding: u32,
    name: String,
}

/// The number in `(n)` at the start of `text`, and what follows it.
fn number_in_parens(text: &str) -> Option<(u32, &str)> {
    let (inside, rest) = text.trim_start().strip_prefix('(')?.split_once(')')?;
    Some((inside.trim().parse().ok()?, rest))
}

/// The declaration after `@group` in `text`: `(g) @binding(n) var<…> name:`.
fn declaration(text: &str) -> Option<(u32, u32, String)> {
    let (group, rest) = number_in_parens(text)?;
    let (binding, rest) = number_in_parens(rest.trim_start().strip_prefix("@binding")?)?;
    let mut rest = rest.trim_start().strip_prefix("var")?.trim_start();
    if let Some(after) = rest.strip_prefix('<') {
        rest = after.split_once('>')?.1.trim_start();
    }
    let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
    rest[name.len()..].trim_start().starts_with(':').then_some((group, binding, name))
}

/// Every binding declared in `shaders/`, failing on an `@group` it cannot read.
fn declarations() -> Vec<Declaration> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = common::files_under(&root.join("shaders"), "wgsl");
    files.sort();
    let mut found = Vec::new();
    for path in files {
        let file = path.strip_prefix(root).unwrap().to_string_lossy().replace('\\', "/");
        let text = std::fs::read_to_string(&path).unwrap();
        let code: Vec<&str> = text.lines().map(|l| l.split("//").next().unwrap_or("")).collect();
        let code = code.join("\n");
        for (at, _) in code.match_indices("@group") {
            let (group, binding, name) = declaration(&code[at + "@group".len()..])
                .unwrap_or_else(|| panic!("{file}: cannot read the declaration at byte {at}"));
            found.push(Declaration { file: file.clone(), group, binding, name });
        }
    }
    assert!(found.len() > 30, "found only {} bindings in shaders/", found.len());
    found
}

#[test]
fn one_binding_number_means_one_variable_in_every_shader() {
    let mut names: BTreeMap<(u32, u32), BTreeMap<String, Vec<String>>> = BTreeMap::new();
    for d in declarations() {
        names.entry((d.group, d.binding)).or_default().entry(d.name).or_default().push(d.file);
    }
    let reused: Vec<String> = names
        .iter()
        .filter(|(_, by_name)| by_name.len() > 1)
        .map(|((group, binding), by_name)| {
            let uses: Vec<String> =
                by_name.iter().map(|(name, files)| format!("{name} in {}", files.join(", "))).collect();
            format!("@group({group}) @binding({binding}): {}", uses.join("; "))
        })
        .collect();
    assert!(reused.is_empty(), "binding numbers with more than one meaning:\n{}", reused.join("\n"));
}

#[test]
fn the_shaders_bindings_are_the_rust_constants_of_their_names() {
    let constants: BTreeMap<String, u32> = ALL.iter().map(|&(name, n)| (name.to_lowercase(), n)).collect();
    let mut problems = Vec::new();
    let mut declared = BTreeMap::new();
    for d in declarations() {
        let place = format!("{}: @group({}) @binding({}) {}", d.file, d.group, d.binding, d.name);
        match constants.get(&d.name) {
            None => problems.push(format!("{place} has no constant {}", d.name.to_uppercase())),
            Some(&n) if n != d.binding || d.group != 0 => {
                problems.push(format!("{place}, but {} is @group(0) @binding({n})", d.name.to_uppercase()))
            }
            Some(_) => {}
        }
        declared.insert(d.name, ());
    }
    for name in constants.keys().filter(|name| !declared.contains_key(*name)) {
        problems.push(format!("{} names no binding in shaders/", name.to_uppercase()));
    }
    let mut by_number: BTreeMap<u32, Vec<&str>> = BTreeMap::new();
    for &(name, n) in ALL {
        by_number.entry(n).or_default().push(name);
    }
    for (n, names) in by_number.iter().filter(|(_, names)| names.len() > 1) {
        problems.push(format!("{} share the number {n}", names.join(", ")));
    }
    assert!(problems.is_empty(), "the shaders and src/device/bindings.rs disagree:\n{}", problems.join("\n"));
}
