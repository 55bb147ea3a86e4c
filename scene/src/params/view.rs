//! How the surface is shown and built, for teaching: display modes, grid overlays, a field slice,
//! triangle colouring, lights, projection, and the two construction toggles (interpolation, blend).

use super::choice::choice;
use super::{Expected, ParamError, Settings, check_f32};
use crate::decimal::num;

choice!(
    /// How the surface is drawn. The triangle count is the same in every mode but `exact`, which draws
    /// the surface without the mesh.
    Display {
        /// Smooth Blinn-Phong with the analytic vertex normals.
        Shaded = "shaded",
        /// One normal per face, so the facets show.
        Flat = "flat",
        /// The triangles' edges over a faint surface.
        Wireframe = "wireframe",
        /// The shared vertices alone.
        Points = "points",
        /// Short segments along each vertex normal over the shaded surface.
        Normals = "normals",
        /// No mesh: the exact surface f = iso, ray cast through the analytic field.
        Exact = "exact",
    }
);

choice!(
    /// The exact surface beside the mesh.
    Compare {
        None = "none",
        /// The mesh left of a divider, the exact surface right of it.
        Split = "split",
        /// The exact surface's outline over the mesh.
        Overlay = "overlay",
    }
);

choice!(
    /// What of the sampling grid is drawn over the surface.
    GridView {
        None = "none",
        /// The grid's lines, faint and fading with distance.
        Lattice = "lattice",
        /// The cells the surface crosses, coloured by their case's class.
        Cells = "cells",
        /// The 4³-cell blocks empty-space skipping kept.
        Blocks = "blocks",
    }
);

choice!(
    /// What colours the triangles.
    ColorBy {
        /// The material's colour.
        None = "none",
        /// Area relative to a cell face's area.
        Area = "area",
        /// Shape: the ratio of inscribed to circumscribed radius (1 equilateral, 0 a sliver).
        Quality = "quality",
        /// The emitting cell's case class among the 15.
        Case = "case",
        /// The level of detail of the emitting block (with `lod=on`), finest first.
        Level = "level",
        /// Each vertex's distance to the exact surface f = iso, in cells.
        Error = "error",
        /// Dual contouring: the rank of each vertex's QEF (1 a face, 2 an edge, 3 a corner), darker
        /// where its minimiser lay outside its cell.
        Rank = "rank",
    }
);

choice!(
    /// Where a vertex lands on a crossed edge.
    Interpolation {
        /// Where the field, interpolated linearly between the edge's ends, equals the iso level.
        Linear = "linear",
        /// At the edge's midpoint, whatever the values.
        Midpoint = "midpoint",
    }
);

choice!(
    /// How marching cubes joins a cell's ambiguous faces (those whose two inside corners sit on a
    /// diagonal, which the corners' signs alone cannot decide).
    CaseTable {
        /// The classic table's fixed choice, whatever the values.
        Classic = "classic",
        /// The asymptotic decider: the bilinear interpolant's saddle on each such face decides, so the
        /// surface meets every cell face as the interpolant does (the cell's interior is not resolved).
        Decider = "decider",
        /// MC33: the faces as the decider joins them, and a tunnel through the cell where the
        /// trilinear interpolant joins two loops inside it, so each cell has the interpolant's topology.
        Mc33 = "mc33",
    }
);

choice!(
    /// How the spheres' fields combine.
    Blend {
        /// The metaball sum: nearby spheres merge.
        Sum = "sum",
        /// The largest term: the union of separate spheres.
        Max = "max",
    }
);

choice!(
    /// The shape of each sphere's term in the field, as a function of the distance d from its centre;
    /// every kernel is 1 at d = r, so a lone sphere's surface at iso 1 is the sphere itself.
    Kernel {
        /// r² / d²: infinite support, infinite at the centre.
        InverseSquare = "inverse_square",
        /// Blinn's blobby Gaussian, exp(B (1 − d² / r²)) with blobbiness B: infinite support.
        Blinn = "blinn",
        /// Wyvill's soft objects, 2 C(d / 2r): a polynomial in d² that is 0 from d = 2r on.
        Wyvill = "wyvill",
    }
);

choice!(
    /// Perspective or orthographic camera; the orthographic view keeps the perspective one's framing.
    Projection {
        Perspective = "perspective",
        Orthographic = "orthographic",
    }
);

choice!(
    /// Where the mesh is made: the GPU's compute passes or the CPU mesher (faster on software
    /// adapters, and the only one without compute shaders).
    MeshOn {
        /// The CPU on software adapters and without compute shaders, else the GPU.
        Auto = "auto",
        Gpu = "gpu",
        Cpu = "cpu",
    }
);

