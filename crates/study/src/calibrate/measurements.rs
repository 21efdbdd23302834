//! Measurements to calibrate against, and their misfit to a finished run.
//!
//! A CSV file with a header line; lines starting with `#` are comments. The header says
//! what is measured (docs/reference/calibrate.md):
//! - `gate`, `speed_m_s`: front speed at each gate (cases/flume/gates.csv; gate `L3` or `3`;
//!   an empty speed is a gate without a measurement) against the run's front speed at the
//!   gates of its `gates.csv`, interpolated in time from its front series so that it is
//!   continuous in the parameters ([`runout_post::gates::speed_at_gate`]);
//! - `t`, `x`: front position x [m, the case's x] at time t [s] against the run's front
//!   (`front.csv`, else `bulk.csv`'s `front_x`), interpolated linearly in t;
//! - `y` and one of `eps_s`, `u_s`, `theta`, `u_g`, `v_g`: a profile against the run's
//!   profile file (`profile_x<x>_t<t>.csv`; a run with several needs a comment line
//!   `# profile: <file name>`), interpolated linearly in y.
//!
//! The measurement error σ of each point comes from a `sigma` column (per row), else a line
//! `# sigma: <value>` (every point), else `--sigma` (which overrides both). Other columns are
//! ignored. The misfit is χ² = Σ (s_i − m_i)²/σ_i² over every measured point, reported with
//! the RMS of s_i − m_i; a point the run does not reach (a gate never crossed, a time after
//! the run's end) leaves the misfit undefined (infinite). The run's front is the
//! interpolated one ([`runout_post::front`]).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use runout_post::folder::csv_files;
use runout_post::front::{front_series, FrontDefinition};
use runout_post::gates::interpolated_gate_speeds;
use runout_post::table::Table;

use runout_mesh::{interpolate, Beyond};

/// The profile columns a measured profile may compare.
pub const PROFILE_COLUMNS: [&str; 5] = ["eps_s", "u_s", "theta", "u_g", "v_g"];

/// What a measurements file holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Kind {
    /// (gate number, front speed [m/s])
    GateSpeeds(Vec<(usize, f64)>),
    /// (t [s], front x [m])
    Front(Vec<(f64, f64)>),
    /// a profile column against y, with the run's profile file if named
    Profile {
        /// the compared column of the profile file
        column: String,
        /// `# profile:` file name, if given
        file: Option<String>,
        /// (y [m], value)
        points: Vec<(f64, f64)>,
    },
}

/// A measurements file, read and checked.
#[derive(Clone, Debug)]
pub struct Measurements {
    /// the file
    pub path: PathBuf,
    /// its data
    pub kind: Kind,
    /// the measurement error σ of each point, in the order of the points
    pub sigma: Vec<f64>,
    /// where σ came from, for the summary
    pub sigma_source: String,
}

/// The misfit of one run.
#[derive(Clone, Debug, PartialEq)]
pub struct Misfit {
    /// χ² = Σ (s_i − m_i)²/σ_i²; infinite if a point is missing
    pub chi2: f64,
    /// RMS of simulated − measured; infinite if a point is missing
    pub rms: f64,
    /// points compared
    pub compared: usize,
    /// the points the run has no value for
    pub missing: Vec<String>,
    /// what the run's front is (front measurements)
    pub front: Option<FrontDefinition>,
    /// (s_i − m_i)/σ_i of every measured point in order; empty if a point is missing
    pub residuals: Vec<f64>,
}

impl Misfit {
    /// From the differences s_i − m_i and the σ_i of the points compared.
    fn from_differences(diffs: &[(f64, f64)], missing: Vec<String>) -> Misfit {
        let n = diffs.len();
        let (rms, chi2) = if missing.is_empty() && n > 0 {
            (
                (diffs.iter().map(|(d, _)| d * d).sum::<f64>() / n as f64).sqrt(),
                diffs.iter().map(|(d, s)| (d / s).powi(2)).sum(),
            )
        } else {
            (f64::INFINITY, f64::INFINITY)
        };
        let residuals = if missing.is_empty() {
            diffs.iter().map(|(d, s)| d / s).collect()
        } else {
            Vec::new()
        };
        Misfit {
            chi2,
            rms,
            compared: n,
            missing,
            front: None,
            residuals,
        }
    }
}

