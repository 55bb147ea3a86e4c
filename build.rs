//! Gives the shaders short names before the crate carries them: every name the shaders under `shaders/`
//! declare (functions, structs, their members, constants, variables, parameters) is replaced by a
//! short one, the same in every file (a pass's shader is joined with `shaders/common.wgsl` and other
//! shared parts), the most used names the shortest. Left as they are: the entry points and the
//! overrides the host names, and names that are also WGSL's own (a builtin such as `position`, a
//! swizzle such as `xyz`). Comments go and line breaks stay, so a shader error's line number still
//! points at its line under `shaders/`. The files go to `$OUT_DIR/shaders/`, where `wgsl!`
//! (`src/device/wgsl.rs`) reads them and drops the indentation and the spaces that separate nothing.

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// WGSL's keywords, the builtin functions and types a declared name could shadow, and its address
/// spaces and access modes (a parameter may be called `workgroup`, as `var<workgroup>` says).
const WGSL_OWN: &[&str] = &[
    "alias",
    "break",
    "case",
    "const",
    "const_assert",
    "continue",
    "continuing",
    "default",
    "diagnostic",
    "discard",
    "else",
    "enable",
    "false",
    "fn",
    "for",
    "if",
    "let",
    "loop",
    "override",
    "requires",
    "return",
    "struct",
    "switch",
    "true",
    "var",
    "while",
    "abs",
    "acos",
    "all",
    "any",
    "arrayLength",
    "asin",
    "atan",
    "atan2",
    "atomicAdd",
    "atomicAnd",
    "atomicLoad",
    "atomicMax",
    "atomicMin",
    "atomicOr",
    "atomicStore",
    "atomicSub",
    "bitcast",
    "ceil",
    "clamp",
    "cos",
    "countOneBits",
    "cross",
    "degrees",
    "determinant",
    "distance",
    "dot",
    "dpdx",
    "dpdy",
    "exp",
    "exp2",
    "floor",
    "fma",
    "fract",
    "fwidth",
    "inverseSqrt",
    "length",
    "log",
    "log2",
    "max",
    "min",
    "mix",
    "normalize",
    "pow",
    "radians",
    "reflect",
    "round",
    "saturate",
    "select",
    "sign",
    "sin",
    "smoothstep",
    "sqrt",
    "step",
    "tan",
    "textureLoad",
    "textureSample",
    "textureStore",
    "textureDimensions",
    "transpose",
    "trunc",
    "workgroupBarrier",
    "storageBarrier",
    "array",
    "atomic",
    "bool",
    "f32",
    "f16",
    "i32",
    "u32",
    "vec2",
    "vec3",
    "vec4",
    "mat2x2",
    "mat3x3",
    "mat4x4",
    "ptr",
    "sampler",
    "NULL",
    "Self",
    "function",
    "private",
    "workgroup",
    "uniform",
    "storage",
    "read",
    "write",
    "read_write",
    "handle",
];

fn main() {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").unwrap());
    let out = PathBuf::from(std::env::var("OUT_DIR").unwrap()).join("shaders");
    println!("cargo:rerun-if-changed=shaders");
    let mut files = Vec::new();
    wgsl_files(&root.join("shaders"), &mut files);
    files.sort();
    let codes: Vec<String> =
        files.iter().map(|f| without_comments(&std::fs::read_to_string(f).unwrap())).collect();
    let names = short_names(&codes);
    for (file, code) in files.iter().zip(&codes) {
        let target = out.join(file.strip_prefix(root.join("shaders")).unwrap());
        std::fs::create_dir_all(target.parent().unwrap()).unwrap();
        let renamed = tokens(code)
            .iter()
            .map(|t| match t {
                Token::Name(name) => names.get(name.as_str()).map_or(name.as_str(), String::as_str),
                Token::Other(text) => text.as_str(),
            })
            .collect::<String>();
        std::fs::write(target, renamed).unwrap();
    }
}

fn wgsl_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            wgsl_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "wgsl") {
            out.push(path);
        }
    }
}

/// Each line without its `//` comment (WGSL has no strings, so `//` always starts one).
fn without_comments(source: &str) -> String {
    source.split('\n').map(|line| line.split("//").next().unwrap()).collect::<Vec<_>>().join("\n")
}

enum Token {
    Name(String),
    Other(String),
}

