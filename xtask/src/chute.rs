//! `cargo xtask verify chute`: issue 7's inclined-plane check at full size, the `chute`
//! check of runout-verification ([`Chute::run_full`], `runout_verification::problems::chute_column`),
//! written up. The 2-D two-fluid solver on a periodic column, marched to
//! a steady state, against the 1-D steady boundary-value solve (`chute1d`) of the same
//! equations on the same 80-cell y grid, at 15°, 25° (docs/studies/chute1d.md's reference case) and
//! 35°, and at 25° with side walls (docs/model.md §8). Passes when every run is steady and εs, u_s and θ agree within 2 % of their largest
//! value. Writes docs/reports/chute.md and docs/reports/chute/profiles-25deg.svg.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use plotters::prelude::*;
use runout_verification::checks::{relative_change, Chute, ChuteRun, CHUTE_TOLERANCE};
use runout_verification::problems::chute_column::ChuteCheck;
use runout_verification::Outcome;

use runout_study::plots::{plot_error, LINE_COLOURS};

/// Acceptance: largest difference relative to the largest value (issue 7).
const TOLERANCE: f64 = CHUTE_TOLERANCE;
/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (1200, 500);

/// Runs the full-size chute check and writes docs/reports/chute.md and its figure; returns the
/// check's outcome.
pub fn verify(root: &Path) -> Result<Outcome> {
    let mut md = String::new();
    writeln!(
        md,
        "# Steady chute flow: the 2-D solver against the 1-D reference (issue 7)\n\n\
         Written by `cargo xtask verify chute` (`xtask/src/chute.rs`, \
         `crates/verification/src/checks/chute.rs`; fast version: \
         `cargo test -p runout-verification --release --test chute_column`, 40 cells at 25°).\n\n\
         **Setup** (docs/studies/chute1d.md §3): a confined strip H = 8.7 mm high holding 5 mm of \
         solids (mean εs 0.575); the paper's material (d = 0.5 mm, ρs = 2000 kg m⁻³, e = 0.9, \
         Princeton friction φ = 35°, εs,max = 0.65, εs,min = 0.5); Johnson–Jackson floor \
         φ' = 0.1, e_w = 0.7, δ_w = 11°; free-slip lid with zero θ flux; 80 uniform cells.\n\n\
         - **2-D:** `TwoFluid` on one periodic column (a periodic x axis, `Axis::periodic`, MFIX's \
         `CYCLIC_X` on one cell), started from uniform εs, u = 0.3 m/s, θ = 1e-3 m²/s², \
         marched with implicit Euler (MFIX's outer iteration, tolerance 1e-3) until the \
         largest relative rate of change of εs, u_s and θ is below 1e-4 s⁻¹.\n\
         - **1-D:** `chute1d::solve`, Newton on the steady equations to 1e-10, dry.\n\
         - **The gas.** The two-fluid solver always carries a gas, so it is made negligible: \
         ρ_g = 1e-3 kg m⁻³, μ_g = 1e-8 Pa s. The table gives what it leaves: the largest drag \
         force on the solids relative to their weight along the slope, and the buoyancy \
         ρ_g/ρ_s = 5e-7.\n\n\
         Errors are max over cells of |2-D − 1-D| divided by the largest 1-D value; θ also \
         pointwise (|θ/θ_ref − 1|, θ spans three decades across the layer). The last row \
         adds side walls with the floor's condition (docs/model.md §8) to both solvers; its \
         \"u_s change\" is the largest change of the 1-D u_s from the plane 25° reference \
         relative to that reference's largest u_s, so the walls' effect is material.\n"
    )?;
    writeln!(
        md,
        "| slope | side walls | εs error | u_s error | θ error (of max) | θ error (pointwise) | floor slip 1-D [m/s] | u_s change | steps (rejected) | simulated [s] | final rate [s⁻¹] | mass change | drag/weight | wall [s] | verdict |\n\
         |---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
    )?;
    let (outcome, runs) = Chute.run_full()?;
    let mut at_25: Option<&ChuteCheck> = None;
    for ChuteRun {
        slope_deg: slope,
        sidewalls,
        check: c,
    } in &runs
    {
        let (slope, sidewalls) = (*slope, *sidewalls);
        let (walls, change) = match (sidewalls, at_25) {
            (Some(width), Some(plane)) => (
                format!("W = {width} m, floor's JJ"),
                format!("{:.2}", relative_change(c, &plane.reference.u_s)),
            ),
            _ => ("none".to_string(), "–".to_string()),
        };
        let ok = c.column.steady
            && c.eps_error < TOLERANCE
            && c.velocity_error < TOLERANCE
            && c.theta_error < TOLERANCE;
        writeln!(
            md,
            "| {slope}° | {walls} | {:.1e} | {:.1e} | {:.1e} | {:.1e} | {:.3} | {change} | {} ({}) | {:.2} | {:.1e} | {:.1e} | {:.1e} | {:.1} | {} |",
            c.eps_error,
            c.velocity_error,
            c.theta_error,
            c.theta_pointwise_error,
            c.reference.floor.slip,
            c.column.steps,
            c.column.rejected,
            c.column.time,
            c.column.final_rate,
            c.column.mass_change,
            c.column.drag_to_weight,
            c.column.wall_time,
            if ok { "PASS" } else { "FAIL" }
        )?;
        if slope == 25.0 && sidewalls.is_none() {
            at_25 = Some(c);
        }
    }
    writeln!(
        md,
        "\nWhy the agreement is this close: both codes discretise the same equations on the \
         same cells with the same closures and the same wall conventions (the fluid cell's \
         values in the floor closure, docs/model.md §3.1, §3.5–3.6), so at a steady state the \
         2-D column solves the 1-D discrete equations; what differs is the path (time \
         marching with the outer iteration, partial elimination, the εs correction and the \
         gas pressure correction against a Newton solve). The remaining differences are the \
         steady-state and step tolerances. The check therefore verifies the 2-D machinery \
         (momentum, εs correction, θ, the wall closures per face) in the fully developed \
         limit; the 1-D solver itself is verified against closed forms and grid \
         convergence in docs/studies/chute1d.md.\n"
    )?;
    let dir = root.join("docs/reports/chute");
    std::fs::create_dir_all(&dir).with_context(|| format!("creating {}", dir.display()))?;
    if let Some(c) = at_25 {
        draw(c, &dir.join("profiles-25deg.svg"))?;
        writeln!(
            md,
            "![profiles at 25°](chute/profiles-25deg.svg)\n\nProfiles at 25°: lines 1-D, \
             circles 2-D (every second cell)."
        )?;
    }
    let path = root.join("docs/reports/chute.md");
    std::fs::write(&path, md).with_context(|| format!("writing {}", path.display()))?;
    eprintln!("wrote {}", path.display());
    Ok(outcome)
}

