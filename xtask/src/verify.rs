//! `cargo xtask verify <name> [--report]`: the checks of runout-verification at full size
//! ([`runout_verification::registry`]), one by name or a group of them:
//!
//! - a check: `cavity`, `poiseuille`, `taylor-green`, `chute`, `incline`, `haff`, `cooling`,
//!   `settling`, `fluidized-bed`, `s-jj-phi` (`chute` also writes docs/reports/chute.md,
//!   [`crate::chute`]);
//! - a group: `single-phase` (cavity, poiseuille, taylor-green), `two-fluid` (haff,
//!   cooling, settling, fluidized-bed, s-jj-phi) or `all` (every check);
//! - `cavity-re1000`: the investigation of the Re = 1000 deviation (docs/studies/verification.md):
//!   every sample against both references, centreline extrema, a tighter steady tolerance
//!   and the 65 × 65 grid (a study without a limit, not a check).
//!
//! `--report` adds the error-against-run-time study over grid levels and both convection
//! schemes (for `cavity` and `poiseuille`, also when a group holds them): CSV, SVG and a
//! Markdown table per problem in docs/reports/verification/.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use runout_solver::{Scheme, SinglePhase};
use runout_verification::checks::CAVITY_CELLS;
use runout_verification::problems::{
    cavity, cavity_solve, centreline_extrema, compare_centrelines, poiseuille_order, CavitySetup,
    CentrelineComparison, ChannelGrid, BOTELLA_PEYRET_RE1000, BOTELLA_PEYRET_RE1000_EXTREMA,
    GHIA_RE1000,
};
use runout_verification::{find, group, registry, Outcome, Size};

use runout_study::plots::{legend, plot_error, LINE_COLOURS};

/// Output directory of `--report`, relative to the workspace root.
const OUTPUT_DIR: &str = "docs/reports/verification";
/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (1000, 700);

/// The checks `name` stands for: a group or one registered check.
fn selection(name: &str) -> Result<Vec<&'static str>> {
    if let Some(names) = group(name) {
        return Ok(names);
    }
    match find(name) {
        Some(check) => Ok(vec![check.name()]),
        None => {
            let known: Vec<&str> = registry().iter().map(|c| c.name()).collect();
            bail!(
                "unknown verification `{name}` (checks: {}; groups: single-phase, two-fluid, \
                 all; studies: cavity-re1000, collapse, mfix-slope)",
                known.join(", ")
            )
        }
    }
}

/// Runs the full-size check `name`; `chute` through [`crate::chute::verify`], which also
/// writes its page.
fn run_check(name: &str, root: &Path) -> Result<Outcome> {
    if name == "chute" {
        return crate::chute::verify(root);
    }
    let check = find(name).with_context(|| format!("no check `{name}`"))?;
    println!("== {name}: {}", check.description());
    check.run(Size::Full)
}

/// Runs verification `name` (a check, a group or `cavity-re1000`) at full size and prints
/// its numbers; with `report`, also writes the error-against-run-time study into
/// `root/docs/reports/verification/`. Fails if a check misses its target.
pub fn verify(name: &str, report: bool, root: &Path) -> Result<()> {
    if name == "cavity-re1000" {
        return cavity_re1000();
    }
    let names = selection(name)?;
    let mut failures = Vec::new();
    for n in &names {
        let outcome = run_check(n, root)?;
        print!("{outcome}");
        failures.extend(outcome.failures().map(|m| format!("{n}: {m}")));
        if outcome.measures.is_empty() {
            failures.push(format!("{n}: nothing measured"));
        }
    }
    if report {
        let out = root.join(OUTPUT_DIR);
        std::fs::create_dir_all(&out).with_context(|| format!("creating {}", out.display()))?;
        if names.contains(&"cavity") {
            cavity_error_time(&out)?;
        }
        if names.contains(&"poiseuille") {
            poiseuille_error_time(&out)?;
        }
    }
    if !failures.is_empty() {
        bail!(
            "{} check(s) failed:\n  {}",
            failures.len(),
            failures.join("\n  ")
        );
    }
    Ok(())
}

