//! `cargo xtask verify collapse [--fidelity smoke|coarse]`: issue 7's granular column
//! collapse check (family C, cases/collapse/, verification-notes.md §2f).
//!
//! Runs the four columns a = H0/L0 = 0.5, 1, 3, 6 one after the other into
//! `runs/<case>/<fidelity>/`, reads the front of the bulk monitor (the largest x whose floor
//! cell has εs ≥ 0.01) and the last field file, and reports the runout (L∞ − L0)/L0 beside
//! the laboratory laws of Lajeunesse et al. (2005) and Lube et al. (2005), untuned: nothing
//! is fitted and no agreement is required. The check fails only if a run does not complete
//! or loses solids mass. At `coarse` the table goes to docs/collapse.md and the log–log
//! figure to docs/collapse/runout.svg; at `smoke` both go to runs/collapse-report/smoke/
//! (the committed report is the coarse one). With `--reuse`, a finished run whose
//! `resolved.ron` equals the case as it would run now is read instead of rerun (its
//! recorded wall time is reported), e.g. to regenerate the report after changing it.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};
use plotters::prelude::*;
use runout_case::{load, Case, Fidelity, Gravity, Loaded};
use runout_output::{RunStatus, RunSummary};
use runout_solver::run_case;

use crate::sweep::finished_run;

/// The folder of the collapse cases under cases/ (left out of `cargo xtask sweep`).
pub const COLLAPSE_DIR: &str = "collapse";

/// The four columns, smallest aspect ratio first.
const CASE_FILES: [&str; 4] = [
    "cases/collapse/C-a0.5.ron",
    "cases/collapse/C-a1.ron",
    "cases/collapse/C-a3.ron",
    "cases/collapse/C-a6.ron",
];
/// εs threshold of the dense-deposit front read from the last field file [-] (the bulk
/// monitor's front uses the case's threshold, 0.01).
const DENSE_FRONT_EPS_S: f64 = 0.3;
/// "Stopped": front speed and εs-weighted mean u_s below this fraction of √(g H0).
const STOP_FRACTION: f64 = 0.01;
/// The front speed is measured over this last fraction of the run.
const STOP_WINDOW: f64 = 0.1;
/// The lab fronts stop after about this many √(H0/g) (Lajeunesse et al. 2005); the runout
/// is also reported at this time.
const LAB_STOP_TIMES: f64 = 3.0;
/// Largest relative change of the solids mass accepted over a run.
const MASS_TOLERANCE: f64 = 1e-8;
/// SVG size [px].
const FIGURE_SIZE: (u32, u32) = (900, 650);

/// A planar runout law (L∞ − L0)/L0 = λ1 a below the crossover, λ2 a^{2/3} above it
/// (verification-notes.md §2f, compiled from Lagrée, Staron & Popinet 2011 Eqs. 3.1–3.2;
/// not re-checked against the originals).
#[derive(Clone, Copy, Debug)]
pub struct ScalingLaw {
    /// short citation
    pub name: &'static str,
    /// what was collapsed
    pub material: &'static str,
    /// slope of the linear branch
    pub lambda1: f64,
    /// prefactor of the a^{2/3} branch
    pub lambda2: f64,
    /// the crossover aspect ratio, as a range (a0_low, a0_high)
    pub a0: (f64, f64),
}

/// Lajeunesse, Monnier & Homsy (2005), Phys. Fluids 17:103302 (glass beads).
pub const LAJEUNESSE: ScalingLaw = ScalingLaw {
    name: "Lajeunesse et al. 2005",
    material: "glass beads",
    lambda1: 1.8,
    lambda2: 2.3,
    a0: (3.0, 3.0),
};

/// Lube, Huppert, Sparks & Freundt (2005), Phys. Rev. E (sand, rice, sugar).
pub const LUBE: ScalingLaw = ScalingLaw {
    name: "Lube et al. 2005",
    material: "sand, rice, sugar",
    lambda1: 1.2,
    lambda2: 1.9,
    a0: (1.8, 2.8),
};

impl ScalingLaw {
    /// The linear branch λ1 a.
    pub fn linear(&self, a: f64) -> f64 {
        self.lambda1 * a
    }

