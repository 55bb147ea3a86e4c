#!/usr/bin/env bash
# Compiles the workspace's own crates with Clippy's lints on and every warning an error, so that the
# test builds are also the lints (`RUSTC_WORKSPACE_WRAPPER`; the dependencies are compiled as usual).
# Cargo calls it as `clippy-rustc.sh RUSTC ARGS…`; `clippy-driver` takes the same form.
exec clippy-driver "$@" -D warnings
