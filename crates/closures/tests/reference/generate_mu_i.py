#!/usr/bin/env python3
"""Independent reference values for the mu(I) friction of runout-closures (docs/model.md 2.4.3).

Written from the equations, not from the Rust code, with plain `math`, in the other algebraic
forms: mu(I) as mu_s + (mu_2 - mu_s)/(I_0/I + 1) (Jop, Forterre & Pouliquen 2006, Eq. 2;
the Rust code writes mu_s + dmu I/(I_0 + I)), the shear rate from the velocity gradient of
a 2-D flow (not from S:S), and the critical-state pressure written with (1 - eps_g)
(paper Eq. 10). Run from this directory:

    python3 generate_mu_i.py       # writes mu_i_values.json next to this script

`tests/mu_i_reference.rs` compares at a relative tolerance of 1e-12.
"""
import json
import math
import os

D_P = 5.3e-4        # glass beads of Jop et al. (2005) [m]
RHO_S = 2500.0      # [kg/m3]
EPS_MAX, EPS_MIN = 0.65, 0.5
FR, N_PC, D_PC, DELTA = 0.05, 2.0, 5.0, 0.01   # Princeton P_c (paper Eq. 10, MFIX constants)
MU_S = math.tan(math.radians(20.9))
MU_2 = math.tan(math.radians(32.76))
I_0 = 0.279
FLOOR = 1e-3


def p_c(es):
    """Critical-state pressure, written with the gas fraction eps_g = 1 - es."""
    eg = 1.0 - es
    eg_star = 1.0 - EPS_MAX
    if es <= EPS_MIN:
        return 0.0
    es_at = EPS_MAX - DELTA
    if es > es_at:
        p_at = FR * (es_at - EPS_MIN) ** N_PC / DELTA ** D_PC
        slope = FR * (N_PC * (es_at - EPS_MIN) ** (N_PC - 1) / DELTA ** D_PC
                      + D_PC * (es_at - EPS_MIN) ** N_PC / DELTA ** (D_PC + 1))
        return p_at + slope * (es - es_at)
    return FR * ((1.0 - eg) - EPS_MIN) ** N_PC / (eg - eg_star) ** D_PC


def mu_of_i(i):
    if i == 0.0:
        return MU_S
    return MU_S + (MU_2 - MU_S) / (I_0 / i + 1.0)


def shear_rate(dudx, dudy, dvdx, dvdy):
    """|gamma_dot| = sqrt(1/2 gdot_ij gdot_ij) of the deviator, gdot = grad u + grad u^T,
    in plane strain (3-D tensor with zero z row)."""
    tr = dudx + dvdy
    g = [[2 * dudx - 2 * tr / 3, dudy + dvdx, 0.0],
         [dudy + dvdx, 2 * dvdy - 2 * tr / 3, 0.0],
         [0.0, 0.0, -2 * tr / 3]]
    return math.sqrt(0.5 * sum(g[a][b] ** 2 for a in range(3) for b in range(3)))


def s_ddot_s(dudx, dudy, dvdx, dvdy):
    """S:S = tr(D^2) - (tr D)^2/3, the input the Rust closure takes."""
    dxy = 0.5 * (dudy + dvdx)
    tr = dudx + dvdy
    return dudx ** 2 + dvdy ** 2 + 2 * dxy ** 2 - tr ** 2 / 3


def stress(es, grad, p_kin):
    """mu(I) on the total solids pressure P_kin + P_c; only P_c is the added P_fric."""
    pc = p_c(es)
    p = p_kin + pc
    if p == 0.0:
        return dict(p_fric=0.0, mu_fric=0.0, inertial_number=0.0)
    rate = shear_rate(*grad)
    i = 0.0 if rate == 0.0 else D_P * rate * math.sqrt(RHO_S / p)
    return dict(p_fric=pc, mu_fric=mu_of_i(i) * p / math.sqrt(rate ** 2 + FLOOR ** 2),
                inertial_number=i)


def joined_viscosity(mu_kin, mu_fric):
    """The larger-of join (mu_kin^4 + mu_fric^4)^(1/4), written as the larger times
    (1 + (smaller/larger)^4)^(1/4) with Fraction arithmetic for the fourth powers."""
    from fractions import Fraction
    big, small = max(mu_kin, mu_fric), min(mu_kin, mu_fric)
    if big == 0.0:
        return 0.0
    q4 = (Fraction(small) / Fraction(big)) ** 4
    return big * float(1 + q4) ** 0.25


def main():
    out = dict(parameters=dict(d_p=D_P, rho_s=RHO_S, eps_s_max=EPS_MAX, eps_s_min=EPS_MIN,
                               mu_s=MU_S, mu_2=MU_2, i_0=I_0, shear_rate_floor=FLOOR))
    out["law"] = [dict(i=i, mu=mu_of_i(i), dmu_di=(MU_2 - MU_S) / I_0 / (1 + i / I_0) ** 2)
                  for i in [0.0, 1e-6, 1e-3, 0.05, 0.279, 0.5, 2.0, 100.0]]
    rows = []
    for es in [0.45, 0.5, 0.55, 0.6, 0.635, 0.645, 0.66]:
        for grad in [(0.0, 0.0, 0.0, 0.0), (0.0, 1e-4, 0.0, 0.0), (0.0, 3.0, 0.0, 0.0),
                     (0.5, 20.0, -1.0, -2.0), (10.0, -100.0, 5.0, 4.0)]:
            for p_kin in [0.0, 0.37, 250.0]:
                row = dict(eps_s=es, s_ddot_s=s_ddot_s(*grad), p_kin=p_kin,
                           **stress(es, grad, p_kin))
                rows.append(row)
    out["stress"] = rows
    out["join"] = [dict(mu_kin=k, mu_fric=f, mu_s=joined_viscosity(k, f))
                   for k in [0.0, 1e-9, 0.003, 0.09, 1.0, 4.2]
                   for f in [0.0, 1e-12, 0.05, 0.09, 1.46, 1e4]]
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "mu_i_values.json"), "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