    /// The power branch λ2 a^{2/3}.
    pub fn power(&self, a: f64) -> f64 {
        self.lambda2 * a.powf(2.0 / 3.0)
    }

    /// (low, high) runout at `a`: one value outside the crossover range, the two branches
    /// inside it (a0_low ≤ a ≤ a0_high).
    pub fn runout(&self, a: f64) -> (f64, f64) {
        if a < self.a0.0 {
            (self.linear(a), self.linear(a))
        } else if a > self.a0.1 {
            (self.power(a), self.power(a))
        } else {
            let (l, p) = (self.linear(a), self.power(a));
            (l.min(p), l.max(p))
        }
    }

    /// The runout as a table entry: one value, or "low–high" in the crossover range.
    fn label(&self, a: f64) -> String {
        let (lo, hi) = self.runout(a);
        if hi - lo < 1e-9 {
            format!("{lo:.2}")
        } else {
            format!("{lo:.2}–{hi:.2}")
        }
    }
}

/// The initial column of a collapse case: the first block, standing on the floor against
/// the west wall.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Column {
    /// half-width L0 [m] (the block's x extent, from the west wall)
    pub l0: f64,
    /// height H0 [m]
    pub h0: f64,
    /// x of the west wall [m]
    pub x_wall: f64,
    /// |g| [m s⁻²]
    pub gravity: f64,
}

impl Column {
    /// The column of `case`, or why the case is not a column collapse.
    pub fn of(case: &Case) -> Result<Self> {
        let block = case
            .initial
            .regions
            .first()
            .with_context(|| format!("case `{}` has no initial block", case.name))?;
        let grid = case.grid()?;
        let x_wall = grid.x.start();
        if (block.x.0 - x_wall).abs() > 1e-12 || (block.y.0 - grid.y.start()).abs() > 1e-12 {
            bail!(
                "case `{}`: the column must stand on the floor against the west wall",
                case.name
            );
        }
        let gravity = match case.gravity {
            Gravity::Constant {
                magnitude,
                slope: 0.0,
            } => magnitude,
            _ => bail!(
                "case `{}`: a collapse needs constant gravity straight down",
                case.name
            ),
        };
        Ok(Column {
            l0: block.x.1 - block.x.0,
            h0: block.y.1 - block.y.0,
            x_wall,
            gravity,
        })
    }

    /// The aspect ratio a = H0/L0, rounded to 1e-9 (0.15/0.05 is 2.9999999999999996 in
    /// floating point, which would put a = 3 on the wrong side of a crossover).
    pub fn aspect(&self) -> f64 {
        (self.h0 / self.l0 * 1e9).round() / 1e9
    }

    /// The free-fall time √(H0/g) [s].
    pub fn time_scale(&self) -> f64 {
        (self.h0 / self.gravity).sqrt()
    }

    /// The velocity scale √(g H0) [m s⁻¹].
    pub fn velocity_scale(&self) -> f64 {
        (self.gravity * self.h0).sqrt()
    }

    /// (L∞ − L0)/L0 of a front at `x`.
    pub fn runout(&self, x: f64) -> f64 {
        (x - self.x_wall - self.l0) / self.l0
    }
}

/// One row of `bulk.csv`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BulkRow {
    /// time [s]
    pub t: f64,
    /// solids mass per unit depth [kg m⁻¹]
    pub mass: f64,
    /// front x [m]
    pub front: f64,
    /// εs-weighted mean u_s [m s⁻¹]
    pub mean_u: f64,
}

/// Reads `bulk.csv` (header t,solids_mass,front_x,mean_u_s).
pub fn read_bulk(path: &Path) -> Result<Vec<BulkRow>> {
    let text =
        std::fs::read_to_string(path).with_context(|| format!("reading {}", path.display()))?;
    let mut rows = Vec::new();
    for (n, line) in text.lines().enumerate().skip(1) {
        let v: Vec<f64> = line
            .split(',')
            .map(|s| s.trim().parse::<f64>())
            .collect::<Result<_, _>>()
            .with_context(|| format!("{}:{}: not numbers", path.display(), n + 1))?;
        if v.len() != 4 {
            bail!("{}:{}: expected 4 columns", path.display(), n + 1);
        }
        rows.push(BulkRow {
            t: v[0],
            mass: v[1],
            front: v[2],
            mean_u: v[3],
        });
    }
    if rows.is_empty() {
        bail!("{}: no samples", path.display());
    }
    Ok(rows)
}

