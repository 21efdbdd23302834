//! `cargo xtask verify <name> [--report]`: the checks of runout-verification at full size
//! ([`runout_verification::registry`]), one by name or a group of them:
//!
//! - a check: `cavity`, `poiseuille`, `taylor-green`, `chute`, `incline`, `haff`, `cooling`,
//!   `settling`, `fluidized-bed`, `s-jj-phi` (`chute` also writes docs/reports/chute.md,
//!   [`crate::chute`]);
//! - a group: `single-phase` (cavity, poiseuille, taylor-green), `two-fluid` (haff,
//!   cooling, settling, fluidized-bed, s-jj-phi) or `all` (every check).
//!
//! The registry's studies (cavity-re1000, collapse, mfix-slope) are not run here: `main`
//! passes their options to [`runout_verification::find_study`]'s study.
//!
//! `--report` adds the error-against-run-time study over grid levels and both convection
//! schemes (for `cavity` and `poiseuille`, also when a group holds them): CSV, SVG and a
//! Markdown table per problem in docs/reports/verification/.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use runout_solver::Scheme;
use runout_verification::problems::{cavity, poiseuille_order, CavitySetup, ChannelGrid};
use runout_verification::{find, group, registry, studies, Outcome, Size};

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
            let studies: Vec<&str> = studies().iter().map(|s| s.name()).collect();
            bail!(
                "unknown verification `{name}` (checks: {}; groups: single-phase, two-fluid, \
                 all; studies: {})",
                known.join(", "),
                studies.join(", ")
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

/// Runs verification `name` (a check or a group) at full size and prints its numbers; with
/// `report`, also writes the error-against-run-time study into
/// `root/docs/reports/verification/`. Fails if a check misses its target.
pub fn verify(name: &str, report: bool, root: &Path) -> Result<()> {
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
