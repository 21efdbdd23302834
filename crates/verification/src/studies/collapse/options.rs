//! The options of the collapse check, typed from the command line's strings
//! ([`crate::study::Args`]): `--fidelity`, `--reuse`, `--friction`, `--aspect`,
//! `--sidewalls`.

use anyhow::{bail, Result};
use runout_case::Fidelity;

use super::column::ChannelWalls;
use crate::study::Args;

/// The friction law of a collapse check.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Friction {
    /// the paper's material and Princeton friction (the four shipped C-a* cases), untuned:
    /// the check fails only on a failed run or lost mass
    Princeton,
    /// glass beads with μ(I) (cases/collapse/CM-a1.ron as template): the runout and H∞
    /// within 25 % of Lajeunesse et al.'s and the deposit at rest by 10 √(H0/g)
    MuI,
    /// the μ(I) columns and beside each the same glass-bead column with Princeton friction
    /// (`column::with_princeton`); the thresholds judge the μ(I) columns only
    Both,
}

impl Friction {
    /// `princeton`, `mu-i` or `both`.
    pub fn parse(s: &str) -> Result<Self> {
        match s {
            "princeton" => Ok(Self::Princeton),
            "mu-i" => Ok(Self::MuI),
            "both" => Ok(Self::Both),
            _ => bail!("--friction {s}: expected princeton, mu-i or both"),
        }
    }
}

/// What the collapse check runs and how.
#[derive(Clone, Debug, PartialEq)]
pub struct Options {
    /// `--fidelity`: smoke or coarse (default coarse); μ(I) and both also paper (L0/20)
    pub fidelity: Fidelity,
    /// `--reuse`: take finished runs of unchanged cases instead of rerunning them
    pub reuse: bool,
    /// `--friction`: princeton (default), mu-i or both
    pub friction: Friction,
    /// `--aspect`: the a of the columns built from the friction's template (default: the
    /// four shipped Princeton cases, or μ(I) columns of a = 0.5, 1, 3, 6)
    pub aspects: Option<Vec<f64>>,
    /// `--sidewalls W_L0,MU_W`: every column in a channel with side walls
    pub walls: Option<ChannelWalls>,
}

impl Options {
    /// The options of `args`, with their defaults.
    pub fn parse(args: &Args) -> Result<Self> {
        let fidelity = args
            .get("fidelity")
            .unwrap_or("coarse")
            .parse()
            .map_err(anyhow::Error::msg)?;
        let friction = Friction::parse(args.get("friction").unwrap_or("princeton"))?;
        let aspects = args.list("aspect")?;
        let walls = args
            .list::<f64>("sidewalls")?
            .as_deref()
            .map(ChannelWalls::parse)
            .transpose()?;
        Ok(Self {
            fidelity,
            reuse: args.is_set("reuse"),
            friction,
            aspects,
            walls,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn options_from_the_command_line_with_defaults() {
        let o = Options::parse(&Args::new()).unwrap();
        assert_eq!(
            o,
            Options {
                fidelity: Fidelity::Coarse,
                reuse: false,
                friction: Friction::Princeton,
                aspects: None,
                walls: None,
            }
        );
        let args = Args::new()
            .with("fidelity", Some("smoke"))
            .with("friction", Some("both"))
            .with("aspect", Some("1,3"))
            .with("sidewalls", Some("5,0.38"))
            .flag("reuse", true);
        let o = Options::parse(&args).unwrap();
        assert_eq!(o.fidelity, Fidelity::Smoke);
        assert_eq!(o.friction, Friction::Both);
        assert_eq!(o.aspects, Some(vec![1.0, 3.0]));
        assert_eq!(o.walls, Some(ChannelWalls::parse(&[5.0, 0.38]).unwrap()));
        assert!(o.reuse);
        for (name, bad) in [
            ("fidelity", "fine"),
            ("friction", "coulomb"),
            ("aspect", "1,x"),
            ("sidewalls", "5"),
        ] {
            assert!(Options::parse(&Args::new().with(name, Some(bad))).is_err());
        }
    }
}
