//! One-factor families of sweeps (issue 23, item 3): the runs of one sweep that differ in
//! one numeric parameter only, found from the sweep files of a case matrix; their
//! elasticities are [`crate::sensitivity`]'s.

use std::fmt::Write as _;
use std::path::Path;

use anyhow::{Context, Result};
use runout_case::{Param, Sweep};

use crate::sweep::Matrix;

/// A parameter a family varies: its symbol and unit.
pub fn symbol(p: &Param) -> (&'static str, &'static str) {
    match p {
        Param::Diameter(_) => ("d", "m"),
        Param::Specularity(_) => ("φ", "-"),
        Param::PartialSlipHu(_) => ("h_w^u", "1/m"),
        Param::PartialSlipHTheta(_) => ("h_w^θ", "1/m"),
        Param::PartialSlipC(_) => ("c_w", "m/s²"),
        Param::Slope(_) => ("slope", "deg"),
        Param::SolidsWalls(_) => ("wall", ""),
        Param::Release(_) => ("release", ""),
        Param::Clock(_) => ("clock", ""),
        Param::Aeration(_) => ("aeration", "-"),
    }
}

/// The values of a numeric parameter (`None` for the wall condition and the release).
pub fn values(p: &Param) -> Option<&[f64]> {
    match p {
        Param::Diameter(v)
        | Param::Specularity(v)
        | Param::PartialSlipHu(v)
        | Param::PartialSlipHTheta(v)
        | Param::PartialSlipC(v)
        | Param::Slope(v)
        | Param::Aeration(v) => Some(v),
        Param::SolidsWalls(_) | Param::Release(_) | Param::Clock(_) => None,
    }
}

/// A one-factor family: the runs of one sweep that differ in one parameter only.
#[derive(Clone, Debug, PartialEq)]
pub struct Family {
    /// the sweep's name
    pub sweep: String,
    /// the parameter's symbol
    pub symbol: &'static str,
    /// its unit
    pub unit: &'static str,
    /// the sweep's other varied parameters at this family's values, e.g. "slope = 40"
    pub fixed: Vec<String>,
    /// (parameter value, case name), in the sweep's order
    pub points: Vec<(f64, String)>,
}

impl Family {
    /// "S-PS-cw: c_w (slope = 40)".
    pub fn label(&self) -> String {
        let fixed = if self.fixed.is_empty() {
            String::new()
        } else {
            format!(" ({})", self.fixed.join(", "))
        };
        format!("{}: {}{fixed}", self.sweep, self.symbol)
    }
}

/// The one-factor families of a sweep: for each numeric varied parameter with two values or
/// more, one family per combination of the other varied parameters' values. Case names are
/// built as [`runout_case::expand`] builds them.
pub fn sweep_families(sweep: &Sweep) -> Vec<Family> {
    let vary = &sweep.vary;
    let name = |index: &[usize]| {
        let mut n = sweep.name.clone();
        for (p, &i) in vary.iter().zip(index) {
            let _ = write!(n, "_{}={}", p.key(), p.label(i));
        }
        n
    };
    let mut out = Vec::new();
    for (k, param) in vary.iter().enumerate() {
        let Some(v) = values(param).filter(|v| v.len() >= 2) else {
            continue;
        };
        let others: Vec<usize> = (0..vary.len()).filter(|&j| j != k).collect();
        let mut index = vec![0usize; vary.len()];
        'combinations: loop {
            let points = (0..v.len())
                .map(|i| {
                    index[k] = i;
                    (v[i], name(&index))
                })
                .collect();
            let (sym, unit) = symbol(param);
            out.push(Family {
                sweep: sweep.name.clone(),
                symbol: sym,
                unit,
                fixed: others
                    .iter()
                    .map(|&j| format!("{} = {}", symbol(&vary[j]).0, vary[j].label(index[j])))
                    .collect(),
                points,
            });
            // next combination of the others, the last fastest
            let mut d = others.len();
            loop {
                if d == 0 {
                    break 'combinations;
                }
                d -= 1;
                let j = others[d];
                index[j] += 1;
                if index[j] < vary[j].len() {
                    break;
                }
                index[j] = 0;
            }
        }
    }
    out
}

/// The one-factor families of the sweeps in the matrix whose file lies below `dir` (a
/// folder, or a sweep file itself), in the matrix's order.
pub fn families(matrix: &Matrix, dir: &Path) -> Result<Vec<Family>> {
    let mut files = Vec::new();
    for r in &matrix.runs {
        if r.base.is_some() && r.file.starts_with(dir) && !files.contains(&r.file) {
            files.push(r.file.clone());
        }
    }
    let mut out = Vec::new();
    for f in files {
        let text =
            std::fs::read_to_string(&f).with_context(|| format!("reading {}", f.display()))?;
        let sweep: Sweep = ron::Options::default()
            .with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
            .from_str(&text)
            .with_context(|| format!("reading the sweep of {}", f.display()))?;
        out.extend(sweep_families(&sweep));
    }
    Ok(out)
}