/// What the front history of one run says.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FrontMetrics {
    /// (L∞ − L0)/L0 at the last sample
    pub runout: f64,
    /// (L − L0)/L0 at t = 3 √(H0/g), if the run got there
    pub runout_at_lab_stop: Option<f64>,
    /// the front reached the east wall: the runout is a lower bound
    pub reached_end_wall: bool,
    /// front speed over the last 10 % of the run over √(g H0) [-]
    pub front_speed: f64,
    /// εs-weighted mean u_s at the last sample over √(g H0) [-]
    pub mean_u: f64,
    /// both below 1 %
    pub stopped: bool,
}

/// The front metrics of a bulk history `rows` of a column whose domain ends at `x_end`.
pub fn front_metrics(rows: &[BulkRow], column: &Column, x_end: f64) -> FrontMetrics {
    let last = rows[rows.len() - 1];
    let u_ref = column.velocity_scale();
    let lab_stop = LAB_STOP_TIMES * column.time_scale();
    let runout_at_lab_stop = rows
        .iter()
        .find(|r| r.t >= lab_stop * (1.0 - 1e-9))
        .map(|r| column.runout(r.front));
    let window_start = last.t * (1.0 - STOP_WINDOW);
    let first = rows
        .iter()
        .find(|r| r.t >= window_start)
        .copied()
        .unwrap_or(last);
    let front_speed = if last.t > first.t {
        (last.front - first.front) / (last.t - first.t) / u_ref
    } else {
        f64::INFINITY
    };
    let mean_u = last.mean_u / u_ref;
    FrontMetrics {
        runout: column.runout(last.front),
        runout_at_lab_stop,
        reached_end_wall: last.front >= x_end * (1.0 - 1e-12),
        front_speed,
        mean_u,
        stopped: front_speed.abs() < STOP_FRACTION && mean_u.abs() < STOP_FRACTION,
    }
}

/// The values of DataArray `name` in a `.vtr` written by runout-output.
fn vtr_array(xml: &str, name: &str) -> Result<Vec<f64>> {
    runout_output::read_vtr_array(xml, name).with_context(|| format!("no readable array `{name}`"))
}

/// The last field file of a run: εs and θ per cell.
fn last_fields(run_dir: &Path) -> Result<(Vec<f64>, Vec<f64>)> {
    let pvd_path = run_dir.join("fields.pvd");
    let pvd = std::fs::read_to_string(&pvd_path)
        .with_context(|| format!("reading {}", pvd_path.display()))?;
    let last = pvd
        .rsplit("file=\"")
        .next()
        .and_then(|s| s.split('"').next())
        .context("fields.pvd lists no file")?;
    let path = run_dir.join(last);
    let xml =
        std::fs::read_to_string(&path).with_context(|| format!("reading {}", path.display()))?;
    Ok((vtr_array(&xml, "eps_s")?, vtr_array(&xml, "theta")?))
}

/// The largest x whose floor cell has εs ≥ `threshold` (the wall if none), like the bulk
/// monitor's front.
fn floor_front(eps: &[f64], faces: &[f64], threshold: f64) -> f64 {
    let nx = faces.len() - 1;
    (0..nx)
        .rev()
        .find(|&i| eps[i] >= threshold)
        .map_or(faces[0], |i| faces[i + 1])
}

/// The median of `v` (NaN if empty).
fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return f64::NAN;
    }
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One collapse run and what it says.
struct Outcome {
    name: String,
    column: Column,
    /// a of the column as the grid holds it: initial solids mass / (ρs εs0 L0²)
    a_gridded: f64,
    cells: (usize, usize),
    front: FrontMetrics,
    /// runout of the dense deposit (floor εs ≥ 0.3) in the last field file
    dense_runout: f64,
    /// median θ of the cells with εs ≥ εs,min at the end [m² s⁻²]
    deposit_theta: f64,
    /// largest θ of the dilute fringe (10⁻⁴ ≤ εs < 10⁻²) at the end [m² s⁻²]
    fringe_theta: f64,
    /// particle diameter [m]
    diameter: f64,
    end_time: f64,
    summary: RunSummary,
}

