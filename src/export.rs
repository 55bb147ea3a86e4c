//! The surface as a file other programs read: binary STL for slicers, OBJ with normals for modellers,
//! and binary PLY; natively, optionally simplified to a target triangle count first.
//!
//! The mesh written is the welded one the passes emit (one vertex per crossed grid edge, shared by
//! every triangle that uses it), so the surface is closed wherever it lies inside the box, and every
//! format keeps its triangles wound counter-clockwise seen from outside.

use crate::extract::mesh::IndexedMesh;
use crate::scene::decimal::num;
use glam::Vec3;
use std::fmt::Write as _;

/// A mesh file format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshFormat {
    /// Binary STL: facets with their normals, in millimetres (the box 50 mm wide), Z up.
    Stl,
    /// Wavefront OBJ with per-vertex normals, in box units (the box spans −1…1), Y up.
    Obj,
    /// Binary little-endian PLY with per-vertex normals, in box units, Y up.
    Ply,
}

impl MeshFormat {
    pub const WORDS: &[&str] = &["stl", "obj", "ply"];

    /// Reads `stl`, `obj` or `ply` (any case); the error says what is accepted.
    pub fn parse(word: &str) -> Result<MeshFormat, crate::ParamError> {
        match word.trim().to_ascii_lowercase().as_str() {
            "stl" => Ok(Self::Stl),
            "obj" => Ok(Self::Obj),
            "ply" => Ok(Self::Ply),
            _ => Err(crate::ParamError::Invalid {
                name: "mesh format",
                value: word.to_string(),
                expected: format!("one of {}", Self::WORDS.join(", ")).into(),
            }),
        }
    }

    /// The format a file name asks for by its extension.
    pub fn from_file_name(name: &str) -> Option<MeshFormat> {
        let (_, extension) = name.rsplit_once('.')?;
        Self::parse(extension).ok()
    }

    pub fn extension(self) -> &'static str {
        Self::WORDS[self as usize]
    }

    /// The media type of a download.
    pub fn mime(self) -> &'static str {
        match self {
            Self::Stl => "model/stl",
            Self::Obj => "model/obj",
            Self::Ply => "application/ply",
        }
    }

    /// File units per box half-width: STL is read as millimetres by slicers, so the box is 50 mm
    /// there; modellers take OBJ and PLY in the scene's own units.
    pub fn default_scale(self) -> f32 {
        match self {
            Self::Stl => 25.0,
            Self::Obj | Self::Ply => 1.0,
        }
    }
}

/// `mesh` encoded as `format`, positions multiplied by `scale`.
pub fn encode(mesh: &IndexedMesh, format: MeshFormat, scale: f32) -> Vec<u8> {
    match format {
        MeshFormat::Stl => stl(mesh, scale),
        MeshFormat::Obj => obj(mesh, scale).into_bytes(),
        MeshFormat::Ply => ply(mesh, scale),
    }
}

/// Y up to Z up, a rotation (the winding, and so the outside, is kept).
fn z_up(p: Vec3) -> Vec3 {
    Vec3::new(p.x, -p.z, p.y)
}

fn stl(mesh: &IndexedMesh, scale: f32) -> Vec<u8> {
    let mut out = Vec::with_capacity(84 + 50 * mesh.triangles.len());
    let mut header = [b' '; 80];
    let title = b"metaballs isosurface, millimetres, Z up";
    header[..title.len()].copy_from_slice(title);
    out.extend_from_slice(&header);
    out.extend_from_slice(&(mesh.triangles.len() as u32).to_le_bytes());
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| z_up(mesh.positions[i as usize] * scale));
        let normal = (b - a).cross(c - a).normalize_or_zero();
        for v in [normal, a, b, c] {
            for x in v.to_array() {
                out.extend_from_slice(&x.to_le_bytes());
            }
        }
        out.extend_from_slice(&0u16.to_le_bytes());
    }
    out
}

fn obj(mesh: &IndexedMesh, scale: f32) -> String {
    let mut out = String::with_capacity(64 * mesh.positions.len() + 32 * mesh.triangles.len());
    let _ = writeln!(
        out,
        "# metaballs isosurface: {} vertices, {} triangles, box units (the box spans -1..1), Y up",
        mesh.positions.len(),
        mesh.triangles.len()
    );
    for p in &mesh.positions {
        let p = *p * scale;
        let _ = writeln!(out, "v {} {} {}", num(p.x), num(p.y), num(p.z));
    }
    for n in &mesh.normals {
        let _ = writeln!(out, "vn {} {} {}", num(n.x), num(n.y), num(n.z));
    }
    for t in &mesh.triangles {
        let [a, b, c] = t.map(|i| i + 1);
        let _ = writeln!(out, "f {a}//{a} {b}//{b} {c}//{c}");
    }
    out
}

