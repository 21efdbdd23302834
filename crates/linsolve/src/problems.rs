//! Model problems on stretched grids for tests, benchmarks and examples.
//!
//! A structured 2-D grid is given by its face coordinates `xf` (nx + 1 values) and `yf`
//! (ny + 1 values), so this crate needs nothing from `runout-mesh`. The grids mimic the
//! paper's: cells of 0.02 m × 0.005 m (aspect ratio 4:1) in a focus band, growing by 10 %
//! per cell away from it.

use crate::{CellKind, LinSolveError, Pattern, Stencil5};

/// Parameters of a focus-band axis: uniform cells of width `h0` in the band, growing by
/// `growth` per cell away from it until they reach `max_ratio · h0`.
#[derive(Clone, Copy, Debug)]
pub struct FocusAxis {
    /// Width of the cells in the focus band, m.
    pub h0: f64,
    /// Growth ratio per cell outside the band (dimensionless).
    pub growth: f64,
    /// Largest cell width as a multiple of `h0` (dimensionless).
    pub max_ratio: f64,
    /// Band as fractions of the cell count, `[start, end)`.
    pub band: (f64, f64),
}

impl FocusAxis {
    /// The paper-like x axis: 0.02 m cells in the middle half, growth 1.1, up to 10 h0.
    pub fn paper_x() -> Self {
        Self {
            h0: 0.02,
            growth: 1.1,
            max_ratio: 10.0,
            band: (0.25, 0.75),
        }
    }
    /// The paper-like y axis (wall normal): 0.005 m cells in the lower half (the floor
    /// layer), growth 1.1 upwards, up to 10 h0.
    pub fn paper_y() -> Self {
        Self {
            h0: 0.005,
            growth: 1.1,
            max_ratio: 10.0,
            band: (0.0, 0.5),
        }
    }

    /// Face coordinates (n + 1 values, starting at 0) for `n` cells.
    pub fn faces(&self, n: usize) -> Vec<f64> {
        let start = (self.band.0 * n as f64).round() as usize;
        let end = ((self.band.1 * n as f64).round() as usize).clamp(start, n);
        let mut faces = Vec::with_capacity(n + 1);
        faces.push(0.0);
        for c in 0..n {
            let dist = if c < start {
                start - c
            } else if c >= end {
                c + 1 - end
            } else {
                0
            };
            let w = self.h0 * self.growth.powi(dist as i32).min(self.max_ratio);
            faces.push(faces[c] + w);
        }
        faces
    }
}

/// A grid for model problems.
#[derive(Clone, Debug)]
pub struct Grid {
    /// x faces (nx + 1).
    pub xf: Vec<f64>,
    /// y faces (ny + 1).
    pub yf: Vec<f64>,
}

impl Grid {
    /// Paper-like stretched grid with `nx × ny` cells.
    pub fn paper(nx: usize, ny: usize) -> Self {
        Self {
            xf: FocusAxis::paper_x().faces(nx),
            yf: FocusAxis::paper_y().faces(ny),
        }
    }
    /// Paper-like grid with about `cells` cells and nx = 2 ny.
    pub fn paper_with_cells(cells: usize) -> Self {
        let ny = ((cells as f64 / 2.0).sqrt().round() as usize).max(2);
        let nx = (cells as f64 / ny as f64).round() as usize;
        Self::paper(nx, ny)
    }
    /// Cells in x.
    pub fn nx(&self) -> usize {
        self.xf.len() - 1
    }
    /// Cells in y.
    pub fn ny(&self) -> usize {
        self.yf.len() - 1
    }
    /// Cell centre x.
    pub fn xc(&self, i: usize) -> f64 {
        0.5 * (self.xf[i] + self.xf[i + 1])
    }
    /// Cell centre y.
    pub fn yc(&self, j: usize) -> f64 {
        0.5 * (self.yf[j] + self.yf[j + 1])
    }
    /// Cell width Δx.
    pub fn dx(&self, i: usize) -> f64 {
        self.xf[i + 1] - self.xf[i]
    }
    /// Cell height Δy.
    pub fn dy(&self, j: usize) -> f64 {
        self.yf[j + 1] - self.yf[j]
    }
    /// Largest Δx/Δy or Δy/Δx over the grid.
    pub fn max_aspect_ratio(&self) -> f64 {
        let (dxs, dys): (Vec<f64>, Vec<f64>) = (
            (0..self.nx()).map(|i| self.dx(i)).collect(),
            (0..self.ny()).map(|j| self.dy(j)).collect(),
        );
        let mx = |v: &[f64]| v.iter().cloned().fold(0.0, f64::max);
        let mn = |v: &[f64]| v.iter().cloned().fold(f64::INFINITY, f64::min);
        (mx(&dxs) / mn(&dys)).max(mx(&dys) / mn(&dxs))
    }
}

