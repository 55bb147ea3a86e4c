#!/usr/bin/env bash
# Builds the page and lays out what an author puts on a static host in dist/: index.html, embed.html, squares.html, embed-2d.html,
# www/ (the element and the page's script, bundled; the stylesheets; the lecture example), pkg/ (the
# WebAssembly), pkg-webgl/ (the WebGL2 build, fetched only by browsers without WebGPU), pkg-levels/ (the
# critical points' module, fetched only by a figure that shows them), widget.js and widget-2d.js (the
# notebook widgets' modules, for anywidget hosts such as MyST's {anywidget} directive). Every path inside
# is relative, so the folder works under any sub-path of any host.
#
# The element's modules are bundled (esbuild, pinned in www/tools/) into two entry files (and the
# mesher worker's, in www/lib/engine/ beside the code that starts it) and one shared file, so a visitor's browser fetches three scripts at once instead of discovering the modules
# import by import. The shared file sits in www/lib/engine/, where the module that loads the
# WebAssembly was, so the relative paths to it stay as they are in the sources.
set -euo pipefail
cd "$(dirname "$0")/.."
source www/need-deb.sh

# tests/run.sh builds the WebAssembly once for all of its outputs and says so.
[ "${METABALLS_WASM_BUILT:-}" = 1 ] || bash www/build.sh
# The clip encoders (www/vendor/, which www/build.sh writes), for a chunk of their own that only
# recording a clip fetches.
need_clip_codecs

rm -rf dist
mkdir -p dist/www dist/pkg dist/pkg-webgl dist/pkg-levels
cp index.html embed.html embed-2d.html squares.html dist/
"$esbuild" www/metaballs-view.js www/page.js www/lib/engine/mesh-worker.js www/lib/engine/levels-worker.js --bundle --splitting --format=esm --minify --charset=utf8 --sourcemap \
    --target=es2022 --outbase=www --outdir=dist/www --chunk-names='lib/engine/[name]-[hash]' \
    --external:'../../../pkg/*' --external:'../../../pkg-webgl/*' --external:'../../../pkg-levels/*' --log-level=warning
# The 2D figure is bundled on its own (it loads no wasm), so that a page of 3D figures fetches no chunk
# it shares with it; the clip encoders stay a chunk of their own, fetched only when a clip is made.
"$esbuild" www/metaballs-2d.js www/plane-page.js --bundle --splitting --format=esm --minify --charset=utf8 --sourcemap --target=es2022 \
    --outdir=dist/www --chunk-names='lib/plane/[name]-[hash]' --log-level=warning
if grep -l 'mediabunny' dist/www/metaballs-2d.js dist/www/metaballs-view.js; then
    echo "dist.sh: the clip encoders were bundled into an element's module: they are to load only when a clip is made" >&2
    exit 1
fi
if grep -l 'pkg/metaballs' dist/www/*.js; then
    echo "dist.sh: the code that loads the WebAssembly was bundled outside www/lib/engine/, where its paths hold" >&2
    exit 1
fi
cp -r www/examples www/metaballs-view.css www/style.css dist/www/
cp pkg/metaballs.js pkg/metaballs_bg.wasm dist/pkg/
cp pkg-webgl/metaballs.js pkg-webgl/metaballs_bg.wasm dist/pkg-webgl/
cp pkg-levels/metaballs_levels.js pkg-levels/metaballs_levels_bg.wasm dist/pkg-levels/
# Every file the bundled modules name relative to themselves (`new URL("…", import.meta.url)`: the
# WebAssembly, its JavaScript, the mesher worker) is where that path leads from the file that names it.
missing=0
while IFS= read -r file; do
    while IFS= read -r path; do
        if [ ! -f "$(dirname "$file")/$path" ]; then
            echo "dist.sh: $file names $path, which is not beside it in dist/" >&2
            missing=1
        fi
    done < <(grep -oE 'new URL\("[^"]+",import\.meta\.url\)' "$file" | sed -E 's/^new URL\("([^"]+)".*/\1/')
done < <(find dist/www -name '*.js')
[ "$missing" = 0 ] || exit 1
bundle_widget dist/widget.js
bundle_plane_widget dist/widget-2d.js
echo "dist/ is ready ($(du -sh dist | cut -f1)): copy it to a static host"