impl Outcome {
    fn completed(&self) -> bool {
        self.summary.status == RunStatus::Completed
    }
}

/// Runs `case` at `fidelity` into runs/<case>/<fidelity>/ (written as `.partial`, renamed
/// when done), or with `reuse` takes the finished run of the same resolved case, and
/// measures it.
fn run_one(root: &Path, case: &Case, fidelity: Fidelity, reuse: bool) -> Result<Outcome> {
    let column = Column::of(case)?;
    let resolved = case.at_fidelity(fidelity);
    let grid = resolved.grid()?;
    let runs = root.join("runs").join(&case.name);
    let done = runs.join(fidelity.name());
    let partial = runs.join(format!("{}.partial", fidelity.name()));
    let previous = if reuse {
        finished_run(&done, &resolved)
    } else {
        None
    };
    let summary = if let Some(summary) = previous {
        println!(
            "{}: reusing the finished run in {}",
            case.name,
            done.display()
        );
        summary
    } else {
        let _ = std::fs::remove_dir_all(&partial);
        println!(
            "{}: a = {}, {} × {} cells, to t = {} s ...",
            case.name,
            column.aspect(),
            grid.nx(),
            grid.ny(),
            resolved.run.end_time
        );
        let summary = run_case(case, fidelity, &partial, |p| {
            if p.steps % 250 == 0 {
                eprintln!(
                    "  t = {:.3} s, dt = {:.1e} s, {} it",
                    p.time, p.dt, p.iterations
                );
            }
        })
        .with_context(|| format!("running {}", case.name))?;
        let _ = std::fs::remove_dir_all(&done);
        std::fs::rename(&partial, &done)
            .with_context(|| format!("renaming {} to {}", partial.display(), done.display()))?;
        summary
    };
    let rows = read_bulk(&done.join("bulk.csv"))?;
    let front = front_metrics(&rows, &column, grid.x.end());
    let (eps, theta) = last_fields(&done)?;
    let solids = case
        .solids
        .first()
        .context("a collapse case has one solids phase")?;
    let eps0 = case.initial.regions[0].solids[0].eps_s;
    let a_gridded = rows[0].mass / (solids.density * eps0 * column.l0 * column.l0);
    let deposit_theta = median(
        eps.iter()
            .zip(&theta)
            .filter(|(&e, _)| e >= solids.friction_min_packing)
            .map(|(_, &t)| t)
            .collect(),
    );
    let fringe_theta = eps
        .iter()
        .zip(&theta)
        .filter(|(&e, _)| (1e-4..1e-2).contains(&e))
        .map(|(_, &t)| t)
        .fold(0.0, f64::max);
    Ok(Outcome {
        name: case.name.clone(),
        column,
        a_gridded,
        cells: (grid.nx(), grid.ny()),
        front,
        dense_runout: column.runout(floor_front(&eps, grid.x.faces(), DENSE_FRONT_EPS_S)),
        deposit_theta,
        fringe_theta,
        diameter: solids.diameter,
        end_time: resolved.run.end_time,
        summary,
    })
}

