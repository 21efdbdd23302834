//! `cargo xtask verify mfix-slope`: family M against MFIX 21.3.2 (issue 9; cases.md
//! "Family M").
//!
//! Runs cases/mfix-slope/jj.ron (MFIX's grid at `--fidelity paper`) once per thread count
//! of `--threads` (rayon pool of that size, in this process), and prints at t = 0.3, 0.5
//! and 0.8 s the front position and the εs-weighted mean solids x-velocity beside MFIX's,
//! with the relative differences; fails if any differs by more than 5 %. Also prints the
//! solids mass error, accepted and rejected steps, mean Δt, outer iterations per step, the
//! CPU seconds per simulated second (getrusage of this process: user + system, all
//! threads) beside MFIX's 490, and where the wall time went. Unless `--skip-variants`, the
//! other floors (revisited JJ, Jenkins, user partial slip) run too, and their
//! wall-adjacent solids velocity, θ and front at t = 0.3 s are compared. Everything goes to
//! docs/reports/mfix-slope.md as well. [`MfixSlope`] is the study of the registry: its
//! [`Options`] from the command line, then [`run`].

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context as _, Result};
use runout_case::{load, Fidelity, Loaded, SourcedCase};
use runout_output::{read_vtr_array, RunSummary};
use runout_run::cpu_time::cpu_seconds;
use runout_run::run_case;

use crate::references::mfix_family_m::{MFIX, MFIX_CPU_PER_SIMULATED_SECOND, MFIX_REJECTED};
use crate::study::{Args, Context, Study};

/// Largest relative difference allowed (issue 9).
pub const TOLERANCE: f64 = 0.05;
/// The time of the floor-variant comparison (issue 9, item 4) [s].
const VARIANT_TIME: f64 = 0.3;
/// εs above which a floor cell counts as part of the flow in the variant comparison.
const FLOW_EPS: f64 = 0.01;

/// Options of the check.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// `--fidelity`: default paper (MFIX's 200 × 50 grid)
    pub fidelity: Fidelity,
    /// `--threads`: rayon thread counts to time the JJ case with (default 1)
    pub threads: Vec<usize>,
    /// `--skip-variants`: skip the three other floors
    pub skip_variants: bool,
}

impl Options {
    /// The options of `args`, with their defaults.
    pub fn parse(args: &Args) -> Result<Self> {
        Ok(Self {
            fidelity: args
                .get("fidelity")
                .unwrap_or("paper")
                .parse()
                .map_err(anyhow::Error::msg)?,
            threads: args
                .list("threads")
                .context("--threads must be a comma-separated list of counts")?
                .unwrap_or_else(|| vec![1]),
            skip_variants: args.is_set("skip-variants"),
        })
    }
}

/// Family M against MFIX as a study of the registry.
pub struct MfixSlope;

impl Study for MfixSlope {
    fn name(&self) -> &'static str {
        "mfix-slope"
    }

    fn description(&self) -> &'static str {
        "family M (the paper's slide on four floors) against MFIX 21.3.2"
    }

    fn run(&self, args: &Args, context: &Context) -> Result<()> {
        run(context, &Options::parse(args)?)
    }
}

/// One timed run.
struct Timed {
    summary: RunSummary,
    cpu: f64,
    threads: usize,
    dir: PathBuf,
}

fn load_one(file: &Path) -> Result<SourcedCase> {
    match load(file).with_context(|| format!("loading {}", file.display()))? {
        Loaded::Cases(mut cases) if cases.len() == 1 => Ok(cases.remove(0)),
        _ => bail!("{} must hold exactly one case", file.display()),
    }
}

/// Runs `case` on a pool of `threads`; the output goes to the sweep's folder
/// runs/<case>/<fidelity> (read by `cargo xtask report`) when `primary`, else to
/// runs/<case>/<fidelity>-threads<n>.
fn run_timed(
    case: &SourcedCase,
    fidelity: Fidelity,
    threads: usize,
    primary: bool,
    root: &Path,
) -> Result<Timed> {
    let leaf = if primary {
        fidelity.name().to_string()
    } else {
        format!("{}-threads{threads}", fidelity.name())
    };
    let dir = root.join("runs").join(&case.case.name).join(leaf);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .context("building the thread pool")?;
    let cpu0 = cpu_seconds();
    let wall = Instant::now();
    let mut last_print = Instant::now();
    let summary = pool
        .install(|| {
            run_case(&case.case, fidelity, &dir, |p| {
                if last_print.elapsed().as_secs_f64() > 10.0 {
                    last_print = Instant::now();
                    eprintln!(
                        "  {} ({threads} thread(s)): t = {:.3} s, dt = {:.2e} s, {:.0} s wall",
                        case.case.name,
                        p.time,
                        p.dt,
                        wall.elapsed().as_secs_f64()
                    );
                }
            })
        })
        .with_context(|| format!("running {}", case.case.name))?;
    let cpu = cpu_seconds() - cpu0;
    Ok(Timed {
        summary,
        cpu,
        threads,
        dir,
    })
}