/// Splits the non-comment lines into (1-based line number, fields); the directives
/// `# key: value` are returned apart.
type Lines = Vec<(usize, Vec<String>)>;
fn split(text: &str) -> (Lines, Vec<(String, String)>) {
    let mut lines = Vec::new();
    let mut directives = Vec::new();
    for (k, line) in text.lines().enumerate() {
        let trimmed = line.trim();
        if let Some(comment) = trimmed.strip_prefix('#') {
            if let Some((key, value)) = comment.split_once(':') {
                directives.push((key.trim().to_string(), value.trim().to_string()));
            }
        } else if !trimmed.is_empty() {
            lines.push((
                k + 1,
                line.split(',').map(|f| f.trim().to_string()).collect(),
            ));
        }
    }
    (lines, directives)
}

impl Measurements {
    /// Reads and checks `path`, σ from the file or `sigma` (`--sigma`, which overrides the
    /// file's): an error names the file, the line and the column.
    pub fn read(path: &Path, sigma: Option<f64>) -> Result<Measurements> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("{}: cannot read the measurements", path.display()))?;
        let (kind, in_file) = parse(&text).with_context(|| format!("{}", path.display()))?;
        let n = kind.len();
        let (sigma, sigma_source) = match (sigma, in_file) {
            (Some(s), _) if s > 0.0 && s.is_finite() => (vec![s; n], format!("σ = {s} (--sigma)")),
            (Some(s), _) => bail!("--sigma {s}: a measurement error is a finite number > 0"),
            (None, Some((sigma, source))) => (sigma, source),
            (None, None) => bail!(
                "{}: no measurement error σ: give a column `sigma`, a line `# sigma: <value>` \
                 or --sigma <value> (in the measurement's unit)",
                path.display()
            ),
        };
        Ok(Measurements {
            path: path.to_path_buf(),
            kind,
            sigma,
            sigma_source,
        })
    }

    /// What is measured, for messages and the summary.
    pub fn describe(&self) -> String {
        match &self.kind {
            Kind::GateSpeeds(v) => format!("{} gate speeds [m/s]", v.len()),
            Kind::Front(v) => format!("{} front positions [m]", v.len()),
            Kind::Profile { column, points, .. } => {
                format!("a profile of {column}, {} points", points.len())
            }
        }
    }

    /// The unit of the misfit.
    pub fn unit(&self) -> &'static str {
        match &self.kind {
            Kind::GateSpeeds(_) => "m/s",
            Kind::Front(_) => "m",
            Kind::Profile { column, .. } => match column.as_str() {
                "eps_s" => "-",
                "theta" => "m²/s²",
                _ => "m/s",
            },
        }
    }

    /// The misfit of the finished run in `dir`; an error if its monitor files are absent.
    pub fn misfit(&self, dir: &Path) -> Result<Misfit> {
        match &self.kind {
            Kind::GateSpeeds(measured) => {
                let simulated = interpolated_gate_speeds(dir).map_err(anyhow::Error::msg)?;
                let mut diffs = Vec::new();
                let mut missing = Vec::new();
                for ((g, v), s) in measured.iter().zip(&self.sigma) {
                    match simulated.iter().find(|(k, _)| k == g) {
                        Some((_, speed)) => diffs.push((speed - v, *s)),
                        None => missing.push(format!("gate L{g} not crossed")),
                    }
                }
                Ok(Misfit::from_differences(&diffs, missing))
            }
            Kind::Front(measured) => {
                let (definition, simulated) = front_series(dir).map_err(anyhow::Error::msg)?;
                let mut m = compare(measured, &self.sigma, &simulated, Beyond::Missing, "t");
                m.front = Some(definition);
                Ok(m)
            }
            Kind::Profile {
                column,
                file,
                points,
            } => {
                let simulated = profile(dir, column, file.as_deref())?;
                Ok(compare(points, &self.sigma, &simulated, Beyond::Clamp, "y"))
            }
        }
    }
}

impl Kind {
    /// The number of measured points.
    pub fn len(&self) -> usize {
        match self {
            Kind::GateSpeeds(v) => v.len(),
            Kind::Front(v) => v.len(),
            Kind::Profile { points, .. } => points.len(),
        }
    }

