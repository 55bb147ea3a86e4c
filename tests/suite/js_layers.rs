//! The page's JavaScript keeps its layers: every `import … from '…'`, `export … from '…'`, bare
//! `import '…'` and `import('…')` in `www/**/*.js` (not `node_modules/`, `tools/` or the generated
//! table) is read, and a module that imports one of a higher layer, a module that is in no layer, an
//! import of a file that is not there, or modules that import each other in a cycle fail the test.
//! `docs/architecture.md` names every module of `www/lib/`.

use std::collections::BTreeMap;
use std::fs;
use std::path::{Component, Path, PathBuf};

/// The layers, lowest first: a module may import its own layer and those before it.
const LAYERS: &[(&str, &[&str])] = &[
    // The parameter table, written by `metaballs manifest`.
    ("table", &["www/lib/attributes.js"]),
    // The words the figures show: the catalogues by language and what finds and formats them.
    ("words", &["www/lib/i18n/"]),
    // Marching squares in the plane: computed without the DOM or the wasm.
    ("plane", &["www/lib/plane/"]),
    // The element's core: the table's columns, a figure's settings, its context, the frame counts.
    ("core", &["www/lib/core/"]),
    // What the page shares: the wasm, the device hub, the page's observers, the element's base class.
    ("engine", &["www/lib/engine/"]),
    // One figure: its renderer and frames, its size, its markup, its look.
    ("figure", &["www/lib/figure/"]),
    // The figure's features: HUD, panel, camera, inspector, editor, scene files, sync, topology, ….
    ("features", &["www/lib/features/"]),
    // The element.
    ("element", &["www/metaballs-view.js", "www/metaballs-2d.js"]),
    // The full pages (3D and 2D) and the benchmark.
    ("page", &["www/page.js", "www/bench.js", "www/plane-page.js"]),
];

/// Files that are written by a tool, not by hand: their imports are not read.
const GENERATED: &[&str] = &["www/lib/attributes.js"];

/// Folders under `www/` that hold no module of the page (`vendor/` holds libraries bundled by
/// `www/build.sh`, whose imports are not ours to read).
const SKIPPED: &[&str] = &["node_modules", "tools", "vendor"];

/// Modules that `www/build.sh` writes, each with the file it is built from: any layer may import one
/// (they import nothing of the page), and it need not be built yet for the test, but its source must be
/// there.
const BUILT: &[(&str, &str)] = &[("www/vendor/clip-codecs.js", "www/tools/clip-codecs-entry.js")];

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// Every `.js` file under `www/`, as paths relative to the repository (with `/`).
fn modules() -> Vec<String> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let mut entries: Vec<_> = fs::read_dir(dir)
            .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
            .map(|e| e.expect("a directory entry").path())
            .collect();
        entries.sort();
        for path in entries {
            let name = path.file_name().and_then(|n| n.to_str()).unwrap_or("");
            if path.is_dir() {
                if !SKIPPED.contains(&name) {
                    walk(&path, out);
                }
            } else if name.ends_with(".js") {
                out.push(path);
            }
        }
    }
    let mut found = Vec::new();
    walk(&root().join("www"), &mut found);
    found.into_iter().map(|p| relative(&p)).collect()
}

fn relative(path: &Path) -> String {
    let rel = path.strip_prefix(root()).unwrap_or(path);
    rel.components().map(|c| c.as_os_str().to_string_lossy().into_owned()).collect::<Vec<_>>().join("/")
}

/// The layer of a module (its index in `LAYERS`), or None when it is in none.
fn layer_of(module: &str) -> Option<usize> {
    LAYERS.iter().position(|(_, places)| {
        places.iter().any(
            |place| {
                if place.ends_with('/') { module.starts_with(place) } else { module == *place }
            },
        )
    })
}

