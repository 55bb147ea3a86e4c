#!/usr/bin/env bash
# Installs what the tests need (skipping what is present) and runs every test: formatting and lints
# (native and wasm32), the native suite on the GPU adapter at hand (lavapipe without a GPU), the engine
# in headless Chromium's WebGPU (wasm-bindgen-test), the notebook widget's Python tests and the page end
# to end (Playwright), then prints each stage's wall time. It leaves the checkout as it found it.
set -euo pipefail
cd "$(dirname "$0")/.."

# Each stage's wall time, printed at the end, so a slow stage shows.
run_start=$(date +%s)
stage_names=()
stage_seconds=()
stage_start=$run_start
stage() {
    local now
    now=$(date +%s)
    if [ ${#stage_names[@]} -gt 0 ]; then stage_seconds+=($((now - stage_start))); fi
    stage_names+=("$1")
    stage_start=$now
    echo "== $1"
}
stage_report() {
    local now i
    now=$(date +%s)
    stage_seconds+=($((now - stage_start)))
    echo "stage times:"
    for i in "${!stage_names[@]}"; do
        printf '  %5ds  %s\n' "${stage_seconds[$i]}" "${stage_names[$i]}"
    done
    printf '  %5ds  all (%dm %02ds)\n' $((now - run_start)) $(((now - run_start) / 60)) $(((now - run_start) % 60))
}
# The tests' output, for the closing count; the stage times are printed however the run ends.
log="$(mktemp)"
trap 'rm -f "$log"; stage_report' EXIT

source www/need-deb.sh

stage "tools (installed when missing)"

# ffmpeg: ffprobe and ffmpeg read back the clips tests/e2e/clip.test.js records.
need_deb mesa-vulkan-drivers chromium chromium-driver poppler-utils python3 g++ ffmpeg
command -v node >/dev/null && command -v npm >/dev/null || need_deb nodejs npm
rustup target list --installed | grep -qx wasm32-unknown-unknown || rustup target add wasm32-unknown-unknown
rustup component list --installed | grep -q '^clippy' || rustup component add clippy
rustup component list --installed | grep -q '^rustfmt' || rustup component add rustfmt

# Vulkan loaders complain on stderr without a runtime directory.
if [ -z "${XDG_RUNTIME_DIR:-}" ] || [ ! -d "${XDG_RUNTIME_DIR}" ]; then
    export XDG_RUNTIME_DIR="${TMPDIR:-/tmp}/metaballs-runtime-$(id -u)"
    mkdir -p "$XDG_RUNTIME_DIR" && chmod 700 "$XDG_RUNTIME_DIR"
fi

# A test run builds each crate once: incremental caches would only take disk.
export CARGO_INCREMENTAL="${CARGO_INCREMENTAL:-0}"

stage "format"
cargo fmt --all --check

# Everything the tests use is built once: the two release wasm builds, then from them dist/, the npm
# package and the notebook's wheel (each of whose scripts would otherwise build the wasm again). The
# end-to-end tests take these as they are (they build one themselves only when it is missing or older
# than its sources, as when a test file is run on its own). The build runs beside the test
# builds: its whole-program optimisation keeps one core busy for long stretches, which they fill.
page_log="$(mktemp)"
setsid bash -c 'set -euo pipefail
    started=$(date +%s)
    bash www/build.sh
    export METABALLS_WASM_BUILT=1
    bash www/dist.sh
    bash www/pack.sh
    bash python/build.sh
    echo "page build: $(($(date +%s) - started)) s beside the test builds"' >"$page_log" 2>&1 &
page_build=$!
# Stopped with the run, whichever way it ends.
trap 'kill -- -"$page_build" 2>/dev/null || true; rm -f "$log" "$page_log"; stage_report' EXIT

stage "crate package (metadata and file list)"
cargo package --allow-dirty --no-verify --quiet

# The test builds are the lints: the workspace's crates are compiled by Clippy's driver with every
# warning an error (native: the library, its tests, the command and the suite; wasm32: the library and
# the browser tests), so the dependencies are compiled once for both. Every later `cargo test` of the
# run uses the same wrapper, or it would compile the crates again.
lints=(env RUSTC_WORKSPACE_WRAPPER="$PWD/tests/tools/clippy-rustc.sh")
stage "test builds with the lints (native, wasm32)"
"${lints[@]}" cargo test --no-run
"${lints[@]}" cargo test --target wasm32-unknown-unknown --test browser --no-run

stage "page build (release wasm, dist/, npm package, wheel)"
if ! wait "$page_build"; then
    cat "$page_log"
    echo "the page build failed (above)" >&2
    exit 1
fi
cat "$page_log"
export METABALLS_WASM_BUILT=1

stage "native tests"
"${lints[@]}" cargo test 2>&1 | tee -a "$log"

stage "engine in headless Chromium (WebGPU)"
CHROMEDRIVER=/usr/bin/chromedriver "${lints[@]}" cargo test --target wasm32-unknown-unknown --test browser 2>&1 | tee -a "$log"

stage "notebook widget (Python tests)"
venv=target/python/test-venv
if [ ! -x "$venv/bin/pip" ]; then
    python3 -c 'import venv, ensurepip' 2>/dev/null || need_deb python3-venv
    python3 -m venv "$venv"
fi
"$venv/bin/pip" install --quiet --force-reinstall --no-deps target/python/dist/*.whl
"$venv/bin/pip" install --quiet target/python/dist/*.whl pytest jupyterlab
METABALLS_CLI="$PWD/target/debug/metaballs" "$venv/bin/pytest" -q -p no:cacheprovider python/tests 2>&1 | tee -a "$log"

stage "page end to end (Playwright, headless Chromium)"
(
    cd tests/e2e
    # The locked test tools (Playwright, TypeScript, publint, VitePress, reveal.js, axe-core, MyST),
    # installed exactly as locked when missing or older than the lock. The lock lists every platform's
    # builds of the bundlers' optional native packages, so `npm ci` takes it as it is and the checkout
    # stays unchanged.
    if [ ! -f node_modules/.package-lock.json ] || [ node_modules/.package-lock.json -ot package-lock.json ]; then
        PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund
    fi
    # Two files at a time, longest first, then those that time the page's responsiveness alone (all.js).
    npm test
) 2>&1 | tee -a "$log"

# One closing line for the whole run.
awk '/^test result:/ { passed += $4; failed += $6 }
     /^# pass /       { passed += $3 }
     /^# fail /       { failed += $3 }
     / in [0-9.]+s/ && /(passed|failed)/ {
         for (i = 2; i <= NF; i++) {
             if ($i ~ /^passed,?$/) passed += $(i - 1)
             if ($i ~ /^failed,?$/) failed += $(i - 1)
         }
     }
     END { printf "all tests: %d passed, %d failed\n", passed, failed }' "$log"
