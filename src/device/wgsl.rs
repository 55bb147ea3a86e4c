//! The shaders as the binary carries them: [`wgsl!`](crate::device::wgsl) drops the line comments and
//! the indentation of a WGSL source while the crate compiles, keeping every line break so that a
//! shader error's line number still points at the same line of the file under `shaders/`. The
//! comments are most of the shaders' bytes, and every byte of them is downloaded with the page's
//! WebAssembly.

/// `source` (`include_str!` of a WGSL file) without its comments and indentation, as a `&'static str`
/// made at compile time.
macro_rules! wgsl {
    ($source:expr) => {{
        const SOURCE: &str = $source;
        const LEN: usize = SOURCE.len();
        const MINIFIED: ([u8; LEN], usize) = $crate::device::wgsl::minify::<LEN>(SOURCE);
        const USED: usize = MINIFIED.1;
        const BYTES: [u8; USED] = $crate::device::wgsl::prefix::<LEN, USED>(&MINIFIED.0);
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

    /// Every shader the crate ships keeps its lines and loses at least a third of its bytes; what is
    /// left of each line is a prefix of the original line's code, trimmed.
    #[test]
    fn the_shaders_keep_their_lines_and_code() {
        let shaders = concat!(
            include_str!("../../shaders/common.wgsl"),
            include_str!("../../shaders/extract/lod.wgsl"),
            include_str!("../../shaders/draw/shade.wgsl"),
            include_str!("../../shaders/draw/views/exact.wgsl"),
        );
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
}
