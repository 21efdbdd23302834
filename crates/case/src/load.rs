//! Reading case, sweep and analytic files, with errors that name the file.

use std::fmt;
use std::path::{Path, PathBuf};
use std::str::FromStr;

use runout_mesh::{Grid, MeshError};

use crate::checker::FieldError;
use crate::name::{allowed_names, is_valid_name};
use crate::read::read_text;
use crate::ron_error;
use crate::schema::{Analytic, Case};
use crate::sweep::{apply_set, expand, Sweep};
use crate::sweep_base::sweep_base;
use crate::validate::{validate_analytic, validate_case};

/// Anything wrong with an input file, always naming the file.
#[derive(Debug, thiserror::Error)]
pub enum CaseError {
    /// The file could not be read.
    #[error("{file}: cannot read: {source}")]
    Io {
        /// the file
        file: PathBuf,
        /// the I/O error
        source: std::io::Error,
    },
    /// The file is larger than [`crate::limits::MAX_FILE_BYTES`].
    #[error(
        "{file}: {} bytes: a case, sweep or analytic file may have at most {} bytes (1 MiB)",
        bytes.map_or(format!("more than {}", crate::limits::MAX_FILE_BYTES), |b| b.to_string()),
        crate::limits::MAX_FILE_BYTES
    )]
    TooLarge {
        /// the file
        file: PathBuf,
        /// its size, when its metadata states one
        bytes: Option<u64>,
    },
    /// The file is not UTF-8 text.
    #[error(
        "{file}:{line}: byte 0x{byte:02x} at offset {offset} is not UTF-8: case files are UTF-8 \
         text"
    )]
    Encoding {
        /// the file
        file: PathBuf,
        /// 1-based line of the byte
        line: usize,
        /// 0-based offset of the byte in the file
        offset: usize,
        /// the byte
        byte: u8,
    },
    /// The file is not valid RON for its kind (syntax, unknown or missing field, bad variant).
    #[error("{file}:{line}:{col}: {message}")]
    Parse {
        /// the file
        file: PathBuf,
        /// 1-based line
        line: usize,
        /// 1-based column
        col: usize,
        /// what the parser said
        message: String,
    },
    /// The file does not start with `Case(`, `Sweep(` or `Analytic(`.
    #[error(
        "{file}: unknown file kind `{found}`: expected Case(...), Sweep(...) or Analytic(...)"
    )]
    Kind {
        /// the file
        file: PathBuf,
        /// the leading word found
        found: String,
    },
    /// Fields out of range.
    #[error("{}", format_invalid(file, case, errors))]
    Invalid {
        /// the file the values came from (for an expanded sweep: the sweep file)
        file: PathBuf,
        /// the (expanded) case name
        case: String,
        /// every field error found
        errors: Vec<FieldError>,
    },
    /// A sweep that cannot be expanded.
    #[error("{file}: {field}: {message}")]
    Sweep {
        /// the sweep file
        file: PathBuf,
        /// the sweep field
        field: String,
        /// what is wrong
        message: String,
    },
}

fn format_invalid(file: &Path, case: &str, errors: &[FieldError]) -> String {
    let mut s = format!(
        "{}: case `{case}`: {} invalid field{}",
        file.display(),
        errors.len(),
        if errors.len() == 1 { "" } else { "s" }
    );
    for e in errors {
        s.push_str(&format!("\n  {}: {e}", file.display()));
    }
    s
}

/// Simulation fidelity: same physics, different grid and end time (cases.md presets).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Fidelity {
    /// seconds: a coarse grid and a short time, for CI
    Smoke,
    /// minutes: the README's default sweep
    Coarse,
    /// the wall layer resolved: the paper's cells in y, x coarsened (preset `wall`)
    Wall,
    /// the paper's grids and times
    Paper,
}

impl Fidelity {
    /// Lower-case name.
    pub fn name(self) -> &'static str {
        match self {
            Fidelity::Smoke => "smoke",
            Fidelity::Coarse => "coarse",
            Fidelity::Wall => "wall",
            Fidelity::Paper => "paper",
        }
    }
}

impl fmt::Display for Fidelity {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Fidelity {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "smoke" => Ok(Fidelity::Smoke),
            "coarse" => Ok(Fidelity::Coarse),
            "wall" => Ok(Fidelity::Wall),
            "paper" => Ok(Fidelity::Paper),
            _ => Err(format!(
                "unknown fidelity `{s}`: expected smoke, coarse, wall or paper"
            )),
        }
    }
}

impl Case {
    /// This case at a fidelity, resolved for a run: the grid coarsened (per axis where the
    /// preset says) and the end time set by the preset (`Paper` keeps the case's grid and
    /// end time), and times counted from the start ([`Case::with_start_clock`]). Monitor
    /// times after the end are kept; they simply never fire.
    pub fn at_fidelity(&self, fidelity: Fidelity) -> Case {
        let preset = match fidelity {
            Fidelity::Paper => return self.clone().with_start_clock(),
            Fidelity::Smoke => self.fidelity.smoke.clone(),
            Fidelity::Coarse => self.fidelity.coarse.clone(),
            Fidelity::Wall => self.fidelity.wall_preset(),
        };
        let mut case = self.clone();
        case.domain.x = self.domain.x.coarsened(preset.coarsen);
        case.domain.y = self.domain.y.coarsened(preset.factor_y());
        case.run.end_time = preset.end_time;
        case.with_start_clock()
    }

    /// The case's grid.
    pub fn grid(&self) -> Result<Grid, MeshError> {
        Grid::from_specs(&self.domain.x, &self.domain.y)
    }
}