/// 4-point Lagrange interpolation at `x` in increasing abscissae.
fn cubic(xs: &[f64], ys: &[f64], x: f64) -> f64 {
    let k = xs.partition_point(|&a| a <= x).clamp(2, xs.len() - 2);
    let idx = [k - 2, k - 1, k, k + 1];
    idx.iter()
        .map(|&i| {
            idx.iter()
                .filter(|&&m| m != i)
                .map(|&m| (x - xs[m]) / (xs[i] - xs[m]))
                .product::<f64>()
                * ys[i]
        })
        .sum()
}

/// The cavity centrelines sampled with cubic instead of linear interpolation across the
/// centreline (nodes plus the no-slip wall values; the other direction is the midpoint mean
/// of the two staggered columns at x = 0.5 or rows at y = 0.5, as in `u_at`). Only for
/// judging the interpolation part of the deviation; needs an even split at 0.5 (odd n).
fn cubic_centrelines(s: &SinglePhase) -> (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) {
    let g = s.grid();
    let (nx, ny) = (g.nx(), g.ny());
    let (i, j) = (nx / 2, ny / 2); // u columns i, i+1 straddle x = 0.5; v rows j, j+1 y = 0.5
    let mut ys = vec![0.0];
    let mut us = vec![0.0];
    for (jj, &y) in g.y.centres().iter().enumerate() {
        ys.push(y);
        us.push(0.5 * (s.u[i + (nx + 1) * jj] + s.u[i + 1 + (nx + 1) * jj]));
    }
    ys.push(1.0);
    us.push(1.0); // the lid
    let mut xs = vec![0.0];
    let mut vs = vec![0.0];
    for (ii, &x) in g.x.centres().iter().enumerate() {
        xs.push(x);
        vs.push(0.5 * (s.v[ii + nx * j] + s.v[ii + nx * (j + 1)]));
    }
    xs.push(1.0);
    vs.push(0.0);
    (ys, us, xs, vs)
}

fn print_comparison(
    title: &str,
    s: &SinglePhase,
    ghia: &CentrelineComparison,
    botella: &CentrelineComparison,
) {
    println!("  {title}");
    println!(
        "    {:>2} {:>7} {:>9} {:>9} {:>10} {:>9} {:>9} {:>9} {:>9}",
        "", "at", "ours", "Ghia", "Botella", "-Ghia", "-Botella", "Ghia-Bot", "cub-Bot"
    );
    let (ys, us, xs, vs) = cubic_centrelines(s);
    let mut cubic_max: f64 = 0.0;
    for (name, g, b) in [("u", &ghia.u, &botella.u), ("v", &ghia.v, &botella.v)] {
        for (sg, sb) in g.iter().zip(b.iter()) {
            let c = if name == "u" {
                cubic(&ys, &us, sg.position)
            } else {
                cubic(&xs, &vs, sg.position)
            };
            cubic_max = cubic_max.max((c - sb.reference).abs());
            println!(
                "    {name:>2} {:>7.4} {:>9.5} {:>9.5} {:>10.7} {:>+9.5} {:>+9.5} {:>+9.5} {:>+9.5}",
                sg.position,
                sg.computed,
                sg.reference,
                sb.reference,
                sg.computed - sg.reference,
                sb.computed - sb.reference,
                sg.reference - sb.reference,
                c - sb.reference
            );
        }
    }
    println!("    (cub-Bot: cubic instead of linear interpolation across the centreline; max {cubic_max:.5})");
    let ghia_vs_botella = ghia
        .u
        .iter()
        .zip(&botella.u)
        .chain(ghia.v.iter().zip(&botella.v))
        .map(|(g, b)| (g.reference - b.reference).abs())
        .fold(0.0, f64::max);
    println!(
        "    max |ours - Ghia| {:.5}, max |ours - Botella| {:.5}, max |Ghia - Botella| {:.5}",
        ghia.max_error(),
        botella.max_error(),
        ghia_vs_botella
    );
}

