//! One verification study behind one trait: a [`Study`] runs the whole program (cases
//! through the driver into run folders it may reuse) with options, and writes a page of
//! what it found. Unlike a [`crate::Check`] it has no fast size for the test suite; it
//! runs on demand (`cargo xtask verify <name>`) with its options as the command line gave
//! them ([`Args`]), in a [`Context`] that says where the repository's cases, runs and pages
//! are. Each study parses [`Args`] into its own typed options (and ignores the names it
//! does not take), so the caller needs to know nothing of them.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use anyhow::{Context as _, Result};

/// A study's options as the command line gave them, by name without the dashes (`fidelity`,
/// `aspect`, `skip-variants`): a value, a comma-separated list, or `true` for a flag given.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Args(BTreeMap<String, String>);

impl Args {
    /// No options.
    pub fn new() -> Self {
        Self::default()
    }

    /// With option `name` set to `value`, if given.
    pub fn with(mut self, name: &str, value: Option<impl Into<String>>) -> Self {
        if let Some(value) = value {
            self.0.insert(name.to_string(), value.into());
        }
        self
    }

    /// With flag `name`, if `on`.
    pub fn flag(self, name: &str, on: bool) -> Self {
        self.with(name, on.then_some("true"))
    }

    /// The value of option `name`, if given.
    pub fn get(&self, name: &str) -> Option<&str> {
        self.0.get(name).map(String::as_str)
    }

    /// Whether flag `name` was given.
    pub fn is_set(&self, name: &str) -> bool {
        self.get(name) == Some("true")
    }

    /// The comma-separated values of option `name`, each parsed, if given.
    pub fn list<T: FromStr>(&self, name: &str) -> Result<Option<Vec<T>>>
    where
        T::Err: std::error::Error + Send + Sync + 'static,
    {
        self.get(name)
            .map(|list| {
                list.split(',')
                    .map(|v| {
                        v.trim()
                            .parse()
                            .with_context(|| format!("--{name} {list}: `{v}`"))
                    })
                    .collect()
            })
            .transpose()
    }
}

/// Where a study finds its cases and writes its runs and pages.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Context {
    /// the folder that holds `cases/` and `runs/`: the repository root
    pub root: PathBuf,
    /// the folder of the generated pages (`docs/reports/` of the root)
    pub reports: PathBuf,
}

impl Context {
    /// The context of the repository at `root`.
    pub fn at(root: &Path) -> Self {
        Self {
            root: root.to_path_buf(),
            reports: root.join("docs/reports"),
        }
    }
}

/// A verification study: a name, what it studies, and a run with options.
pub trait Study: Send + Sync {
    /// Short name, as given to `cargo xtask verify <name>`.
    fn name(&self) -> &'static str;

    /// One line: what is studied against what.
    fn description(&self) -> &'static str;

    /// Runs the study with `args` in `context`, printing its numbers and writing its page.
    /// An error is an option it refuses, a run that could not finish, or a result that
    /// misses the study's limits (the page is written first).
    fn run(&self, args: &Args, context: &Context) -> Result<()>;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn args_hold_values_lists_and_flags() {
        let args = Args::new()
            .with("fidelity", Some("smoke"))
            .with("aspect", Some("0.5, 1,3"))
            .with("friction", None::<String>)
            .flag("reuse", true)
            .flag("skip-variants", false);
        assert_eq!(args.get("fidelity"), Some("smoke"));
        assert_eq!(args.get("friction"), None);
        assert!(args.is_set("reuse") && !args.is_set("skip-variants"));
        assert_eq!(
            args.list::<f64>("aspect").unwrap(),
            Some(vec![0.5, 1.0, 3.0])
        );
        assert_eq!(args.list::<f64>("sidewalls").unwrap(), None);
        let bad = Args::new().with("threads", Some("1,x"));
        assert!(bad.list::<usize>("threads").is_err());
    }
}