    /// No measured point (a file is refused so; see [`Measurements::read`]).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// Simulated − measured at each measured abscissa, the simulation interpolated linearly
/// ([`interpolate`]); outside the simulated range as `beyond` says (`Missing`: the point
/// is missing; `Clamp`: the end value is used).
fn compare(
    measured: &[(f64, f64)],
    sigma: &[f64],
    simulated: &[(f64, f64)],
    beyond: Beyond,
    what: &str,
) -> Misfit {
    let (xs, ys): (Vec<f64>, Vec<f64>) = simulated.iter().copied().unzip();
    let mut diffs = Vec::new();
    let mut missing = Vec::new();
    for (&(a, v), &s) in measured.iter().zip(sigma) {
        match interpolate(&xs, &ys, a, beyond) {
            Some(sim) => diffs.push((sim - v, s)),
            None => missing.push(format!("{what} = {a}: outside the run")),
        }
    }
    Misfit::from_differences(&diffs, missing)
}

/// Two numeric columns of a run's monitor CSV, by name ([`Table`]); rows with an empty cell
/// in either are left out.
fn columns(file: &Path, x: &str, y: &str) -> Result<Vec<(f64, f64)>> {
    let pairs = Table::read(file)
        .and_then(|t| t.pairs(x, y))
        .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    Ok(pairs
        .into_iter()
        .filter(|(a, b)| !a.is_nan() && !b.is_nan())
        .collect())
}

/// The run's profile `column` against y.
fn profile(dir: &Path, column: &str, file: Option<&str>) -> Result<Vec<(f64, f64)>> {
    let chosen = match file {
        Some(name) => dir.join(name),
        None => {
            let mut found = csv_files(dir, "profile_x");
            match found.len() {
                1 => found.remove(0),
                0 => bail!("{}: no profile_x*.csv", dir.display()),
                _ => bail!(
                    "{}: several profile files: name one in the measurements with a line \
                     `# profile: <file name>`",
                    dir.display()
                ),
            }
        }
    };
    columns(&chosen, "y", column)
}

/// A number in `line` at `column`; empty is `None`.
fn number(fields: &[String], index: usize, name: &str, line: usize) -> Result<Option<f64>> {
    let text = fields.get(index).map_or("", |s| s.as_str());
    if text.is_empty() {
        return Ok(None);
    }
    match text.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(Some(v)),
        _ => bail!("line {line}: column `{name}`: `{text}` is not a finite number"),
    }
}

/// σ of the file: per point from the `sigma` column (an empty cell takes the `# sigma:`
/// line's value), or the `# sigma:` value for every point; `None` if the file gives none.
type FileSigma = Option<(Vec<f64>, String)>;

/// The file's σ from each point's own (`sigma` column, if `column`) or common (`# sigma:`)
/// value; `None` if the file gives neither.
fn file_sigma(column: bool, common: Option<f64>, sigmas: Vec<Option<f64>>) -> Result<FileSigma> {
    let source = match (column, common) {
        (false, None) => return Ok(None),
        (true, _) => "σ per point (the file's `sigma` column)".to_string(),
        (false, Some(s)) => format!("σ = {s} (the file's `# sigma:` line)"),
    };
    let all: Option<Vec<f64>> = sigmas.into_iter().collect();
    let all =
        all.context("column `sigma`: a point without σ (an empty cell and no `# sigma:` line)")?;
    Ok(Some((all, source)))
}

