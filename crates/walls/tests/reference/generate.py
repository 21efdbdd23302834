#!/usr/bin/env python3
"""Independent reference values for runout-walls.

Written directly from the text of docs/model.md §2.2, §2.4.2, §2.6 (wall Wen-Yu)
and §3.5-3.8 (not from the Rust code), with plain `math`. Run from this directory:

    python3 generate.py            # writes values.json next to this script

The Rust integration test `tests/reference.rs` reads values.json and compares every wall
coefficient at a relative tolerance of 1e-12. Where the spec offers two equivalent forms, the
one NOT used by the Rust code is used here: the JJ theta coefficients through the combined
factor K = rho_s eps_s g0 sqrt(theta) (h = pi sqrt3 (1-e_w^2) K/(4 eps_max)), the Jenkins
h_theta as (3/8) sqrt(3/theta) (1 - e_w) P_k, g0 as the three-term Carnahan-Starling sum.
"""
import json
import math
import os

PI = math.pi

# ---- the paper's sensitivity-analysis values (paper Table 3, docs/model.md §5) ----------------
D_P = 5e-4            # particle diameter [m]
RHO_S = 2000.0        # solids density [kg/m3]
E = 0.9               # particle-particle restitution
E_W = 0.7             # particle-wall restitution
PHI_W_DEG = 11.0      # wall friction angle
PHI_DEG = 35.0        # internal friction angle
EPS_MAX = 0.65        # 1 - EP_STAR
EPS_MIN = 0.5         # EPS_F_MIN
RHO_G = 1.2
MU_G = 1.8e-5
ALPHA = 1.6
SMALL = 1e-15         # SMALL_NUMBER
LARGE = 1e32          # LARGE_NUMBER
DIL_EP_S = 1e-4
THETA_WALL = 1e-8     # theta <= 0 at the wall
SDDS_FLOOR = 1e-10    # S:S floor at the wall (calc_s_ddot_s.f)
FR, N_PC, D_PC, N_PF, DELTA = 0.05, 2.0, 5.0, 1.03, 0.01

ETA = (1.0 + E) / 2.0
SIN_PHI = math.sin(math.radians(PHI_DEG))
TAN_W = math.tan(math.radians(PHI_W_DEG))


def g0_cs(es):
    return 1.0 / (1.0 - es) + 1.5 * es / (1.0 - es) ** 2 + 0.5 * es ** 2 / (1.0 - es) ** 3


def dga_wen_yu_wall(es, vrel):
    """docs/model.md §2.6 last bullet: Re = eps_g rho_g d |v|/mu_g, DgA = 0.75 Cd rho_g eps_g |v|/(d eps_g^2.65)."""
    if vrel == 0.0:
        return LARGE
    eg = 1.0 - es
    re = eg * RHO_G * D_P * vrel / MU_G
    cd = 24.0 / (re + SMALL) * (1.0 + 0.15 * re ** 0.687) if re < 1000.0 else 0.44
    return 0.75 * cd * RHO_G * eg * vrel / (D_P * eg ** 2.65)


def lun(es, th, vrel, gas=True):
    """docs/model.md §2.2 table with F_gs/eps_s = DgA."""
    g0 = g0_cs(es)
    xi = es * g0
    mu0 = 5.0 / 96.0 * RHO_S * D_P * math.sqrt(PI * th)
    mub = 256.0 / (5.0 * PI) * mu0 * es * xi
    k0 = 75.0 * RHO_S * D_P * math.sqrt(PI * th) / (48.0 * ETA * (41.0 - 33.0 * ETA))
    if not gas:
        mus, ks = mu0, k0
    elif th < SMALL:
        mus, ks = 0.0, 0.0
    else:
        dga = dga_wen_yu_wall(es, vrel)
        mus = RHO_S * es * g0 * th * mu0 / (RHO_S * xi * th + 2.0 * dga * mu0 / RHO_S)
        ks = RHO_S * es * g0 * th * k0 / (RHO_S * xi * th + 1.2 * dga * k0 / RHO_S)
    mu = (2.0 + ALPHA) / 3.0 * (mus / (ETA * (2.0 - ETA) * g0) * (1.0 + 1.6 * ETA * xi)
                                * (1.0 + 1.6 * ETA * (3.0 * ETA - 2.0) * xi) + 0.6 * ETA * mub)
    kappa = ks / g0 * ((1.0 + 2.4 * ETA * xi) * (1.0 + 2.4 * ETA ** 2 * (4.0 * ETA - 3.0) * xi)
                       + 64.0 / (25.0 * PI) * (41.0 - 33.0 * ETA) * ETA ** 2 * xi ** 2)
    p = RHO_S * es * th * (1.0 + 4.0 * ETA * xi)
    return dict(g0=g0, mu=mu, kappa=kappa, p=p)


