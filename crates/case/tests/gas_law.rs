//! An ideal gas the case cannot hold is refused before any step, naming the field (issue 60
//! item 1; docs/model.md §1.4): a molar mass or temperature outside its band or not a number,
//! a `gas.density` more than 1 % from the law's at the reference pressure, an ideal gas in a
//! case without solids (the single-phase solver's gas has a constant density).

use std::path::Path;

use runout_case::{load_case, Case, GasLaw};

fn ideal_box() -> Case {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    load_case(&root.join("cases/gas/ideal-gas-box.ron")).unwrap()
}

fn refused(case: &Case) -> Vec<String> {
    runout_case::validate_case(case)
        .err()
        .unwrap_or_default()
        .into_iter()
        .map(|e| e.field)
        .collect()
}

fn with_law(molar_mass: f64, temperature: f64) -> Vec<String> {
    let mut case = ideal_box();
    case.gas.as_mut().unwrap().law = GasLaw::IdealGas {
        molar_mass,
        temperature,
    };
    refused(&case)
}

#[test]
fn bad_ideal_gases_name_their_field() {
    assert!(refused(&ideal_box()).is_empty());
    // air at 294.15 K is 1.2000 kg/m³ at 101 325 Pa: 0.34 % from the box's 1.2041, accepted
    assert!(with_law(0.028965, 294.15).is_empty());
    // at 350 K it is 1.0085: 19 % off
    assert_eq!(with_law(0.028965, 350.0), ["gas.density"]);
    assert_eq!(
        with_law(1e-4, 293.15),
        ["gas.law.IdealGas.molar_mass", "gas.density"]
    );
    assert_eq!(
        with_law(0.028965, f64::NAN),
        ["gas.law.IdealGas.temperature"]
    );
    assert_eq!(
        with_law(0.028965, 1e5),
        ["gas.law.IdealGas.temperature", "gas.density"]
    );
    let mut gas_only = ideal_box();
    gas_only.solids.clear();
    gas_only.initial.regions.clear();
    assert!(
        refused(&gas_only).contains(&"gas.law".to_string()),
        "{:?}",
        refused(&gas_only)
    );
}

#[test]
fn a_constant_density_is_not_written_and_an_ideal_gas_is_read_back() {
    let case = ideal_box();
    let text = ron::ser::to_string(&case).unwrap();
    assert!(text.contains("law:IdealGas"), "{text}");
    let back: Case = ron::from_str(&text).unwrap();
    assert_eq!(back, case);
    let mut constant = case.clone();
    constant.gas.as_mut().unwrap().law = GasLaw::Constant;
    assert!(!ron::ser::to_string(&constant).unwrap().contains("law"));
}
