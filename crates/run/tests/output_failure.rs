//! A run whose output cannot be written (here: a field file's name taken by a folder, as a
//! full disk or a vanished mount would fail a write) stops with status `Failed` and the
//! reason in `summary.json`, and leaves no temporary file behind (issue 21).

use std::path::Path;

use runout_case::{load, Fidelity, Loaded};
use runout_output::{RunStatus, RunSummary};

#[test]
fn a_failed_write_ends_the_run_with_a_summary_and_no_temporary_file() {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/cavity-re100.ron");
    let Loaded::Cases(cases) = load(&file).unwrap() else {
        panic!("a case")
    };
    let case = &cases[0].case;
    let out = std::env::temp_dir().join(format!("runout-output-failure-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    // the smoke run writes fields_00000.vtr at t = 0 and fields_00001.vtr at its end
    let blocker = out.join("fields_00001.vtr");
    let err = runout_run::run_case(case, Fidelity::Smoke, &out, |_| {
        if !blocker.exists() {
            std::fs::create_dir_all(blocker.join("in-the-way")).unwrap();
        }
    })
    .unwrap_err();
    assert!(err.to_string().contains("fields_00001.vtr"), "{err}");
    let summary: RunSummary =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(
        matches!(&summary.status, RunStatus::Failed { reason } if reason.contains("fields_00001.vtr")),
        "{:?}",
        summary.status
    );
    let leftovers: Vec<_> = std::fs::read_dir(&out)
        .unwrap()
        .flatten()
        .filter(|e| e.file_name().to_string_lossy().ends_with(".tmp"))
        .collect();
    assert!(leftovers.is_empty(), "{leftovers:?}");
    std::fs::remove_dir_all(&out).unwrap();
}