def princeton(es, th, trd, sdds):
    """docs/model.md §2.4.2 steps 1-5 (SAVAGE = 2)."""
    zeta = math.sqrt(th / D_P ** 2 + sdds)
    at = EPS_MAX - DELTA
    if es > at:
        pc_at = FR * (at - EPS_MIN) ** N_PC / DELTA ** D_PC
        slope = FR * (N_PC * (at - EPS_MIN) ** (N_PC - 1) / DELTA ** D_PC
                      + D_PC * (at - EPS_MIN) ** N_PC / DELTA ** (D_PC + 1))
        pc = pc_at + slope * (es - at)
    else:
        pc = FR * (es - EPS_MIN) ** N_PC / (EPS_MAX - es) ** D_PC
    n = math.sqrt(3.0) / (2.0 * SIN_PHI) if trd >= 0.0 else N_PF
    r = trd / (n * math.sqrt(2.0) * SIN_PHI * zeta)
    if r > 1.0:
        ratio = 0.0
    elif trd == 0.0:
        ratio = 1.0
    else:
        ratio = (1.0 - r) ** (n - 1.0)
    pf = pc * ratio
    mf = math.sqrt(2.0) * pf * SIN_PHI * (n - (n - 1.0) * ratio ** (1.0 / (n - 1.0)))
    cap = (n / (n - 1.0)) ** (n - 1.0)
    if ratio > cap:
        pf, mf = pc * cap, 0.0
    return dict(pf=pf, muf=mf / (2.0 * zeta), zeta=zeta)


# ---- §3.7 Li & Benyahia ---------------------------------------------------------------------
K_LB = 3.5 * TAN_W * (1.0 + E_W)
POLY = [-0.0012596340709032689, 0.10645510095633175, -0.04281476447854031,
        0.009759402181229842, -0.0012508257938705263, 0.00008369829630479206,
        -0.000002269550565981776]


def phi0_of(k):
    if k <= 0.2:
        return 0.09094568176225006 * k
    return sum(c * k ** j for j, c in enumerate(POLY))


PHI0 = phi0_of(K_LB)
C7 = 7.0 * math.sqrt(6.0 * PI)
R_SWITCH = 4.0 * K_LB / (C7 * PHI0)


def phi_lb(slip, th):
    r = slip / math.sqrt(3.0 * th)
    if r <= R_SWITCH:
        return PHI0 - C7 * PHI0 ** 2 / (8.0 * K_LB) * r
    return 2.0 * K_LB / (C7 * r)


# ---- §3.5 / §3.8 momentum -------------------------------------------------------------------
def momentum(model, phi_const, st):
    es_f, es, th, slip, vrel, trd, sdds, snn = (st[k] for k in (
        "eps_s_fluid", "eps_s", "theta", "slip", "gas_slip", "tr_d", "s_ddot_s", "s_nn"))
    if es_f <= DIL_EP_S:
        return dict(h=0.0, col=0.0, fri=0.0, mu_k=0.0, mu_f=0.0, phi=None)
    if th <= 0.0:
        th = THETA_WALL
    kt = lun(es, th, vrel)
    phi = None
    if model == "jenkins":
        col = 0.0 if slip == 0.0 else TAN_W * kt["p"] / slip
    else:
        phi = phi_const if model == "jj" else phi_lb(slip, th)
        col = phi * math.sqrt(3.0 * th) * PI * RHO_S * es * kt["g0"] / (6.0 * EPS_MAX)
    fri, muf = 0.0, 0.0
    if es_f > EPS_MIN:
        if es > EPS_MIN:
            fr = princeton(es, th, trd, max(SDDS_FLOOR, sdds))
            fri = TAN_W * (fr["pf"] - 2.0 * fr["muf"] * snn)
            muf = fr["muf"]
        h = 0.0 if slip == 0.0 else (col + fri) / (kt["mu"] + muf)
    else:
        h = col / kt["mu"]
    return dict(h=h, col=col, fri=fri, mu_k=kt["mu"], mu_f=muf, phi=phi)


