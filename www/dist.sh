#!/usr/bin/env bash
# Builds the page and copies what an author puts on a static host into dist/: index.html, embed.html,
# www/ (the element, its modules and the lecture example), pkg/ (the WebAssembly) and pkg-webgl/ (the
# WebGL2 build, fetched only by browsers without WebGPU). Every path inside
# is relative, so the folder works under any sub-path of any host.
set -euo pipefail
cd "$(dirname "$0")/.."

bash www/build.sh
rm -rf dist
mkdir -p dist/www dist/pkg dist/pkg-webgl
cp index.html embed.html dist/
cp -r www/lib www/examples www/metaballs-view.js www/metaballs-view.css www/page.js www/bench.js www/style.css \
    dist/www/
cp pkg/metaballs.js pkg/metaballs_bg.wasm dist/pkg/
cp pkg-webgl/metaballs.js pkg-webgl/metaballs_bg.wasm dist/pkg-webgl/
echo "dist/ is ready ($(du -sh dist | cut -f1)): copy it to a static host"
