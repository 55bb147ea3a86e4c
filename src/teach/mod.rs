//! What the teaching views and the cell inspector explain, computed on the CPU from the scene and the
//! tables: the 15 classes of the 256 cases, and the cell a ray picks with everything inside it. No
//! GPU here: `draw` puts the classes on screen, the renderer and the page show the picked cell.

pub mod case_classes;
pub mod error;
pub mod inspect;
pub mod subcases;