choice!(
    /// How the mesh is made from the sampled field.
    Method {
        /// One to five triangles per crossed cell from the 256-case table, vertices on the grid's edges.
        MarchingCubes = "marching_cubes",
        /// One vertex per crossed cell at its crossings' mean, quads across crossed edges (on the CPU;
        /// the uniform grid only).
        SurfaceNets = "surface_nets",
        /// Surface nets' quads, each cell's vertex at the minimiser of its crossings' quadratic error
        /// function (their tangent planes), so sharp edges and corners stay sharp (on the CPU; the
        /// uniform grid only).
        DualContouring = "dual_contouring",
        /// Each cell cut into tetrahedra (`split`), each tetrahedron cut by one triangle or two, with
        /// no ambiguous case (the uniform grid only).
        MarchingTetrahedra = "marching_tetrahedra",
    }
);

choice!(
    /// How marching tetrahedra cuts a cell: the surface depends on the cut, as a cell's diagonals
    /// carry vertices of their own.
    Split {
        /// Six tetrahedra around the diagonal from the cell's lowest corner to its highest, the same
        /// in every cell (Kuhn's triangulation): diagonals on every face and through the cell.
        Six = "six",
        /// Five: the tetrahedron of four corners no two of which share an edge, and the four corners
        /// cut off around it, mirrored cell to cell so that neighbours cut their shared face alike.
        Five = "five",
    }
);

impl Method {
    /// Marching cubes: the one method with cases and cell lists, which the teaching views of cells
    /// read and the case table changes.
    pub fn has_cases(self) -> bool {
        self == Method::MarchingCubes
    }

    /// The primal methods, whose whole meshes are closed 2-manifolds (a dual method's vertex can join
    /// sheets): from outside the box their back faces never show.
    pub fn closes_its_mesh(self) -> bool {
        matches!(self, Method::MarchingCubes | Method::MarchingTetrahedra)
    }
}

choice!(
    /// How marching squares joins a saddle square of the field slice: one whose two inside corners sit
    /// on a diagonal (cases 5 and 10), which the corners alone cannot decide.
    Saddle {
        /// The table's fixed choice: each inside corner cut off on its own.
        Table = "table",
        /// The mean of the four corners decides: above the iso level, the inside corners join.
        Center = "center",
        /// The asymptotic decider: the bilinear interpolant's value at its saddle point decides, so the
        /// contour has the interpolant's topology.
        Decider = "decider",
    }
);

/// Light kinds a scene can have at once (up to one of each).
pub const LIGHT_KINDS: &[&str] = &["point", "directional", "spot"];

/// A plane through the box, perpendicular to an axis, showing the field on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slice {
    /// 0, 1, 2 for x, y, z.
    pub axis: u32,
    /// Where it cuts the axis, in [-1, 1] (the box's extent); it snaps to the nearest grid plane.
    pub position: f32,
}

impl Slice {
    /// Reads `off` or `x|y|z:position`.
    pub fn parse(text: &str) -> Result<Option<Slice>, ParamError> {
        let text = text.trim().to_ascii_lowercase();
        if text.is_empty() || text == "off" || text == "none" {
            return Ok(None);
        }
        let invalid =
            || ParamError::Invalid { name: "slice", value: text.clone(), expected: Expected::Slice };
        let (axis, position) = text.split_once(':').unwrap_or((&text, "0"));
        let axis = ["x", "y", "z"].iter().position(|a| *a == axis.trim()).ok_or_else(invalid)? as u32;
        let position = crate::number::parse_f32(position.trim()).ok_or_else(invalid)?;
        check_f32("slice position", position, -1.0, 1.0)?;
        Ok(Some(Slice { axis, position }))
    }

    /// The text `parse` reads.
    pub fn text(slice: Option<Slice>) -> String {
        match slice {
            None => "off".into(),
            // An axis past z (a slice made in code) reads back as one the parser refuses.
            Some(s) => {
                format!("{}:{}", ["x", "y", "z"].get(s.axis as usize).unwrap_or(&"?"), num(s.position))
            }
        }
    }

    /// The grid plane (0 ..= cells) the slice snaps to.
    pub fn plane(&self, cells_per_axis: u32) -> u32 {
        (((self.position + 1.0) * 0.5 * cells_per_axis as f32).round() as u32).min(cells_per_axis)
    }
}