/// Runs the collapse check at `fidelity` (smoke or coarse) and writes its report; `reuse`
/// takes finished runs of unchanged cases instead of rerunning them.
pub fn verify(root: &Path, fidelity: Fidelity, reuse: bool) -> Result<()> {
    if fidelity == Fidelity::Paper {
        bail!("`verify collapse` runs at smoke or coarse fidelity");
    }
    let mut outcomes = Vec::new();
    for path in case_paths(root) {
        let Loaded::Cases(cases) = load(&path)? else {
            bail!("{} is not a case file", path.display());
        };
        for c in cases {
            outcomes.push(run_one(root, &c.case, fidelity, reuse)?);
        }
    }
    let table = markdown_table(&outcomes);
    println!("\n{table}");
    let out_dir = match fidelity {
        Fidelity::Coarse => root.join("docs"),
        _ => root.join("runs/collapse-report").join(fidelity.name()),
    };
    let figure_dir = match fidelity {
        Fidelity::Coarse => out_dir.join("collapse"),
        _ => out_dir.clone(),
    };
    std::fs::create_dir_all(&figure_dir)
        .with_context(|| format!("creating {}", figure_dir.display()))?;
    let figure = figure_dir.join("runout.svg");
    draw(&outcomes, &figure)?;
    let report = out_dir.join("collapse.md");
    let figure_link = figure
        .strip_prefix(&out_dir)
        .unwrap_or(&figure)
        .display()
        .to_string();
    std::fs::write(&report, document(&outcomes, fidelity, &table, &figure_link))
        .with_context(|| format!("writing {}", report.display()))?;
    println!("wrote {} and {}", report.display(), figure.display());
    let mut failures = Vec::new();
    for o in &outcomes {
        if !o.completed() {
            failures.push(format!("{}: {:?}", o.name, o.summary.status));
        }
        if o.summary.solids_mass_change.abs() > MASS_TOLERANCE {
            failures.push(format!(
                "{}: solids mass changed by {:.2e} (limit {MASS_TOLERANCE:e})",
                o.name, o.summary.solids_mass_change
            ));
        }
    }
    if !failures.is_empty() {
        bail!(
            "{} collapse run(s) failed:\n  {}",
            failures.len(),
            failures.join("\n  ")
        );
    }
    Ok(())
}

fn yes_no(b: bool) -> &'static str {
    if b {
        "yes"
    } else {
        "no"
    }
}

/// The results table (Markdown).
fn markdown_table(outcomes: &[Outcome]) -> String {
    let mut s = String::new();
    s.push_str(
        "| a | a as gridded | cells | (L∞ − L0)/L0, εs ≥ 0.01 | εs ≥ 0.3 | at t = 3√(H0/g) | \
         Lajeunesse | Lube | front speed / √(gH0) | mean u_s / √(gH0) | stopped? | \
         end wall reached? | solids mass change | steps (rejected) | wall time [s] |\n",
    );
    s.push_str("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for o in outcomes {
        let a = o.column.aspect();
        let f = &o.front;
        let lower = if f.reached_end_wall { "> " } else { "" };
        let _ = writeln!(
            s,
            "| {a} | {:.2} | {} × {} | {lower}{:.2} | {:.2} | {} | {} | {} | {:.3} | {:.3} | {} | {} | \
             {:.1e} | {} ({}) | {:.1} |",
            o.a_gridded,
            o.cells.0,
            o.cells.1,
            f.runout,
            o.dense_runout,
            f.runout_at_lab_stop
                .map_or("(run shorter)".to_string(), |r| format!("{r:.2}")),
            LAJEUNESSE.label(a),
            LUBE.label(a),
            f.front_speed,
            f.mean_u,
            yes_no(f.stopped),
            yes_no(f.reached_end_wall),
            o.summary.solids_mass_change,
            o.summary.steps,
            o.summary.rejected_steps,
            o.summary.wall_time,
        );
    }
    s
}

