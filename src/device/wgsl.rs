//! The shaders as the binary carries them: `build.rs` gives the names they declare short ones and drops
//! their comments (into `$OUT_DIR/shaders/`), then [`wgsl!`](crate::device::wgsl) drops the
//! indentation and the spaces that separate nothing while the crate compiles, keeping every line break
//! so that a shader error's line number still points at the same line of the file under `shaders/`.
//! The comments and the long names are most of the shaders' bytes, and every byte of them is
//! downloaded with the page's WebAssembly.

/// The shader at `path` under `shaders/`, as `build.rs` renamed it, without its indentation and the
/// spaces that separate nothing, as a `&'static str` made at compile time.
macro_rules! wgsl {
    ($path:literal) => {{
        const SOURCE: &str = include_str!(concat!(env!("OUT_DIR"), "/shaders/", $path));
        const LEN: usize = SOURCE.len();
        const MINIFIED: ([u8; LEN], usize) = $crate::device::wgsl::minify::<LEN>(SOURCE);
        const SQUEEZED: ([u8; LEN], usize) = $crate::device::wgsl::squeeze::<LEN>(&MINIFIED.0, MINIFIED.1);
        const USED: usize = SQUEEZED.1;
        const BYTES: [u8; USED] = $crate::device::wgsl::prefix::<LEN, USED>(&SQUEEZED.0);
        match ::core::str::from_utf8(&BYTES) {
            Ok(text) => text,
            Err(_) => panic!("a minified shader is not UTF-8"),
        }
    }};
}
pub(crate) use wgsl;

/// Writes `source` into the first bytes of the array, leaving out every `//` comment (WGSL has no
/// string literals, so `//` always starts one) and the spaces and tabs that begin or end a line, and
/// returns how many bytes it wrote. `N` is at least the source's length. Block comments are kept as
/// they are (the shaders have none).
pub const fn minify<const N: usize>(source: &str) -> ([u8; N], usize) {
    let bytes = source.as_bytes();
    let mut out = [0u8; N];
    let mut used = 0;
    let mut i = 0;
    while i < bytes.len() {
        // One line: from `i` to its line break (or the end).
        let mut end = i;
        while end < bytes.len() && bytes[end] != b'\n' {
            end += 1;
        }
        let mut code_end = i;
        while code_end + 1 < end && !(bytes[code_end] == b'/' && bytes[code_end + 1] == b'/') {
            code_end += 1;
        }
        if code_end + 1 >= end {
            code_end = end;
        }
        let mut start = i;
        while start < code_end && (bytes[start] == b' ' || bytes[start] == b'\t') {
            start += 1;
        }
        while code_end > start && (bytes[code_end - 1] == b' ' || bytes[code_end - 1] == b'\t') {
            code_end -= 1;
        }
        while start < code_end {
            out[used] = bytes[start];
            used += 1;
            start += 1;
        }
        if end < bytes.len() {
            out[used] = b'\n';
            used += 1;
        }
        i = end + 1;
    }
    (out, used)
}

/// The first `used` bytes of `bytes` without the spaces and tabs that separate nothing: a run of them
/// between two tokens becomes one space only where the bytes on either side would otherwise run
/// together, as two word characters (`let x`, `1u`) or as two characters that together begin a comment
/// or make another operator (`a - -b`, `x > >`, `/ /`). WGSL reads a space as nothing but a
/// separator, so the shader means the same; line breaks stay.
pub const fn squeeze<const N: usize>(bytes: &[u8; N], used: usize) -> ([u8; N], usize) {
    let mut out = [0u8; N];
    let mut kept = 0;
    let mut i = 0;
    while i < used {
        let b = bytes[i];
        if b == b' ' || b == b'\t' {
            let mut next = i;
            while next < used && (bytes[next] == b' ' || bytes[next] == b'\t') {
                next += 1;
            }
            if kept > 0 && next < used && runs_together(out[kept - 1], bytes[next]) {
                out[kept] = b' ';
                kept += 1;
            }
            i = next;
        } else {
            out[kept] = b;
            kept += 1;
            i += 1;
        }
    }
    (out, kept)
}