/// Names, and everything between them (numbers, with their suffixes and exponents, kept whole).
fn tokens(code: &str) -> Vec<Token> {
    let bytes = code.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        let start = i;
        let word = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
        if bytes[i].is_ascii_alphabetic() || bytes[i] == b'_' {
            while i < bytes.len() && word(bytes[i]) {
                i += 1;
            }
            out.push(Token::Name(code[start..i].to_string()));
            continue;
        }
        if bytes[i].is_ascii_digit() {
            let hex = bytes[i..].starts_with(b"0x");
            while i < bytes.len() && (word(bytes[i]) || bytes[i] == b'.') {
                let exponent = !hex && (bytes[i] == b'e' || bytes[i] == b'E');
                i += 1;
                if exponent && i < bytes.len() && (bytes[i] == b'+' || bytes[i] == b'-') {
                    i += 1;
                }
            }
        } else {
            i += 1;
        }
        out.push(Token::Other(code[start..i].to_string()));
    }
    out
}

/// The short name of every name to rename.
fn short_names(codes: &[String]) -> BTreeMap<String, String> {
    let mut declared = BTreeSet::new();
    let mut kept: BTreeSet<String> = WGSL_OWN.iter().map(|s| s.to_string()).collect();
    let mut uses: BTreeMap<String, usize> = BTreeMap::new();
    for code in codes {
        let tokens = tokens(code);
        // The significant tokens (names and punctuation, without spaces), in order.
        let mut seq: Vec<&str> = Vec::new();
        for t in &tokens {
            match t {
                Token::Name(n) => {
                    *uses.entry(n.clone()).or_default() += 1;
                    seq.push(n);
                }
                Token::Other(o) => seq.extend(o.split(char::is_whitespace).filter(|s| !s.is_empty())),
            }
        }
        let is_name = |s: &str| s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_');
        let mut depth_in_attribute = 0;
        for k in 0..seq.len() {
            let s = seq[k];
            // Inside an attribute's parentheses (`@builtin(position)`): WGSL's own words.
            if k >= 2 && seq[k - 2] == "@" && s == "(" {
                depth_in_attribute = 1;
                continue;
            }
            if depth_in_attribute > 0 {
                match s {
                    "(" => depth_in_attribute += 1,
                    ")" => depth_in_attribute -= 1,
                    _ if is_name(s) => {
                        kept.insert(s.to_string());
                    }
                    _ => {}
                }
                continue;
            }
            if !is_name(s) {
                continue;
            }
            let previous = if k > 0 { seq[k - 1] } else { "" };
            let next = seq.get(k + 1).copied().unwrap_or("");
            // An attribute's name (`@size`, `@vertex`) is WGSL's own.
            if previous == "@" {
                kept.insert(s.to_string());
                continue;
            }
            // `var<storage, read> name`: the name right after the address space's `>`.
            let after_space = previous == ">" && {
                let opened = seq[..k].iter().rposition(|t| *t == "<");
                opened.is_some_and(|at| at > 0 && seq[at - 1] == "var" && !seq[at..k - 1].contains(&">"))
            };
            if matches!(previous, "fn" | "struct" | "let" | "var" | "const" | "alias" | "override")
                || after_space
                || next == ":"
            {
                declared.insert(s.to_string());
            }
            if previous == "override" {
                kept.insert(s.to_string());
            }
            if previous == "fn" {
                // An entry point: `@compute`, `@vertex` or `@fragment` since the last item.
                let item = seq[..k].iter().rev().take_while(|t| !matches!(**t, "}" | ";"));
                if item.clone().any(|t| matches!(*t, "compute" | "vertex" | "fragment")) {
                    kept.insert(s.to_string());
                }
            }
        }
    }
    let swizzle = |s: &str| {
        s.len() <= 4 && (s.bytes().all(|b| b"xyzw".contains(&b)) || s.bytes().all(|b| b"rgba".contains(&b)))
    };
    let mut renamed: Vec<&String> =
        declared.iter().filter(|n| n.len() > 2 && !kept.contains(*n) && !swizzle(n)).collect();
    renamed.sort_by_key(|n| std::cmp::Reverse(uses[*n]));
    let taken: BTreeSet<&String> = uses.keys().collect();
    let mut candidates = (0..).map(short).filter(|c| !taken.contains(c) && !kept.contains(c));
    renamed.into_iter().map(|n| (n.clone(), candidates.next().unwrap())).collect()
}

/// The `k`-th short name: an upper-case letter, then letters and digits.
fn short(mut k: usize) -> String {
    const FIRST: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZ";
    const REST: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    let mut name = vec![FIRST[k % 26]];
    k /= 26;
    while k > 0 {
        k -= 1;
        name.push(REST[k % REST.len()]);
        k /= REST.len();
    }
    String::from_utf8(name).unwrap()
}