/// Three panels: εs, u_s and θ (log) against height, 1-D lines and 2-D circles.
fn draw(c: &ChuteCheck, path: &Path) -> Result<()> {
    let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let panels = root.split_evenly((1, 3));
    let height_mm: Vec<f64> = c.reference.y.iter().map(|y| y * 1e3).collect();
    let y_top = c.reference.y.last().copied().unwrap_or(0.0) * 1e3 + 0.2;
    let (blue, red) = (LINE_COLOURS[0], LINE_COLOURS[1]);
    let series: [(&str, &[f64], &[f64], bool); 3] = [
        ("εs", &c.reference.eps_s, &c.column.eps_s, false),
        ("u_s [m/s]", &c.reference.u_s, &c.column.u_s, false),
        ("θ [m²/s²]", &c.reference.theta, &c.column.theta, true),
    ];
    for (panel, (label, reference, column, log)) in panels.iter().zip(series) {
        let lo = reference.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = reference.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        let mut builder = ChartBuilder::on(panel);
        builder
            .caption(format!("{label}, 25°"), ("sans-serif", 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(50);
        let line: Vec<(f64, f64)> = reference.iter().cloned().zip(height_mm.clone()).collect();
        let dots: Vec<(f64, f64)> = column
            .iter()
            .cloned()
            .zip(height_mm.clone())
            .step_by(2)
            .collect();
        if log {
            let mut chart = builder
                .build_cartesian_2d((lo / 2.0..hi * 2.0).log_scale(), 0.0..y_top)
                .map_err(plot_error)?;
            chart
                .configure_mesh()
                .x_desc(label)
                .y_desc("height [mm]")
                .draw()
                .map_err(plot_error)?;
            chart
                .draw_series(LineSeries::new(line, blue.stroke_width(2)))
                .map_err(plot_error)?;
            chart
                .draw_series(dots.into_iter().map(|p| Circle::new(p, 3, red)))
                .map_err(plot_error)?;
        } else {
            let pad = 0.05 * (hi - lo).max(1e-12);
            let mut chart = builder
                .build_cartesian_2d(lo - pad..hi + pad, 0.0..y_top)
                .map_err(plot_error)?;
            chart
                .configure_mesh()
                .x_desc(label)
                .y_desc("height [mm]")
                .draw()
                .map_err(plot_error)?;
            chart
                .draw_series(LineSeries::new(line, blue.stroke_width(2)))
                .map_err(plot_error)?;
            chart
                .draw_series(dots.into_iter().map(|p| Circle::new(p, 3, red)))
                .map_err(plot_error)?;
        }
    }
    root.present().map_err(plot_error)?;
    Ok(())
}