/// docs/collapse.md.
fn document(outcomes: &[Outcome], fidelity: Fidelity, table: &str, figure: &str) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "# Granular column collapse on a horizontal floor (issue 7)\n"
    );
    let _ = writeln!(
        s,
        "Generated by `cargo xtask verify collapse --fidelity {fidelity}` (xtask/src/collapse.rs) \
         from the runs in `runs/C-a*/{fidelity}/`; do not edit by hand. Cases: \
         `cases/collapse/C-a{{0.5,1,3,6}}.ron` (their headers list every assumption).\n"
    );
    s.push_str(
        "**Set-up.** A rectangular column of half-width L0 = 0.05 m and height H0 = a L0 \
         (εs = 0.6) stands against a free-slip west wall on a horizontal floor and collapses \
         in air under gravity. The material and the floor are the paper's (d = 0.5 mm, \
         ρs = 2000 kg/m³, e = 0.9, δ_int = 35°, Princeton friction, Lun 1984 + θ PDE; floor: \
         Johnson–Jackson φ = 0.1, e_w = 0.7, δ_w = 11°), not the laboratory ones. Nothing is \
         tuned.\n\n",
    );
    let _ = writeln!(s, "![runout against a]({figure})\n");
    s.push_str(table);
    s.push_str(
        "\n**Columns.** *a as gridded*: the initial solids mass over ρs εs L0², i.e. the \
         aspect ratio the grid holds (cells whose centre lies in the block are filled). \
         *(L∞ − L0)/L0, εs ≥ 0.01*: L∞ is the last front of `bulk.csv` (the largest x whose \
         floor cell has εs ≥ 0.01), measured from the west wall; `>` marks a front that \
         reached the east wall (a lower bound). *εs ≥ 0.3*: the same from the last field \
         file with threshold 0.3 (the dense deposit, not its dilute fringe). *at t = \
         3√(H0/g)*: the front when the laboratory fronts have stopped. *Lajeunesse*, \
         *Lube*: λ1 a below the crossover a0, λ2 a^{2/3} above it; a range where a lies in \
         the crossover range (both branches). *front speed*: over the last 10 % of the run. \
         *stopped?*: front speed and εs-weighted mean u_s both below 1 % of √(g H0); the \
         front moves by whole cells, so its speed resolves only (cell width)/(window). \
         *wall time*: of this run on the machine that generated the file.\n\n",
    );
    s.push_str("**Laboratory laws** (verification-notes.md §2f, compiled from Lagrée, Staron & Popinet 2011 Eqs. 3.1–3.2; not re-checked against the originals):\n\n");
    s.push_str("| source | material | λ1 | λ2 | a0 |\n|---|---|---|---|---|\n");
    for law in [LAJEUNESSE, LUBE] {
        let a0 = if law.a0.0 == law.a0.1 {
            format!("≈ {}", law.a0.0)
        } else {
            format!("{}–{}", law.a0.0, law.a0.1)
        };
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} | {a0} |",
            law.name, law.material, law.lambda1, law.lambda2
        );
    }
    s.push_str(
        "\nThe laws come from dry-grain experiments; this set-up has air, the paper's \
         Johnson–Jackson floor (δ_w = 11°, below δ_int = 35°) and 0.5 mm grains, so the match \
         need not be close, but the deposit should stop within a few √(H0/g). The laws are \
         evaluated at the nominal a.",
    );
    for o in outcomes {
        let a = o.column.aspect();
        if (o.a_gridded / a - 1.0).abs() > 0.01 {
            let _ = write!(
                s,
                " {} holds a = {:.2} on its grid ({:+.1} % runout by the a^(2/3) branch, \
                 {:+.1} % by the linear one).",
                o.name,
                o.a_gridded,
                100.0 * ((o.a_gridded / a).powf(2.0 / 3.0) - 1.0),
                100.0 * (o.a_gridded / a - 1.0)
            );
        }
    }
    s.push_str("\n\n");
    s.push_str("**What the runs show** (numbers from the table and the last field files):\n\n");
    for o in outcomes {
        let f = &o.front;
        let (laj_lo, laj_hi) = LAJEUNESSE.runout(o.column.aspect());
        let ratio = f.runout / (0.5 * (laj_lo + laj_hi));
        let _ = writeln!(
            s,
            "- {} (a = {}, to t = {} s = {:.1} √(H0/g)): runout {}{:.2}, {:.1} times \
             Lajeunesse's; {}. At the end the median θ of the cells with εs ≥ εs,min is \
             {:.2e} m²/s², so √θ/d = {:.1} s⁻¹ against the collapse's strain-rate scale \
             √(g/H0) = {:.1} s⁻¹; the dilute fringe (10⁻⁴ ≤ εs < 10⁻²) reaches θ = {:.2e} m²/s².",
            o.name,
            o.column.aspect(),
            o.end_time,
            o.end_time / o.column.time_scale(),
            if f.reached_end_wall { "> " } else { "" },
            f.runout,
            ratio,
            if f.stopped {
                "the deposit stopped".to_string()
            } else {
                format!(
                    "still moving at the end (mean u_s = {:.1} % of √(g H0))",
                    100.0 * f.mean_u
                )
            },
            o.deposit_theta,
            o.deposit_theta.sqrt() / o.diameter,
            1.0 / o.column.time_scale(),
            o.fringe_theta,
        );
    }
    s.push_str(
        "\nHow to read the θ numbers: MFIX's Princeton model (SAVAGE = 2, paper Eq. 9) uses the \
         strain scale ζ = √(θ/d² + S:S) and μ_fric ∝ P_f sinφ/ζ. Where √θ/d exceeds the strain \
         rate, the frictional shear stress is ≈ P_f sinφ S d/√θ, a viscosity, not the Coulomb \
         stress P_f sinφ that would bring a deposit to rest; a layer whose θ is kept up (by \
         conduction from a hot fringe or by slip heating at the floor) keeps creeping.\n",
    );
    s
}

