#!/usr/bin/env bash
# Installs what the tests need (skipping what is present) and runs every test:
# formatting and lints (native and wasm32), the native suite on the GPU adapter at hand (lavapipe
# without a GPU), and the wasm32 library build.
set -euo pipefail
cd "$(dirname "$0")/.."

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

need_deb mesa-vulkan-drivers
rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
rustup component list --installed | grep -q '^clippy' || rustup component add clippy
rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt

# Vulkan loaders complain on stderr without a runtime directory.
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -d "${XDG_RUNTIME_DIR}" ]; then
    export XDG_RUNTIME_DIR="${TMPDIR:-/tmp}/metaballs-runtime-$(id -u)"
    mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
fi

echo "== format"
cargo fmt --all --check
echo "== lints (native)"
cargo clippy --all-targets -- -D warnings
echo "== lints (wasm32)"
cargo clippy --lib --target wasm32-unknown-unknown -- -D warnings
echo "== wasm32 build"
cargo build --lib --target wasm32-unknown-unknown
echo "== native tests"
log="$(mktemp)"
trap 'rm -f "$log"' EXIT
cargo test 2>&1 | tee "$log"

# One closing line for the whole run.
awk '/^test result:/ { passed += $4; failed += $6 } END { printf "all tests: %d passed, %d failed\n", passed, failed }' "$log"