/// A smooth manufactured solution on the grid, O(1), not aligned with the grid.
pub fn manufactured_solution(g: &Grid) -> Vec<f64> {
    let (lx, ly) = (g.xf[g.nx()], g.yf[g.ny()]);
    let mut x = Vec::with_capacity(g.nx() * g.ny());
    for j in 0..g.ny() {
        for i in 0..g.nx() {
            let (s, t) = (g.xc(i) / lx, g.yc(j) / ly);
            x.push((3.0 * s).sin() * (2.0 * t + 0.5).cos() + s * t + 0.3);
        }
    }
    x
}

/// Pressure-correction-like SPD system: cell-centred diffusion −∇·(Γ∇p') with a
/// coefficient Γ varying by a factor 10 (like ρ ε d of docs/model.md §4.6), Neumann walls on
/// all four sides and the reference cell (nx−1, ny−1) fixed (its value pinned). The
/// faces use the harmonic mean of Γ (docs/model.md §4.1). Returns the stencil with b = 0.
pub fn pressure_like(g: &Grid) -> Result<Stencil5, LinSolveError> {
    let (nx, ny) = (g.nx(), g.ny());
    let reference = (nx - 1, ny - 1);
    let pattern = Pattern::from_fn(nx, ny, |i, j| {
        if (i, j) == reference {
            CellKind::Fixed
        } else {
            CellKind::Active
        }
    })?;
    let (lx, ly) = (g.xf[nx], g.yf[ny]);
    let gamma = |i: usize, j: usize| {
        1.0 + 9.0 * (0.5 + 0.5 * (7.0 * g.xc(i) / lx + 5.0 * g.yc(j) / ly).sin())
    };
    let harmonic = |a: f64, b: f64, wa: f64, wb: f64| (wa + wb) / (wa / a + wb / b);
    let mut a = Stencil5::new(pattern);
    a.par_fill_rows(|j, row| {
        for i in 0..nx {
            if (i, j) == reference {
                row.a_p[i] = 1.0;
                continue;
            }
            let gp = gamma(i, j);
            if i + 1 < nx {
                let gf = harmonic(gp, gamma(i + 1, j), g.dx(i), g.dx(i + 1));
                row.a_e[i] = gf * g.dy(j) / (g.xc(i + 1) - g.xc(i));
            }
            if i > 0 {
                let gf = harmonic(gp, gamma(i - 1, j), g.dx(i), g.dx(i - 1));
                row.a_w[i] = gf * g.dy(j) / (g.xc(i) - g.xc(i - 1));
            }
            if j + 1 < ny {
                let gf = harmonic(gp, gamma(i, j + 1), g.dy(j), g.dy(j + 1));
                row.a_n[i] = gf * g.dx(i) / (g.yc(j + 1) - g.yc(j));
            }
            if j > 0 {
                let gf = harmonic(gp, gamma(i, j - 1), g.dy(j), g.dy(j - 1));
                row.a_s[i] = gf * g.dx(i) / (g.yc(j) - g.yc(j - 1));
            }
            row.a_p[i] = row.a_e[i] + row.a_w[i] + row.a_n[i] + row.a_s[i];
        }
    });
    Ok(a)
}

