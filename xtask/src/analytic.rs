//! `cargo xtask report analytic`: the paper's Fig. 1 (family A of shared/docs/cases.md).
//!
//! Reads `cases/analytic/A-fig1.ron`, evaluates the closed-form profiles of paper Eqs. 12–13
//! (`runout_walls::analytic::RobinProfile`: dφ/dn = c − h(φ − φ_w) from the bulk value at
//! n = 0 to the wall at n = depth; docs/reference/walls.md says why this is the problem the paper
//! solved) and writes into `docs/reports/analytic/`:
//! - `fig1.svg`: U(n) for every h_w^u, and θ(n) for every h_w^θ, one panel per c_w; lines are
//!   the closed forms, dots the discrete solution of the same boundary-value problem with the
//!   solver's wall-face closure on the paper's 5 mm cells;
//! - `fig1_velocity.csv` (h_u, n, distance_from_wall, u), `fig1_temperature.csv`
//!   (h_theta, c, theta_inf, n, distance_from_wall, theta): the closed forms;
//! - `fig1_discrete.csv` (quantity, h, c, n, discrete, exact): the dots, with their error.

use std::path::Path;

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use runout_case::{load, Analytic, Loaded};
use runout_walls::analytic::RobinProfile;

use runout_study::plots::{legend, plot_error, LINE_COLOURS};

/// Points per closed-form curve (CSV and SVG).
const SAMPLES: usize = 201;

/// Cell height of the paper's focus area, 0.005 m (paper §2.2.1, Fig. 2): the spacing of the
/// discrete check drawn as dots.
const PAPER_CELL_HEIGHT: f64 = 0.005;

/// SVG size [px]: two columns, two rows of panels.
const FIGURE_SIZE: (u32, u32) = (1200, 900);

/// The case file of family A, relative to the workspace root.
const CASE_FILE: &str = "cases/analytic/A-fig1.ron";

/// Output directory, relative to the workspace root.
const OUTPUT_DIR: &str = "docs/reports/analytic";

/// One curve of a panel.
struct Curve {
    label: String,
    profile: RobinProfile,
}

/// One panel of the figure.
struct Panel {
    title: String,
    y_label: &'static str,
    curves: Vec<Curve>,
}

/// Reads the family-A case file under `root` and writes Fig. 1 as SVG and CSV into
/// `root/docs/reports/analytic/`.
pub fn report(root: &Path) -> Result<()> {
    let file = root.join(CASE_FILE);
    let analytic = match load(&file)? {
        Loaded::Analytic(a) => a,
        Loaded::Cases(_) => bail!("{}: expected an Analytic(...) file", file.display()),
    };
    let out = root.join(OUTPUT_DIR);
    std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
    let panels = panels(&analytic);
    write_closed_forms(&analytic, &out)?;
    let worst = write_discrete(&analytic, &panels, &out)?;
    draw(&analytic, &panels, &out.join("fig1.svg"))?;
    println!(
        "family A `{}`: wrote {}/fig1.svg and fig1_{{velocity,temperature,discrete}}.csv \
         (depth {} m; discrete check on {} m cells, largest error {:.2e} of the profile's range)",
        analytic.name, OUTPUT_DIR, analytic.depth, PAPER_CELL_HEIGHT, worst
    );
    Ok(())
}

/// The velocity panel and one θ panel per c_w.
fn panels(a: &Analytic) -> Vec<Panel> {
    let v = &a.velocity;
    let t = &a.temperature;
    let mut panels = vec![Panel {
        title: format!("Eq. 12: U = {}, U_w = {} m/s", v.bulk, v.wall),
        y_label: "U [m/s]",
        curves: v
            .h_u
            .iter()
            .map(|&h| Curve {
                label: format!("h_u = {h} 1/m"),
                profile: RobinProfile::velocity(v.bulk, v.wall, h),
            })
            .collect(),
    }];
    for &c in &t.c {
        panels.push(Panel {
            title: format!(
                "Eq. 13: theta = {}, theta_w = {}, c_w = {c} m/s2",
                t.bulk, t.wall
            ),
            y_label: "theta [m2/s2]",
            curves: t
                .h_theta
                .iter()
                .map(|&h| Curve {
                    label: format!("h_theta = {h} 1/m"),
                    profile: RobinProfile::temperature(t.bulk, t.wall, h, c),
                })
                .collect(),
        });
    }
    panels
}

/// n_k = k · depth/(SAMPLES − 1), from the bulk (0) to the wall (depth).
fn samples(depth: f64) -> impl Iterator<Item = f64> {
    (0..SAMPLES).map(move |k| depth * k as f64 / (SAMPLES - 1) as f64)
}

