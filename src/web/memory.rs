//! The wasm's heap, counted: every allocation goes through `cap`'s counting wrapper around the system
//! allocator, so the page can tell the bytes its figures hold from the size of the linear memory
//! (which only grows, to the most they ever held at once, and keeps the gaps between blocks).

use cap::Cap;
use std::alloc::{GlobalAlloc, Layout, System};
use wasm_bindgen::prelude::*;

static COUNTED: Cap<System> = Cap::new(System, usize::MAX);

/// Calls `COUNTED` out of line: inlined, its count would be copied into every place that allocates
/// (about 9 KB more of gzipped wasm).
struct OutOfLine;

unsafe impl GlobalAlloc for OutOfLine {
    #[inline(never)]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        unsafe { COUNTED.alloc(layout) }
    }
    #[inline(never)]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { COUNTED.dealloc(ptr, layout) }
    }
    #[inline(never)]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        unsafe { COUNTED.alloc_zeroed(layout) }
    }
    #[inline(never)]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        unsafe { COUNTED.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static ALLOCATOR: OutOfLine = OutOfLine;

/// Bytes allocated on the wasm heap and not yet freed, by every view on the page together.
#[wasm_bindgen]
pub fn heap_bytes() -> usize {
    COUNTED.allocated()
}
