//! The further figures of `--plot FILE`: beside FILE (the interface pressure or midplane σ_z),
//! `two` writes FILE-gap (the gap g(r) between the plates, zero in contact and opening beyond
//! R_o) and both commands FILE-deformed (the joint's cross-section, displacements exaggerated,
//! over the dashed undeformed outline; a symmetric joint or the single plate's computed upper
//! half shown with its mirror image), same extension. Drawn by [`boltzone::plot`].
//!
//! # Accuracy
//!
//! `tests/io/figure_joint.rs` (the gap against the CSV of the same run, the deformed drawing's
//! R_o marker and exaggeration against the JSON and the VTU's displacements).
//!
//! # Cost
//!
//! Two drawings per run, beside the solve they draw (`cargo bench --bench contact`); timed by
//! nothing separately.

use boltzone::fem::Mesh;
use boltzone::plot::{
    svg_string, write_figure, CurveFigure, Marker, Outline, SectionFigure, PALETTE,
};
use std::path::Path;

pub use super::figure::sibling;

/// The exaggeration of the drawing: the round number 1, 2 or 5 × 10ᵏ at or below
/// `0.15 · thickness / max|u|` (the largest displacement drawn as 15 % of the joint's thickness).
pub fn exaggeration(thickness: f64, max_u: f64) -> f64 {
    if !(max_u > 0.0 && thickness > 0.0) {
        return 1.0;
    }
    let want = 0.15 * thickness / max_u;
    let p = 10f64.powf(want.log10().floor());
    [5.0, 2.0, 1.0]
        .into_iter()
        .map(|m| m * p)
        .find(|&v| v <= want)
        .unwrap_or(p)
}

/// One plate's outline cut at radial column `cut`: bottom face outwards, the cut, top face
/// inwards, the inner edge down; each node at its position + `k`·u, z × `sz` (±1: mirror).
fn outline(
    mesh: &Mesh,
    u: &[[f64; 2]],
    plate: usize,
    cut: usize,
    k: f64,
    sz: f64,
) -> Vec<(f64, f64)> {
    let at = |n: usize| {
        let (p, d) = (mesh.nodes()[n], u[n]);
        (p[0] + k * d[0], sz * (p[1] + k * d[1]))
    };
    let mut loop_: Vec<usize> = mesh.bottom(plate)[..=cut].to_vec();
    loop_.extend(mesh.column(plate, cut).into_iter().skip(1));
    loop_.extend(mesh.top(plate)[..cut].iter().rev());
    loop_.extend(mesh.inner(plate).into_iter().rev().skip(1));
    loop_.into_iter().map(at).collect()
}

/// What the deformed drawing shows: the mesh with its displacements, whether its mirror image
/// in z = 0 completes the joint, the plate names, B and R_o (± error), and how far out to draw.
pub struct Deformed<'a> {
    /// What is drawn ("joint", "single plate 2D thick").
    pub what: &'a str,
    /// Mesh (one or two plates) in the joint's units.
    pub mesh: &'a Mesh,
    /// Nodal displacements.
    pub u: &'a [[f64; 2]],
    /// Mirror the mesh in z = 0 (symmetric joint, single plate's upper half).
    pub mirror: bool,
    /// Legend text of each drawn plate (mesh plates bottom to top, then the mirror images).
    pub names: Vec<String>,
    /// Bearing radius B (in).
    pub b: f64,
    /// Computed R_o and its error (in).
    pub r_o: (f64, f64),
    /// Draw out to this radius (the curve figure's right end).
    pub x_end: f64,
    /// Symbol of the length unit (`in`, `mm`, `m`).
    pub length: &'a str,
}

/// Draws `d` to `path` ([`deformed_figure`]).
pub fn deformed_plot(path: &Path, d: &Deformed<'_>) -> anyhow::Result<()> {
    write_figure(&deformed_figure(d), path, super::figure::SIZE)?;
    eprintln!("wrote {}", path.display());
    Ok(())
}

/// The drawing of `d` (module docs).
pub fn deformed_figure(d: &Deformed<'_>) -> SectionFigure {
    // the radii of the node columns from the nodes (in the joint's units)
    let r: Vec<f64> = (0..d.mesh.radial_nodes().len())
        .map(|i| d.mesh.nodes()[d.mesh.node_at(0, i, 0)][0])
        .collect();
    let cut = r
        .iter()
        .rposition(|&x| x <= d.x_end * (1.0 + 1e-12))
        .unwrap_or(r.len() - 1)
        .max(1);
    let n_plates = d.mesh.n_plates();
    let z: Vec<f64> = d.mesh.nodes().iter().map(|p| p[1]).collect();
    let (z0, z1) = z
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let (z0, z1) = if d.mirror { (-z1, z1) } else { (z0, z1) };
    let max_u = d
        .mesh
        .nodes()
        .iter()
        .zip(d.u)
        .filter(|(p, _)| p[0] <= r[cut])
        .map(|(_, u)| u[0].hypot(u[1]))
        .fold(0.0, f64::max);
    let k = exaggeration(z1 - z0, max_u);
    let colors = [PALETTE[5], PALETTE[3], PALETTE[2], PALETTE[7]];
    let mut outlines = Vec::new();
    let signs: &[f64] = if d.mirror { &[1.0, -1.0] } else { &[1.0] };
    let mut name = d.names.iter();
    for (m, &sz) in signs.iter().enumerate() {
        for p in 0..n_plates {
            outlines.push(Outline {
                label: String::new(),
                points: outline(d.mesh, d.u, p, cut, 0.0, sz),
                color: (120, 120, 120),
                filled: false,
                dashed: true,
            });
            outlines.push(Outline {
                label: name.next().cloned().unwrap_or_default(),
                points: outline(d.mesh, d.u, p, cut, k, sz),
                color: colors[(m * n_plates + p) % colors.len()],
                filled: true,
                dashed: false,
            });
        }
    }
    if let Some(o) = outlines.first_mut() {
        o.label = "undeformed".into();
    }
    let l = d.length;
    let markers = vec![
        Marker {
            label: format!("B = {:.4} {l}", d.b),
            x: d.b,
            color: PALETTE[1],
        },
        Marker {
            label: format!("Rₒ = {:.4} ± {:.1e} {l} (computed)", d.r_o.0, d.r_o.1),
            x: d.r_o.0,
            color: PALETTE[6],
        },
    ];
    let h = z1 - z0;
    SectionFigure {
        title: format!(
            "Deformed {}, displacements × {k}, cut at r = {:.4} {l}",
            d.what, r[cut]
        ),
        x_label: format!("r [{l}]"),
        y_label: format!("z [{l}]"),
        outlines,
        markers,
        x_range: (0.0, r[cut] * 1.02),
        // room above for the legend
        y_range: (z0 - 0.15 * h, z1 + 0.75 * h),
    }
}

