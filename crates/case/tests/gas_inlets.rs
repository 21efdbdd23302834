//! Gas inlets the case cannot hold are refused before any step, naming the field (issue 60
//! item 2): an inlet on an outlet, outside its side, reversed, with a negative or NaN rate,
//! closing before it opens, overlapping another on the same side while both are open, or in
//! a case without solids.

use std::path::Path;

use runout_case::{load_case, Case, GasInlet, InletRate};
use runout_mesh::Side;

fn bed() -> Case {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    load_case(&root.join("cases/gas/fluidised-bed.ron")).unwrap()
}

fn refused(case: &Case) -> Vec<String> {
    runout_case::validate_case(case)
        .err()
        .unwrap_or_default()
        .into_iter()
        .map(|e| e.field)
        .collect()
}

fn with(inlets: Vec<GasInlet>) -> Vec<String> {
    let mut case = bed();
    case.gas_inlets = inlets;
    refused(&case)
}

fn inlet(side: Side, along: (f64, f64), rate: InletRate) -> GasInlet {
    GasInlet {
        side,
        along,
        rate,
        from: 0.0,
        until: None,
    }
}

#[test]
fn bad_gas_inlets_name_their_field() {
    // the bed: 0.1 × 0.3 m, walls west, east and south, an outlet north
    let floor = |along| inlet(Side::South, along, InletRate::Velocity(0.5));
    assert!(refused(&bed()).is_empty());
    assert!(with(vec![floor((0.0, 0.05)), floor((0.05, 0.1))]).is_empty());
    assert!(with(vec![inlet(
        Side::West,
        (0.0, 0.3),
        InletRate::MassFlux(0.1)
    )])
    .is_empty());
    assert_eq!(
        with(vec![inlet(
            Side::North,
            (0.0, 0.1),
            InletRate::Velocity(0.5)
        )]),
        ["gas_inlets[0].side"]
    );
    assert_eq!(with(vec![floor((0.05, 0.2))]), ["gas_inlets[0].along.1"]);
    assert_eq!(with(vec![floor((-0.01, 0.05))]), ["gas_inlets[0].along.0"]);
    assert_eq!(with(vec![floor((0.06, 0.05))]), ["gas_inlets[0].along.1"]);
    // on the west side `along` is y: 0.3 m high
    assert_eq!(
        with(vec![inlet(
            Side::West,
            (0.1, 0.4),
            InletRate::Velocity(0.5)
        )]),
        ["gas_inlets[0].along.1"]
    );
    assert_eq!(
        with(vec![inlet(
            Side::South,
            (0.0, 0.1),
            InletRate::Velocity(-0.5)
        )]),
        ["gas_inlets[0].rate.Velocity"]
    );
    assert_eq!(
        with(vec![inlet(
            Side::South,
            (0.0, 0.1),
            InletRate::MassFlux(f64::NAN)
        )]),
        ["gas_inlets[0].rate.MassFlux"]
    );
    let shut_before_open = GasInlet {
        from: 1.0,
        until: Some(0.5),
        ..floor((0.0, 0.1))
    };
    assert_eq!(with(vec![shut_before_open]), ["gas_inlets[0].until"]);
    let early = GasInlet {
        from: -1.0,
        ..floor((0.0, 0.1))
    };
    assert_eq!(with(vec![early]), ["gas_inlets[0].from"]);
    // overlapping while both are open; one after the other is a schedule
    assert_eq!(
        with(vec![floor((0.0, 0.06)), floor((0.05, 0.1))]),
        ["gas_inlets[1].along"]
    );
    let first = GasInlet {
        until: Some(1.0),
        ..floor((0.0, 0.1))
    };
    let then = GasInlet {
        from: 1.0,
        ..floor((0.0, 0.1))
    };
    assert!(with(vec![first, then]).is_empty());
    // a gas-only case
    let mut gas_only = bed();
    gas_only.solids.clear();
    gas_only.initial.regions.clear();
    assert!(refused(&gas_only).contains(&"gas_inlets".to_string()));
}

/// A sweep's `Aeration` scales every inlet's rate; 0 removes the inlets (the control); a
/// negative factor, or a base without inlets, is refused naming the parameter.
#[test]
fn aeration_scales_or_removes_the_inlets() {
    use runout_case::{expand, Param, Sweep};
    let sweep = |factors: Vec<f64>| Sweep {
        name: "aerated".into(),
        description: String::new(),
        base: "base.ron".into(),
        set: vec![],
        vary: vec![Param::Aeration(factors)],
        sidewalls: None,
        study: None,
    };
    let base = bed();
    let rate = |c: &Case| match c.gas_inlets[0].rate {
        InletRate::Velocity(v) => v,
        InletRate::MassFlux(g) => g,
    };
    let cases = expand(&sweep(vec![0.0, 1.0, 1.5]), &base).unwrap();
    assert!(cases[0].gas_inlets.is_empty());
    assert_eq!(cases[0].name, "aerated_aeration=0");
    assert_eq!(rate(&cases[1]), rate(&base));
    assert_eq!(rate(&cases[2]), 1.5 * rate(&base));
    assert!(cases.iter().all(|c| refused(c).is_empty()));
    let (field, message) = expand(&sweep(vec![-1.0]), &base).unwrap_err();
    assert!(
        field.contains("Aeration") && message.contains(">= 0"),
        "{field}: {message}"
    );
    let mut dry = base.clone();
    dry.gas_inlets.clear();
    let (field, message) = expand(&sweep(vec![1.0]), &dry).unwrap_err();
    assert!(
        field.contains("Aeration") && message.contains("gas_inlets"),
        "{field}: {message}"
    );
}
