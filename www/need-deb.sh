# Sourced by the build, serve and test scripts: `need_deb PACKAGE...` installs the Debian packages that
# are missing (as root, or through sudo), running `apt-get update` once first.

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

apt_updated=0
need_deb() {
    local missing=()
    for package in "$@"; do
        dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
    done
    [ ${#missing[@]} -eq 0 ] && return
    echo "installing ${missing[*]}"
    if [ $apt_updated -eq 0 ]; then as_root apt-get update -q; apt_updated=1; fi
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
}

# `need_esbuild`: installs the packages pinned in www/tools/package.json (esbuild, binaryen's wasm-opt,
# and the libraries bundled into www/vendor/) when one is missing or not at its pinned version (and
# Node.js with them), and sets `esbuild` to its path. Run from the repository's root.
need_esbuild() {
    esbuild=www/tools/node_modules/.bin/esbuild
    local name version stale=0
    # The pins, one `"name": "version"` a line in devDependencies.
    while read -r name version; do
        grep -qs "\"version\": \"$version\"" "www/tools/node_modules/$name/package.json" || stale=1
    done < <(sed -n '/"devDependencies"/,/}/s/^ *"\([^"]*\)": *"\([^"]*\)".*/\1 \2/p' www/tools/package.json)
    if [ ! -x "$esbuild" ] || [ "$stale" = 1 ]; then
        command -v npm >/dev/null || need_deb nodejs npm
        (cd www/tools && npm install --no-audit --no-fund --silent)
    fi
}

# `need_clip_codecs`: bundles what a recorded clip is encoded with (mediabunny and gifenc, pinned in
# www/tools/package.json, as www/tools/clip-codecs-entry.js names them) into www/vendor/clip-codecs.js,
# which www/lib/figure/clip.js imports only when a clip is encoded; again when the entry or the pins
# changed. One notice at its top names both libraries, their versions, licences and sources.
need_clip_codecs() {
    need_esbuild
    local out=www/vendor/clip-codecs.js entry=www/tools/clip-codecs-entry.js
    if [ -f "$out" ] && [ "$out" -nt "$entry" ] && [ "$out" -nt www/tools/package-lock.json ] \
        && [ "$out" -nt www/need-deb.sh ]; then
        return
    fi
    local modules=www/tools/node_modules mediabunny gifenc
    mediabunny=$(sed -n 's/^ *"version": "\([^"]*\)".*/\1/p' "$modules/mediabunny/package.json" | head -1)
    gifenc=$(sed -n 's/^ *"version": "\([^"]*\)".*/\1/p' "$modules/gifenc/package.json" | head -1)
    local notice
    notice="/*! www/vendor/clip-codecs.js: npm packages bundled unmodified by www/build.sh (esbuild).
 * mediabunny $mediabunny, Copyright (c) 2026-present, Vanilagy and contributors. This Source Code Form
 * is subject to the terms of the Mozilla Public License, v. 2.0 (https://mozilla.org/MPL/2.0/). Its
 * source: the npm package mediabunny@$mediabunny, https://github.com/Vanilagy/mediabunny.
 * gifenc $gifenc, Copyright (c) 2017 Matt DesLauriers (https://github.com/mattdesl/gifenc). MIT licence:
$(sed '1,2d; s/^/ * /; s/[[:space:]]*$//' "$modules/gifenc/LICENSE.md")
 */"
    mkdir -p www/vendor
    "$esbuild" "$entry" --bundle --format=esm --minify --target=es2022 --main-fields=module,main \
        --legal-comments=none --banner:js="$notice" --outfile="$out.tmp" --log-level=warning
    mv "$out.tmp" "$out"
    echo "built $out ($(wc -c < "$out") bytes, $(gzip -9c "$out" | wc -c) gzipped)"
}

# `bundle_widget FILE`: bundles the notebook widget's module (python/js/widget.js, an anywidget front-end
# module) with the element and both builds' JavaScript into one file, the clip encoders inline (a host
# loads the file from a blob: URL, where no chunk beside it could be fetched). Its WebAssembly is looked
# up in pkg/ and pkg-webgl/ beside it (or under the model's `wasm_url`), as dist/ and the wheel lay them out.
bundle_widget() {
    need_clip_codecs
    "$esbuild" python/js/widget.js --bundle --format=esm --minify --target=es2022 --outfile="$1" \
        --log-level=warning
}

# `bundle_plane_widget FILE`: bundles the 2D notebook widget's module (python/js/widget-2d.js) with the
# 2D figure into one file (it loads no WebAssembly).
bundle_plane_widget() {
    need_clip_codecs
    "$esbuild" python/js/widget-2d.js --bundle --format=esm --minify --target=es2022 --outfile="$1" \
        --log-level=warning
}