/// A validated case and the file(s) it came from.
#[derive(Clone, Debug)]
pub struct SourcedCase {
    /// the case (for a sweep: expanded and renamed)
    pub case: Case,
    /// the file named on the command line
    pub file: PathBuf,
    /// the base case file of a sweep
    pub base: Option<PathBuf>,
    /// the study of its sweep file (`None`: the paper's matrix)
    pub study: Option<String>,
}

/// What a file holds.
#[derive(Clone, Debug)]
pub enum Loaded {
    /// one case, or the cases a sweep expands to
    Cases(Vec<SourcedCase>),
    /// a family-A description
    Analytic(Analytic),
}

/// RON options: `Some(...)` may be omitted around optional values.
fn ron_options() -> ron::Options {
    ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
}

fn parse<T: serde::de::DeserializeOwned>(file: &Path, text: &str) -> Result<T, CaseError> {
    ron_options().from_str(text).map_err(|e| CaseError::Parse {
        file: file.to_path_buf(),
        line: e.span.start.line,
        col: e.span.start.col,
        message: ron_error::message(text, &e),
    })
}

/// The first identifier of a RON text, skipping whitespace, comments and `#![...]`.
fn leading_word(text: &str) -> String {
    let mut rest = text;
    loop {
        rest = rest.trim_start();
        if let Some(r) = rest.strip_prefix("//") {
            rest = r.split_once('\n').map_or("", |(_, tail)| tail);
        } else if let Some(r) = rest.strip_prefix("/*") {
            rest = r.split_once("*/").map_or("", |(_, tail)| tail);
        } else if let Some(r) = rest.strip_prefix("#!") {
            rest = r.split_once(']').map_or("", |(_, tail)| tail);
        } else {
            break;
        }
    }
    rest.chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// Reads and validates a `Case(...)` file.
pub fn load_case(file: &Path) -> Result<Case, CaseError> {
    case_from_text(file, &read_text(file)?)
}

/// Parses and validates the text of a `Case(...)` file.
fn case_from_text(file: &Path, text: &str) -> Result<Case, CaseError> {
    let case: Case = parse(file, text)?;
    validate_case(&case).map_err(|errors| CaseError::Invalid {
        file: file.to_path_buf(),
        case: case.name.clone(),
        errors,
    })?;
    Ok(case)
}

/// Every `.ron` file named in `paths` or found below a named directory, each directory's
/// entries in sorted order. A directory that cannot be read is returned as a path, so that
/// [`load`] reports it.
pub fn case_files(paths: &[PathBuf]) -> Vec<PathBuf> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            out.push(dir.to_path_buf());
            return;
        };
        let mut entries: Vec<PathBuf> = entries.filter_map(|e| e.ok().map(|e| e.path())).collect();
        entries.sort();
        for p in entries {
            if p.is_dir() {
                walk(&p, out);
            } else if p.extension().is_some_and(|e| e == "ron") {
                out.push(p);
            }
        }
    }
    let mut out = Vec::new();
    for p in paths {
        if p.is_dir() {
            walk(p, &mut out);
        } else {
            out.push(p.clone());
        }
    }
    out
}

/// Reads any case-directory file, expands sweeps and validates everything.
pub fn load(file: &Path) -> Result<Loaded, CaseError> {
    let text = read_text(file)?;
    match leading_word(&text).as_str() {
        "Case" => Ok(Loaded::Cases(vec![SourcedCase {
            case: case_from_text(file, &text)?,
            file: file.to_path_buf(),
            base: None,
            study: None,
        }])),
        "Sweep" => {
            let sweep: Sweep = parse(file, &text)?;
            let sweep_error = |(field, message)| CaseError::Sweep {
                file: file.to_path_buf(),
                field,
                message,
            };
            if let Some(study) = sweep.study.as_deref().filter(|s| !is_valid_name(s)) {
                return Err(sweep_error((
                    "study".into(),
                    format!("`{study}`: {}", allowed_names()),
                )));
            }
            let base_path = sweep_base(file, &sweep.base).map_err(sweep_error)?;
            let base = load_case(&base_path)?;
            // `set` values are validated even where `vary` overrides them
            let fixed = apply_set(&sweep, &base).map_err(sweep_error)?;
            validate_case(&fixed).map_err(|errors| CaseError::Invalid {
                file: file.to_path_buf(),
                case: format!("{} (the base with `set` applied)", sweep.name),
                errors,
            })?;
            let cases = expand(&sweep, &base).map_err(sweep_error)?;
            cases
                .into_iter()
                .map(|case| {
                    validate_case(&case).map_err(|errors| CaseError::Invalid {
                        file: file.to_path_buf(),
                        case: case.name.clone(),
                        errors,
                    })?;
                    Ok(SourcedCase {
                        case,
                        file: file.to_path_buf(),
                        base: Some(base_path.clone()),
                        study: sweep.study.clone(),
                    })
                })
                .collect::<Result<Vec<_>, _>>()
                .map(Loaded::Cases)
        }
        "Analytic" => {
            let a: Analytic = parse(file, &text)?;
            validate_analytic(&a).map_err(|errors| CaseError::Invalid {
                file: file.to_path_buf(),
                case: a.name.clone(),
                errors,
            })?;
            Ok(Loaded::Analytic(a))
        }
        other => Err(CaseError::Kind {
            file: file.to_path_buf(),
            found: other.to_string(),
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::leading_word;

    #[test]
    fn leading_word_skips_comments_and_attributes() {
        assert_eq!(
            leading_word("// a\n/* b */ #![enable(implicit_some)]\n Sweep(x)"),
            "Sweep"
        );
        assert_eq!(leading_word("Case("), "Case");
        assert_eq!(leading_word("  ( a: 1 )"), "");
    }
}
