//! A release the grid cannot hold is refused before any step, naming the field: a polygon
//! that crosses itself, has two corners or reaches outside the domain; a gate outside the
//! domain, taller than it, opening before t = 0 or lifted at no speed.

use std::path::Path;

use runout_case::{load_case, Gate, GateOpening, Polygon};

fn refused(polygons: Vec<Polygon>, gates: Vec<Gate>) -> Vec<String> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let mut case = load_case(&root.join("cases/collapse/CM-a1.ron")).unwrap();
    let solids = case.initial.regions[0].solids.clone();
    case.initial.polygons = polygons
        .into_iter()
        .map(|p| Polygon {
            solids: solids.clone(),
            ..p
        })
        .collect();
    case.gates = gates;
    runout_case::validate_case(&case)
        .err()
        .unwrap_or_default()
        .into_iter()
        .map(|e| e.field)
        .collect()
}

fn polygon(points: &[(f64, f64)]) -> Polygon {
    Polygon {
        points: points.to_vec(),
        solids: Vec::new(),
    }
}

#[test]
fn bad_polygons_and_gates_name_their_field() {
    // CM-a1: 0.6 × 0.08 m, a horizontal floor
    let pile = polygon(&[(0.0, 0.0), (0.1, 0.0), (0.1, 0.03), (0.0, 0.05)]);
    let gate = |x: f64, height: f64, open: GateOpening| Gate { x, height, open };
    assert!(refused(
        vec![pile.clone()],
        vec![gate(0.1, 0.05, GateOpening::Removed { at: 0.0 })]
    )
    .is_empty());
    let bow_tie = polygon(&[(0.0, 0.0), (0.1, 0.05), (0.1, 0.0), (0.0, 0.05)]);
    assert_eq!(
        refused(vec![bow_tie], vec![]),
        ["initial.polygons[0].points[0]"]
    );
    assert_eq!(
        refused(vec![polygon(&[(0.0, 0.0), (0.1, 0.0)])], vec![]),
        ["initial.polygons[0].points"]
    );
    let too_high = polygon(&[(0.0, 0.0), (0.1, 0.0), (0.1, 0.09)]);
    assert_eq!(
        refused(vec![too_high], vec![]),
        ["initial.polygons[0].points[2]"]
    );
    let beyond = polygon(&[(0.5, 0.0), (0.7, 0.0), (0.5, 0.02)]);
    assert_eq!(
        refused(vec![beyond], vec![]),
        ["initial.polygons[0].points[1]"]
    );
    assert_eq!(
        refused(
            vec![],
            vec![gate(0.7, 0.05, GateOpening::Removed { at: 0.0 })]
        ),
        ["gates[0].x"]
    );
    assert_eq!(
        refused(
            vec![],
            vec![gate(0.1, 0.2, GateOpening::Removed { at: 0.0 })]
        ),
        ["gates[0].height"]
    );
    assert_eq!(
        refused(
            vec![],
            vec![gate(0.1, 0.05, GateOpening::Removed { at: -1.0 })]
        ),
        ["gates[0].open.Removed.at"]
    );
    assert_eq!(
        refused(
            vec![],
            vec![gate(
                0.1,
                0.05,
                GateOpening::Lifted {
                    at: 0.0,
                    speed: 0.0
                }
            )]
        ),
        ["gates[0].open.Lifted.speed"]
    );
}