/// Parses the text of a measurements file: its points and its σ.
pub fn parse(text: &str) -> Result<(Kind, FileSigma)> {
    let (lines, directives) = split(text);
    let Some(((_, header), rows)) = lines.split_first() else {
        bail!("no header line");
    };
    let col = |name: &str| header.iter().position(|h| h == name);
    let need = |name: &str, what: &str| {
        col(name).with_context(|| {
            format!(
                "header `{}`: {what} need a column `{name}`",
                header.join(",")
            )
        })
    };
    let common_sigma = match directives.iter().find(|(k, _)| k == "sigma") {
        Some((_, v)) => match v.parse::<f64>() {
            Ok(s) if s > 0.0 && s.is_finite() => Some(s),
            _ => bail!("`# sigma: {v}`: a measurement error is a finite number > 0"),
        },
        None => None,
    };
    let sigma_col = col("sigma");
    // σ of one row: its `sigma` cell, else the common value
    let row_sigma = |f: &[String], line: usize| -> Result<Option<f64>> {
        let own = match sigma_col {
            Some(k) => number(f, k, "sigma", line)?,
            None => None,
        };
        match own.or(common_sigma) {
            Some(s) if s <= 0.0 => bail!("line {line}: column `sigma`: {s} is not > 0"),
            s => Ok(s),
        }
    };
    let triples =
        |a: usize, an: &str, b: usize, bn: &str| -> Result<Vec<(f64, f64, Option<f64>)>> {
            let mut out = Vec::new();
            for (line, f) in rows {
                let x = number(f, a, an, *line)?
                    .with_context(|| format!("line {line}: column `{an}` is empty"))?;
                if let Some(y) = number(f, b, bn, *line)? {
                    out.push((x, y, row_sigma(f, *line)?));
                }
            }
            Ok(out)
        };
    let (kind, sigmas): (Kind, Vec<Option<f64>>) = if let Some(g) = col("gate") {
        let s = need("speed_m_s", "gate speeds")?;
        let mut out = Vec::new();
        let mut sigmas = Vec::new();
        for (line, f) in rows {
            let name = f.get(g).map_or("", |s| s.as_str());
            let gate: usize = name.trim_start_matches('L').parse().ok().with_context(|| {
                format!("line {line}: column `gate`: `{name}` is not L<k> or k")
            })?;
            if let Some(v) = number(f, s, "speed_m_s", *line)? {
                out.push((gate, v));
                sigmas.push(row_sigma(f, *line)?);
            }
        }
        (Kind::GateSpeeds(out), sigmas)
    } else if let Some(t) = col("t") {
        let mut p = triples(t, "t", need("x", "front positions")?, "x")?;
        p.sort_by(|a, b| a.0.total_cmp(&b.0));
        (
            Kind::Front(p.iter().map(|q| (q.0, q.1)).collect()),
            p.iter().map(|q| q.2).collect(),
        )
    } else if let Some(y) = col("y") {
        let name = PROFILE_COLUMNS
            .iter()
            .find(|c| col(c).is_some())
            .with_context(|| {
                format!(
                    "header `{}`: a profile needs `y` and one of {}",
                    header.join(","),
                    PROFILE_COLUMNS.join(", ")
                )
            })?;
        let file = directives
            .iter()
            .find(|(k, _)| k == "profile")
            .map(|(_, v)| v.clone());
        let p = triples(y, "y", col(name).expect("found"), name)?;
        (
            Kind::Profile {
                column: name.to_string(),
                file,
                points: p.iter().map(|q| (q.0, q.1)).collect(),
            },
            p.iter().map(|q| q.2).collect(),
        )
    } else {
        bail!(
            "header `{}`: expected the columns gate,speed_m_s (gate speeds), t,x (front \
             positions) or y and one of {} (a profile)",
            header.join(","),
            PROFILE_COLUMNS.join(", ")
        );
    };
    if kind.is_empty() {
        bail!("no measured values (every value cell is empty)");
    }
    let sigma = file_sigma(sigma_col.is_some(), common_sigma, sigmas)?;
    Ok((kind, sigma))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_gate_speeds_are_read() {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases/flume/gates.csv");
        let m = Measurements::read(&file, Some(0.3)).unwrap();
        assert_eq!(m.sigma, [0.3; 6]);
        assert_eq!(
            m.kind,
            Kind::GateSpeeds(vec![
                (2, 4.0),
                (3, 4.0),
                (4, 4.0),
                (5, 4.0),
                (6, 4.0),
                (7, 5.4)
            ])
        );
    }

    #[test]
    fn fronts_and_profiles_are_read() {
        assert_eq!(
            parse("# a comment\nt,x\n0.2,1.5\n0.1,1.0\n").unwrap().0,
            Kind::Front(vec![(0.1, 1.0), (0.2, 1.5)])
        );
        assert_eq!(
            parse("# profile: profile_x11_t1.25.csv\ny,u_s,note\n0.01,2.0,a\n0.02,,b\n")
                .unwrap()
                .0,
            Kind::Profile {
                column: "u_s".into(),
                file: Some("profile_x11_t1.25.csv".into()),
                points: vec![(0.01, 2.0)],
            }
        );
    }

    #[test]
    fn sigma_comes_per_row_from_a_line_or_from_the_command_line() {
        // per row, sorted with the points; an empty cell takes the `# sigma:` line's value
        let (kind, sigma) = parse("# sigma: 0.01\nt,x,sigma\n0.2,1.5,0.02\n0.1,1.0,\n").unwrap();
        assert_eq!(kind, Kind::Front(vec![(0.1, 1.0), (0.2, 1.5)]));
        assert_eq!(sigma.unwrap().0, [0.01, 0.02]);
        let (_, sigma) = parse("# sigma: 0.2\ngate,speed_m_s\nL2,4\nL3,4\n").unwrap();
        assert_eq!(sigma.unwrap().0, [0.2, 0.2]);
        assert_eq!(parse("t,x\n0.1,1\n").unwrap().1, None);
        let err = |text: &str| format!("{:#}", parse(text).unwrap_err());
        assert!(err("t,x,sigma\n0.1,1,\n").contains("a point without σ"));
        assert!(err("t,x,sigma\n0.1,1,-1\n").contains("not > 0"));
        assert!(err("# sigma: none\nt,x\n0.1,1\n").contains("finite number > 0"));
        let dir = std::env::temp_dir().join(format!("runout-sigma-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let file = dir.join("m.csv");
        std::fs::write(&file, "t,x\n0.1,1\n").unwrap();
        let e = format!("{:#}", Measurements::read(&file, None).unwrap_err());
        assert!(e.contains("--sigma"), "{e}");
        assert_eq!(Measurements::read(&file, Some(0.5)).unwrap().sigma, [0.5]);
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn bad_files_name_the_column() {
        let err = |text: &str| format!("{:#}", parse(text).unwrap_err());
        assert!(err("gate,distance_m\nL1,1.65\n").contains("need a column `speed_m_s`"));
        assert!(err("t,y_front\n0.1,1\n").contains("need a column `x`"));
        assert!(err("a,b\n1,2\n").contains("expected the columns"));
        assert!(err("t,x\n0.1,fast\n").contains("line 2: column `x`: `fast`"));
        assert!(err("gate,speed_m_s\nX1,3\n").contains("column `gate`"));
        assert!(err("y,eps_s\n,0.5\n").contains("column `y` is empty"));
        assert!(err("gate,speed_m_s\nL1,\n").contains("no measured values"));
        assert!(err("y,rho\n0.1,1\n").contains("one of eps_s"));
        assert!(err("# only comments\n").contains("no header"));
        let missing = Path::new("/nonexistent/m.csv");
        let e = format!("{:#}", Measurements::read(missing, Some(1.0)).unwrap_err());
        assert!(e.contains("/nonexistent/m.csv"), "{e}");
    }

    #[test]
    fn the_misfit_of_a_run_folder() {
        let dir = std::env::temp_dir().join(format!("runout-measured-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(
            dir.join("gates.csv"),
            "gate,x,t_cross,speed\n1e0,2.15,0.5,3.0\n2e0,2.6,0.6,5.0\n",
        )
        .unwrap();
        // a front at 2 m/s: 2 m/s at every gate (the speed is the front series', not the
        // sampled `speed` column's)
        std::fs::write(
            dir.join("front.csv"),
            "t,front_x\n0,0\n0.5,1\n1,2\n1.5,3\n2,4\n",
        )
        .unwrap();
        let gates = |text: &str| {
            let kind = parse(text).unwrap().0;
            Measurements {
                path: "m.csv".into(),
                sigma: vec![0.5; kind.len()],
                sigma_source: String::new(),
                kind,
            }
        };
        // RMS of (2 − 4, 2 − 3) = √2.5; χ² = (4 + 1)/0.5²
        let m = gates("gate,speed_m_s\nL1,4\nL2,3\n").misfit(&dir).unwrap();
        assert!((m.rms - 2.5f64.sqrt()).abs() < 1e-12 && (m.chi2 - 20.0).abs() < 1e-9);
        assert_eq!(m.compared, 2);
        let m = gates("gate,speed_m_s\nL1,4\nL3,4\n").misfit(&dir).unwrap();
        assert!(m.rms.is_infinite());
        assert_eq!(m.missing, ["gate L3 not crossed"]);
        let m = gates("t,x\n0.5,1.5\n").misfit(&dir).unwrap();
        assert!((m.rms - 0.5).abs() < 1e-12 && (m.chi2 - 1.0).abs() < 1e-12);
        assert_eq!(m.front, Some(FrontDefinition::Interpolated));
        assert!(
            gates("y,u_s\n0.1,1\n").misfit(&dir).is_err(),
            "no profile file"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn interpolation_and_missing_points() {
        let sim = [(0.0, 0.0), (1.0, 2.0), (2.0, 2.0)];
        let m = compare(
            &[(0.5, 2.0), (1.5, 2.0)],
            &[1.0, 2.0],
            &sim,
            Beyond::Missing,
            "t",
        );
        assert!((m.rms - (0.5f64).sqrt()).abs() < 1e-12);
        assert!((m.chi2 - 1.0).abs() < 1e-12);
        let m = compare(
            &[(0.5, 2.0), (5.0, 2.0)],
            &[1.0; 2],
            &sim,
            Beyond::Missing,
            "t",
        );
        assert!(m.rms.is_infinite());
        assert_eq!(m.missing.len(), 1);
        // clamped, the point beyond the run takes the last value: 2 − 2
        let m = compare(
            &[(0.5, 2.0), (5.0, 2.0)],
            &[1.0; 2],
            &sim,
            Beyond::Clamp,
            "y",
        );
        assert!(m.missing.is_empty() && (m.chi2 - 1.0).abs() < 1e-12);
    }
}