/// Whether `a` written right before `b` would read as one token (or a comment) where a space between
/// them reads as two.
const fn runs_together(a: u8, b: u8) -> bool {
    const fn word(c: u8) -> bool {
        c.is_ascii_alphanumeric() || c == b'_' || c == b'.'
    }
    if word(a) && word(b) {
        return true;
    }
    // Every two-character operator and comment marker of WGSL; longer ones (`>>=`, `<<=`) begin with
    // one of these.
    const PAIRS: [&[u8; 2]; 22] = [
        b"//", b"/*", b"*/", b"==", b"!=", b"<=", b">=", b"+=", b"-=", b"*=", b"/=", b"%=", b"&=", b"|=",
        b"^=", b"->", b"++", b"--", b"&&", b"||", b"<<", b">>",
    ];
    let mut k = 0;
    while k < PAIRS.len() {
        if PAIRS[k][0] == a && PAIRS[k][1] == b {
            return true;
        }
        k += 1;
    }
    false
}

/// The first `M` bytes of `bytes`.
pub const fn prefix<const N: usize, const M: usize>(bytes: &[u8; N]) -> [u8; M] {
    let mut out = [0u8; M];
    let mut i = 0;
    while i < M {
        out[i] = bytes[i];
        i += 1;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn minified(source: &str) -> String {
        let (bytes, used) = minify::<256>(source);
        String::from_utf8(bytes[..used].to_vec()).unwrap()
    }

    /// Comments and indentation go, code and line breaks stay, so lines keep their numbers.
    #[test]
    fn drops_comments_and_indentation_and_keeps_lines() {
        let source = "// A comment line.\nfn f(x: f32) -> f32 {\n    // Inside.\n    return x * 2.0; // After code.\n}\n\t let a = 1;  \n";
        assert_eq!(minified(source), "\nfn f(x: f32) -> f32 {\n\nreturn x * 2.0;\n}\nlet a = 1;\n");
        assert_eq!(minified("let a = 1u; /* kept */"), "let a = 1u; /* kept */");
        assert_eq!(minified("a / b\n/"), "a / b\n/");
        assert_eq!(minified(""), "");
    }

    fn squeezed(source: &str) -> String {
        let mut bytes = [0u8; 256];
        bytes[..source.len()].copy_from_slice(source.as_bytes());
        let (out, used) = squeeze::<256>(&bytes, source.len());
        String::from_utf8(out[..used].to_vec()).unwrap()
    }

    /// Spaces go between tokens that stay apart without them, and stay (one of them) where two words,
    /// an operator and its neighbour, or a comment marker would run together.
    #[test]
    fn squeezes_only_the_spaces_that_separate_nothing() {
        assert_eq!(
            squeezed("fn f(x: f32) -> f32 {\nreturn x * 2.0;\n}"),
            "fn f(x:f32)->f32{\nreturn x*2.0;\n}"
        );
        assert_eq!(squeezed("let a  =\t1u;"), "let a=1u;");
        assert_eq!(
            squeezed("a - -b; c > >d; e / /f; g = = h; i & &j; k < =l; m - > n; o. 5"),
            "a- -b;c> >d;e/ /f;g= =h;i& &j;k< =l;m- >n;o. 5"
        );
        assert_eq!(squeezed("x = -1; y == -z; vec3<f32>(a, b)"), "x=-1;y==-z;vec3<f32>(a,b)");
        assert_eq!(squeezed("  lead\ntrail  "), "lead\ntrail");
    }

    /// Shaders the crate ships, one after another.
    const SHIPPED: &str = concat!(
        include_str!("../../shaders/common.wgsl"),
        include_str!("../../shaders/extract/lod.wgsl"),
        include_str!("../../shaders/draw/shade.wgsl"),
        include_str!("../../shaders/draw/views/exact.wgsl"),
    );

    /// Squeezed, every shader the crate ships reads as the same tokens, on the same lines.
    #[test]
    fn the_squeezed_shaders_keep_their_tokens_and_lines() {
        let shaders = SHIPPED;
        const LEN: usize = 64 * 1024;
        let (bytes, used) = minify::<LEN>(shaders);
        let (out, kept) = squeeze::<LEN>(&bytes, used);
        let (before, after) =
            (std::str::from_utf8(&bytes[..used]).unwrap(), std::str::from_utf8(&out[..kept]).unwrap());
        assert_eq!(after.lines().count(), before.lines().count());
        assert!(kept < used * 19 / 20, "{kept} of {used} bytes left");
        for (ours, original) in after.lines().zip(before.lines()) {
            // Without its spaces each line is the same text, and every space left stands between two
            // bytes that would run together.
            assert_eq!(ours.replace(' ', ""), original.replace([' ', '\t'], ""));
            for (i, _) in ours.match_indices(' ') {
                assert!(runs_together(ours.as_bytes()[i - 1], ours.as_bytes()[i + 1]), "{ours}");
            }
        }
    }

    /// Every shader the crate ships keeps its lines and loses at least a third of its bytes; what is
    /// left of each line is a prefix of the original line's code, trimmed.
    #[test]
    fn the_shaders_keep_their_lines_and_code() {
        let shaders = SHIPPED;
        const LEN: usize = 64 * 1024;
        assert!(shaders.len() <= LEN);
        let (bytes, used) = minify::<LEN>(shaders);
        let small = std::str::from_utf8(&bytes[..used]).unwrap();
        assert_eq!(small.lines().count(), shaders.lines().count());
        assert!(used * 3 < shaders.len() * 2, "{used} of {} bytes left", shaders.len());
        for (ours, original) in small.lines().zip(shaders.lines()) {
            let code = original.split("//").next().unwrap().trim();
            assert_eq!(ours, code);
        }
    }

    /// What `build.rs` gives the crate: every shader under `shaders/`, renamed, by its path there.
    fn renamed() -> Vec<(String, String, String)> {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("shaders");
        let out = std::path::Path::new(env!("OUT_DIR")).join("shaders");
        let mut files = Vec::new();
        let mut dirs = vec![root.clone()];
        while let Some(dir) = dirs.pop() {
            for entry in std::fs::read_dir(dir).unwrap() {
                let path = entry.unwrap().path();
                if path.is_dir() {
                    dirs.push(path);
                } else if path.extension().is_some_and(|e| e == "wgsl") {
                    let name = path.strip_prefix(&root).unwrap().to_string_lossy().into_owned();
                    let original = std::fs::read_to_string(&path).unwrap();
                    let shipped = std::fs::read_to_string(out.join(&name)).unwrap();
                    files.push((name, original, shipped));
                }
            }
        }
        assert!(files.len() > 20, "{} shaders", files.len());
        files
    }

    /// The words of a line of code and what lies between them (numbers whole).
    fn words(line: &str) -> Vec<(bool, String)> {
        let mut out: Vec<(bool, String)> = Vec::new();
        let mut in_number = false;
        for c in line.chars() {
            let word = c.is_ascii_alphanumeric() || c == '_';
            in_number =
                in_number && (word || c == '.') || (c.is_ascii_digit() && !out.last().is_some_and(|w| w.0));
            let is_name = word && !in_number;
            match out.last_mut() {
                Some((name, text)) if *name == is_name && (is_name || !word) => text.push(c),
                _ => out.push((is_name, c.to_string())),
            }
        }
        out
    }

    /// The shipped shaders are the shaders with their comments gone and their names renamed: line for
    /// line the same code between the names; one short name for each name, the same in every file, no
    /// two names sharing one; and the entry points and overrides the host names kept.
    #[test]
    fn the_renamed_shaders_are_the_shaders_with_one_short_name_for_each_name() {
        let mut to_short = std::collections::BTreeMap::new();
        let mut from_short = std::collections::BTreeMap::new();
        let (mut before, mut after) = (0, 0);
        for (file, original, shipped) in renamed() {
            assert_eq!(shipped.lines().count(), original.lines().count(), "{file}");
            for (line, (theirs, ours)) in original.lines().zip(shipped.lines()).enumerate() {
                let code = theirs.split("//").next().unwrap();
                let (theirs, ours) = (words(code), words(ours));
                assert_eq!(theirs.len(), ours.len(), "{file}:{}: {code} | {ours:?}", line + 1);
                for ((is_name, name), (_, short)) in theirs.iter().zip(&ours) {
                    if !is_name {
                        assert_eq!(name, short, "{file}:{}", line + 1);
                        continue;
                    }
                    assert_eq!(
                        to_short.entry(name.clone()).or_insert(short.clone()),
                        short,
                        "{file}: {name}"
                    );
                    assert_eq!(
                        from_short.entry(short.clone()).or_insert(name.clone()),
                        name,
                        "{file}: {short}"
                    );
                    before += name.len();
                    after += short.len();
                }
            }
        }
        for kept in
            ["make_vertices", "make_tetra_triangles", "finalize_draw", "LIGHT_SLOTS", "position", "xyz"]
        {
            assert_eq!(to_short.get(kept).map(String::as_str), Some(kept));
        }
        assert!(after * 3 < before * 2, "names of {after} bytes, from {before}");
    }
}