/// The text with its comments blanked out (strings are kept, so a `//` inside one stays).
fn without_comments(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    let mut quote: Option<u8> = None;
    while i < bytes.len() {
        let c = bytes[i];
        if let Some(q) = quote {
            if c == b'\\' && i + 1 < bytes.len() {
                out.push(c as char);
                out.push(if bytes[i + 1].is_ascii() { bytes[i + 1] as char } else { ' ' });
                i += 2;
                continue;
            }
            if c == q || (c == b'\n' && q != b'`') {
                quote = None;
            }
            out.push(if c.is_ascii() { c as char } else { ' ' });
            i += 1;
            continue;
        }
        if c == b'/' && bytes.get(i + 1) == Some(&b'/') {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
            continue;
        }
        if c == b'/' && bytes.get(i + 1) == Some(&b'*') {
            i += 2;
            while i + 1 < bytes.len() && !(bytes[i] == b'*' && bytes[i + 1] == b'/') {
                i += 1;
            }
            i += 2;
            out.push(' ');
            continue;
        }
        if c == b'\'' || c == b'"' || c == b'`' {
            quote = Some(c);
        }
        // Only ASCII matters to the search below; other characters become spaces.
        out.push(if c.is_ascii() { c as char } else { ' ' });
        i += 1;
    }
    out
}

/// The quoted text starting at `at` (after optional spaces), if a quote opens there and closes on the
/// same line.
fn quoted(text: &str, at: usize) -> Option<String> {
    let rest = text[at..].trim_start();
    let quote = rest.chars().next().filter(|c| *c == '\'' || *c == '"')?;
    let end = rest[1..].find(quote)?;
    let spec = &rest[1..1 + end];
    (!spec.contains('\n')).then(|| spec.to_string())
}

fn word_at(text: &str, at: usize, word: &str) -> bool {
    let before_ok = at == 0 || {
        let b = text.as_bytes()[at - 1];
        !(b.is_ascii_alphanumeric() || b == b'_' || b == b'$' || b == b'.')
    };
    let after = at + word.len();
    let after_ok =
        text.as_bytes().get(after).is_none_or(|b| !(b.is_ascii_alphanumeric() || *b == b'_' || *b == b'$'));
    text[at..].starts_with(word) && before_ok && after_ok
}

/// The specifiers a module imports: `from '…'` (imports and re-exports), `import '…'` and `import('…')`.
fn imports(source: &str) -> Vec<String> {
    let text = without_comments(source);
    let mut found = Vec::new();
    for (at, _) in text.match_indices("from") {
        if word_at(&text, at, "from") {
            if let Some(spec) = quoted(&text, at + 4) {
                found.push(spec);
            }
        }
    }
    for (at, _) in text.match_indices("import") {
        if !word_at(&text, at, "import") {
            continue;
        }
        let rest = text[at + 6..].trim_start();
        let offset = text.len() - rest.len();
        let spec = if rest.starts_with('(') { quoted(&text, offset + 1) } else { quoted(&text, offset) };
        if let Some(spec) = spec {
            found.push(spec);
        }
    }
    found
}

/// `spec` imported by `module`, as a path relative to the repository, when it is a relative path.
fn resolve(module: &str, spec: &str) -> Option<String> {
    if !spec.starts_with("./") && !spec.starts_with("../") {
        return None;
    }
    let mut parts: Vec<String> = module.split('/').map(String::from).collect();
    parts.pop();
    for component in Path::new(spec).components() {
        match component {
            Component::ParentDir => {
                parts.pop();
            }
            Component::Normal(name) => parts.push(name.to_string_lossy().into_owned()),
            _ => {}
        }
    }
    Some(parts.join("/"))
}

/// Each module of the page and the modules under `www/` it imports.
fn graph() -> BTreeMap<String, Vec<String>> {
    let mut edges = BTreeMap::new();
    for module in modules() {
        if GENERATED.contains(&module.as_str()) {
            edges.insert(module, Vec::new());
            continue;
        }
        let source = fs::read_to_string(root().join(&module)).expect("a module's text");
        let targets = imports(&source)
            .iter()
            .filter_map(|spec| resolve(&module, spec))
            .filter(|target| target.starts_with("www/"))
            .collect();
        edges.insert(module, targets);
    }
    edges
}

