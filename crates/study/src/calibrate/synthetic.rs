//! Synthetic measurements from a run (issue 48): the run's interpolated front at given
//! times, its gate speeds, or a column of one of its station profiles where the flow is
//! (εs at least a stated value), as a measurements file with a stated σ, optionally with
//! Gaussian noise of that σ added (a seeded generator, so a file is reproducible). A
//! calibration against them has a known truth: the run's own parameters.

use std::path::Path;

use anyhow::{bail, Context, Result};

use super::measurements::PROFILE_COLUMNS;
use runout_mesh::{interpolate, Beyond};
use runout_post::front::{front_series, FrontDefinition};
use runout_post::gates::interpolated_gate_speeds;
use runout_post::table::Table;

/// What to take from the run.
#[derive(Clone, Debug, PartialEq)]
pub enum Measured {
    /// the interpolated front x at these times [s]
    Front(Vec<f64>),
    /// the front speed at each gate the run crossed
    GateSpeeds,
    /// one column of a profile file of the run (`profile_x<x>_t<t>.csv`) against y, at the
    /// rows whose εs is at least `min_eps_s` (the flow, not the empty cells above it)
    Profile {
        /// the profile file's name
        file: String,
        /// the column (one of [`super::measurements::PROFILE_COLUMNS`])
        column: String,
        /// the least εs of a measured row
        min_eps_s: f64,
    },
}

/// Normal deviates from a seed: SplitMix64 (Steele, Lea & Flood 2014) for uniforms, the
/// Box–Muller transform for the normals.
pub struct Normal(u64);

impl Normal {
    /// The generator of `seed`.
    pub fn new(seed: u64) -> Normal {
        Normal(seed)
    }

    fn uniform(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^= z >> 31;
        // in (0, 1]: 53 random bits
        ((z >> 11) + 1) as f64 / (1u64 << 53) as f64
    }