/// Rows (t, front, ū_s) of a run's bulk.csv ([`runout_post::bulk::read_bulk`]).
fn read_bulk(dir: &Path) -> Result<Vec<(f64, f64, f64)>> {
    let rows = runout_post::bulk::read_bulk(&dir.join("bulk.csv")).map_err(anyhow::Error::msg)?;
    Ok(rows.iter().map(|r| (r.t, r.front, r.mean_u)).collect())
}

/// Linear interpolation of (front, ū) at time t from bulk rows.
pub fn at_time(rows: &[(f64, f64, f64)], t: f64) -> Option<(f64, f64)> {
    let i = rows.iter().position(|r| r.0 >= t)?;
    if i == 0 {
        return Some((rows[0].1, rows[0].2));
    }
    let (a, b) = (rows[i - 1], rows[i]);
    let w = if b.0 > a.0 {
        (t - a.0) / (b.0 - a.0)
    } else {
        1.0
    };
    Some((a.1 + w * (b.1 - a.1), a.2 + w * (b.2 - a.2)))
}

/// The `.vtr` of a run's `fields.pvd` closest to time t, with its time.
fn fields_near(dir: &Path, t: f64) -> Result<(f64, String)> {
    let entries = runout_post::fields::field_files(dir)
        .with_context(|| format!("reading {}/fields.pvd", dir.display()))?;
    let (time, file) = runout_post::fields::nearest(&entries, t)
        .cloned()
        .context("no fields in fields.pvd")?;
    let text = std::fs::read_to_string(dir.join(&file))
        .with_context(|| format!("reading {}", dir.join(&file).display()))?;
    Ok((time, text))
}

/// Floor-row values at the field time nearest `t`: (time, εs-weighted mean u_s, εs-weighted
/// mean θ, largest u_s) over the floor cells with εs > [`FLOW_EPS`].
fn floor_row(dir: &Path, t: f64) -> Result<(f64, f64, f64, f64)> {
    let (time, text) = fields_near(dir, t)?;
    let eps = read_vtr_array(&text, "eps_s").context("eps_s missing")?;
    let u = read_vtr_array(&text, "u_s").context("u_s missing")?;
    let theta = read_vtr_array(&text, "theta").context("theta missing")?;
    let (nx, _) = runout_output::read_vtr_cells(&text).context("WholeExtent missing")?;
    // u_s is written with three components per cell (VTK vectors) or one
    let stride = u.len() / eps.len();
    let (mut w, mut su, mut st, mut umax) = (0.0, 0.0, 0.0, 0.0_f64);
    for i in 0..nx {
        if eps[i] > FLOW_EPS {
            w += eps[i];
            su += eps[i] * u[i * stride];
            st += eps[i] * theta[i];
            umax = umax.max(u[i * stride]);
        }
    }
    if w == 0.0 {
        bail!("no floor cell above εs = {FLOW_EPS} at t = {time}");
    }
    Ok((time, su / w, st / w, umax))
}