fn write_closed_forms(a: &Analytic, out: &Path) -> Result<()> {
    let mut w = csv::Writer::from_path(out.join("fig1_velocity.csv"))?;
    w.write_record(["h_u", "n", "distance_from_wall", "u"])?;
    for &h in &a.velocity.h_u {
        let p = RobinProfile::velocity(a.velocity.bulk, a.velocity.wall, h);
        for n in samples(a.depth) {
            w.serialize((h, n, a.depth - n, p.value(n)))?;
        }
    }
    w.flush()?;
    let t = &a.temperature;
    let mut w = csv::Writer::from_path(out.join("fig1_temperature.csv"))?;
    w.write_record([
        "h_theta",
        "c",
        "theta_inf",
        "n",
        "distance_from_wall",
        "theta",
    ])?;
    for &c in &t.c {
        for &h in &t.h_theta {
            let p = RobinProfile::temperature(t.bulk, t.wall, h, c);
            // θ_∞ = θ_w + c/h; empty for h = 0 (linear growth)
            let inf = p.asymptote().map_or(String::new(), |v| v.to_string());
            for n in samples(a.depth) {
                w.write_record([
                    h.to_string(),
                    c.to_string(),
                    inf.clone(),
                    n.to_string(),
                    (a.depth - n).to_string(),
                    p.value(n).to_string(),
                ])?;
            }
        }
    }
    w.flush()?;
    Ok(())
}

/// Number of cells of the discrete check: the paper's cell height over the depth.
fn discrete_cells(depth: f64) -> usize {
    ((depth / PAPER_CELL_HEIGHT).round() as usize).max(1)
}

/// Writes the discrete check and returns its largest error relative to each profile's range.
fn write_discrete(a: &Analytic, panels: &[Panel], out: &Path) -> Result<f64> {
    let mut w = csv::Writer::from_path(out.join("fig1_discrete.csv"))?;
    w.write_record(["quantity", "h", "c", "n", "discrete", "exact"])?;
    let cells = discrete_cells(a.depth);
    let mut worst: f64 = 0.0;
    for (k, panel) in panels.iter().enumerate() {
        let (quantity, c) = if k == 0 {
            ("u", 0.0)
        } else {
            ("theta", a.temperature.c[k - 1])
        };
        for curve in &panel.curves {
            let p = &curve.profile;
            let d = p.discrete(a.depth, cells);
            let range = (p.value(0.0) - p.value(a.depth))
                .abs()
                .max(f64::MIN_POSITIVE);
            let points = d.n.iter().copied().zip(d.values.iter().copied());
            for (n, v) in points.chain([(a.depth, d.wall_value)]) {
                worst = worst.max((v - p.value(n)).abs() / range);
                w.serialize((quantity, p.face.h, c, n, v, p.value(n)))?;
            }
        }
    }
    w.flush()?;
    Ok(worst)
}

fn draw(a: &Analytic, panels: &[Panel], path: &Path) -> Result<()> {
    let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let rows = panels.len().div_ceil(2);
    let areas = root.split_evenly((rows, 2));
    let cells = discrete_cells(a.depth);
    for (panel, area) in panels.iter().zip(areas.iter()) {
        let values: Vec<f64> = panel
            .curves
            .iter()
            .flat_map(|c| samples(a.depth).map(move |n| c.profile.value(n)))
            .collect();
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        let pad = 0.05 * (hi - lo).max(f64::EPSILON);
        let mut chart = ChartBuilder::on(area)
            .caption(&panel.title, ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(55)
            .build_cartesian_2d(0.0..a.depth, (lo - pad)..(hi + pad))
            .map_err(plot_error)?;
        chart
            .configure_mesh()
            .x_desc(
                "n [m], fluid-to-wall (wall at the right); lines: closed form, dots: 5 mm cells",
            )
            .y_desc(panel.y_label)
            .draw()
            .map_err(plot_error)?;
        for (k, curve) in panel.curves.iter().enumerate() {
            let colour = LINE_COLOURS[k % LINE_COLOURS.len()];
            let p = curve.profile;
            chart
                .draw_series(LineSeries::new(
                    samples(a.depth).map(|n| (n, p.value(n))),
                    colour.stroke_width(2),
                ))
                .map_err(plot_error)?
                .label(curve.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
            let d = p.discrete(a.depth, cells);
            chart
                .draw_series(
                    d.n.iter()
                        .zip(&d.values)
                        .map(|(&n, &v)| Circle::new((n, v), 3, colour.filled())),
                )
                .map_err(plot_error)?;
        }
        legend(&mut chart, SeriesLabelPosition::MiddleRight).map_err(plot_error)?;
    }
    root.present().map_err(plot_error)?;
    Ok(())
}