/// A figure of the user's joint: a curve against r or a cross-section.
pub enum JointFigure {
    /// Curve against r ([`super::figure::radius_figure`]).
    Curve(CurveFigure),
    /// Cross-section ([`deformed_figure`]).
    Section(SectionFigure),
}

impl JointFigure {
    /// Writes the figure to `path` (SVG or PNG).
    pub fn write(&self, path: &Path) -> anyhow::Result<()> {
        let size = super::figure::SIZE;
        match self {
            Self::Curve(f) => write_figure(f, path, size)?,
            Self::Section(f) => write_figure(f, path, size)?,
        }
        eprintln!("wrote {}", path.display());
        Ok(())
    }

    /// The figure as SVG text.
    pub fn svg(&self) -> anyhow::Result<String> {
        let size = super::figure::SIZE;
        Ok(match self {
            Self::Curve(f) => svg_string(f, size)?,
            Self::Section(f) => svg_string(f, size)?,
        })
    }
}

/// The interface of a two-plate answer, to draw against r ([`interface_figures`]): in the
/// answer's units.
pub struct Interface<'a> {
    /// Radii of the curve (increasing).
    pub r: &'a [f64],
    /// Interface pressure at the radii.
    pub p: &'a [f64],
    /// The gap at the radii, where the route gives it beyond R_o (None: the semi-analytic
    /// route, whose curve ends at R_o).
    pub gap: Option<&'a [f64]>,
    /// R_o and its error estimate.
    pub r_o: (f64, f64),
    /// The captions' tail (`model: frictionless`, with the method for a scene).
    pub model: String,
    /// What the curves are, after their legend's `p(r)` (`finest mesh`; empty: nothing).
    pub source: &'static str,
    /// The unit system of every number.
    pub units: boltzone::scene::UnitSystem,
}

/// The interface figures of `c` on the joint `geom` (B, D, D₂, C): p(r) (file suffix "") and,
/// where the gap is given, g(r) (suffix "gap"), each with its caption; and the right end of
/// their r axis. `two --plot`, its report and a scene's `[outputs] plot` and `report` draw
/// these.
pub fn interface_figures(
    c: &Interface<'_>,
    geom: (f64, f64, f64, Option<f64>),
) -> (Vec<(&'static str, &'static str, JointFigure)>, f64) {
    use super::figure::{radius_figure, RadiusCurve};
    let (l, st, _) = c.units.symbols();
    let label = |y: &str| match c.source {
        "" => format!("{y}(r)"),
        s => format!("{y}(r), {s}"),
    };
    let (p_label, g_label) = (format!("p [{st}]"), format!("g [{l}]"));
    let (p_legend, g_legend) = (label("p"), label("g"));
    let curve = |title: &str, y_label, label, y| RadiusCurve {
        title: format!("{title}; {}", c.model),
        y_label,
        label,
        r: c.r,
        y,
        r_o: c.r_o,
        length: l,
    };
    let (p, x_end) = radius_figure(&curve("Interface pressure", &p_label, &p_legend, c.p), geom);
    let mut figs = vec![("", "interface pressure against r", JointFigure::Curve(p))];
    if let Some(gap) = c.gap {
        let (g, _) = radius_figure(
            &curve("Gap between the plates", &g_label, &g_legend, gap),
            geom,
        );
        figs.push((
            "gap",
            "gap between the plates against r",
            JointFigure::Curve(g),
        ));
    }
    (figs, x_end)
}

/// The joint diagram of a bolted-joint answer `a` (in `units`) to FILE-joint beside `path`
/// (`two --plot` and a scene's `[outputs] plot` with a `[bolt]`), when the answer has the
/// preload and both compliances ([`boltzone::plot::joint_diagram`]).
pub fn write_joint_diagram(
    path: &Path,
    a: &boltzone::route::joint::JointAnswer,
    units: boltzone::scene::UnitSystem,
) -> anyhow::Result<()> {
    let (Some(preload), Some(bolt_compliance), Some(member)) =
        (a.preload, a.bolt_compliance, a.member_compliance.as_ref())
    else {
        return Ok(());
    };
    let (length, _, force) = units.symbols();
    let fig = boltzone::plot::joint_diagram::JointDiagram {
        preload,
        bolt_compliance,
        member_compliance: member.value,
        length,
        force,
    }
    .figure();
    boltzone::plot::write_figure(&fig, &sibling(path, "joint"), super::figure::SIZE)?;
    Ok(())
}
