//! The module import graph of `src/`, read from the source: which file each file imports, and the
//! cycles among them.

use std::collections::{BTreeMap, BTreeSet};

fn is_ident(c: char) -> bool {
    c.is_alphanumeric() || c == '_'
}

/// The module a file of `src/` is: `extract/lod/mod.rs` is `extract::lod`, `lib.rs` the crate root.
fn module_of(file: &str) -> Vec<String> {
    let mut parts: Vec<String> = file.trim_end_matches(".rs").split('/').map(str::to_string).collect();
    if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
        parts.pop();
    }
    parts
}

/// Where the word `word` starts in `code`, standing alone.
fn words<'a>(code: &'a str, word: &'a str) -> impl Iterator<Item = usize> + 'a {
    code.match_indices(word)
        .map(|(at, _)| at)
        .filter(move |&at| !code[..at].ends_with(is_ident) && !code[at + word.len()..].starts_with(is_ident))
}

/// The identifier at the start of `text`, after any whitespace.
fn ident_after(text: &str) -> &str {
    let text = text.trim_start();
    &text[..text.find(|c: char| !is_ident(c)).unwrap_or(text.len())]
}

/// `code` with its inline modules (`mod tests { … }`) cut out, and those modules' names and bodies.
fn inline_modules(code: &str) -> (String, Vec<(String, String)>) {
    let mut outer = String::new();
    let mut inline = Vec::new();
    let mut from = 0;
    for at in words(code, "mod") {
        if at < from {
            continue;
        }
        let name = ident_after(&code[at + 3..]);
        let after = code[at + 3..].trim_start()[name.len()..].trim_start();
        if name.is_empty() || !after.starts_with('{') {
            continue;
        }
        let open = code.len() - after.len();
        let mut depth = 0;
        let Some(close) = code[open..].char_indices().find_map(|(i, c)| {
            depth += match c {
                '{' => 1,
                '}' => -1,
                _ => 0,
            };
            (depth == 0).then_some(open + i)
        }) else {
            continue;
        };
        outer.push_str(&code[from..at]);
        inline.push((name.to_string(), code[open + 1..close].to_string()));
        from = close + 1;
    }
    outer.push_str(&code[from..]);
    (outer, inline)
}

/// The tokens of a `use` tree: names, `::`, braces, commas and `*`; `None` for anything else.
fn use_tokens(tree: &str) -> Option<Vec<String>> {
    let mut tokens = Vec::new();
    let mut chars = tree.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            c if c.is_whitespace() => {}
            ':' if chars.next_if_eq(&':').is_some() => tokens.push("::".to_string()),
            '{' | '}' | ',' | '*' => tokens.push(c.to_string()),
            c if is_ident(c) => {
                let mut name = c.to_string();
                while let Some(c) = chars.next_if(|&c| is_ident(c)) {
                    name.push(c);
                }
                tokens.push(name);
            }
            _ => return None,
        }
    }
    Some(tokens)
}

/// Every path a `use` tree names, from `tokens[*at]` on, each after `prefix`.
fn expand_use(tokens: &[String], at: &mut usize, prefix: &[String], paths: &mut Vec<Vec<String>>) {
    let mut path = prefix.to_vec();
    while let Some(token) = tokens.get(*at) {
        *at += 1;
        match token.as_str() {
            "{" => {
                while tokens.get(*at).is_some_and(|t| t != "}") {
                    expand_use(tokens, at, &path, paths);
                    if tokens.get(*at).is_some_and(|t| t == ",") {
                        *at += 1;
                    }
                }
                *at += 1;
                return;
            }
            "::" => {}
            "*" => break,
            "self" if !path.is_empty() => break,
            name => {
                path.push(name.to_string());
                if tokens.get(*at).is_some_and(|t| t == "as") {
                    *at += 2;
                }
                if tokens.get(*at).is_none_or(|t| t != "::") {
                    break;
                }
            }
        }
    }
    paths.push(path);
}

