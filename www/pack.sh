#!/usr/bin/env bash
# Makes the npm package `metaballs-view` as `npm pack` would publish it: builds the WebAssembly, lays
# out the element's modules, both wasm builds and the critical points' module, embed.html, the stylesheet that reserves each figure's
# box, the TypeScript declarations and the Custom Elements Manifest under target/npm/package/, and packs
# it into target/npm/metaballs-view-VERSION.tgz (the version is the crate's). Needs node and npm. The
# modules come with www/vendor/, the clip encoders they import when a clip is recorded.
set -euo pipefail
cd "$(dirname "$0")/.."

# tests/run.sh builds the WebAssembly once for all of its outputs and says so.
[ "${METABALLS_WASM_BUILT:-}" = 1 ] || bash www/build.sh
# The clip encoders in www/vendor/ (written by www/build.sh), imported by www/lib/figure/clip.js.
source www/need-deb.sh
need_clip_codecs
version=$(awk -F'"' '/^version = / { print $2; exit }' Cargo.toml)
out=target/npm/package
rm -rf "$out"
mkdir -p "$out/www" "$out/pkg" "$out/pkg-webgl" "$out/pkg-levels"
cp embed.html embed-2d.html "$out/"
cp -r www/lib www/vendor www/metaballs-view.js www/metaballs-2d.js www/metaballs-view.d.ts www/metaballs-2d.d.ts www/metaballs-view.css www/custom-elements.json \
    www/page.js www/plane-page.js www/bench.js www/style.css "$out/www/"
cp pkg/metaballs.js pkg/metaballs_bg.wasm "$out/pkg/"
cp pkg-webgl/metaballs.js pkg-webgl/metaballs_bg.wasm "$out/pkg-webgl/"
cp pkg-levels/metaballs_levels.js pkg-levels/metaballs_levels_bg.wasm "$out/pkg-levels/"
cp www/package/README.md "$out/"
sed "s/\"version\": \"0.0.0\"/\"version\": \"$version\"/" www/package/package.json > "$out/package.json"
tarball=$(cd "$out" && npm pack --silent --pack-destination ..)
echo "packed target/npm/$tarball ($(wc -c < "target/npm/$tarball") bytes)"