/// The Re = 1000 investigation of docs/studies/verification.md.
fn cavity_re1000() -> Result<()> {
    println!("lid-driven cavity, Re = 1000, Superbee: ours against Ghia (1982) and Botella & Peyret (1998)");
    let b = BOTELLA_PEYRET_RE1000_EXTREMA;
    let mut rows = Vec::new();
    // (cells, momentum tolerance, mass tolerance per cell): the acceptance setup, a looser
    // and a tighter one (iteration error), and the next coarser grid (discretisation error)
    // (cells, momentum tolerance, mass tolerance per cell, iteration cap); the 1e-9 run
    // is capped: it shows whether the fields still move after the 1e-7 stop
    for (cells, tolerance, mass_tolerance, max_iterations) in [
        (CAVITY_CELLS, 1e-7, 1e-14, 40_000),
        (CAVITY_CELLS, 1e-6, 1e-12, 40_000),
        (CAVITY_CELLS, 1e-9, 1e-15, 15_000),
        (65, 1e-7, 1e-14, 40_000),
        (257, 1e-7, 1e-14, 80_000),
    ] {
        let setup = CavitySetup {
            tolerance,
            mass_tolerance,
            max_iterations,
            ..CavitySetup::new(cells, 1000.0, Scheme::Superbee)
        };
        let run = cavity_solve(&setup)?;
        let g = compare_centrelines(&run.solver, &GHIA_RE1000);
        let bp = compare_centrelines(&run.solver, &BOTELLA_PEYRET_RE1000);
        print_comparison(
            &format!(
                "{cells} x {cells}, tolerances {tolerance:e} (momentum), {mass_tolerance:e} \
                 (mass per cell): {} outer iterations (converged {}; last residuals u+v {:.1e}, \
                 mass {:.1e}), {:.1} s",
                run.report.iterations,
                run.report.converged,
                run.report.residuals.u + run.report.residuals.v,
                run.report.residuals.mass,
                run.wall_time
            ),
            &run.solver,
            &g,
            &bp,
        );
        let e = centreline_extrema(&run.solver);
        println!(
            "    extrema: u_min {:.5} at y {:.4} (Botella {:.7} at {:.4}); v_max {:.5} at x {:.4} \
             (Botella {:.7} at {:.4}); v_min {:.5} at x {:.4} (Botella {:.7} at {:.4})",
            e.u_min,
            e.y_u_min,
            b.u_min,
            b.y_u_min,
            e.v_max,
            e.x_v_max,
            b.v_max,
            b.x_v_max,
            e.v_min,
            e.x_v_min,
            b.v_min,
            b.x_v_min
        );
        rows.push(run.solver);
    }
    // tolerance effect and grid effect, point by point
    let (fine, loose, tight, coarse, finer) = (&rows[0], &rows[1], &rows[2], &rows[3], &rows[4]);
    let diff = |a: &SinglePhase, b: &SinglePhase| {
        let ca = compare_centrelines(a, &GHIA_RE1000);
        let cb = compare_centrelines(b, &GHIA_RE1000);
        ca.u.iter()
            .zip(&cb.u)
            .chain(ca.v.iter().zip(&cb.v))
            .map(|(x, y)| (x.computed - y.computed).abs())
            .fold(0.0, f64::max)
    };
    println!(
        "  largest change of a sample at 129: tolerance 1e-6 -> 1e-7: {:.2e}, 1e-7 -> 1e-9: {:.2e}; \
         grid 65 -> 129: {:.5}, 129 -> 257: {:.5}",
        diff(loose, fine),
        diff(fine, tight),
        diff(fine, coarse),
        diff(fine, finer)
    );
    let against = |s: &SinglePhase, r| compare_centrelines(s, r).max_error();
    let e: Vec<f64> = [coarse, fine, finer]
        .iter()
        .map(|s| against(s, &BOTELLA_PEYRET_RE1000))
        .collect();
    println!(
        "  max |ours - Botella| on 65, 129, 257: {:.5}, {:.5}, {:.5} (observed orders {:.2}, {:.2}); \
         max |ours - Ghia|: {:.5}, {:.5}, {:.5}",
        e[0],
        e[1],
        e[2],
        (e[0] / e[1]).log2(),
        (e[1] / e[2]).log2(),
        against(coarse, &GHIA_RE1000),
        against(fine, &GHIA_RE1000),
        against(finer, &GHIA_RE1000)
    );
    Ok(())
}