/// The paths `code` names from module `module`, absolute, with the names of the modules it declares;
/// its inline modules are read as modules inside it.
fn named_paths(code: &str, module: &[String], paths: &mut Vec<Vec<String>>) {
    let (outer, inline) = inline_modules(code);
    for (name, body) in inline {
        let inner: Vec<String> = module.iter().cloned().chain([name]).collect();
        named_paths(&body, &inner, paths);
    }
    let children: BTreeSet<&str> = words(&outer, "mod")
        .map(|at| ident_after(&outer[at + 3..]))
        .filter(|name| !name.is_empty())
        .collect();
    let mut relative = Vec::new();
    let mut rest = outer.clone();
    for at in words(&outer, "use") {
        let Some(end) = outer[at..].find(';') else { continue };
        if let Some(tokens) = use_tokens(&outer[at + 3..at + end]) {
            expand_use(&tokens, &mut 0, &[], &mut relative);
            rest.replace_range(at..at + end, &" ".repeat(end));
        }
    }
    for (at, _) in rest.match_indices("::") {
        let before = &rest[..at];
        let start = before.trim_end_matches(is_ident).len();
        if before[..start].ends_with(':') || start == at {
            continue;
        }
        let path: Vec<String> = rest[start..]
            .split("::")
            .map(|segment| {
                segment[..segment.find(|c: char| !is_ident(c)).unwrap_or(segment.len())].to_string()
            })
            .take_while(|segment| !segment.is_empty())
            .collect();
        relative.push(path);
    }
    for path in relative {
        let Some(first) = path.first() else { continue };
        let (mut absolute, skip) = match first.as_str() {
            "crate" => (Vec::new(), 1),
            "super" | "self" => (module.to_vec(), 0),
            name if children.contains(name) => (module.to_vec(), 0),
            _ => continue,
        };
        let mut lost = false;
        for segment in &path[skip..] {
            match segment.as_str() {
                "super" => lost |= absolute.pop().is_none(),
                "self" => {}
                _ => absolute.push(segment.clone()),
            }
        }
        if !lost {
            paths.push(absolute);
        }
    }
}

/// The files of `src/` each file imports (module = file), from its `use` trees and its `crate::`,
/// `super::`, `self::` and child-module paths (the children named by its `mod` declarations). A file's
/// imports of its own ancestors (`super::Renderer`, a test module's `super::*`) are not counted: a
/// module and its parent are one unit, as Rust's privacy has it, while the parent's imports of its
/// files are. `main.rs` is a crate of its own and left out.
pub fn import_graph(code: &BTreeMap<String, String>) -> BTreeMap<String, BTreeSet<String>> {
    let files: BTreeMap<Vec<String>, &str> = code
        .keys()
        .filter(|file| file.as_str() != "main.rs")
        .map(|file| (module_of(file), file.as_str()))
        .collect();
    let mut graph = BTreeMap::new();
    for (module, file) in &files {
        let mut paths = Vec::new();
        named_paths(&code[*file], module, &mut paths);
        let mut targets = BTreeSet::new();
        for path in paths {
            // The deepest module the path names that is a file.
            let mut deepest = Vec::new();
            for segment in path {
                deepest.push(segment);
                if !files.contains_key(&deepest) {
                    deepest.pop();
                    break;
                }
            }
            if !module.starts_with(&deepest) {
                targets.insert(files[&deepest].to_string());
            }
        }
        graph.insert(file.to_string(), targets);
    }
    graph
}

/// Each cycle of `graph`, as the files it passes through with the first repeated at the end.
pub fn cycles(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    fn visit<'a>(
        node: &'a str,
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        path: &mut Vec<&'a str>,
        done: &mut BTreeSet<&'a str>,
        found: &mut BTreeSet<Vec<String>>,
    ) {
        if let Some(at) = path.iter().position(|&n| n == node) {
            let mut cycle: Vec<String> = path[at..].iter().map(|n| n.to_string()).collect();
            let first = (0..cycle.len()).min_by_key(|&i| &cycle[i]).unwrap_or(0);
            cycle.rotate_left(first);
            cycle.push(cycle[0].clone());
            found.insert(cycle);
            return;
        }
        if done.contains(node) {
            return;
        }
        path.push(node);
        for next in graph.get(node).into_iter().flatten() {
            visit(next, graph, path, done, found);
        }
        path.pop();
        done.insert(node);
    }
    let mut found = BTreeSet::new();
    let mut done = BTreeSet::new();
    for node in graph.keys() {
        visit(node, graph, &mut Vec::new(), &mut done, &mut found);
    }
    found.into_iter().collect()
}
