//! The ladder of grids: the levels (`tiny` to `finer`) and what each does to a case, the
//! convection schemes by name, and a case stopped early (`--end-time`).

use std::str::FromStr;

use runout_case::{Case, Convection};

/// Refinement factor of the `finer` level over the paper grid, coarsening of `half` from it
/// (and extra coarsening of `tiny` over the smoke grid).
const LEVEL_STEP: u32 = 2;

/// A grid of the ladder, coarsest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Level {
    /// the smoke grid coarsened 2× more: a pipeline check only
    Tiny,
    /// the smoke preset's grid
    Smoke,
    /// the coarse preset's grid
    Coarse,
    /// the paper grid coarsened 2×: with `coarse`, `paper` and `finer` a ladder refined 2×
    /// at every step (family S: 250 × 23, 500 × 45, 1000 × 90, 2000 × 180)
    Half,
    /// the case's own (the paper's) grid
    Paper,
    /// the paper grid refined 2×
    Finer,
}

impl Level {
    /// Every level, coarsest first.
    pub const ALL: [Level; 6] = [
        Level::Tiny,
        Level::Smoke,
        Level::Coarse,
        Level::Half,
        Level::Paper,
        Level::Finer,
    ];

    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Level::Tiny => "tiny",
            Level::Smoke => "smoke",
            Level::Coarse => "coarse",
            Level::Half => "half",
            Level::Paper => "paper",
            Level::Finer => "finer",
        }
    }

    /// `case` on this level's grid, to the case's own end time.
    pub fn case(self, case: &Case) -> Case {
        let mut c = case.clone();
        let coarsen = |factor: u32, c: &mut Case| {
            c.domain.x = case.domain.x.coarsened(factor);
            c.domain.y = case.domain.y.coarsened(factor);
        };
        match self {
            Level::Tiny => coarsen(LEVEL_STEP * case.fidelity.smoke.coarsen, &mut c),
            Level::Smoke => coarsen(case.fidelity.smoke.coarsen, &mut c),
            Level::Coarse => coarsen(case.fidelity.coarse.coarsen, &mut c),
            Level::Half => coarsen(LEVEL_STEP, &mut c),
            Level::Paper => {}
            Level::Finer => {
                c.domain.x = case.domain.x.refined(LEVEL_STEP);
                c.domain.y = case.domain.y.refined(LEVEL_STEP);
            }
        }
        c
    }
}

impl std::fmt::Display for Level {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Level {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        Level::ALL
            .into_iter()
            .find(|l| l.name() == s.trim())
            .ok_or_else(|| {
                format!("unknown level `{s}`: expected tiny, smoke, coarse, half, paper or finer")
            })
    }
}

/// Lower-case name of a convection scheme.
pub fn scheme_name(scheme: &Convection) -> &'static str {
    match scheme {
        Convection::Upwind => "upwind",
        Convection::Superbee => "superbee",
    }
}

/// A convection scheme from its name.
pub fn parse_scheme(s: &str) -> Result<Convection, String> {
    match s.trim() {
        "upwind" => Ok(Convection::Upwind),
        "superbee" => Ok(Convection::Superbee),
        other => Err(format!(
            "unknown scheme `{other}`: expected upwind or superbee"
        )),
    }
}

/// `case` stopped at `t`: end time `t`, every profile monitor at `t` only, and the fidelity
/// presets ending no later.
pub fn ending_at(case: &Case, t: f64) -> Case {
    let mut c = case.clone();
    c.run.end_time = t;
    for p in &mut c.monitors.profiles {
        p.times = vec![t];
    }
    for preset in [&mut c.fidelity.smoke, &mut c.fidelity.coarse] {
        preset.end_time = preset.end_time.min(t);
    }
    c
}

#[cfg(test)]
mod tests {
    use std::path::Path;

    use runout_case::{validate_case, Fidelity};

    use super::*;
    use runout_study::sweep::matrix;

    #[test]
    fn levels_use_the_presets_and_the_refined_paper_grid() {
        let cases = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../cases");
        let runs = matrix(&cases).unwrap().runs;
        let case = &runs
            .iter()
            .find(|r| r.case.name == "S-JJ-phi_phi=0.1")
            .unwrap()
            .case;
        let cells = |l: Level| {
            let g = l.case(case).grid().unwrap();
            (g.nx(), g.ny())
        };
        assert_eq!(cells(Level::Paper), (1000, 90));
        assert_eq!(cells(Level::Half), (500, 45));
        assert_eq!(cells(Level::Finer), (2000, 180));
        assert_eq!(
            cells(Level::Coarse),
            case.at_fidelity(Fidelity::Coarse)
                .grid()
                .map(|g| (g.nx(), g.ny()))
                .unwrap()
        );
        assert_eq!(cells(Level::Smoke), (100, 9));
        assert_eq!(cells(Level::Tiny).0, 50);
        // every level runs to the case's own end time
        assert!(Level::ALL
            .iter()
            .all(|l| l.case(case).run.end_time == case.run.end_time));
        assert_eq!("finer".parse::<Level>(), Ok(Level::Finer));
        assert!("fine".parse::<Level>().is_err());
        assert_eq!(parse_scheme("superbee"), Ok(Convection::Superbee));
        // --end-time: the run and the profile stop there, and the case stays valid
        let early = ending_at(case, 0.3);
        assert_eq!(early.run.end_time, 0.3);
        assert_eq!(early.monitors.profiles[0].times, vec![0.3]);
        assert!(validate_case(&Level::Smoke.case(&early)).is_ok());
    }
}