fn ply(mesh: &IndexedMesh, scale: f32) -> Vec<u8> {
    let header = format!(
        "ply\nformat binary_little_endian 1.0\ncomment metaballs isosurface, box units, Y up\n\
         element vertex {}\nproperty float x\nproperty float y\nproperty float z\n\
         property float nx\nproperty float ny\nproperty float nz\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        mesh.positions.len(),
        mesh.triangles.len()
    );
    let mut out = Vec::with_capacity(header.len() + 24 * mesh.positions.len() + 13 * mesh.triangles.len());
    out.extend_from_slice(header.as_bytes());
    for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
        for x in (*p * scale).to_array().into_iter().chain(n.to_array()) {
            out.extend_from_slice(&x.to_le_bytes());
        }
    }
    for t in &mesh.triangles {
        out.push(3);
        for i in t {
            out.extend_from_slice(&i.to_le_bytes());
        }
    }
    out
}

/// The volume the mesh encloses (divergence theorem over its triangles; positive when they are
/// wound counter-clockwise seen from outside).
pub fn enclosed_volume(mesh: &IndexedMesh) -> f64 {
    mesh.enclosed_volume()
}

/// The mesh reduced to about `target_triangles` by edge collapses (meshoptimizer), keeping it closed:
/// vertices keep their positions and normals, unused ones are dropped. A target at or above the
/// mesh's count returns it unchanged.
#[cfg(not(target_arch = "wasm32"))]
pub fn simplified(mesh: &IndexedMesh, target_triangles: usize) -> IndexedMesh {
    if target_triangles >= mesh.triangles.len() {
        return mesh.clone();
    }
    // A vertex exactly on a grid point is made once per grid edge meeting there: join such vertices
    // and drop the triangles they flatten, or edge collapses would open the surface there.
    let mut mesh = mesh.to_soup().weld_by_position();
    mesh.triangles.retain(|t| t[0] != t[1] && t[1] != t[2] && t[2] != t[0]);
    let indices: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
    let positions: Vec<[f32; 3]> = mesh.positions.iter().map(|p| p.to_array()).collect();
    // An error bound of the whole mesh's size: the target count alone decides where to stop.
    let kept = meshopt::simplify_decoder(
        &indices,
        &positions,
        3 * target_triangles,
        1.0,
        meshopt::SimplifyOptions::None,
        None,
    );
    let mut remap = vec![u32::MAX; mesh.positions.len()];
    let mut out = IndexedMesh::default();
    for &i in &kept {
        if remap[i as usize] == u32::MAX {
            remap[i as usize] = out.positions.len() as u32;
            out.positions.push(mesh.positions[i as usize]);
            out.normals.push(mesh.normals[i as usize]);
        }
    }
    out.triangles = kept.chunks(3).map(|t| [0, 1, 2].map(|k| remap[t[k] as usize])).collect();
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetrahedron() -> IndexedMesh {
        let p = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
        IndexedMesh {
            positions: p.to_vec(),
            normals: p.map(|v| (v - Vec3::splat(0.25)).normalize()).to_vec(),
            triangles: vec![[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
        }
    }

    #[test]
    fn formats_have_their_sizes_and_headers() {
        let mesh = tetrahedron();
        assert!((enclosed_volume(&mesh) - 1.0 / 6.0).abs() < 1e-9);
        let stl = encode(&mesh, MeshFormat::Stl, 1.0);
        assert_eq!(stl.len(), 84 + 50 * 4);
        assert_eq!(u32::from_le_bytes(stl[80..84].try_into().unwrap()), 4);
        let obj = String::from_utf8(encode(&mesh, MeshFormat::Obj, 1.0)).unwrap();
        assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 4);
        assert!(obj.contains("f 1//1 3//3 2//2"));
        let ply = encode(&mesh, MeshFormat::Ply, 1.0);
        let header_end = ply.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
        assert_eq!(ply.len() - header_end, 4 * 24 + 4 * 13);
        assert_eq!(MeshFormat::from_file_name("blob.STL"), Some(MeshFormat::Stl));
        assert_eq!(MeshFormat::from_file_name("blob"), None);
        assert!(MeshFormat::parse("3mf").unwrap_err().to_string().contains("one of stl, obj, ply"));
    }
}