/// Where the step-through of the march stands: a cell (x, y, z) of the grid. Marching cubes visits the
/// cells x fastest, then y, then z; with the march at a cell, only the cells visited up to it (itself
/// included) give triangles, on the uniform grid's marching cubes (the GPU's passes, the CPU's mesher
/// and the oracle); level of detail and surface nets draw their whole mesh. A cell past the grid
/// stands for the grid's last cell on that axis ([`March::on_grid`]).
pub struct March;

impl March {
    /// The most cells per axis a cell may name.
    const MAX_COORDINATE: u32 = super::MAX_RESOLUTION;

    /// Reads `off`, or a cell `x,y,z` (whole numbers).
    pub fn parse(text: &str) -> Result<Option<[u32; 3]>, ParamError> {
        let text = text.trim().to_ascii_lowercase();
        if text.is_empty() || text == "off" || text == "none" {
            return Ok(None);
        }
        let parts: Vec<Option<u32>> = text.split(',').map(|t| t.trim().parse::<u32>().ok()).collect();
        match parts[..] {
            [Some(x), Some(y), Some(z)] if x.max(y).max(z) < Self::MAX_COORDINATE => Ok(Some([x, y, z])),
            _ => Err(ParamError::Invalid { name: "march", value: text.clone(), expected: Expected::Cell }),
        }
    }

    /// The text `parse` reads.
    pub fn text(march: Option<[u32; 3]>) -> String {
        match march {
            None => "off".into(),
            Some([x, y, z]) => format!("{x},{y},{z}"),
        }
    }

    /// The march on a grid of `cells_per_axis`: each coordinate past the grid at its last cell.
    pub fn on_grid(march: Option<[u32; 3]>, cells_per_axis: u32) -> Option<[u32; 3]> {
        march.map(|cell| cell.map(|v| v.min(cells_per_axis.saturating_sub(1))))
    }

    /// True when the march at `march` has reached `cell` (always when it is off).
    pub fn reached(march: Option<[u32; 3]>, [x, y, z]: [u32; 3]) -> bool {
        march.is_none_or(|[mx, my, mz]| (z, y, x) <= (mz, my, mx))
    }
}

/// The lights in the scene, up to one of each kind.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Lights {
    pub point: bool,
    pub directional: bool,
    pub spot: bool,
}

impl Lights {
    /// From a normalised list value (`all`, `none` or kinds).
    pub fn from_list(list: &str) -> Self {
        let has = |kind| list == "all" || list.split(',').any(|k| k == kind);
        Self { point: has("point"), directional: has("directional"), spot: has("spot") }
    }

    /// The shading shader's light slots that are on: bit 0 the point light, 1 the directional, 2 the spot.
    pub fn slots(&self) -> u32 {
        self.point as u32 | (self.directional as u32) << 1 | (self.spot as u32) << 2
    }

    /// The list text (`none` when no light is on).
    pub fn text(&self) -> String {
        let on: Vec<&str> = [(self.point, "point"), (self.directional, "directional"), (self.spot, "spot")]
            .iter()
            .filter(|(on, _)| *on)
            .map(|(_, k)| *k)
            .collect();
        if on.is_empty() { "none".into() } else { on.join(",") }
    }
}

choice!(
    /// The figure's colours around the surface: the background the shading pass draws (and, on a page,
    /// the panel's colours).
    Theme {
        Dark = "dark",
        Light = "light",
        /// Follows the reader's colour scheme on a page; dark elsewhere.
        Auto = "auto",
    }
);

impl Theme {
    /// The background's gradient in linear RGB: top, then bottom.
    pub fn background(self) -> [[f32; 3]; 2] {
        match self {
            Theme::Dark | Theme::Auto => [[0.060, 0.075, 0.110], [0.010, 0.012, 0.018]],
            Theme::Light => [[0.930, 0.945, 0.965], [0.700, 0.740, 0.800]],
        }
    }
}

