//! Finite-volume transport assembly on a structured block of control volumes
//! (docs/model.md §4.2–4.3): first-order upwind in the matrix, Superbee through deferred
//! correction in the source, and diffusion through face conductances.
//!
//! The block has `mx × my` nodes, x fastest. Face arrays hold, for every face of the block
//! including its outer faces, the mass flux F (positive in +x or +y) and the diffusion
//! conductance D = Γ A / δ. Outer faces must carry D = 0 and their convective effect is the
//! caller's business (walls have F = 0; outlets are zero-gradient, docs/model.md §3).

use runout_linsolve::{for_each_row, Stencil5};

use crate::direction::{Direction, X, Y};

/// Convection scheme (MFIX `DISCRETIZE` 0 and 2, docs/model.md §4.2).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scheme {
    /// first-order upwind
    Upwind,
    /// Superbee TVD limiter, applied by deferred correction (MFIX `DEF_COR = .TRUE.`)
    Superbee,
}

/// Mass fluxes and conductances on the faces of a block.
#[derive(Clone, Debug)]
pub struct FaceData {
    /// nodes in x
    pub mx: usize,
    /// nodes in y
    pub my: usize,
    /// F on x-faces: index i + (mx+1) j is the face west of node (i, j) [kg s⁻¹ per m depth]
    pub flux_x: Vec<f64>,
    /// F on y-faces: index i + mx j is the face south of node (i, j)
    pub flux_y: Vec<f64>,
    /// D on x-faces [kg s⁻¹ per m depth]
    pub cond_x: Vec<f64>,
    /// D on y-faces
    pub cond_y: Vec<f64>,
    /// the Superbee deferred-correction flux δ of every interior x-face, written by
    /// [`assemble_masked`]
    pub correction_x: Vec<f64>,
    /// δ of every interior y-face
    pub correction_y: Vec<f64>,
}

impl FaceData {
    /// All zero, for a block of `mx × my` nodes.
    pub fn zeros(mx: usize, my: usize) -> Self {
        FaceData {
            mx,
            my,
            flux_x: vec![0.0; (mx + 1) * my],
            flux_y: vec![0.0; mx * (my + 1)],
            cond_x: vec![0.0; (mx + 1) * my],
            cond_y: vec![0.0; mx * (my + 1)],
            correction_x: vec![0.0; (mx + 1) * my],
            correction_y: vec![0.0; mx * (my + 1)],
        }
    }

    /// Index of the x-face west of node (i, j), i in 0..=mx.
    #[inline]
    pub fn xf(&self, i: usize, j: usize) -> usize {
        i + (self.mx + 1) * j
    }

    /// Index of the y-face south of node (i, j), j in 0..=my.
    #[inline]
    pub fn yf(&self, i: usize, j: usize) -> usize {
        i + self.mx * j
    }
}

/// Superbee's limited weight ξ of the downwind value in φ_f = φ_C + ξ (φ_D − φ_C), from the
/// normalised variable φ̃_C = (φ_C − φ_U)/(φ_D − φ_U) (docs/model.md §4.2, MFIX
/// `discretization_mod.f`): with t = φ̃/(1 − φ̃), ξ = ½ max(0, min(1, 2t), min(2, t));
/// ξ = 1 at φ̃ = 1 and 0 outside [0, 1).
#[inline]
pub fn superbee_weight(up: f64, centre: f64, down: f64) -> f64 {
    let denom = down - up;
    if denom == 0.0 {
        return 0.0;
    }
    let phi_tilde = (centre - up) / denom;
    if phi_tilde == 1.0 {
        return 1.0;
    }
    if !(0.0..1.0).contains(&phi_tilde) {
        return 0.0;
    }
    let t = phi_tilde / (1.0 - phi_tilde);
    0.5 * (2.0 * t).min(1.0).max(t.min(2.0)).max(0.0)
}

/// Value of a cell field on the face between cells `lo` and `hi` (indices into `field`, `lo`
/// on the low-coordinate side) for a velocity `vel` (positive from lo to hi): the upwind
/// value, or with Superbee the TVD value φ_C + ξ (φ_D − φ_C) using the far-upwind cell
/// (`lo_lo` or `hi_hi`; upwind where it does not exist), never above the upwind value.
/// This is how MFIX forms the face
/// densities of the continuity equations and of the momentum fluxes (docs/model.md §4.2,
/// `conv_rop.f`, `DISCRETIZE(1..2)`).
#[inline]
pub fn face_value(
    scheme: Scheme,
    field: &[f64],
    lo_lo: Option<usize>,
    lo: usize,
    hi: usize,
    hi_hi: Option<usize>,
    vel: f64,
) -> f64 {
    let (up, centre, down) = if vel >= 0.0 {
        (lo_lo, field[lo], field[hi])
    } else {
        (hi_hi, field[hi], field[lo])
    };
    match (scheme, up) {
        // capped at the upwind value: a face never carries more than its donor cell holds,
        // so the implicit continuity update keeps εs ≥ 0 and no mass is created by clipping
        // (MFIX clips ρε at 0 instead, docs/model.md §4.7; the cap only matters where the flow
        // runs into a denser cell, the front sharpening of Superbee is kept)
        (Scheme::Superbee, Some(u)) => {
            (centre + superbee_weight(field[u], centre, down) * (down - centre)).min(centre)
        }
        _ => centre,
    }
}

/// The deferred-correction flux F (φ_f − φ_C) through one face whose upwind node is C,
/// downwind node D and far-upwind node U (`None` at a block edge: no correction).
#[inline]
fn correction(flux: f64, up: Option<f64>, centre: f64, down: f64) -> f64 {
    match up {
        Some(u) => flux * superbee_weight(u, centre, down) * (down - centre),
        None => 0.0,
    }
}

