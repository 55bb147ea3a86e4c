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

# `need_esbuild`: installs the esbuild pinned in www/tools/ when missing (and Node.js with it), and sets
# `esbuild` to its path. Run from the repository's root.
need_esbuild() {
    esbuild=www/tools/node_modules/.bin/esbuild
    if [ ! -x "$esbuild" ]; then
        command -v npm >/dev/null || need_deb nodejs npm
        (cd www/tools && npm install --no-audit --no-fund --silent)
    fi
}

# `bundle_widget FILE`: bundles the notebook widget's module (python/js/widget.js, an anywidget front-end
# module) with the element and both builds' JavaScript into one file. Its WebAssembly is looked up in
# pkg/ and pkg-webgl/ beside it (or under the model's `wasm_url`), as dist/ and the wheel lay them out.
bundle_widget() {
    need_esbuild
    "$esbuild" python/js/widget.js --bundle --format=esm --minify --target=es2022 --outfile="$1" \
        --log-level=warning
}

# `bundle_plane_widget FILE`: bundles the 2D notebook widget's module (python/js/widget-2d.js) with the
# 2D figure into one file (it loads no WebAssembly).
bundle_plane_widget() {
    need_esbuild
    "$esbuild" python/js/widget-2d.js --bundle --format=esm --minify --target=es2022 --outfile="$1" \
        --log-level=warning
}