fn plot_error<E: std::fmt::Debug>(e: E) -> anyhow::Error {
    anyhow::anyhow!("plotting: {e:?}")
}

/// Log–log runout against a: the runs (filled: εs ≥ 0.01 front, triangles where it reached
/// the end wall; hollow: εs ≥ 0.3) and both laws, each branch over its side of a0.
fn draw(outcomes: &[Outcome], path: &Path) -> Result<()> {
    let (a_lo, a_hi) = (0.3, 10.0);
    let y_hi = outcomes
        .iter()
        .map(|o| o.front.runout.max(o.dense_runout))
        .fold(LAJEUNESSE.power(a_hi), f64::max)
        * 1.5;
    let y_lo = outcomes
        .iter()
        .map(|o| o.dense_runout.min(o.front.runout))
        .filter(|&r| r > 0.0)
        .fold(LUBE.linear(a_lo), f64::min)
        / 1.5;
    let root = SVGBackend::new(path, FIGURE_SIZE).into_drawing_area();
    root.fill(&WHITE).map_err(plot_error)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Column collapse: runout against aspect ratio (untuned)",
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((a_lo..a_hi).log_scale(), (y_lo..y_hi).log_scale())
        .map_err(plot_error)?;
    chart
        .configure_mesh()
        .x_desc("a = H0/L0")
        .y_desc("(L∞ − L0)/L0")
        .draw()
        .map_err(plot_error)?;
    let samples =
        |from: f64, to: f64| (0..=100).map(move |k| from * (to / from).powf(k as f64 / 100.0));
    for (law, colour) in [
        (LAJEUNESSE, RGBColor(31, 119, 180)),
        (LUBE, RGBColor(44, 160, 44)),
    ] {
        chart
            .draw_series(LineSeries::new(
                samples(a_lo, law.a0.1).map(|a| (a, law.linear(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?
            .label(format!(
                "{}: {} a, {} a^(2/3)",
                law.name, law.lambda1, law.lambda2
            ))
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], colour));
        chart
            .draw_series(LineSeries::new(
                samples(law.a0.0, a_hi).map(|a| (a, law.power(a))),
                colour.stroke_width(2),
            ))
            .map_err(plot_error)?;
    }
    let red = RGBColor(214, 39, 40);
    let points: Vec<(f64, f64, bool)> = outcomes
        .iter()
        .filter(|o| o.front.runout > 0.0)
        .map(|o| (o.column.aspect(), o.front.runout, o.front.reached_end_wall))
        .collect();
    chart
        .draw_series(
            points
                .iter()
                .filter(|p| !p.2)
                .map(|&(a, r, _)| Circle::new((a, r), 5, red.filled())),
        )
        .map_err(plot_error)?
        .label("runout, front εs ≥ 0.01")
        .legend(move |(x, y)| Circle::new((x + 10, y), 5, red.filled()));
    chart
        .draw_series(
            points
                .iter()
                .filter(|p| p.2)
                .map(|&(a, r, _)| TriangleMarker::new((a, r), 7, red.filled())),
        )
        .map_err(plot_error)?
        .label("front reached the end wall (lower bound)")
        .legend(move |(x, y)| TriangleMarker::new((x + 10, y), 7, red.filled()));
    chart
        .draw_series(
            outcomes
                .iter()
                .filter(|o| o.dense_runout > 0.0)
                .map(|o| Circle::new((o.column.aspect(), o.dense_runout), 5, red.stroke_width(2))),
        )
        .map_err(plot_error)?
        .label("runout, dense front εs ≥ 0.3")
        .legend(move |(x, y)| Circle::new((x + 10, y), 5, red.stroke_width(2)));
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()
        .map_err(plot_error)?;
    root.present().map_err(plot_error)?;
    Ok(())
}

/// The case files of the check.
pub fn case_paths(root: &Path) -> Vec<PathBuf> {
    CASE_FILES.iter().map(|f| root.join(f)).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn column() -> Column {
        Column {
            l0: 0.05,
            h0: 0.05,
            x_wall: 0.0,
            gravity: 9.81,
        }
    }

    #[test]
    fn laws_match_the_notes_at_a_2() {
        // verification-notes.md §2f: "at a = 2" column
        assert!((LUBE.runout(2.0).0 - 2.4).abs() < 1e-12);
        assert!((LUBE.runout(2.0).1 - LUBE.power(2.0)).abs() < 1e-12);
        assert_eq!(LAJEUNESSE.runout(2.0), (3.6, 3.6));
        // the crossover: both branches at a = 3 for Lajeunesse, the power branch for Lube
        let (lo, hi) = LAJEUNESSE.runout(3.0);
        assert!((lo - 2.3 * 3f64.powf(2.0 / 3.0)).abs() < 1e-12 && (hi - 5.4).abs() < 1e-12);
        assert_eq!(LUBE.runout(6.0).0, LUBE.runout(6.0).1);
    }

    #[test]
    fn front_metrics_of_a_stopping_and_a_moving_front() {
        let c = column();
        let u = c.velocity_scale();
        // stops at x = 0.14 (runout 1.8) by t = 0.2, then rests until 0.45
        let rows: Vec<BulkRow> = (1..=90)
            .map(|k| {
                let t = 0.005 * k as f64;
                let front = if t < 0.2 { 0.05 + 0.09 * t / 0.2 } else { 0.14 };
                let mean_u = if t < 0.2 { 0.3 } else { 0.001 * u };
                BulkRow {
                    t,
                    mass: 3.0,
                    front,
                    mean_u,
                }
            })
            .collect();
        let m = front_metrics(&rows, &c, 0.5);
        assert!((m.runout - 1.8).abs() < 1e-12);
        assert!(m.stopped && !m.reached_end_wall);
        assert_eq!(m.front_speed, 0.0);
        // at 3 √(H0/g) = 0.214 s the front has stopped already
        assert!((m.runout_at_lab_stop.unwrap() - 1.8).abs() < 1e-12);
        // the same history still creeping: not stopped
        let creeping: Vec<BulkRow> = rows
            .iter()
            .map(|r| BulkRow {
                front: r.front + 0.05 * r.t,
                mean_u: 0.05 * u,
                ..*r
            })
            .collect();
        let m = front_metrics(&creeping, &c, 0.5);
        assert!(!m.stopped);
        assert!((m.front_speed - 0.05 / u).abs() < 1e-9);
        // a front at the east wall is flagged as a lower bound
        let at_wall: Vec<BulkRow> = rows.iter().map(|r| BulkRow { front: 0.5, ..*r }).collect();
        assert!(front_metrics(&at_wall, &c, 0.5).reached_end_wall);
    }

    #[test]
    fn floor_front_takes_the_last_floor_cell_above_the_threshold() {
        let faces = [0.0, 0.1, 0.2, 0.3, 0.4];
        // floor row then a second row (ignored)
        let eps = [0.6, 0.4, 0.005, 0.0, 0.6, 0.6, 0.6, 0.6];
        assert_eq!(floor_front(&eps, &faces, 0.01), 0.2);
        assert_eq!(floor_front(&eps, &faces, 0.5), 0.1);
        assert_eq!(floor_front(&eps, &faces, 0.7), 0.0);
    }

    #[test]
    fn shipped_collapse_cases_are_columns_of_the_four_aspect_ratios() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR")).parent().unwrap();
        let aspects: Vec<f64> = case_paths(root)
            .iter()
            .map(|p| {
                let Loaded::Cases(c) = load(p).unwrap() else {
                    panic!("{} is not a case", p.display())
                };
                Column::of(&c[0].case).unwrap().aspect()
            })
            .collect();
        for (a, want) in aspects.iter().zip([0.5, 1.0, 3.0, 6.0]) {
            assert_eq!(*a, want, "{aspects:?}");
        }
    }
}
