//! Measurements to calibrate against, and their misfit to a finished run.
//!
//! A CSV file with a header line; lines starting with `#` are comments. The header says
//! what is measured (docs/calibrate.md):
//! - `gate`, `speed_m_s`: front speed at each gate (cases/flume/gates.csv; gate `L3` or `3`;
//!   an empty speed is a gate without a measurement) against the run's `gates.csv`;
//! - `t`, `x`: front position x [m, the case's x] at time t [s] against the run's front
//!   (`front.csv`, else `bulk.csv`'s `front_x`), interpolated linearly in t;
//! - `y` and one of `eps_s`, `u_s`, `theta`, `u_g`, `v_g`: a profile against the run's
//!   profile file (`profile_x<x>_t<t>.csv`; a run with several needs a comment line
//!   `# profile: <file name>`), interpolated linearly in y.
//!
//! Other columns are ignored. The misfit is the RMS of simulated − measured over every
//! measured point; a point the run does not reach (a gate never crossed, a time after the
//! run's end) leaves the misfit undefined (infinite).

use std::path::{Path, PathBuf};

use anyhow::{bail, Context, Result};

use crate::metrics::{gate_speeds, mse_vs_described};
use runout_post::folder::csv_files;
use runout_post::table::Table;

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
}

/// The misfit of one run.
#[derive(Clone, Debug, PartialEq)]
pub struct Misfit {
    /// RMS of simulated − measured; infinite if a point is missing
    pub rms: f64,
    /// points compared
    pub compared: usize,
    /// the points the run has no value for
    pub missing: Vec<String>,
}