/// Runs the check; writes `mfix-slope.md` into the context's reports.
pub fn run(context: &Context, opts: &Options) -> Result<()> {
    let root = context.root.as_path();
    let dir = root.join("cases/mfix-slope");
    let jj = load_one(&dir.join("jj.ron"))?;
    let mut md = String::new();
    let mut failures = Vec::new();
    writeln!(
        md,
        "# Family M against MFIX 21.3.2\n\nWritten by `cargo xtask verify mfix-slope --fidelity {} \
         --threads {}` ({}). MFIX's numbers are those of cases.md (\"Family M\"), run with MFIX \
         21.3.2 on the same kind of machine; they were not re-measured here.\n",
        opts.fidelity.name(),
        opts.threads
            .iter()
            .map(|t| t.to_string())
            .collect::<Vec<_>>()
            .join(","),
        jj.file.display()
    )?;
    let mut timed = Vec::new();
    for (n, &threads) in opts.threads.iter().enumerate() {
        eprintln!("running {} with {threads} thread(s)", jj.case.name);
        timed.push(run_timed(&jj, opts.fidelity, threads, n == 0, root)?);
    }
    let first = timed.first().context("--threads is empty")?;
    front_section(&mut md, first, &mut failures)?;
    cost_section(&mut md, &timed)?;
    let s = &first.summary;
    if s.rejected_steps > MFIX_REJECTED {
        failures.push(format!(
            "{} rejected steps, more than MFIX's {MFIX_REJECTED}",
            s.rejected_steps
        ));
    }
    profile_section(&mut md, first)?;
    if !opts.skip_variants {
        variants_section(&mut md, root, &dir, &jj, first, opts)?;
    }
    if failures.is_empty() {
        writeln!(
            md,
            "**Result: pass** (all within ±{:.0} %).",
            TOLERANCE * 100.0
        )?;
    } else {
        writeln!(md, "**Result: fail**: {}.", failures.join("; "))?;
    }
    print!("{md}");
    let out = context.reports.join("mfix-slope.md");
    std::fs::write(&out, &md).with_context(|| format!("writing {}", out.display()))?;
    eprintln!("wrote {}", out.display());
    if !failures.is_empty() {
        bail!("mfix-slope: {}", failures.join("; "));
    }
    Ok(())
}

/// The front and mean solids velocity of the JJ run against MFIX's at its three times; a
/// difference beyond the tolerance is a failure.
fn front_section(md: &mut String, first: &Timed, failures: &mut Vec<String>) -> Result<()> {
    let rows = read_bulk(&first.dir)?;
    writeln!(
        md,
        "## Front and mean solids velocity (JJ floor, φ = 0.1; {} × {} cells)\n",
        first.summary.cells.0, first.summary.cells.1
    )?;
    writeln!(
        md,
        "| t [s] | front runout [m] | front MFIX [m] | diff | ū_s runout [m/s] | ū_s MFIX [m/s] | diff |\n|---|---|---|---|---|---|---|"
    )?;
    for (t, front_mfix, u_mfix) in MFIX {
        let (front, u) =
            at_time(&rows, t).with_context(|| format!("the run ended before t = {t}"))?;
        let (df, du) = (front / front_mfix - 1.0, u / u_mfix - 1.0);
        writeln!(
            md,
            "| {t} | {front:.3} | {front_mfix} | {:+.1} % | {u:.3} | {u_mfix} | {:+.1} % |",
            df * 100.0,
            du * 100.0
        )?;
        if df.abs() > TOLERANCE {
            failures.push(format!("front at t = {t}: {:+.1} %", df * 100.0));
        }
        if du.abs() > TOLERANCE {
            failures.push(format!("mean u_s at t = {t}: {:+.1} %", du * 100.0));
        }
    }
    writeln!(
        md,
        "\nFront = largest x with εs > 0.01; ū_s = εs-weighted mean solids x-velocity (bulk.csv, \
         interpolated linearly in time between its 0.01 s samples). Pass: every difference within \
         ±{:.0} %.\n",
        TOLERANCE * 100.0
    )?;
    Ok(())
}

/// One row per timed run: steps, iterations, mass error and cost against MFIX's.
fn cost_section(md: &mut String, timed: &[Timed]) -> Result<()> {
    writeln!(md, "## Run statistics and cost\n")?;
    writeln!(
        md,
        "| threads | simulated [s] | steps | rejected | mean Δt [s] | outer it./step | solids mass error | wall [s] | CPU [s] | CPU s per simulated s | MFIX / runout |\n|---|---|---|---|---|---|---|---|---|---|---|"
    )?;
    for t in timed {
        let s = &t.summary;
        let per = t.cpu / s.simulated_time.max(1e-12);
        writeln!(
            md,
            "| {} | {:.3} | {} | {} | {:.3e} | {:.1} | {:.1e} | {:.1} | {:.1} | {:.1} | {:.2} |",
            t.threads,
            s.simulated_time,
            s.steps,
            s.rejected_steps,
            s.dt.mean,
            s.outer_iterations as f64 / s.steps.max(1) as f64,
            s.solids_mass_change,
            s.wall_time,
            t.cpu,
            per,
            MFIX_CPU_PER_SIMULATED_SECOND / per
        )?;
    }
    writeln!(
        md,
        "\nMFIX: {MFIX_CPU_PER_SIMULATED_SECOND} CPU s per simulated second on one core, 1205 \
         accepted and {MFIX_REJECTED} rejected steps, 10.5 outer iterations per step. The \
         target (issue 9) is at most {:.0} CPU s per simulated second on one thread.\n",
        MFIX_CPU_PER_SIMULATED_SECOND / 10.0
    )?;
    Ok(())
}

