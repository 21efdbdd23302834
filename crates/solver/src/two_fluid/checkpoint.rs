//! The two-fluid solver's state between steps, for checkpoints (issue 21).
//!
//! What carries over a step boundary, and so goes into a checkpoint:
//! - the fields: εg, P_g, u_g, v_g and per phase εs, u_s, v_s, θ (the old time level is
//!   copied from them when the next step begins, [`TwoFluid::begin_step`]);
//! - the closure values of the last outer iteration (P_s, P*, μ, λ, κ, K_cp, F_gs and the
//!   kinetic parts): the first assembly of a step reads some of them before the closure pass
//!   refreshes them;
//! - the explicit stress sources, strain traces and the last corrections (e, ε', P', d),
//!   read as lagged values by the first outer iteration;
//! - the wall closures of the state-dependent walls, their cycle watch and the wall-face
//!   velocities: a closure is relaxed against its last value, and the strain rates of the
//!   wall cells use the last wall-face velocity;
//! - the θ-row classes and their change counts, and h_w^u at the floor probe.
//!
//! Work arrays that every step rewrites before reading (stencils, face data, the strain
//! rates) are left out; the restart test
//! (`crates/run/tests/restart.rs`) shows the set is complete: a run restarted from a
//! checkpoint repeats the uninterrupted run bit for bit.

use runout_walls::RobinFace;

use super::dilute::ClosureCycle;
use super::TwoFluid;
use crate::momentum::WallFaces;
use crate::state::{SolverState, StateError};
use runout_mesh::Side;

impl TwoFluid {
    /// The state the next step reads (module doc).
    pub fn save_state(&self) -> SolverState {
        let mut st = SolverState::default();
        st.put("gravity", &[self.model.gravity.0, self.model.gravity.1]);
        let g = self.state.gas();
        st.put("eps_g", g.eps());
        st.put("p_g", &g.p);
        st.put("u_g", &g.u);
        st.put("v_g", &g.v);
        st.put("d_u", &self.workspace.d_u);
        st.put("d_v", &self.workspace.d_v);
        st.put("p_corr", &self.workspace.p_corr);
        let solids = self
            .workspace
            .solids
            .iter()
            .zip(&self.coefficients)
            .zip(&self.wall_closures);
        for (m, (((wk, c), w), p)) in solids.zip(self.state.phases()).enumerate() {
            let name = |field: &str| format!("solids[{m}].{field}");
            for (field, values) in [
                ("eps", p.eps()),
                ("u", &p.u),
                ("v", &p.v),
                ("theta", &p.theta),
                ("p_s", &c.p_s),
                ("p_star", &c.p_star),
                ("mu", &c.mu),
                ("lambda", &c.lambda),
                ("kappa", &c.kappa),
                ("k_cp", &c.k_cp),
                ("f_gs", &c.f_gs),
                ("p_kin_over_theta", &c.p_kin_over_theta),
                ("mu_kin", &c.mu_kin),
                ("lambda_kin", &c.lambda_kin),
                ("gamma_over_theta", &c.gamma_over_theta),
                ("j_slip", &c.j_slip),
                ("tau_u", &c.tau_u),
                ("tau_v", &c.tau_v),
                ("tr_d", &c.tr_d),
                ("tr_d2", &c.tr_d2),
                ("e_u", &wk.e_u),
                ("e_v", &wk.e_v),
                ("eps_prime", &wk.eps_prime),
                ("floor_h_u", &w.floor_h_u),
            ] {
                st.put(name(field), values);
            }
            st.put_counts(name("dilute_u"), wk.dilute_u.iter().map(|&b| b as u8));
            st.put_counts(name("dilute_v"), wk.dilute_v.iter().map(|&b| b as u8));
            st.put_counts(name("theta_dense"), wk.theta_dense.iter().map(|&b| b as u8));
            st.put_counts(
                name("theta_class_changes"),
                wk.theta_class_changes.iter().copied(),
            );
            for side in Side::ALL {
                let tag = |what: &str| name(&format!("{what}.{side:?}"));
                st.put(tag("wall_face_velocity"), w.wall_face_velocity.get(side));
                put_faces(
                    &mut st,
                    &tag("wall_velocity"),
                    wall_side(&w.wall_velocity, side),
                );
                put_faces(&mut st, &tag("wall_theta"), wall_side(&w.wall_theta, side));
                let cycle = w.wall_velocity_cycle.get(side);
                st.put(
                    tag("wall_velocity_cycle"),
                    &cycle.iter().map(|c| c.last_change).collect::<Vec<_>>(),
                );
            }
        }
        st
    }

