//! Drawing the mesh the extractors made: Blinn-Phong shading into a view, the teaching views over the
//! buffers the compute passes fill (display modes, grid views, colourings, the slice), and the shading
//! uniforms. Reads extraction's buffers; never writes them.

pub mod measure;
pub mod shade;
pub mod slice;
pub mod uniforms;
pub mod views;