/// Fills a_e, a_w, a_n, a_s (upwind + diffusion) and sets a_p = Σ a_nb and b = the
/// deferred-correction source (zero for upwind). The continuity-subtracted form of
/// docs/model.md §4.3 is used: a_P carries no net-outflow term. Transient, pressure, body
/// force and wall terms are added by the caller afterwards.
pub fn assemble(faces: &mut FaceData, phi: &[f64], scheme: Scheme, a: &mut Stencil5) {
    assemble_masked(faces, phi, scheme, None, a);
}

/// [`assemble`], leaving the rows of the nodes marked in `skip` untouched, b included
/// (the caller replaces those rows; their faces' fluxes must be zero unless a neighbour
/// is active).
pub fn assemble_masked(
    faces: &mut FaceData,
    phi: &[f64],
    scheme: Scheme,
    skip: Option<&[bool]>,
    a: &mut Stencil5,
) {
    let superbee = scheme == Scheme::Superbee;
    if superbee {
        deferred_corrections(faces, phi);
    }
    let faces = &*faces;
    let (mx, my) = (faces.mx, faces.my);
    // each node's row from its own faces, rows in parallel
    a.par_fill_rows(|j, row| {
        for i in 0..mx {
            let k = i + mx * j;
            if skip.is_some_and(|s| s[k]) {
                continue;
            }
            let (w, e) = (faces.xf(i, j), faces.xf(i + 1, j));
            let (s, n) = (faces.yf(i, j), faces.yf(i, j + 1));
            let (fe, fw) = (faces.flux_x[e], faces.flux_x[w]);
            let (fn_, fs) = (faces.flux_y[n], faces.flux_y[s]);
            let ae = faces.cond_x[e] + (-fe).max(0.0);
            let aw = faces.cond_x[w] + fw.max(0.0);
            let an = faces.cond_y[n] + (-fn_).max(0.0);
            let as_ = faces.cond_y[s] + fs.max(0.0);
            // outer faces have no neighbour in the block
            row.a_e[i] = if i + 1 < mx { ae } else { 0.0 };
            row.a_w[i] = if i > 0 { aw } else { 0.0 };
            row.a_n[i] = if j + 1 < my { an } else { 0.0 };
            row.a_s[i] = if j > 0 { as_ } else { 0.0 };
            row.a_p[i] = row.a_e[i] + row.a_w[i] + row.a_n[i] + row.a_s[i];
            let mut b = 0.0;
            if superbee {
                // δ enters through the west/south face and leaves through the east/north
                // face; nothing where F = 0, e.g. where a phase is absent
                if i > 0 && fw != 0.0 {
                    b += faces.correction_x[w];
                }
                if i + 1 < mx && fe != 0.0 {
                    b -= faces.correction_x[e];
                }
                if j > 0 && fs != 0.0 {
                    b += faces.correction_y[s];
                }
                if j + 1 < my && fn_ != 0.0 {
                    b -= faces.correction_y[n];
                }
            }
            row.b[i] = b;
        }
    });
}

/// The Superbee deferred-correction flux δ = F (φ_f − φ_upwind) of every interior face
/// with F ≠ 0 (docs/model.md §4.2), rows in parallel; the others keep a stale value that
/// [`assemble_masked`] does not read.
fn deferred_corrections(faces: &mut FaceData, phi: &[f64]) {
    let FaceData {
        mx,
        my,
        flux_x,
        flux_y,
        correction_x,
        correction_y,
        ..
    } = faces;
    let dims = (*mx, *my);
    corrections_along::<X>(dims, flux_x, phi, correction_x);
    corrections_along::<Y>(dims, flux_y, phi, correction_y);
}

/// [`deferred_corrections`] of the faces normal to direction `D` of an `mx` × `my` block:
/// the face (a, b) between nodes a − 1 and a, with its fluxes `flux` and corrections `out`
/// (the far-upwind node two before the upwind one, none beyond the block).
fn corrections_along<D: Direction>(
    (mx, my): (usize, usize),
    flux: &[f64],
    phi: &[f64],
    out: &mut [f64],
) {
    let n_a = D::pick(mx, my);
    let row_len = D::row_len(mx);
    let value = |a: usize, b: usize| phi[D::cell(a, b, mx)];
    for_each_row(out, row_len, |j, row| {
        for (i, delta) in row.iter_mut().enumerate() {
            let (a, b) = D::ab(i, j);
            if a == 0 || a >= n_a {
                continue;
            }
            let f = flux[i + row_len * j];
            if f == 0.0 {
                continue; // not read (assemble_masked)
            }
            *delta = if f > 0.0 {
                let up = (a >= 2).then(|| value(a - 2, b));
                correction(f, up, value(a - 1, b), value(a, b))
            } else {
                let up = (a + 1 < n_a).then(|| value(a + 1, b));
                correction(f, up, value(a, b), value(a - 1, b))
            };
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn superbee_weight_limits() {
        // smooth monotone data (φ̃ = ½, t = 1): ξ = ½ (central differencing)
        assert!((superbee_weight(0.0, 1.0, 2.0) - 0.5).abs() < 1e-15);
        // extremum: first order
        assert_eq!(superbee_weight(0.0, 3.0, 2.0), 0.0);
        // steep: ξ = min(1, 2t)/2 for small t
        let w = superbee_weight(0.0, 0.1, 1.0);
        let t: f64 = 0.1 / 0.9;
        assert!((w - 0.5 * (2.0 * t)).abs() < 1e-15);
        assert_eq!(superbee_weight(1.0, 1.0, 1.0), 0.0);
    }
}