/// Everything about how the surface is shown and built beyond the basic settings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ViewOptions {
    pub display: Display,
    pub compare: Compare,
    /// With `compare=split`, where the exact half starts, as a fraction of the width.
    pub divider: f32,
    pub grid: GridView,
    pub color_by: ColorBy,
    pub slice: Option<Slice>,
    /// The step-through of the march: only the cells up to this one give triangles ([`March`]).
    pub march: Option<[u32; 3]>,
    /// Marks the cell faces whose two inside corners sit on a diagonal (the ambiguous faces).
    pub ambiguous: bool,
    pub interpolation: Interpolation,
    /// How marching cubes joins ambiguous faces.
    pub case_table: CaseTable,
    pub blend: Blend,
    /// The shape of each sphere's term.
    pub kernel: Kernel,
    /// With `Kernel::Blinn`, how fast a term falls off (Blinn's B; larger is less blobby).
    pub blobbiness: f32,
    /// How the field slice's contour joins its saddle squares.
    pub saddle: Saddle,
    pub lights: Lights,
    /// The spot light's cone half-angle, degrees.
    pub spot_angle: f32,
    /// The spot light's soft edge, as a fraction of the cone (0 hard, 1 all soft).
    pub spot_softness: f32,
    pub projection: Projection,
    pub mesh_on: MeshOn,
    /// How the mesh is made (with `lod`, always marching cubes and its transition cells).
    pub method: Method,
    /// Level of detail: fine cells near the camera, coarse far away (`resolution` is the finest).
    pub lod: bool,
    /// How marching tetrahedra cuts a cell.
    pub split: Split,
    /// With `lod`, the largest a cell may look on screen, in pixels.
    pub lod_pixels: f32,
    /// With `lod`, keep the current selection of levels whatever the camera does.
    pub lod_freeze: bool,
    pub theme: Theme,
    /// A background gradient given by the page (top, bottom; linear RGB) in place of the theme's.
    pub background: Option<[[f32; 3]; 2]>,
}

impl Default for ViewOptions {
    fn default() -> Self {
        Settings::default().view
    }
}

impl ViewOptions {
    /// Options before the table's defaults are put in (see `Settings::default`).
    pub(super) const fn unset() -> Self {
        Self {
            display: Display::Shaded,
            compare: Compare::None,
            divider: 0.0,
            grid: GridView::None,
            color_by: ColorBy::None,
            slice: None,
            march: None,
            ambiguous: false,
            interpolation: Interpolation::Linear,
            case_table: CaseTable::Classic,
            blend: Blend::Sum,
            kernel: Kernel::InverseSquare,
            blobbiness: 0.0,
            saddle: Saddle::Table,
            lights: Lights { point: false, directional: false, spot: false },
            spot_angle: 0.0,
            spot_softness: 0.0,
            projection: Projection::Perspective,
            mesh_on: MeshOn::Auto,
            method: Method::MarchingCubes,
            split: Split::Six,
            lod: false,
            lod_pixels: 0.0,
            lod_freeze: false,
            theme: Theme::Dark,
            background: None,
        }
    }

    /// Returns the options if every one is in range.
    pub fn validated(self) -> Result<Self, ParamError> {
        Settings { view: self, ..Settings::default() }.validated().map(|_| self)
    }

    /// The background's gradient (top, bottom; linear RGB): the page's, else the theme's.
    pub fn background(&self) -> [[f32; 3]; 2] {
        self.background.unwrap_or_else(|| self.theme.background())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Value;

    #[test]
    fn slices_read_an_axis_and_a_position_inside_the_box() {
        assert_eq!(Slice::parse("z:0.25"), Ok(Some(Slice { axis: 2, position: 0.25 })));
        assert_eq!(Slice::parse("off"), Ok(None));
        assert_eq!(Slice::parse("x"), Ok(Some(Slice { axis: 0, position: 0.0 })));
        let e = Slice::parse("y:1.5").unwrap_err().to_string();
        assert_eq!(e, "slice position must be between -1 and 1, got 1.5");
        assert!(Slice::parse("w:0").unwrap_err().to_string().contains("x, y or z"));
        assert!(Slice::parse("z:NaN").unwrap_err().to_string().contains("NaN"));
        assert_eq!(Slice { axis: 0, position: -1.0 }.plane(16), 0);
        assert_eq!(Slice { axis: 0, position: 0.0 }.plane(16), 8);
        assert_eq!(Slice { axis: 0, position: 1.0 }.plane(16), 16);
        assert_eq!(Slice::text(Slice::parse("y:-0.5").unwrap()), "y:-0.5");
    }

    #[test]
    fn lights_are_a_set_of_kinds() {
        assert_eq!(Lights::from_list("spot,point"), Lights { point: true, directional: false, spot: true });
        assert_eq!(Lights::from_list("all").text(), "point,directional,spot");
        assert_eq!(Lights::from_list("none").text(), "none");
    }

    #[test]
    fn options_are_set_by_name_and_refuse_bad_values() {
        let mut o = ViewOptions::default();
        assert_eq!(o.set("display", &Value::Text("wireframe".into())), Ok(true));
        assert_eq!(o.display, Display::Wireframe);
        assert!(o.set("display", &Value::Text("sketch".into())).is_err());
        assert_eq!(o.display, Display::Wireframe);
        assert!(o.set("spot_angle", &Value::Number(f64::NAN)).is_err());
        assert_eq!(o.set("iso", &Value::Number(1.0)), Ok(false));
    }
}