/// Where the first run's wall time went, by solver part (nothing if it has no profile).
fn profile_section(md: &mut String, first: &Timed) -> Result<()> {
    let s = &first.summary;
    if !s.profile.is_empty() {
        let total: f64 = s.profile.iter().map(|p| p.1).sum();
        writeln!(
            md,
            "## Where the time goes ({} thread(s), wall time of the solver's parts)\n\n| part | wall [s] | share |\n|---|---|---|",
            first.threads
        )?;
        for (name, secs) in &s.profile {
            writeln!(md, "| {name} | {secs:.2} | {:.1} % |", 100.0 * secs / total)?;
        }
        writeln!(
            md,
            "| rest of the run (time loop, monitors, output) | {:.2} | |\n",
            s.wall_time - total
        )?;
    }
    Ok(())
}

/// The four floors (issue 9, item 4): runs the other three on the first thread count and
/// tabulates the floor row of each at [`VARIANT_TIME`].
fn variants_section(
    md: &mut String,
    root: &Path,
    dir: &Path,
    jj: &SourcedCase,
    first: &Timed,
    opts: &Options,
) -> Result<()> {
    writeln!(
        md,
        "## The four floors at t = {VARIANT_TIME} s (issue 9, item 4)\n\nFloor-row (wall-adjacent) \
         cells with εs > {FLOW_EPS}: εs-weighted mean solids x-velocity and θ, the largest \
         solids x-velocity, and the front. Fields nearest t = {VARIANT_TIME} s.\n\n| floor | \
         field time [s] | ū_s wall row [m/s] | max u_s wall row [m/s] | θ wall row [m²/s²] | \
         front [m] | status |\n|---|---|---|---|---|---|---|"
    )?;
    let mut cases = vec![(jj.clone(), first.dir.clone(), first.summary.status.clone())];
    for file in ["rjj.ron", "jenkins.ron", "partial-slip.ron"] {
        let case = load_one(&dir.join(file))?;
        eprintln!("running {}", case.case.name);
        let t = run_timed(&case, opts.fidelity, opts.threads[0], true, root)?;
        cases.push((case, t.dir, t.summary.status));
    }
    for (case, run_dir, status) in &cases {
        let (time, u, theta, umax) = floor_row(run_dir, VARIANT_TIME)?;
        let front = at_time(&read_bulk(run_dir)?, VARIANT_TIME).map_or(f64::NAN, |r| r.0);
        writeln!(
            md,
            "| {} | {time:.3} | {u:.3} | {umax:.3} | {theta:.3e} | {front:.3} | {status:?} |",
            case.case.name
        )?;
    }
    writeln!(md)?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_from_the_command_line_with_defaults() {
        let o = Options::parse(&Args::new()).unwrap();
        assert_eq!(
            (o.fidelity, o.threads, o.skip_variants),
            (Fidelity::Paper, vec![1], false)
        );
        let args = Args::new()
            .with("fidelity", Some("coarse"))
            .with("threads", Some("1, 2"))
            .flag("skip-variants", true);
        let o = Options::parse(&args).unwrap();
        assert_eq!(
            (o.fidelity, o.threads, o.skip_variants),
            (Fidelity::Coarse, vec![1, 2], true)
        );
        assert!(Options::parse(&Args::new().with("threads", Some("1,x"))).is_err());
    }

    #[test]
    fn interpolates_bulk_rows_in_time() {
        let rows = [(0.0, 0.5, 0.0), (0.2, 0.7, 1.0), (0.4, 1.1, 2.0)];
        let (f, u) = at_time(&rows, 0.3).unwrap();
        assert!((f - 0.9).abs() < 1e-12 && (u - 1.5).abs() < 1e-12);
        assert!(at_time(&rows, 0.5).is_none());
    }
}