# ---- §3.6 / §3.8 granular temperature ---------------------------------------------------------
def theta_bc(model, phi_const, st):
    es, th, slip, vrel = st["eps_s"], st["theta"], st["slip"], st["gas_slip"]
    if es <= DIL_EP_S:
        return dict(g=1.0, h=0.0, c=0.0, phi=None)
    if th <= 0.0:
        th = THETA_WALL
    kt = lun(es, th, vrel)
    if model == "jenkins":
        h = 0.375 * math.sqrt(3.0 / th) * (1.0 - E_W) * kt["p"]
        c = 21.0 / 16.0 * TAN_W ** 2 * (1.0 + E_W) * math.sqrt(3.0 * th) * kt["p"]
        return dict(g=kt["kappa"], h=h, c=c, phi=None)
    phi = phi_const if model == "jj" else phi_lb(slip, th)
    k_fac = RHO_S * es * kt["g0"] * math.sqrt(th)
    h = PI * math.sqrt(3.0) * (1.0 - E_W ** 2) * k_fac / (4.0 * EPS_MAX)
    c = PI * math.sqrt(3.0) * phi * k_fac * slip ** 2 / (6.0 * EPS_MAX)
    return dict(g=kt["kappa"], h=h, c=c, phi=phi)


MOMENTUM_STATES = [
    # name, eps_s_fluid, eps_s (interpolated), theta, slip, gas_slip, tr_d, s_ddot_s, s_nn
    ("dense_sliding", 0.58, 0.57, 0.01, 5.0, 0.5, 0.0, 5000.0, 0.0),
    ("kinetic_below_min", 0.3, 0.31, 0.5, 2.0, 0.1, 0.0, 100.0, 0.0),
    ("near_packing_dilating", 0.645, 0.64, 1e-4, 1.5, 0.05, 0.5, 50.0, -2.0),
    ("compacting", 0.62, 0.615, 2e-3, 3.0, 0.2, -3.0, 400.0, 1.5),
    ("zero_slip_dense", 0.6, 0.6, 0.02, 0.0, 0.0, 0.0, 0.0, 0.0),
    ("fluid_above_interp_below_min", 0.52, 0.49, 0.05, 1.0, 0.3, 0.0, 10.0, 0.0),
    ("negative_theta", 0.55, 0.55, -1e-6, 4.0, 1.0, 0.0, 1e-12, 0.0),
    ("dilute_cushion", 0.03, 0.04, 2.2, 6.0, 2.0, 0.0, 1e4, 0.0),
    ("dilute_skip", 5e-5, 1e-3, 0.1, 1.0, 0.0, 0.0, 0.0, 0.0),
]
THETA_STATES = [
    # name, eps_s (fluid cell), theta, slip, gas_slip
    ("dense", 0.58, 0.01, 5.0, 0.5),
    ("kinetic", 0.3, 0.5, 2.0, 0.1),
    ("cushion", 0.03, 2.2, 6.0, 2.0),
    ("zero_slip", 0.6, 0.02, 0.0, 0.0),
    ("negative_theta", 0.55, -1e-6, 4.0, 1.0),
    ("dilute_skip", 5e-5, 0.1, 1.0, 0.0),
]
MODELS = [("jj", 1.0), ("jj", 0.1), ("jj", 0.01), ("rjj", None), ("jenkins", None)]


def main():
    mom_keys = ("eps_s_fluid", "eps_s", "theta", "slip", "gas_slip", "tr_d", "s_ddot_s", "s_nn")
    th_keys = ("eps_s", "theta", "slip", "gas_slip")
    out = {
        "parameters": dict(d_p=D_P, rho_s=RHO_S, e=E, wall_restitution=E_W,
                           wall_friction_angle_deg=PHI_W_DEG, phi_internal_deg=PHI_DEG,
                           eps_s_max=EPS_MAX, eps_s_min=EPS_MIN, rho_g=RHO_G, mu_g=MU_G),
        "li_benyahia": dict(k=K_LB, phi0=PHI0, r_switch=R_SWITCH,
                            table=[dict(r=r, phi=phi_lb(r * math.sqrt(3.0), 1.0))
                                   for r in (0.0, 0.5, 1.0, R_SWITCH, 2.0, 5.0, 10.0)]),
        "momentum": [],
        "theta": [],
    }
    for name, *vals in MOMENTUM_STATES:
        st = dict(zip(mom_keys, vals))
        for model, phi in MODELS:
            out["momentum"].append(dict(state=name, model=model, specularity=phi, **st,
                                        result=momentum(model, phi, st)))
    for name, *vals in THETA_STATES:
        st = dict(zip(th_keys, vals))
        for model, phi in MODELS:
            out["theta"].append(dict(state=name, model=model, specularity=phi, **st,
                                     result=theta_bc(model, phi, st)))
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "values.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
    print(f"wrote {path}: k = {K_LB:.7f}, phi0 = {PHI0:.7f}, r* = {R_SWITCH:.5f}")


if __name__ == "__main__":
    main()