impl Misfit {
    fn from_squares(squares: &[f64], missing: Vec<String>) -> Misfit {
        let rms = if missing.is_empty() && !squares.is_empty() {
            (squares.iter().sum::<f64>() / squares.len() as f64).sqrt()
        } else {
            f64::INFINITY
        };
        Misfit {
            rms,
            compared: squares.len(),
            missing,
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
    /// Reads and checks `path`: an error names the file, the line and the column.
    pub fn read(path: &Path) -> Result<Measurements> {
        let text = std::fs::read_to_string(path)
            .with_context(|| format!("{}: cannot read the measurements", path.display()))?;
        let kind = parse(&text).with_context(|| format!("{}", path.display()))?;
        Ok(Measurements {
            path: path.to_path_buf(),
            kind,
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
                let simulated =
                    gate_speeds(dir).with_context(|| format!("{}: no gates.csv", dir.display()))?;
                let missing: Vec<String> = measured
                    .iter()
                    .filter(|(g, _)| !simulated.iter().any(|(s, _)| s == g))
                    .map(|(g, _)| format!("gate L{g} not crossed"))
                    .collect();
                let (mse, compared) =
                    mse_vs_described(&simulated, measured).unwrap_or((f64::INFINITY, 0));
                let rms = if missing.is_empty() {
                    mse.sqrt()
                } else {
                    f64::INFINITY
                };
                Ok(Misfit {
                    rms,
                    compared,
                    missing,
                })
            }
            Kind::Front(measured) => {
                let simulated = front(dir)?;
                Ok(compare(measured, &simulated, false, "t"))
            }
            Kind::Profile {
                column,
                file,
                points,
            } => {
                let simulated = profile(dir, column, file.as_deref())?;
                Ok(compare(points, &simulated, true, "y"))
            }
        }
    }
}

/// Squares of simulated − measured at each measured abscissa, the simulation interpolated
/// linearly; outside the simulated range a point is missing, unless `clamp` (then the end
/// value is used).
fn compare(measured: &[(f64, f64)], simulated: &[(f64, f64)], clamp: bool, what: &str) -> Misfit {
    let mut squares = Vec::new();
    let mut missing = Vec::new();
    for &(a, v) in measured {
        match interpolate(simulated, a, clamp) {
            Some(s) => squares.push((s - v).powi(2)),
            None => missing.push(format!("{what} = {a}: outside the run")),
        }
    }
    Misfit::from_squares(&squares, missing)
}

/// Linear interpolation in `points` (sorted by abscissa).
pub fn interpolate(points: &[(f64, f64)], a: f64, clamp: bool) -> Option<f64> {
    let (first, last) = (points.first()?, points.last()?);
    if a <= first.0 {
        return (clamp || a == first.0).then_some(first.1);
    }
    if a >= last.0 {
        return (clamp || a == last.0).then_some(last.1);
    }
    let k = points.partition_point(|p| p.0 <= a);
    let (p, q) = (points[k - 1], points[k]);
    Some(p.1 + (q.1 - p.1) * (a - p.0) / (q.0 - p.0))
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

/// The run's front position against time.
fn front(dir: &Path) -> Result<Vec<(f64, f64)>> {
    let f = dir.join("front.csv");
    if f.exists() {
        columns(&f, "t", "front_x")
    } else {
        columns(&dir.join("bulk.csv"), "t", "front_x")
    }
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

/// Parses the text of a measurements file.
pub fn parse(text: &str) -> Result<Kind> {
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
    let pairs = |a: usize, an: &str, b: usize, bn: &str| -> Result<Vec<(f64, f64)>> {
        let mut out = Vec::new();
        for (line, f) in rows {
            let x = number(f, a, an, *line)?
                .with_context(|| format!("line {line}: column `{an}` is empty"))?;
            if let Some(y) = number(f, b, bn, *line)? {
                out.push((x, y));
            }
        }
        Ok(out)
    };
    let kind = if let Some(g) = col("gate") {
        let s = need("speed_m_s", "gate speeds")?;
        let mut out = Vec::new();
        for (line, f) in rows {
            let name = f.get(g).map_or("", |s| s.as_str());
            let gate: usize = name.trim_start_matches('L').parse().ok().with_context(|| {
                format!("line {line}: column `gate`: `{name}` is not L<k> or k")
            })?;
            if let Some(v) = number(f, s, "speed_m_s", *line)? {
                out.push((gate, v));
            }
        }
        Kind::GateSpeeds(out)
    } else if let Some(t) = col("t") {
        let mut p = pairs(t, "t", need("x", "front positions")?, "x")?;
        p.sort_by(|a, b| a.0.total_cmp(&b.0));
        Kind::Front(p)
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
        Kind::Profile {
            column: name.to_string(),
            file,
            points: pairs(y, "y", col(name).expect("found"), name)?,
        }
    } else {
        bail!(
            "header `{}`: expected the columns gate,speed_m_s (gate speeds), t,x (front \
             positions) or y and one of {} (a profile)",
            header.join(","),
            PROFILE_COLUMNS.join(", ")
        );
    };
    let n = match &kind {
        Kind::GateSpeeds(v) => v.len(),
        Kind::Front(v) => v.len(),
        Kind::Profile { points, .. } => points.len(),
    };
    if n == 0 {
        bail!("no measured values (every value cell is empty)");
    }
    Ok(kind)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_shipped_gate_speeds_are_read() {
        let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../cases/flume/gates.csv");
        let m = Measurements::read(&file).unwrap();
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
            parse("# a comment\nt,x\n0.2,1.5\n0.1,1.0\n").unwrap(),
            Kind::Front(vec![(0.1, 1.0), (0.2, 1.5)])
        );
        assert_eq!(
            parse("# profile: profile_x11_t1.25.csv\ny,u_s,note\n0.01,2.0,a\n0.02,,b\n").unwrap(),
            Kind::Profile {
                column: "u_s".into(),
                file: Some("profile_x11_t1.25.csv".into()),
                points: vec![(0.01, 2.0)],
            }
        );
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
        let e = format!("{:#}", Measurements::read(missing).unwrap_err());
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
        std::fs::write(dir.join("front.csv"), "t,front_x\n0,0\n1,2\n").unwrap();
        let gates = |text: &str| Measurements {
            path: "m.csv".into(),
            kind: parse(text).unwrap(),
        };
        // RMS of (3 − 4, 5 − 4) = 1, the report's MSE under a square root
        let m = gates("gate,speed_m_s\nL1,4\nL2,4\n").misfit(&dir).unwrap();
        assert_eq!((m.rms, m.compared), (1.0, 2));
        let m = gates("gate,speed_m_s\nL1,4\nL3,4\n").misfit(&dir).unwrap();
        assert!(m.rms.is_infinite());
        assert_eq!(m.missing, ["gate L3 not crossed"]);
        let m = gates("t,x\n0.5,1.5\n").misfit(&dir).unwrap();
        assert!((m.rms - 0.5).abs() < 1e-12);
        assert!(
            gates("y,u_s\n0.1,1\n").misfit(&dir).is_err(),
            "no profile file"
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn interpolation_and_missing_points() {
        let sim = [(0.0, 0.0), (1.0, 2.0), (2.0, 2.0)];
        assert_eq!(interpolate(&sim, 0.5, false), Some(1.0));
        assert_eq!(interpolate(&sim, 3.0, false), None);
        assert_eq!(interpolate(&sim, 3.0, true), Some(2.0));
        let m = compare(&[(0.5, 2.0), (1.5, 2.0)], &sim, false, "t");
        assert!((m.rms - (0.5f64).sqrt()).abs() < 1e-12);
        let m = compare(&[(0.5, 2.0), (5.0, 2.0)], &sim, false, "t");
        assert!(m.rms.is_infinite());
        assert_eq!(m.missing.len(), 1);
    }
}
