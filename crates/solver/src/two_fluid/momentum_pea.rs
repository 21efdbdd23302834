//! Step 2 of the outer iteration (docs/model.md §4.9): the momentum predictor of the gas and
//! every solids phase, u and v (docs/model.md §4.4, assembled by [`crate::momentum`]), with
//! the gas–solids drag removed by partial elimination (docs/model.md §4.5, [`crate::pea`])
//! and Patankar under-relaxation a_P/ω (docs/model.md §4.10).
//!
//! At a coupled node of face area A with the cells c0, c1 beside it, the drag of solids
//! phase m is F_m = F_gs,c0 V0/2 + F_gs,c1 V1/2 (the face average by volume, MFIX VF_GS_X),
//! and with the relaxed centre coefficients a_g/ω, a_m/ω of the equations before elimination
//! the node also stores what the corrections read:
//!   d_g = A (ε̄g + Σ_m ε̄s,m F_m/(a_m/ω + F_m)) / (a_g/ω + Σ_m F_m (a_m/ω)/(a_m/ω + F_m))
//! of the gas pressure correction (docs/model.md §4.6) and e_m = A/(a_m/ω) of the solids
//! volume-fraction correction (docs/model.md §4.7), ε̄ the mean of the two cells. Dilute
//! solids nodes (DIL_EP_S, docs/model.md §2.7) get the rows of [`super::dilute`] and e = 0;
//! fixed (wall) nodes hold the wall's velocity and have d = e = 0. The momentum residual of
//! docs/model.md §4.11 is taken at every coupled node before the elimination
//! ([`super::residuals::CoupledNode::residual`]), summed per class of node
//! ([`super::residuals::ClassedResidual`]).

use std::time::Instant;

use runout_closures::FaceMean;
use runout_linsolve::{LinearSolver, Stencil5};
use runout_mesh::{Grid, Sides};

use super::diagnostics::since;
use super::diagnostics::Diagnostics;
use super::dilute::{dilute_faces, dilute_row};
use super::model::Model;
use super::relaxation::RelaxationBase;
use super::residuals::{ClassedResidual, CoupledNode, NodeClass};
use super::sidewalls::add_momentum_sinks;
use super::state::GasState;
use super::{
    lin, PhaseCoefficients, PhaseState, PhaseWallClosures, PhaseWork, SolidsSpec, State,
    TwoFluidError, Workspace, MAX_SOLIDS_PHASES,
};
use crate::momentum::{
    assemble_with_fluxes, fixed_row, mass_fluxes, neighbour_sum, Context, MassFluxes, PhaseFields,
};
use crate::pea::eliminate_node;
use crate::staggered::Component;

/// Step 2 (module doc); returns the momentum residual summed over u and v.
#[allow(clippy::too_many_arguments)]
pub(super) fn momentum(
    model: &Model,
    state: &mut State,
    coefficients: &[PhaseCoefficients],
    wall_closures: &[PhaseWallClosures],
    work: &mut Workspace,
    diagnostics: &mut Diagnostics,
    dt: f64,
) -> Result<f64, TwoFluidError> {
    assemble_momentum(model, state, coefficients, wall_closures, work, dt);
    // the u and v components are decoupled from each other here: their eliminations run
    // in parallel, each over its own arrays (the same results on any number of threads)
    let [cu, cv] = Component::of_grid(&model.grid);
    let g = state.gas();
    let gas_u = GasComponent::of(g, &mut work.a_ug, &mut work.d_u);
    let gas_v = GasComponent::of(g, &mut work.a_vg, &mut work.d_v);
    let (mut solids_u, mut solids_v) = (Vec::new(), Vec::new());
    for ((s, p), coef) in work.solids.iter_mut().zip(state.phases()).zip(coefficients) {
        let [su, sv] = s.components(p, coef);
        solids_u.push(su);
        solids_v.push(sv);
    }
    let ((residual_u, worst_u), (residual_v, worst_v)) = rayon::join(
        || decouple_component(model, cu, gas_u, &mut solids_u),
        || decouple_component(model, cv, gas_v, &mut solids_v),
    );
    // u before v, as one sequential pass over both would keep them
    diagnostics.worst.momentum = if worst_v.0 > worst_u.0 {
        worst_v
    } else {
        worst_u
    };
    // docs/model.md §4.11: per class of node, or pooled as MFIX
    let speed_floor = model.momentum_speed_floor();
    let measure = |r: &ClassedResidual| {
        if model.settings.pooled_momentum_residual {
            r.pooled()
        } else {
            r.largest(speed_floor)
        }
    };
    let residual = measure(&residual_u) + measure(&residual_v);
    let t = Instant::now();
    diagnostics.profile.iterations.momentum += solve_momentum(&model.grid, state, work)? as u64;
    // solves are reported apart from the assembly that encloses them
    let solve = since(t);
    diagnostics.profile.momentum_solve += solve;
    diagnostics.profile.momentum_assembly -= solve;
    Ok(residual)
}