#[test]
fn the_import_reader_finds_every_form() {
    let source = "import { a } from './a.js';\nimport * as b from \"../b.js\";\nexport { c } from './c.js';\n\
        import './d.js';\nconst e = () => import('./e.js');\n// import { f } from './f.js';\n/* from './g.js' */\n\
        const h = 'import from';\nimport {\n  i,\n} from './i.js';";
    assert_eq!(imports(source).len(), 6, "{:?}", imports(source));
    for spec in ["./a.js", "../b.js", "./c.js", "./d.js", "./e.js", "./i.js"] {
        assert!(imports(source).contains(&spec.to_string()), "{spec} not found");
    }
    assert_eq!(resolve("www/lib/core/x.js", "../engine/y.js").as_deref(), Some("www/lib/engine/y.js"));
    assert_eq!(resolve("www/lib/core/x.js", "../../../pkg/m.js").as_deref(), Some("pkg/m.js"));
    assert_eq!(resolve("www/lib/core/x.js", "lit"), None);
}

#[test]
fn modules_import_only_their_layer_and_those_below() {
    let mut problems = Vec::new();
    for (module, targets) in graph() {
        let Some(own) = layer_of(&module) else {
            problems.push(format!(
                "{module} is in no layer: place it in a folder of tests/suite/js_layers.rs's LAYERS"
            ));
            continue;
        };
        for target in targets {
            if let Some((_, source)) = BUILT.iter().find(|(built, _)| *built == target) {
                if !root().join(source).is_file() {
                    problems.push(format!("{module} imports {target}, whose source {source} is not there"));
                }
                continue;
            }
            if !root().join(&target).is_file() {
                problems.push(format!("{module} imports {target}, which is not there"));
                continue;
            }
            match layer_of(&target) {
                Some(layer) if layer <= own => {}
                Some(layer) => problems.push(format!(
                    "{module} ({}) imports {target} ({}), a layer above its own",
                    LAYERS[own].0, LAYERS[layer].0
                )),
                None => problems.push(format!("{module} imports {target}, which is in no layer")),
            }
        }
    }
    assert!(problems.is_empty(), "layers of www/ broken:\n  {}", problems.join("\n  "));
}

#[test]
fn modules_import_each_other_in_no_cycle() {
    let edges = graph();
    // Depth first: 0 not seen, 1 on the current path, 2 done.
    let mut state: BTreeMap<&str, u8> = edges.keys().map(|k| (k.as_str(), 0)).collect();
    let mut cycles = Vec::new();
    fn visit<'a>(
        module: &'a str,
        edges: &'a BTreeMap<String, Vec<String>>,
        state: &mut BTreeMap<&'a str, u8>,
        path: &mut Vec<&'a str>,
        cycles: &mut Vec<String>,
    ) {
        state.insert(module, 1);
        path.push(module);
        for target in edges.get(module).into_iter().flatten() {
            match state.get(target.as_str()).copied() {
                Some(0) => visit(target, edges, state, path, cycles),
                Some(1) => {
                    let start = path.iter().position(|m| *m == target).unwrap_or(0);
                    let mut ring: Vec<&str> = path[start..].to_vec();
                    ring.push(target);
                    cycles.push(ring.join(" → "));
                }
                _ => {}
            }
        }
        path.pop();
        state.insert(module, 2);
    }
    for module in edges.keys() {
        if state[module.as_str()] == 0 {
            visit(module, &edges, &mut state, &mut Vec::new(), &mut cycles);
        }
    }
    assert!(cycles.is_empty(), "modules of www/ import each other in a cycle:\n  {}", cycles.join("\n  "));
}

#[test]
fn the_architecture_names_every_module() {
    let docs = fs::read_to_string(root().join("docs/architecture.md")).expect("docs/architecture.md");
    // Its tree names each folder (`lib/core/`) and under it each file (`table.js`).
    let missing: Vec<String> = modules()
        .into_iter()
        .filter(|m| m.starts_with("www/lib/"))
        .filter(|m| {
            let (folder, file) = m.rsplit_once('/').expect("a path with a folder");
            !(docs.contains(&format!("{}/", folder.trim_start_matches("www/"))) && docs.contains(file))
        })
        .collect();
    assert!(missing.is_empty(), "docs/architecture.md does not name {missing:?}");
}