// ---------------------------------------------------------------------------------------
// Error against run time
// ---------------------------------------------------------------------------------------

/// One point of the error-against-run-time study.
struct Point {
    series: String,
    cells: usize,
    error: f64,
    wall_time: f64,
    outer_iterations: usize,
}

fn scheme_name(s: Scheme) -> &'static str {
    match s {
        Scheme::Upwind => "Upwind",
        Scheme::Superbee => "Superbee",
    }
}

/// The cavity part of `--report`: max centreline error against Ghia over grid levels,
/// Re = 100 and 1000, both schemes.
fn cavity_error_time(out: &Path) -> Result<()> {
    println!("error against run time: lid-driven cavity (max |u, v - Ghia| on the centrelines)");
    let mut points = Vec::new();
    for re in [100.0, 1000.0] {
        for scheme in [Scheme::Upwind, Scheme::Superbee] {
            for cells in [16, 32, 64, 128] {
                let r = cavity(&CavitySetup::new(cells, re, scheme))?;
                if !r.converged {
                    bail!("cavity {cells} Re {re} {scheme:?} did not converge");
                }
                println!(
                    "  Re {re:>4} {:<8} {cells:>3}: error {:.4}  {:>6} its  {:>7.2} s",
                    scheme_name(scheme),
                    r.max_error,
                    r.outer_iterations,
                    r.wall_time
                );
                points.push(Point {
                    series: format!("Re {re} {}", scheme_name(scheme)),
                    cells,
                    error: r.max_error,
                    wall_time: r.wall_time,
                    outer_iterations: r.outer_iterations,
                });
            }
        }
    }
    write_csv(&out.join("cavity_error_time.csv"), &points)?;
    draw(
        &out.join("cavity_error_time.svg"),
        "Lid-driven cavity: max centreline error vs Ghia (1982) against wall time",
        "max |u, v - Ghia| / lid speed",
        &points,
    )?;
    let mut md = String::new();
    table(
        &mut md,
        "Lid-driven cavity (max centreline deviation from Ghia, lid speed 1)",
        &points,
    );
    std::fs::write(out.join("cavity_error_time.md"), md)?;
    println!("wrote {OUTPUT_DIR}/cavity_error_time.{{csv,svg,md}}");
    Ok(())
}

/// The Poiseuille part of `--report`: max error against the closed form over grid levels,
/// uniform and stretched, both schemes.
fn poiseuille_error_time(out: &Path) -> Result<()> {
    println!("error against run time: partial-slip Poiseuille (max |u - exact|)");
    let mut points = Vec::new();
    for (grid, name, levels) in [
        (ChannelGrid::Uniform, "uniform", vec![8, 16, 32, 64, 128]),
        (
            ChannelGrid::Stretched { growth: 1.2 },
            "stretched",
            vec![4, 8, 16, 32, 64],
        ),
    ] {
        for scheme in [Scheme::Upwind, Scheme::Superbee] {
            let study = poiseuille_order(grid, &levels, scheme)?;
            for (level, error) in study.levels.iter().zip(&study.errors) {
                println!(
                    "  {name:<9} {:<8} {:>3} cells: error {error:.3e}  {:>4} its  {:>7.3} s",
                    scheme_name(scheme),
                    level.cells,
                    level.outer_iterations,
                    level.wall_time
                );
                points.push(Point {
                    series: format!("{name} {}", scheme_name(scheme)),
                    cells: level.cells,
                    error: *error,
                    wall_time: level.wall_time,
                    outer_iterations: level.outer_iterations,
                });
            }
        }
    }
    write_csv(&out.join("poiseuille_error_time.csv"), &points)?;
    draw(
        &out.join("poiseuille_error_time.svg"),
        "Partial-slip Poiseuille: max error vs closed form against wall time",
        "max |u - u_exact| [m/s]",
        &points,
    )?;
    let mut md = String::new();
    table(
        &mut md,
        "Partial-slip Poiseuille (max |u − u_exact|, cells across the channel, 4 along)",
        &points,
    );
    std::fs::write(out.join("poiseuille_error_time.md"), md)?;
    println!("wrote {OUTPUT_DIR}/poiseuille_error_time.{{csv,svg,md}}");
    Ok(())
}

