//! runout-case: the RON case schema, its validation, sweep expansion and fidelity presets.
//!
//! Three kinds of file live under `cases/`:
//! - `Case(...)`: one simulation ([`Case`]);
//! - `Sweep(...)`: a base case plus parameter lists, expanded into named cases ([`Sweep`]);
//! - `Analytic(...)`: the closed-form profiles of family A ([`Analytic`]).
//!
//! [`load`] reads any of them, validates every field before anything runs, and reports
//! errors that name the file, the field path and the allowed range.
#![deny(missing_docs)]

mod bed;
mod checker;
mod clock;
mod gas_inlet;
pub mod limits;
mod load;
mod name;
mod read;
pub mod reference;
pub mod release;
mod ron_error;
mod run_control;
mod schema;
mod sidewalls;
mod size;
mod sweep;
mod sweep_base;
mod validate;
mod validate_grid;

pub use checker::FieldError;
pub use load::{case_files, load, load_case, CaseError, Fidelity, Loaded, SourcedCase};
pub use name::{is_valid_name, run_dir};
pub use run_control::*;
pub use schema::*;
pub use size::{
    available_memory_bytes, case_size, estimated_memory_bytes, format_bytes, CaseSize,
    AVAILABLE_MEMORY_VAR,
};
pub use sweep::{apply_set, expand, Param, ReleaseBlock, Sweep};
pub use validate::{validate_analytic, validate_case};
