#!/usr/bin/env bash
# Builds the notebook widget's wheel, target/python/dist/metaballs_widget-VERSION-py3-none-any.whl: the
# WebAssembly (www/build.sh), the widget's module bundled with the element and both builds' JavaScript
# (esbuild, from www/tools/), both wasm builds (laid out as in dist/) and the parameter table, packed by hatchling. Needs
# python3 with venv, node and npm (installed when missing).
set -euo pipefail
cd "$(dirname "$0")/.."
source www/need-deb.sh

# tests/run.sh builds the WebAssembly once for all of its outputs and says so.
[ "${METABALLS_WASM_BUILT:-}" = 1 ] || bash www/build.sh

static=python/src/metaballs_widget/static
rm -rf "$static"
mkdir -p "$static/pkg" "$static/pkg-webgl" "$static/pkg-levels"
bundle_widget "$static/widget.js"
bundle_plane_widget "$static/widget-2d.js"
cp pkg/metaballs_bg.wasm "$static/pkg/"
cp pkg-webgl/metaballs_bg.wasm "$static/pkg-webgl/"
cp pkg-levels/metaballs_levels_bg.wasm "$static/pkg-levels/"
cp www/parameters.json "$static/parameters.json"
cp www/plane-parameters.json "$static/plane-parameters.json"

venv=target/python/build-venv
if [ ! -x "$venv/bin/pip" ]; then
    python3 -c 'import venv, ensurepip' 2>/dev/null || need_deb python3-venv
    python3 -m venv "$venv"
fi
rm -rf target/python/dist
"$venv/bin/pip" wheel --quiet --no-deps --wheel-dir target/python/dist ./python
wheel=$(ls target/python/dist/*.whl)
echo "built $wheel ($(wc -c < "$wheel") bytes)"
