//! No case name can make a run write outside `runs/` (issue 21): `run_dir` accepts exactly
//! the valid names, and every folder it returns lies two plain components below
//! `root/runs`.

use std::path::{Component, Path};

use proptest::prelude::*;
use runout_case::{is_valid_name, run_dir, Fidelity};

fn assert_below_runs(root: &Path, name: &str) -> Result<(), TestCaseError> {
    let runs = root.join("runs");
    match run_dir(root, name, Fidelity::Coarse) {
        Ok(dir) => {
            prop_assert!(is_valid_name(name), "{name:?} accepted");
            let rest = dir.strip_prefix(&runs).expect("below root/runs");
            let parts: Vec<Component> = rest.components().collect();
            prop_assert_eq!(parts.len(), 2, "{:?}", dir);
            prop_assert!(parts.iter().all(|c| matches!(c, Component::Normal(_))));
            prop_assert_eq!(parts[0].as_os_str(), name);
            prop_assert_eq!(parts[1].as_os_str(), "coarse");
        }
        Err(e) => {
            prop_assert!(!is_valid_name(name), "{name:?} refused: {e}");
            prop_assert!(e.to_string().contains("name"));
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    /// Any string at all: unicode, separators, NUL, dots.
    #[test]
    fn arbitrary_strings_never_leave_runs(name in any::<String>()) {
        assert_below_runs(Path::new("/tmp/project"), &name)?;
    }

    /// Strings built from the characters that matter, so that valid names, dots and
    /// separators all occur often.
    #[test]
    fn dotted_and_separated_names_never_leave_runs(
        name in "[a./\\\\=_\\-\u{0}\n ]{0,8}",
        root in prop::sample::select(vec!["/tmp/p", ".", "", "rel/dir"]),
    ) {
        assert_below_runs(Path::new(root), &name)?;
    }
}

#[test]
fn the_dangerous_names_are_refused_and_plain_ones_accepted() {
    let root = Path::new("/srv/project");
    for bad in [
        ".", "..", "../x", "a/..", "/etc", ".hidden", "", "a\0b", "a\tb",
    ] {
        assert!(run_dir(root, bad, Fidelity::Paper).is_err(), "{bad:?}");
    }
    let long = "x".repeat(101);
    assert!(run_dir(root, &long, Fidelity::Paper).is_err());
    assert_eq!(
        run_dir(root, "S-JJ-phi_phi=0.01", Fidelity::Smoke).unwrap(),
        root.join("runs/S-JJ-phi_phi=0.01/smoke")
    );
    assert!(run_dir(root, "a..b", Fidelity::Paper).is_ok());
}