    /// The next standard normal deviate.
    pub fn sample(&mut self) -> f64 {
        let (u1, u2) = (self.uniform(), self.uniform());
        (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
    }
}

/// The measurements file of the run in `dir`: `what` with σ = `sigma` on every point
/// (a `# sigma:` line), plus noise N(0, σ²) if `noise_seed` is given.
pub fn measurements_from_run(
    dir: &Path,
    what: &Measured,
    sigma: f64,
    noise_seed: Option<u64>,
) -> Result<String> {
    if !(sigma > 0.0 && sigma.is_finite()) {
        bail!("σ = {sigma}: a finite number > 0");
    }
    let mut noise = noise_seed.map(Normal::new);
    let mut add = |v: f64| noise.as_mut().map_or(v, |n| v + sigma * n.sample());
    let mut text = format!(
        "# synthetic measurements from {} ({}), σ = {sigma}{}\n# sigma: {sigma}\n",
        dir.display(),
        match what {
            Measured::Front(_) => "its interpolated front".to_string(),
            Measured::GateSpeeds => "its gate speeds".to_string(),
            Measured::Profile {
                file,
                column,
                min_eps_s,
            } => format!("{column} of {file} where εs ≥ {min_eps_s}"),
        },
        noise_seed.map_or(", no noise".to_string(), |s| format!(
            ", Gaussian noise of σ added (seed {s})"
        ))
    );
    match what {
        Measured::Front(times) => {
            let (definition, series) = front_series(dir).map_err(anyhow::Error::msg)?;
            if definition != FrontDefinition::Interpolated {
                bail!(
                    "{}: the run has only the whole-cell front: run it again for \
                     bulk.csv's front_x_interpolated",
                    dir.display()
                );
            }
            text.push_str("t,x\n");
            let (ts, xs): (Vec<f64>, Vec<f64>) = series.iter().copied().unzip();
            for &t in times {
                let x = interpolate(&ts, &xs, t, Beyond::Missing)
                    .with_context(|| format!("{}: no front at t = {t}", dir.display()))?;
                text.push_str(&format!("{t},{:.6}\n", add(x)));
            }
        }
        Measured::GateSpeeds => {
            let speeds = interpolated_gate_speeds(dir).map_err(anyhow::Error::msg)?;
            if speeds.is_empty() {
                bail!("{}: the front crossed no gate", dir.display());
            }
            text.push_str("gate,speed_m_s\n");
            for (g, v) in speeds {
                text.push_str(&format!("L{g},{:.6}\n", add(v)));
            }
        }
        Measured::Profile {
            file,
            column,
            min_eps_s,
        } => {
            text.push_str(&format!("# profile: {file}\ny,{column}\n"));
            for (y, v) in profile_rows(&dir.join(file), column, *min_eps_s)? {
                text.push_str(&format!("{y},{:.8}\n", add(v)));
            }
        }
    }
    Ok(text)
}

/// (y, `column`) of the profile file at the rows with εs ≥ `min_eps_s`; an error if there
/// is none.
fn profile_rows(file: &Path, column: &str, min_eps_s: f64) -> Result<Vec<(f64, f64)>> {
    if !PROFILE_COLUMNS.contains(&column) {
        bail!("`{column}`: a profile column is one of {PROFILE_COLUMNS:?}");
    }
    let table = Table::read(file).map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))?;
    let get = |name: &str| {
        table
            .column(name)
            .map_err(|e| anyhow::anyhow!("{}: {e}", file.display()))
    };
    let (y, eps_s, values) = (get("y")?, get("eps_s")?, get(column)?);
    let rows: Vec<(f64, f64)> = (0..y.len())
        .filter(|&k| eps_s[k] >= min_eps_s)
        .map(|k| (y[k], values[k]))
        .collect();
    if rows.is_empty() {
        bail!("{}: no row with εs ≥ {min_eps_s}", file.display());
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_deviates_have_unit_variance() {
        let mut n = Normal::new(7);
        let v: Vec<f64> = (0..20000).map(|_| n.sample()).collect();
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        let var = v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / v.len() as f64;
        assert!(
            mean.abs() < 0.03 && (var - 1.0).abs() < 0.03,
            "{mean} {var}"
        );
    }

    #[test]
    fn a_run_folder_gives_fronts_and_gate_speeds() {
        let dir = std::env::temp_dir().join(format!("runout-synthetic-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("front.csv"), "t,front_x\n0,0.5\n1,2.5\n").unwrap();
        std::fs::write(
            dir.join("gates.csv"),
            "gate,x,t_cross,speed\n2,2.1,0.6,3.5\n",
        )
        .unwrap();
        let text = measurements_from_run(&dir, &Measured::Front(vec![0.5]), 0.01, None).unwrap();
        assert!(
            text.ends_with("# sigma: 0.01\nt,x\n0.5,1.500000\n"),
            "{text}"
        );
        let text = measurements_from_run(&dir, &Measured::GateSpeeds, 0.1, Some(1)).unwrap();
        let (kind, sigma) = super::super::measurements::parse(&text).unwrap();
        assert_eq!(sigma.unwrap().0, [0.1]);
        let super::super::measurements::Kind::GateSpeeds(v) = kind else {
            panic!("gate speeds")
        };
        assert!(
            v[0].0 == 2 && (v[0].1 - 2.0).abs() < 0.5 && v[0].1 != 2.0,
            "{v:?}"
        );
        assert!(measurements_from_run(&dir, &Measured::Front(vec![2.0]), 0.01, None).is_err());
        std::fs::write(
            dir.join("profile_x1_t0.5.csv"),
            "y,eps_s,u_s,theta\n0.01,0.5,1.5,1e-3\n0.03,0.2,2,1e-3\n0.05,0,0.7,1e-5\n",
        )
        .unwrap();
        let profile = Measured::Profile {
            file: "profile_x1_t0.5.csv".into(),
            column: "u_s".into(),
            min_eps_s: 0.01,
        };
        let text = measurements_from_run(&dir, &profile, 0.05, None).unwrap();
        let (kind, _) = super::super::measurements::parse(&text).unwrap();
        assert_eq!(
            kind,
            super::super::measurements::Kind::Profile {
                column: "u_s".into(),
                file: Some("profile_x1_t0.5.csv".into()),
                points: vec![(0.01, 1.5), (0.03, 2.0)],
            }
        );
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
