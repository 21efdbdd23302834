//! `cargo xtask verify cavity-re1000`: the investigation of the lid-driven cavity's
//! Re = 1000 deviation (docs/studies/verification.md): every sample against both Ghia, Ghia
//! & Shin (1982) and Botella & Peyret (1998), the centreline extrema, a looser and a
//! tighter steady tolerance and the 65, 129 and 257 grids. A study without a limit and
//! without options: it prints its numbers (~25 min).

use anyhow::Result;
use runout_solver::{Scheme, SinglePhase};

use crate::checks::CAVITY_CELLS;
use crate::problems::{
    cavity_solve, centreline_extrema, compare_centrelines, CavitySetup, CentrelineComparison,
    BOTELLA_PEYRET_RE1000, BOTELLA_PEYRET_RE1000_EXTREMA, GHIA_RE1000,
};
use crate::study::{Args, Context, Study};

/// The Re = 1000 cavity investigation as a study of the registry.
pub struct CavityRe1000;

impl Study for CavityRe1000 {
    fn name(&self) -> &'static str {
        "cavity-re1000"
    }

    fn description(&self) -> &'static str {
        "lid-driven cavity at Re = 1000 against Ghia and Botella & Peyret, grids and tolerances"
    }

    fn run(&self, _args: &Args, _context: &Context) -> Result<()> {
        cavity_re1000()
    }
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