/// Momentum-like non-symmetric system: first-order upwind convection–diffusion with an
/// implicit-Euler transient term (MFIX form, Patankar 1980 §5.2), a divergence-free
/// recirculating velocity field from a stream function, Dirichlet (φ = 0) walls.
/// `peclet_max` is the largest cell Péclet number ρ|u|Δ/μ, `cfl` the largest |u|Δt/Δ.
pub fn momentum_like(g: &Grid, peclet_max: f64, cfl: f64) -> Result<Stencil5, LinSolveError> {
    let (nx, ny) = (g.nx(), g.ny());
    let (lx, ly) = (g.xf[nx], g.yf[ny]);
    let (rho, mu) = (1.0, 1.0);
    // ψ = sin(πx/Lx) sin(πy/Ly): u = ∂ψ/∂y, v = −∂ψ/∂x; face fluxes from ψ at face ends
    // are exactly divergence free
    let psi = |x: f64, y: f64| {
        (std::f64::consts::PI * x / lx).sin() * (std::f64::consts::PI * y / ly).sin()
    };
    let flux_e = |i: usize, j: usize| psi(g.xf[i + 1], g.yf[j + 1]) - psi(g.xf[i + 1], g.yf[j]);
    let flux_n = |i: usize, j: usize| -(psi(g.xf[i + 1], g.yf[j + 1]) - psi(g.xf[i], g.yf[j + 1]));
    // scale the velocity so that max cell Péclet = peclet_max
    let mut pe = 0.0f64;
    let mut courant = 0.0f64; // |u|/Δ with unit scale
    for j in 0..ny {
        for i in 0..nx {
            let u = (flux_e(i, j) / g.dy(j)).abs();
            let v = (flux_n(i, j) / g.dx(i)).abs();
            pe = pe.max(rho * u * g.dx(i) / mu).max(rho * v * g.dy(j) / mu);
            courant = courant.max(u / g.dx(i)).max(v / g.dy(j));
        }
    }
    let scale = peclet_max / pe;
    let dt = cfl / (courant * scale);
    let mut a = Stencil5::new(Pattern::new(nx, ny)?);
    a.par_fill_rows(|j, row| {
        for i in 0..nx {
            let (dx, dy) = (g.dx(i), g.dy(j));
            // face fluxes (positive in +x / +y) and diffusion conductances
            let fe = if i + 1 < nx {
                scale * rho * flux_e(i, j)
            } else {
                0.0
            };
            let fw = if i > 0 {
                scale * rho * flux_e(i - 1, j)
            } else {
                0.0
            };
            let fn_ = if j + 1 < ny {
                scale * rho * flux_n(i, j)
            } else {
                0.0
            };
            let fs = if j > 0 {
                scale * rho * flux_n(i, j - 1)
            } else {
                0.0
            };
            let de = mu * dy
                / if i + 1 < nx {
                    g.xc(i + 1) - g.xc(i)
                } else {
                    0.5 * dx
                };
            let dw = mu * dy
                / if i > 0 {
                    g.xc(i) - g.xc(i - 1)
                } else {
                    0.5 * dx
                };
            let dn = mu * dx
                / if j + 1 < ny {
                    g.yc(j + 1) - g.yc(j)
                } else {
                    0.5 * dy
                };
            let ds = mu * dx
                / if j > 0 {
                    g.yc(j) - g.yc(j - 1)
                } else {
                    0.5 * dy
                };
            row.a_e[i] = de + (-fe).max(0.0);
            row.a_w[i] = dw + fw.max(0.0);
            row.a_n[i] = dn + (-fn_).max(0.0);
            row.a_s[i] = ds + fs.max(0.0);
            // the links to the walls (φ_wall = 0) stay in a_P but drop out of the matrix
            row.a_p[i] = row.a_e[i]
                + row.a_w[i]
                + row.a_n[i]
                + row.a_s[i]
                + (fe - fw + fn_ - fs)
                + rho * dx * dy / dt;
        }
    });
    Ok(a)
}

/// Sets `a.b = A x` (manufactured right-hand side).
pub fn set_rhs_from_solution(a: &mut Stencil5, x: &[f64]) -> Result<(), LinSolveError> {
    let mut b = vec![0.0; a.len()];
    a.matvec(x, &mut b)?;
    a.b = b;
    Ok(())
}

/// Max-norm relative error ‖x − x_exact‖∞ / ‖x_exact‖∞.
pub fn rel_error_inf(x: &[f64], exact: &[f64]) -> f64 {
    let num = x
        .iter()
        .zip(exact)
        .fold(0.0f64, |m, (a, b)| m.max((a - b).abs()));
    let den = exact.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    num / den
}
