//! Partial elimination of the interphase drag (Spalding's PEA as MFIX applies it,
//! docs/model.md §4.5), for the gas and M solids phases coupled by gas–solids drag only.
//!
//! At one velocity node each phase's assembled equation (without drag) reads
//! a_k φ_k = r_k, r_k = Σ a_nb φ_nb + b with the current neighbour values. With the drag
//! F_m = F_gs,m V_node:
//!   gas:      a_g φ_g = r_g + Σ_m F_m (φ_m − φ_g)
//!   solids m: a_m φ_m = r_m + F_m (φ_g − φ_m).
//! Eliminating the other phase's unknown at the node gives, for any M,
//!   gas:      (a_g + Σ_m F_m a_m/(a_m + F_m)) φ_g = r_g + Σ_m F_m r_m/(a_m + F_m),
//!   solids m: (a_m + F_m − F_m²/(a_g + ΣF)) φ_m = r_m + F_m (r_g + Σ_{n≠m} F_n φ_n)/(a_g + ΣF),
//! with the other solids phases' current values φ_n (exact for M = 1, where the solids
//! form reduces to docs/model.md §4.5's a_s + F a_g/(a_g + F), b_s + F r_g/(a_g + F)). The
//! drag then disappears from the systems, which are solved one phase at a time.

/// One node's coupled equations: centre coefficients `a`, right-hand sides `r`
/// (= Σ a_nb φ_nb + b) and current values `phi` of the gas (index 0) and the solids phases
/// (1..=M), and the drag coefficients `drag[m]` = F_gs,m V of solids phase m+1.
/// Returns the centre coefficients and right-hand sides of the decoupled equations, in
/// `a_out` and `r_out` (same layout).
pub fn eliminate_node(
    a: &[f64],
    r: &[f64],
    phi: &[f64],
    drag: &[f64],
    a_out: &mut [f64],
    r_out: &mut [f64],
) {
    let m = drag.len();
    debug_assert!(a.len() == m + 1 && r.len() == m + 1 && phi.len() == m + 1);
    let total_drag: f64 = drag.iter().sum();
    // gas
    let mut a_g = a[0];
    let mut r_g = r[0];
    for (k, &f) in drag.iter().enumerate() {
        if f > 0.0 {
            a_g += f * a[k + 1] / (a[k + 1] + f);
            r_g += f * r[k + 1] / (a[k + 1] + f);
        }
    }
    a_out[0] = a_g;
    r_out[0] = r_g;
    // solids
    let gas_total = a[0] + total_drag;
    for (k, &f) in drag.iter().enumerate() {
        if f > 0.0 {
            let others: f64 = drag
                .iter()
                .enumerate()
                .filter(|&(n, _)| n != k)
                .map(|(n, &fn_)| fn_ * phi[n + 1])
                .sum();
            a_out[k + 1] = a[k + 1] + f - f * f / gas_total;
            r_out[k + 1] = r[k + 1] + f * (r[0] + others) / gas_total;
        } else {
            a_out[k + 1] = a[k + 1];
            r_out[k + 1] = r[k + 1];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Solves the coupled (M+1) × (M+1) node system directly by Gaussian elimination.
    fn coupled_solution(a: &[f64], r: &[f64], drag: &[f64]) -> Vec<f64> {
        let n = a.len();
        let mut m = vec![vec![0.0; n + 1]; n];
        m[0][0] = a[0] + drag.iter().sum::<f64>();
        m[0][n] = r[0];
        for (k, &f) in drag.iter().enumerate() {
            m[0][k + 1] = -f;
            m[k + 1][k + 1] = a[k + 1] + f;
            m[k + 1][0] = -f;
            m[k + 1][n] = r[k + 1];
        }
        for c in 0..n {
            let p = (c..n)
                .max_by(|&x, &y| m[x][c].abs().total_cmp(&m[y][c].abs()))
                .unwrap();
            m.swap(c, p);
            for row in c + 1..n {
                let l = m[row][c] / m[c][c];
                for col in c..=n {
                    m[row][col] -= l * m[c][col];
                }
            }
        }
        let mut x = vec![0.0; n];
        for row in (0..n).rev() {
            x[row] =
                (m[row][n] - (row + 1..n).map(|c| m[row][c] * x[c]).sum::<f64>()) / m[row][row];
        }
        x
    }

    #[test]
    fn one_solids_phase_is_exact() {
        let (a, r, drag) = ([2.0, 5.0], [1.0, -3.0], [40.0]);
        let exact = coupled_solution(&a, &r, &drag);
        let (mut a2, mut r2) = ([0.0; 2], [0.0; 2]);
        // the current values do not matter for M = 1
        eliminate_node(&a, &r, &[123.0, -7.0], &drag, &mut a2, &mut r2);
        for k in 0..2 {
            assert!(
                (r2[k] / a2[k] - exact[k]).abs() < 1e-12,
                "{k}: {} vs {}",
                r2[k] / a2[k],
                exact[k]
            );
        }
    }

    #[test]
    fn several_phases_converge_to_the_coupled_solution_when_iterated() {
        let (a, r, drag) = ([1.5, 4.0, 0.7], [2.0, -1.0, 3.0], [30.0, 8.0]);
        let exact = coupled_solution(&a, &r, &drag);
        let mut phi = vec![0.0; 3];
        let (mut a2, mut r2) = ([0.0; 3], [0.0; 3]);
        for _ in 0..200 {
            eliminate_node(&a, &r, &phi, &drag, &mut a2, &mut r2);
            for k in 0..3 {
                phi[k] = r2[k] / a2[k];
            }
        }
        for k in 0..3 {
            assert!(
                (phi[k] - exact[k]).abs() < 1e-10,
                "{k}: {} vs {}",
                phi[k],
                exact[k]
            );
        }
        // and at the fixed point the eliminated equations hold exactly
        eliminate_node(&a, &r, &exact, &drag, &mut a2, &mut r2);
        for k in 0..3 {
            assert!((r2[k] / a2[k] - exact[k]).abs() < 1e-12);
        }
    }

    #[test]
    fn no_drag_leaves_the_equations_alone() {
        let (mut a2, mut r2) = ([0.0; 2], [0.0; 2]);
        eliminate_node(
            &[2.0, 3.0],
            &[1.0, 4.0],
            &[0.0, 0.0],
            &[0.0],
            &mut a2,
            &mut r2,
        );
        assert_eq!((a2, r2), ([2.0, 3.0], [1.0, 4.0]));
    }
}
