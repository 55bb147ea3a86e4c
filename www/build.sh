#!/usr/bin/env bash
# Builds the page's WebAssembly (release), installing what it needs when missing: the wasm32 target, the
# wasm-bindgen command line at exactly the version Cargo.lock pins, and Node.js (for
# www/tools/short-imports.mjs, which gives the wasm's imports short names). Two builds: pkg/ draws with
# WebGPU (what nearly every visitor loads), pkg-webgl/ with WebGL2, loaded only where WebGPU is missing
# (wgpu's WebGL2 backend is large, so WebGPU visitors do not pay for it). Also bundles the libraries a
# recorded clip is encoded with into www/vendor/clip-codecs.js (`need_clip_codecs`, www/need-deb.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
source www/need-deb.sh

command -v node >/dev/null || need_deb nodejs
# wasm-opt (binaryen, pinned in www/tools/package.json), installed with the page's other build tools.
need_esbuild
wasm_opt=www/tools/node_modules/.bin/wasm-opt
rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown

# The version of the wasm-bindgen crate in Cargo.lock (the command line must match it exactly).
cargo metadata --format-version 1 >/dev/null  # writes Cargo.lock when missing
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if ! command -v wasm-bindgen >/dev/null || [ "$(wasm-bindgen --version | awk '{print $2}')" != "$version" ]; then
    echo "installing wasm-bindgen-cli $version (a few minutes, once)"
    cargo install wasm-bindgen-cli --version "=$version"
fi

# A panic's message names its source file: name the registry's crates' files from the crate's folder on
# (`wgpu-30.0.1/src/…`), whichever folder this machine keeps them in, so that the build is the same
# size everywhere (and smaller). Added to .cargo/config.toml's flags: cargo joins the lists.
remap=()
for dir in "${CARGO_HOME:-$HOME/.cargo}"/registry/src/*/; do
    [ -d "$dir" ] && remap+=(--config "target.wasm32-unknown-unknown.rustflags=[\"--remap-path-prefix=$dir=\"]")
done

# `optimise FILE`: binaryen's optimisations over the whole module, in place, without its inlining (which
# makes the module smaller but compresses worse: the WebGPU build is about 5 KB smaller gzipped without
# it, 2 KB larger with it). The features are those the module was built with, as
# its target_features section lists them; the section itself is left out (only tools read it). Further
# flags follow: `--converge` repeats the passes until the module stops shrinking (a few hundred bytes
# more, and seconds on the small modules, but minutes on the WebGL2 one, which is run once).
optimise() {
    local file=$1
    shift
    "$wasm_opt" -O3 --flexible-inline-max-function-size=0 --one-caller-inline-max-function-size=0 \
        --strip-target-features "$@" "$file" -o "$file"
}

# build OUT [wasm-opt flags] -- [wasm-bindgen flags] -- [cargo flags]
build() {
    local out=$1
    shift
    local passes=()
    while [ "$1" != "--" ]; do passes+=("$1"); shift; done
    shift
    local bindgen=()
    while [ "$1" != "--" ]; do bindgen+=("$1"); shift; done
    shift
    cargo build "${remap[@]}" --profile wasm --lib --target wasm32-unknown-unknown "$@"
    wasm-bindgen --target web --no-typescript "${bindgen[@]}" --out-dir "$out" \
        target/wasm32-unknown-unknown/wasm/metaballs.wasm
    optimise "$out/metaballs_bg.wasm" ${passes[@]+"${passes[@]}"}
    # Short names for the imports from the glue (wasm-bindgen's carry 16 hex digits of hash each).
    node www/tools/short-imports.mjs "$out"
    echo "built $out/metaballs_bg.wasm ($(wc -c < "$out/metaballs_bg.wasm") bytes, $(gzip -9c "$out/metaballs_bg.wasm" | wc -c) gzipped)"
}
# Both builds use the `wasm` profile (Cargo.toml: optimised for size, whole-program) and drop the
# function names (panic traces show indices instead).
build pkg --converge -- --remove-name-section --remove-producers-section --
build pkg-webgl -- --remove-name-section --remove-producers-section -- --no-default-features --features webgl
# The critical points' search and the measures along the iso level (levels/): a third, small module,
# loaded by the topology worker only when a figure asks for them.
cargo build "${remap[@]}" --profile wasm --lib --target wasm32-unknown-unknown -p metaballs-levels
wasm-bindgen --target web --no-typescript --remove-name-section --remove-producers-section --out-dir pkg-levels \
    target/wasm32-unknown-unknown/wasm/metaballs_levels.wasm
optimise pkg-levels/metaballs_levels_bg.wasm --converge
echo "built pkg-levels/metaballs_levels_bg.wasm ($(wc -c < pkg-levels/metaballs_levels_bg.wasm) bytes, $(gzip -9c pkg-levels/metaballs_levels_bg.wasm | wc -c) gzipped)"
# What www/lib/figure/clip.js loads when a clip is recorded: mediabunny and gifenc, pinned in www/tools/.
need_clip_codecs