fn write_csv(path: &Path, points: &[Point]) -> Result<()> {
    let mut w = csv::Writer::from_path(path)?;
    w.write_record([
        "series",
        "cells",
        "error",
        "wall_time_s",
        "outer_iterations",
    ])?;
    for p in points {
        w.write_record([
            p.series.clone(),
            p.cells.to_string(),
            format!("{:e}", p.error),
            format!("{:.4}", p.wall_time),
            p.outer_iterations.to_string(),
        ])?;
    }
    w.flush()?;
    Ok(())
}

fn table(md: &mut String, title: &str, points: &[Point]) {
    let _ = writeln!(md, "**{title}**\n");
    let _ = writeln!(
        md,
        "| series | cells | error | wall time [s] | outer iterations |"
    );
    let _ = writeln!(md, "|---|---:|---:|---:|---:|");
    for p in points {
        let _ = writeln!(
            md,
            "| {} | {} | {:.3e} | {:.3} | {} |",
            p.series, p.cells, p.error, p.wall_time, p.outer_iterations
        );
    }
    let _ = writeln!(md);
}

/// Log-log plot of error against wall time, one line per series, points labelled by cells.
fn draw(path: &Path, title: &str, y_label: &str, points: &[Point]) -> Result<()> {
    let mut series: Vec<&str> = Vec::new();
    for p in points {
        if !series.contains(&p.series.as_str()) {
            series.push(&p.series);
        }
    }
    let (t_lo, t_hi) = bounds(points.iter().map(|p| p.wall_time.max(1e-4)));
    let (e_lo, e_hi) = bounds(points.iter().map(|p| p.error.max(1e-16)));
    let area = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    area.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&area)
        .caption(title, ("sans-serif", 18))
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(
            (t_lo / 2.0..t_hi * 2.0).log_scale(),
            (e_lo / 2.0..e_hi * 2.0).log_scale(),
        )
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("wall time [s] (labels: cells)")
        .y_desc(y_label)
        .draw()
        .map_err(plot_error)?;
    for (k, name) in series.iter().enumerate() {
        let colour = LINE_COLOURS[k % LINE_COLOURS.len()];
        let pts: Vec<(f64, f64, usize)> = points
            .iter()
            .filter(|p| p.series == *name)
            .map(|p| (p.wall_time.max(1e-4), p.error.max(1e-16), p.cells))
            .collect();
        chart
            .draw_series(LineSeries::new(
                pts.iter().map(|&(t, e, _)| (t, e)),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(name.to_string())
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(
                pts.iter()
                    .map(|&(t, e, _)| Circle::new((t, e), 4, colour.filled())),
            )
            .map_err(plot_error)?;
        chart
            .draw_series(pts.iter().map(|&(t, e, n)| {
                Text::new(
                    format!("{n}"),
                    (t, e),
                    ("sans-serif", 12).into_font().color(&colour),
                )
            }))
            .map_err(plot_error)?;
    }
    legend(&mut chart, SeriesLabelPosition::UpperRight).map_err(plot_error)?;
    area.present().map_err(plot_error)?;
    Ok(())
}

fn bounds(values: impl Iterator<Item = f64>) -> (f64, f64) {
    values.fold((f64::INFINITY, 0.0_f64), |(lo, hi), v| {
        (lo.min(v), hi.max(v))
    })
}
