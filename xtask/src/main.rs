//! Developer tasks of runout, run as `cargo xtask <task>`.
//!
//! - `sweep`: the paper's case matrix (every sweep and stand-alone case under `cases/`),
//!   expanded, validated and listed; solving arrives with the two-fluid solver (issue 7).
//! - `bench linsolve`: the linear-solver timing table of docs/performance.md.
//! - `report analytic`: family A, the closed-form profiles of paper Fig. 1, as SVG and CSV
//!   in docs/analytic/.

mod analytic;

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::Command;

use anyhow::{bail, Context, Result};
use clap::{Parser, Subcommand};
use runout_case::{load, Fidelity, Loaded};

#[derive(Parser)]
#[command(name = "cargo xtask", about = "runout developer tasks")]
struct Cli {
    #[command(subcommand)]
    task: Task,
}

#[derive(Subcommand)]
enum Task {
    /// Expand, validate and list the paper's case matrix (cases/); with a solver, run it.
    Sweep {
        /// smoke, coarse (default) or paper
        #[arg(long, default_value = "coarse")]
        fidelity: String,
        /// run only shard i of n (1-based), e.g. `--shard 2/4`, for cluster job arrays
        #[arg(long)]
        shard: Option<String>,
        /// case directory
        #[arg(long, default_value = "cases")]
        cases: PathBuf,
    },
    /// Figures and tables: `cargo xtask report analytic` (paper Fig. 1 into docs/analytic/).
    Report {
        /// what to report (analytic)
        what: String,
    },
    /// Benchmarks: `cargo xtask bench linsolve [-- --max-cells N]`.
    Bench {
        /// what to benchmark (linsolve)
        what: String,
        /// extra arguments passed to the benchmark program
        #[arg(last = true)]
        args: Vec<String>,
    },
}

/// The workspace root (xtask lives one level below it).
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .expect("workspace root")
        .to_path_buf()
}

fn ron_files(dir: &Path, out: &mut Vec<PathBuf>) -> Result<()> {
    let mut entries: Vec<PathBuf> = std::fs::read_dir(dir)
        .with_context(|| format!("reading {}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            ron_files(&p, out)?;
        } else if p.extension().is_some_and(|e| e == "ron") {
            out.push(p);
        }
    }
    Ok(())
}

/// Parses `i/n` (1-based).
fn parse_shard(s: &str) -> Result<(usize, usize)> {
    let (i, n) = s.split_once('/').context("--shard must look like i/n")?;
    let (i, n): (usize, usize) = (i.trim().parse()?, n.trim().parse()?);
    if n == 0 || i == 0 || i > n {
        bail!("--shard {s}: need 1 <= i <= n");
    }
    Ok((i, n))
}

/// The matrix: every case a sweep expands to, plus stand-alone cases that no sweep uses
/// as its base, plus analytic families; prints each with its grid and end time.
fn sweep(fidelity: Fidelity, shard: Option<(usize, usize)>, cases_dir: &Path) -> Result<()> {
    let mut files = Vec::new();
    ron_files(cases_dir, &mut files)?;
    let mut loaded = Vec::new();
    let mut analytic = Vec::new();
    let mut errors = 0;
    for f in &files {
        match load(f) {
            Ok(Loaded::Cases(cases)) => loaded.push((f.clone(), cases)),
            Ok(Loaded::Analytic(a)) => analytic.push((a.name, f.clone())),
            Err(e) => {
                errors += 1;
                eprintln!("{e}");
            }
        }
    }
    if errors > 0 {
        bail!("{errors} case file(s) rejected; nothing was run");
    }
    // A case file that serves as a sweep's base is not a run of its own.
    let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    let bases: BTreeSet<PathBuf> = loaded
        .iter()
        .flat_map(|(_, cases)| {
            cases
                .iter()
                .filter_map(|c| c.base.as_deref().map(canonical))
        })
        .collect();
    let runs: Vec<_> = loaded
        .into_iter()
        .filter(|(f, _)| !bases.contains(&canonical(f)))
        .flat_map(|(_, cases)| cases)
        .collect();
    let selected: Vec<_> = match shard {
        None => runs.iter().collect(),
        Some((i, n)) => runs
            .iter()
            .enumerate()
            .filter(|(k, _)| k % n == i - 1)
            .map(|(_, r)| r)
            .collect(),
    };
    println!(
        "case matrix at fidelity `{fidelity}`: {} flow case(s){}, {} analytic famil{}",
        selected.len(),
        shard.map_or(String::new(), |(i, n)| format!(
            " (shard {i}/{n} of {})",
            runs.len()
        )),
        analytic.len(),
        if analytic.len() == 1 { "y" } else { "ies" }
    );
    let mut cells = 0usize;
    for r in &selected {
        let c = r.case.at_fidelity(fidelity);
        let g = c.grid()?;
        cells += g.cell_count();
        println!(
            "  {:<34} {:>5} x {:<4} to {:>5} s   {}",
            c.name,
            g.nx(),
            g.ny(),
            c.run.end_time,
            r.file.strip_prefix(root()).unwrap_or(&r.file).display()
        );
    }
    for (name, f) in &analytic {
        println!(
            "  {name:<34} closed form (no flow solve)   {}",
            f.strip_prefix(root()).unwrap_or(f).display()
        );
    }
    println!("total cells over the matrix: {cells}");
    println!(
        "NOT YET: the two-fluid solver does not exist yet (issues 6-7), so no case was solved; \
         this run only expanded and validated the matrix."
    );
    Ok(())
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    match cli.task {
        Task::Sweep {
            fidelity,
            shard,
            cases,
        } => {
            let fidelity: Fidelity = fidelity.parse().map_err(anyhow::Error::msg)?;
            let shard = shard.as_deref().map(parse_shard).transpose()?;
            let dir = if cases.is_absolute() {
                cases
            } else {
                root().join(cases)
            };
            sweep(fidelity, shard, &dir)
        }
        Task::Report { what } => match what.as_str() {
            "analytic" => analytic::report(&root()),
            other => bail!("unknown report `{other}` (known: analytic)"),
        },
        Task::Bench { what, args } => match what.as_str() {
            "linsolve" => {
                let status =
                    Command::new(std::env::var("CARGO").unwrap_or_else(|_| "cargo".into()))
                        .current_dir(root())
                        .args([
                            "run",
                            "--release",
                            "-p",
                            "runout-linsolve",
                            "--example",
                            "linsolve_table",
                            "--",
                        ])
                        .args(&args)
                        .status()?;
                if !status.success() {
                    bail!("linsolve benchmark failed: {status}");
                }
                Ok(())
            }
            other => bail!("unknown benchmark `{other}` (known: linsolve)"),
        },
    }
}
