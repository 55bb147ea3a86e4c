//! The browser entry point: panics are reported on the console instead of failing silently.

use wasm_bindgen::prelude::*;

#[wasm_bindgen(start)]
fn start() {
    console_error_panic_hook::set_once();
}