/// The momentum equations of every phase without drag (docs/model.md §4.4); the solids
/// rows of dilute nodes are skipped (replaced by [`eliminate_drag`]).
fn assemble_momentum(
    model: &Model,
    state: &State,
    coefficients: &[PhaseCoefficients],
    wall_closures: &[PhaseWallClosures],
    work: &mut Workspace,
    dt: f64,
) {
    let grid = &model.grid;
    let g = state.gas();
    let ctx_gas = Context {
        grid,
        bcs: &model.gas_walls,
        gravity: model.gravity,
        bent_floor: model.bent_floor.as_ref(),
        dt,
        scheme: model.settings.scheme,
        gas_pressure: &g.p,
        wall_faces: None,
        form: model.settings.momentum_form,
    };
    let gas_fields = PhaseFields {
        bulk_density: g.bulk_density(),
        bulk_density_old: &g.old().rho_eps,
        volume_fraction: g.eps(),
        viscosity: &model.gas_viscosity,
        viscosity_mean: FaceMean::Harmonic,
        solids_pressure: None,
        plastic_pressure: None,
        // the gas's own cross terms are left out: with uniform μ_g they reduce to
        // μ_g ∇(∇·u_g), negligible here (μ_g = 1.8e-5 Pa s)
        explicit_source: None,
        skip: None,
        velocity_along: Some(&g.u),
    };
    let [cu, cv] = Component::of_grid(grid);
    let (u_g, v_g) = (&g.u, &g.v);
    let (u_faces, a_u) = (&mut work.u_faces, &mut work.a_ug);
    let (v_faces, a_v) = (&mut work.v_faces, &mut work.a_vg);
    let gas_fluxes = &mut work.gas_fluxes;
    let (ctx_gas, gas_fields) = (&ctx_gas, &gas_fields);
    // every system has its own face data and rows: the gas's u and v and each phase's run
    // in parallel, each as it would alone (the same results on any number of threads)
    let solids = work.solids.iter_mut().zip(state.phases()).zip(coefficients);
    let solids = solids.zip(wall_closures).zip(&model.solids_specs);
    rayon::scope(|scope| {
        scope.spawn(move |_| {
            let rho_eps = gas_fields.bulk_density;
            mass_fluxes(grid, ctx_gas.scheme, rho_eps, u_g, v_g, gas_fluxes);
            let fluxes = &*gas_fluxes;
            rayon::join(
                || {
                    assemble_with_fluxes(
                        ctx_gas,
                        gas_fields,
                        cu,
                        u_g,
                        v_g,
                        &g.old().u,
                        fluxes,
                        u_faces,
                        a_u,
                    )
                },
                || {
                    assemble_with_fluxes(
                        ctx_gas,
                        gas_fields,
                        cv,
                        u_g,
                        v_g,
                        &g.old().v,
                        fluxes,
                        v_faces,
                        a_v,
                    )
                },
            );
        });
        for ((((s, p), coef), w), spec) in solids {
            let phase = SolidsPhase {
                phase: p,
                coefficients: coef,
                walls: w,
                spec,
            };
            scope.spawn(move |_| assemble_phase(ctx_gas, [cu, cv], phase, s));
        }
    });
}

