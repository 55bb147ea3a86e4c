#!/usr/bin/env bash
# Builds the page's WebAssembly into pkg/ (release), installing what it needs when missing: the wasm32
# target and the wasm-bindgen command line at exactly the version Cargo.lock pins.
set -euo pipefail
cd "$(dirname "$0")/.."

rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown

# The version of the wasm-bindgen crate in Cargo.lock (the command line must match it exactly).
cargo metadata --format-version 1 >/dev/null  # writes Cargo.lock when missing
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/version = |"/, ""); print; exit }' Cargo.lock)
if ! command -v wasm-bindgen >/dev/null || [ "$(wasm-bindgen --version | awk '{print $2}')" != "$version" ]; then
    echo "installing wasm-bindgen-cli $version (a few minutes, once)"
    cargo install wasm-bindgen-cli --version "=$version"
fi

cargo build --release --lib --target wasm32-unknown-unknown
wasm-bindgen --target web --no-typescript --out-dir pkg target/wasm32-unknown-unknown/release/metaballs.wasm
echo "built pkg/metaballs_bg.wasm ($(wc -c < pkg/metaballs_bg.wasm) bytes, $(gzip -9c pkg/metaballs_bg.wasm | wc -c) gzipped)"