    /// Puts back a state saved by [`TwoFluid::save_state`] from a solver of the same case;
    /// refuses one whose arrays do not match this solver's grid and phases.
    pub fn load_state(&mut self, st: &SolverState) -> Result<(), StateError> {
        let mut gravity = [0.0; 2];
        st.take("gravity", &mut gravity)?;
        self.model.gravity = (gravity[0], gravity[1]);
        // εg is checked, then follows the solids (εg = 1 − Σεs)
        st.take("eps_g", &mut vec![0.0; self.eps_g().len()])?;
        let g = self.state.gas_mut();
        st.take("p_g", &mut g.p)?;
        st.take("u_g", &mut g.u)?;
        st.take("v_g", &mut g.v)?;
        st.take("d_u", &mut self.workspace.d_u)?;
        st.take("d_v", &mut self.workspace.d_v)?;
        st.take("p_corr", &mut self.workspace.p_corr)?;
        self.state.try_update_all_solids(|m, p| {
            let name = |field: &str| format!("solids[{m}].{field}");
            for (field, values) in [("eps", p.eps), ("u", p.u), ("v", p.v), ("theta", p.theta)] {
                st.take(&name(field), values)?;
            }
            Ok(())
        })?;
        let solids = self.workspace.solids.iter_mut().zip(&mut self.coefficients);
        for (m, ((wk, c), w)) in solids.zip(&mut self.wall_closures).enumerate() {
            let name = |field: &str| format!("solids[{m}].{field}");
            for (field, values) in [
                ("p_s", &mut c.p_s),
                ("p_star", &mut c.p_star),
                ("mu", &mut c.mu),
                ("lambda", &mut c.lambda),
                ("kappa", &mut c.kappa),
                ("k_cp", &mut c.k_cp),
                ("f_gs", &mut c.f_gs),
                ("p_kin_over_theta", &mut c.p_kin_over_theta),
                ("mu_kin", &mut c.mu_kin),
                ("lambda_kin", &mut c.lambda_kin),
                ("gamma_over_theta", &mut c.gamma_over_theta),
                ("j_slip", &mut c.j_slip),
                ("tau_u", &mut c.tau_u),
                ("tau_v", &mut c.tau_v),
                ("tr_d", &mut c.tr_d),
                ("tr_d2", &mut c.tr_d2),
                ("e_u", &mut wk.e_u),
                ("e_v", &mut wk.e_v),
                ("eps_prime", &mut wk.eps_prime),
                ("floor_h_u", &mut w.floor_h_u),
            ] {
                st.take(&name(field), values)?;
            }
            load_flags(st, &name("dilute_u"), &mut wk.dilute_u)?;
            load_flags(st, &name("dilute_v"), &mut wk.dilute_v)?;
            load_flags(st, &name("theta_dense"), &mut wk.theta_dense)?;
            let n = wk.theta_class_changes.len();
            wk.theta_class_changes
                .copy_from_slice(st.take_counts(&name("theta_class_changes"), n)?);
            for side in Side::ALL {
                let tag = |what: &str| name(&format!("{what}.{side:?}"));
                st.take(
                    &tag("wall_face_velocity"),
                    w.wall_face_velocity.get_mut(side),
                )?;
                *wall_side_mut(&mut w.wall_velocity, side) = take_faces(st, &tag("wall_velocity"))?;
                *wall_side_mut(&mut w.wall_theta, side) = take_faces(st, &tag("wall_theta"))?;
                let changes = find_len(st, &tag("wall_velocity_cycle"))?;
                let mut last = vec![0.0; changes];
                st.take(&tag("wall_velocity_cycle"), &mut last)?;
                *w.wall_velocity_cycle.get_mut(side) = last
                    .into_iter()
                    .map(|last_change| ClosureCycle {
                        last_change,
                        cycling: false,
                    })
                    .collect();
            }
        }
        Ok(())
    }
}

fn load_flags(st: &SolverState, name: &str, into: &mut [bool]) -> Result<(), StateError> {
    let values = st.take_counts(name, into.len())?;
    for (b, &v) in into.iter_mut().zip(values) {
        *b = v != 0;
    }
    Ok(())
}

fn wall_side(w: &WallFaces, side: Side) -> &Option<Vec<RobinFace>> {
    match side {
        Side::West => &w.west,
        Side::East => &w.east,
        Side::South => &w.south,
        Side::North => &w.north,
    }
}

fn wall_side_mut(w: &mut WallFaces, side: Side) -> &mut Option<Vec<RobinFace>> {
    match side {
        Side::West => &mut w.west,
        Side::East => &mut w.east,
        Side::South => &mut w.south,
        Side::North => &mut w.north,
    }
}

/// A side's per-node closures as (g, h, c) triples; absent when the side has none.
fn put_faces(st: &mut SolverState, name: &str, faces: &Option<Vec<RobinFace>>) {
    if let Some(f) = faces {
        let flat: Vec<f64> = f.iter().flat_map(|r| [r.g, r.h, r.c]).collect();
        st.put(name, &flat);
    }
}

fn take_faces(st: &SolverState, name: &str) -> Result<Option<Vec<RobinFace>>, StateError> {
    let Ok(len) = find_len(st, name) else {
        return Ok(None);
    };
    let mut flat = vec![0.0; len];
    st.take(name, &mut flat)?;
    Ok(Some(
        flat.chunks_exact(3)
            .map(|c| RobinFace {
                g: c[0],
                h: c[1],
                c: c[2],
            })
            .collect(),
    ))
}

fn find_len(st: &SolverState, name: &str) -> Result<usize, StateError> {
    st.len_of(name)
}