/// The linear solves of every phase's u and v; returns their iterations. The u systems
/// (gas, then each phase) and the v systems are independent after the elimination and have
/// their own solvers, so the two components are solved as two tasks (the same results on
/// any number of threads); a failure is reported as the sequential order gas u, gas v,
/// solids u, solids v would meet it first.
fn solve_momentum(
    grid: &Grid,
    state: &mut State,
    work: &mut Workspace,
) -> Result<usize, TwoFluidError> {
    let (gas, phases) = state.gas_mut_and_phases_mut();
    let (mut u_systems, mut v_systems) = (vec![(&work.a_ug, &mut gas.u)], Vec::new());
    v_systems.push((&work.a_vg, &mut gas.v));
    for (s, p) in work.solids.iter().zip(phases.iter_mut()) {
        u_systems.push((&s.a_u, &mut p.u));
        v_systems.push((&s.a_v, &mut p.v));
    }
    let (solver_u, solver_v) = (&mut work.solvers.u, &mut work.solvers.v);
    let (u, v) = rayon::join(
        || solve_component(solver_u.as_mut(), u_systems, "u"),
        || solve_component(solver_v.as_mut(), v_systems, "v"),
    );
    let iterations = match (u, v) {
        (Ok(iu), Ok(iv)) => iu + iv,
        // the first failure in the sequential order: phase index first, then u before v
        (Err((pu, eu)), Err((pv, ev))) => return Err(if pv < pu { ev } else { eu }),
        (Err((_, e)), Ok(_)) | (Ok(_), Err((_, e))) => return Err(e),
    };
    if grid.periodic_x() {
        // node nx of a periodic column is node 0 (fixed in the solves)
        let (nx, ny) = (grid.nx(), grid.ny());
        let mx = nx + 1;
        let copy = |u: &mut [f64]| (0..ny).for_each(|j| u[nx + mx * j] = u[mx * j]);
        copy(&mut state.gas_mut().u);
        state.phases_mut().iter_mut().for_each(|p| copy(&mut p.u));
    }
    Ok(iterations)
}

/// Solves the systems of one velocity component in order (gas, then each solids phase);
/// returns their iterations, or the index of the phase whose solve failed and the error.
fn solve_component(
    solver: &mut dyn LinearSolver,
    systems: Vec<(&Stencil5, &mut Vec<f64>)>,
    component: &str,
) -> Result<usize, (usize, TwoFluidError)> {
    let mut iterations = 0;
    for (phase, (a, x)) in systems.into_iter().enumerate() {
        iterations += solver
            .setup_and_solve(a, x)
            .map_err(|e| {
                let who = if phase == 0 { "gas" } else { "solids" };
                (phase, lin(&format!("{who} {component} momentum"))(e))
            })?
            .iterations;
    }
    Ok(iterations)
}

/// The explicit stress sources of every solids phase from the current velocities and
/// closures (docs/model.md §4.4: once per step, at its start).
pub(super) fn update_stress_sources(
    grid: &Grid,
    state: &State,
    coefficients: &mut [PhaseCoefficients],
    work: &Workspace,
) {
    let fixed_u = work.a_ug.pattern().fixed_mask();
    let fixed_v = work.a_vg.pattern().fixed_mask();
    for (s, p) in coefficients.iter_mut().zip(state.phases()) {
        crate::stress::explicit_stress(
            grid,
            &p.u,
            &p.v,
            &s.mu,
            // harmonic for every phase, μ(I) included: these terms are lagged over the step,
            // and an arithmetic corner beside a dilute cell would carry half a plastic
            // viscosity onto a cell with little mass (docs/model.md §2.4.4)
            FaceMean::Harmonic,
            &s.lambda,
            &s.tr_d,
            fixed_u,
            fixed_v,
            &mut s.tau_u,
            &mut s.tau_v,
        );
    }
}

/// What one solids phase's momentum assembly reads.
struct SolidsPhase<'a> {
    phase: &'a PhaseState,
    coefficients: &'a PhaseCoefficients,
    walls: &'a PhaseWallClosures,
    spec: &'a SolidsSpec,
}

/// The momentum equations of one solids phase without drag (docs/model.md §4.4), with the
/// gas's context `ctx_gas`, u and v in parallel; the rows of dilute nodes are skipped.
fn assemble_phase(
    ctx_gas: &Context<'_>,
    [cu, cv]: [Component; 2],
    solids: SolidsPhase<'_>,
    s: &mut PhaseWork,
) {
    let SolidsPhase {
        phase: p,
        coefficients: coef,
        walls: w,
        spec,
    } = solids;
    // dilute faces (interpolated εs ≤ DIL_EP_S, docs/model.md §2.7): their rows are
    // replaced later, so the assembly skips them (most of a slide's domain)
    // (the phase's u and v patterns are the gas's: the same fixed wall nodes)
    dilute_faces(
        ctx_gas.grid,
        cu,
        p.eps(),
        s.a_u.pattern().fixed_mask(),
        &mut s.dilute_u,
    );
    dilute_faces(
        ctx_gas.grid,
        cv,
        p.eps(),
        s.a_v.pattern().fixed_mask(),
        &mut s.dilute_v,
    );
    let bcs = spec.momentum_bcs(ctx_gas.bcs);
    let ctx = Context {
        bcs: &bcs,
        wall_faces: Some(&w.wall_velocity),
        ..*ctx_gas
    };
    let fields_u = PhaseFields {
        bulk_density: p.bulk_density(),
        bulk_density_old: &p.old().rho_eps,
        volume_fraction: p.eps(),
        viscosity: &coef.mu,
        viscosity_mean: spec.params.friction_model.corner_viscosity_mean(),
        solids_pressure: Some(&coef.p_s),
        // −∇P* only with Schaeffer (docs/model.md §4.4); none with Princeton, where
        // MFIX never computes P* (§2.4.2)
        plastic_pressure: spec
            .params
            .friction_model
            .has_plastic_pressure()
            .then_some(&coef.p_star[..]),
        explicit_source: Some(&coef.tau_u),
        skip: Some(&s.dilute_u),
        velocity_along: Some(&p.u),
    };
    let fields_v = PhaseFields {
        explicit_source: Some(&coef.tau_v),
        skip: Some(&s.dilute_v),
        ..fields_u
    };
    let (u_faces, a_u, v_faces, a_v) = (&mut s.u_faces, &mut s.a_u, &mut s.v_faces, &mut s.a_v);
    let (u, v) = (&p.u, &p.v);
    mass_fluxes(ctx.grid, ctx.scheme, p.bulk_density(), u, v, &mut s.fluxes);
    let fluxes: &MassFluxes = &s.fluxes;
    rayon::join(
        || assemble_with_fluxes(&ctx, &fields_u, cu, u, v, &p.old().u, fluxes, u_faces, a_u),
        || assemble_with_fluxes(&ctx, &fields_v, cv, u, v, &p.old().v, fluxes, v_faces, a_v),
    );
}

/// The gas's part of one component at the coupled nodes.
struct GasComponent<'a> {
    /// the component's equations
    a: &'a mut Stencil5,
    /// d_g of the component's nodes (docs/model.md §4.6)
    d: &'a mut [f64],
    /// gas u and v (the component's unknown is one of them)
    u: &'a [f64],
    v: &'a [f64],
    /// εg per cell
    eps: &'a [f64],
}

impl<'a> GasComponent<'a> {
    /// The gas fields `g` with one component's equations `a` and its d_g.
    fn of(g: &'a GasState, a: &'a mut Stencil5, d: &'a mut [f64]) -> Self {
        Self {
            a,
            d,
            u: &g.u,
            v: &g.v,
            eps: g.eps(),
        }
    }
}

/// One solids phase's part of one component.
pub(super) struct SolidsComponent<'a> {
    /// the component's equations
    pub a: &'a mut Stencil5,
    /// e_s of the component's nodes (docs/model.md §4.7)
    pub e: &'a mut [f64],
    /// the component's dilute nodes (docs/model.md §2.7)
    pub dilute: &'a [bool],
    /// the phase's fields (u, v, εs)
    pub phase: &'a PhaseState,
    /// the phase's closure values (drag, side-wall terms)
    pub coefficients: &'a PhaseCoefficients,
}

impl PhaseWork {
    /// The phase's u and v parts, with fields `p` and closure values `coef`.
    fn components<'a>(
        &'a mut self,
        p: &'a PhaseState,
        coef: &'a PhaseCoefficients,
    ) -> [SolidsComponent<'a>; 2] {
        [
            SolidsComponent {
                a: &mut self.a_u,
                e: &mut self.e_u,
                dilute: &self.dilute_u,
                phase: p,
                coefficients: coef,
            },
            SolidsComponent {
                a: &mut self.a_v,
                e: &mut self.e_v,
                dilute: &self.dilute_v,
                phase: p,
                coefficients: coef,
            },
        ]
    }
}

/// Component `c`'s side-wall sinks, partial elimination and wall rows (module doc); returns
/// its momentum residual by class of node and its largest node residual.
fn decouple_component(
    model: &Model,
    c: Component,
    mut gas: GasComponent<'_>,
    solids: &mut [SolidsComponent<'_>],
) -> (ClassedResidual, (f64, usize, usize, usize, usize)) {
    if let Some(sidewalls) = &model.sidewalls {
        // docs/model.md §8: the side walls' sinks join the rows before the elimination
        let gas_drag = sidewalls.gas_drag(model.gas.viscosity);
        add_momentum_sinks(&model.grid, c, (&mut *gas.a, gas_drag), solids);
    }
    let mut worst = (0.0, 0, 0, 0, 0);
    let mut solids_bases = [RelaxationBase::Centre; MAX_SOLIDS_PHASES];
    for (base, spec) in solids_bases.iter_mut().zip(&model.solids_specs) {
        *base = RelaxationBase::for_phase(
            model.settings.solids_relaxation_base,
            &spec.params.friction_model,
        );
    }
    let relax = Relax {
        omega: model.settings.relax_velocity,
        solids_bases,
    };
    // a gate closes u faces only (it stands across the flow)
    let gate: &[bool] = if c.dir == 0 { &model.gate_faces } else { &[] };
    let residual = eliminate_drag(&model.grid, c, relax, gate, &mut gas, solids, &mut worst);
    fix_wall_rows(c, &model.gas_inflow, gate, &mut gas, solids);
    (residual, worst)
}

/// The momentum relaxation: ω, and the base of each solids phase's rows (the gas's is
/// Patankar's).
#[derive(Clone, Copy, Debug)]
struct Relax {
    omega: f64,
    solids_bases: [RelaxationBase; MAX_SOLIDS_PHASES],
}

/// The partial elimination of the drag at every coupled node of component `c` (not fixed,
/// not closed by a `gate`), with relaxation `relax` (module doc); returns the component's
/// momentum residual by class of node and keeps the largest in `worst`.
fn eliminate_drag(
    grid: &Grid,
    c: Component,
    relax: Relax,
    gate: &[bool],
    gas: &mut GasComponent<'_>,
    solids: &mut [SolidsComponent<'_>],
    worst: &mut (f64, usize, usize, usize, usize),
) -> ClassedResidual {
    // one loop per number of phases, its node arrays sized for it
    let eliminate = match solids.len() {
        0 => eliminate_drag_with::<1>,
        1 => eliminate_drag_with::<2>,
        2 => eliminate_drag_with::<3>,
        3 => eliminate_drag_with::<4>,
        4 => eliminate_drag_with::<5>,
        5 => eliminate_drag_with::<6>,
        6 => eliminate_drag_with::<7>,
        7 => eliminate_drag_with::<8>,
        m => unreachable!("{m} solids phases: the set-up allows at most {MAX_SOLIDS_PHASES}"),
    };
    eliminate(grid, c, relax, gate, gas, solids, worst)
}

/// [`eliminate_drag`] with N phases (the gas and N − 1 solids phases).
fn eliminate_drag_with<const N: usize>(
    grid: &Grid,
    c: Component,
    relax: Relax,
    gate: &[bool],
    gas: &mut GasComponent<'_>,
    solids: &mut [SolidsComponent<'_>],
    worst: &mut (f64, usize, usize, usize, usize),
) -> ClassedResidual {
    let (dx, dy) = (grid.x.widths(), grid.y.widths());
    let m = solids.len();
    debug_assert_eq!(m + 1, N);
    let mut residual = ClassedResidual::default();
    for j in 0..c.my {
        for i in 0..c.mx {
            let k = i + c.mx * j;
            if gas.a.pattern().fixed_mask()[k] || gate.get(k).copied().unwrap_or(false) {
                continue;
            }
            let node = gather::<N>(c, (i, j), dx, dy, gas, solids);
            // momentum residuals of the coupled node (before relaxation, §4.11)
            for p in 0..=m {
                if p > 0 && node.dilute[p - 1] {
                    continue;
                }
                let Some((res, scale, a_p)) = node.residual(p, m) else {
                    continue;
                };
                let class = if p == 0 {
                    NodeClass::Loose
                } else {
                    let coef = solids[p - 1].coefficients;
                    let (c0, c1) = node.cells;
                    NodeClass::of(
                        [c0, c1]
                            .into_iter()
                            .flatten()
                            .map(|c| (coef.mu[c], coef.mu_kin[c])),
                    )
                };
                residual.add(p, class, res, scale, a_p);
                if res > worst.0 {
                    *worst = (res, p, c.dir, i, j);
                }
            }
            let area = c.face_area(i, j, dx, dy);
            decouple(c, (i, j), area, relax, &node, gas, solids);
        }
    }
    residual
}

/// The coupled equations of node (i, j) of component `c` (index 0 the gas, p the solids
/// phase p) as the assembly left them.
fn gather<const N: usize>(
    c: Component,
    (i, j): (usize, usize),
    dx: &[f64],
    dy: &[f64],
    gas: &GasComponent<'_>,
    solids: &[SolidsComponent<'_>],
) -> CoupledNode<N> {
    let k = i + c.mx * j;
    // the cells beside the node and their half volumes
    let [lo, hi] = c.cells(i, j, true);
    let cell = |x: Option<(usize, usize)>| x.map(|(ci, cj)| ci + c.nx * cj);
    let half = |x: Option<(usize, usize)>| x.map_or(0.0, |(ci, cj)| 0.5 * dx[ci] * dy[cj]);
    let (c0, c1, h0, h1) = (cell(lo), cell(hi), half(lo), half(hi));
    let mut node = CoupledNode::<N>::new((c0, c1));
    let gas_phi = c.pick(gas.u, gas.v);
    node.a_in[0] = gas.a.a_p[k];
    node.r_in[0] = neighbour_sum(gas.a, gas_phi, k);
    node.phi[0] = gas_phi[k];
    node.cross[0] = c.cross_velocity(gas.u, gas.v, c0);
    for (p, s) in solids.iter().enumerate() {
        let (ph, coef) = (s.phase, s.coefficients);
        let phi = c.pick(&ph.u, &ph.v);
        // a face whose interpolated εs ≤ DIL_EP_S carries no solids momentum
        // (MFIX `source_u_s.f`, docs/model.md §2.7): its velocity is set by its row
        let dilute = s.dilute[k];
        node.dilute[p] = dilute;
        node.a_in[p + 1] = if dilute { 1.0 } else { s.a.a_p[k] };
        node.r_in[p + 1] = if dilute {
            phi[k]
        } else {
            neighbour_sum(s.a, phi, k)
        };
        node.phi[p + 1] = phi[k];
        node.cross[p + 1] = c.cross_velocity(&ph.u, &ph.v, c0);
        node.drag[p] = if dilute {
            0.0
        } else {
            c0.map_or(0.0, |c| coef.f_gs[c] * h0) + c1.map_or(0.0, |c| coef.f_gs[c] * h1)
        };
    }
    node
}

/// Replaces the rows of node (i, j) by the decoupled, relaxed rows of the partial
/// elimination and stores d_g and e_s (module doc); a dilute solids node gets its dilute row.
fn decouple<const N: usize>(
    c: Component,
    (i, j): (usize, usize),
    area: f64,
    relax: Relax,
    node: &CoupledNode<N>,
    gas: &mut GasComponent<'_>,
    solids: &mut [SolidsComponent<'_>],
) {
    let m = solids.len();
    let k = i + c.mx * j;
    let (a_in, r_in, drag) = (&node.a_in, &node.r_in, &node.drag);
    let (c0, c1) = node.cells;
    // the low-side cell of the node as (ci, cj), the high-side one at the low boundary
    let [lo, hi] = c.cells(i, j, true);
    let low_cell = lo.or(hi);
    let (mut a_out, mut r_out) = ([0.0; N], [0.0; N]);
    eliminate_node(
        &a_in[..=m],
        &r_in[..=m],
        &node.phi[..=m],
        &drag[..m],
        &mut a_out[..=m],
        &mut r_out[..=m],
    );
    // relaxed centre coefficients (relaxation.rs), d_g (docs/model.md §4.6), e_s (§4.7)
    let omega = relax.omega;
    let gas_ap = a_out[0] / omega;
    let eps_face_g = face_mean(gas.eps, c0, c1);
    let mut numerator = eps_face_g;
    let mut denominator = a_in[0] / omega;
    for (p, sc) in solids.iter_mut().enumerate() {
        let links = sc.a.a_w[k] + sc.a.a_e[k] + sc.a.a_s[k] + sc.a.a_n[k];
        let base = relax.solids_bases[p];
        let a_s = base.relaxed_centre(a_in[p + 1], links, omega);
        let f = drag[p];
        let (eps, phi) = (sc.phase.eps(), c.pick(&sc.phase.u, &sc.phase.v));
        let eps_face_s = face_mean(eps, c0, c1);
        numerator += eps_face_s * f / (a_s + f);
        denominator += f * a_s / (a_s + f);
        if node.dilute[p] {
            dilute_row(sc.a, c, (i, j), phi[k], low_cell, eps);
            sc.e[k] = 0.0;
            continue;
        }
        sc.e[k] = area / a_s;
        let ap = base.relaxed_centre(a_out[p + 1], links, omega);
        let false_inertia = match base {
            // as MFIX writes it, (1 − ω) a_P/ω
            RelaxationBase::Centre => (1.0 - omega) * ap,
            RelaxationBase::OwnPart => ap - a_out[p + 1],
        };
        sc.a.b[k] += (r_out[p + 1] - r_in[p + 1]) + false_inertia * phi[k];
        sc.a.a_p[k] = ap;
    }
    let gas_phi = c.pick(gas.u, gas.v);
    gas.a.b[k] += (r_out[0] - r_in[0]) + (1.0 - omega) * gas_ap * gas_phi[k];
    gas.a.a_p[k] = gas_ap;
    gas.d[k] = area * numerator / denominator;
    if c.periodic {
        // a periodic column has no x gradient of P'_g or of K_cp ε'
        gas.d[k] = 0.0;
        solids.iter_mut().for_each(|s| s.e[k] = 0.0);
    }
}

/// Fixed (wall) nodes of component `c`: the gas holds its wall's velocity (its inflow
/// through a distributor, else zero), the solids zero; no d or e. The nodes a `gate` closes
/// hold zero for every phase, as a wall's.
fn fix_wall_rows(
    c: Component,
    inflow: &Sides<Vec<f64>>,
    gate: &[bool],
    gas: &mut GasComponent<'_>,
    solids: &mut [SolidsComponent<'_>],
) {
    for k in 0..gas.d.len() {
        let closed = gate.get(k).copied().unwrap_or(false);
        if gas.a.pattern().fixed_mask()[k] || closed {
            let wall_velocity = if closed {
                0.0
            } else {
                c.wall_inflow(inflow, k)
            };
            fixed_row(gas.a, k, wall_velocity);
            gas.d[k] = 0.0;
            for s in solids.iter_mut() {
                fixed_row(s.a, k, 0.0);
                s.e[k] = 0.0;
            }
        }
    }
}

/// Mean of a cell field over the (one or two) cells beside a face.
fn face_mean(field: &[f64], c0: Option<usize>, c1: Option<usize>) -> f64 {
    match (c0, c1) {
        (Some(a), Some(b)) => 0.5 * (field[a] + field[b]),
        (Some(c), None) | (None, Some(c)) => field[c],
        (None, None) => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use runout_linsolve::Pattern;

    /// One interior u-node of a 2 × 1 grid with one solids phase: the decoupled rows and
    /// d_g, e_s are the module doc's formulas.
    #[test]
    fn decoupled_node_stores_d_and_e_of_the_module_doc() {
        let (nx, ny) = (2, 1);
        let pu = Pattern::new(nx + 1, ny).unwrap();
        let pv = Pattern::new(nx, ny + 1).unwrap();
        let pc = Pattern::new(nx, ny).unwrap();
        let mut solids = PhaseWork::new((nx, ny), &pu, &pv, &pc);
        let mut state = super::super::State::new((nx, ny), 1.0, [1.0], 0.0);
        state.update_solids(0, |p| {
            p.eps.copy_from_slice(&[0.4, 0.6]);
            p.u.copy_from_slice(&[0.0, 0.2, 0.0]);
        });
        let (mut a_g, mut d) = (Stencil5::new(pu), vec![0.0; nx + 1]);
        let (u_g, v_g, eps_g) = (vec![0.0, 1.0, 0.0], vec![0.0; nx * (ny + 1)], [0.6, 0.4]);
        let mut gas = GasComponent {
            a: &mut a_g,
            d: &mut d,
            u: &u_g,
            v: &v_g,
            eps: &eps_g,
        };
        let (a_gas, a_s, f, relax, area) = (3.0, 2.0, 5.0, 0.5, 0.1);
        let mut node = CoupledNode::<2>::new((Some(0), Some(1)));
        node.a_in[..2].copy_from_slice(&[a_gas, a_s]);
        node.r_in[..2].copy_from_slice(&[1.0, 0.5]);
        node.phi[..2].copy_from_slice(&[1.0, 0.2]);
        node.drag[0] = f;
        let c = Component::u(nx, ny, false);
        let coef = PhaseCoefficients::new((nx, ny));
        let [su, _] = solids.components(&state.phases()[0], &coef);
        let relaxation = Relax {
            omega: relax,
            solids_bases: [RelaxationBase::Centre; MAX_SOLIDS_PHASES],
        };
        decouple(c, (1, 0), area, relaxation, &node, &mut gas, &mut [su]);
        let (ag, as_) = (a_gas / relax, a_s / relax);
        let d_expected = area * (0.5 + 0.5 * f / (as_ + f)) / (ag + f * as_ / (as_ + f));
        assert!((d[1] - d_expected).abs() < 1e-15 * d_expected);
        assert_eq!(solids.e_u[1], area / as_);
        // the gas row: a_g + F a_s/(a_s + F), relaxed (docs/model.md §4.5)
        let a_g_out = (a_gas + f * a_s / (a_s + f)) / relax;
        assert!((a_g.a_p[1] - a_g_out).abs() < 1e-14 * a_g_out);
    }
}
