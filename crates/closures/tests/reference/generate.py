#!/usr/bin/env python3
"""Independent reference values for runout-closures.

Written directly from the text of docs/model.md §1.3 and §2 (not from the
Rust code), with plain `math`. Run from this directory:

    python3 generate.py            # writes values.json next to this script

The Rust integration test `tests/reference.rs` reads values.json and compares every
closure at a relative tolerance of 1e-12. Where the spec gives two equivalent forms of
a formula, the form NOT used by the Rust code is used here (e.g. the collisional
dissipation as 12(1-e^2) rho_s eps_s^2 g0 theta^1.5/(d sqrt(pi)) and the Carnahan-Starling
g0 as the three-term sum), so that a transcription slip in either would show.
"""
import json
import math
import os

PI = math.pi

# ---- parameters: the paper's sensitivity-analysis values (paper Table 3, spec §5) ----
D_P = 5e-4          # particle diameter [m]
RHO_S = 2000.0      # solids density [kg/m3]
E = 0.9             # particle-particle restitution [-]
EPS_MAX = 0.65      # 1 - EP_STAR
EPS_MIN = 0.5       # EPS_F_MIN
PHI_DEG = 35.0      # internal friction angle
RHO_G = 1.2
MU_G = 1.8e-5
ALPHA = 1.6         # spec §2.2
SMALL = 1e-15       # SMALL_NUMBER, spec §2.7
LARGE = 1e32        # LARGE_NUMBER (MFIX param1_mod.f)
# Princeton constants, spec §2.4.2
FR, N_PC, D_PC, N_PF, DELTA = 0.05, 2.0, 5.0, 1.03, 0.01
# Schaeffer constants, spec §2.4.1
A_PSTAR, B_PSTAR, MU_MAX = 1e24, 10, 100.0

ETA = (1.0 + E) / 2.0
SIN_PHI = math.sin(math.radians(PHI_DEG))


# ---- §2.1 radial distribution -------------------------------------------------------
def g0_cs(es):
    # three-term Carnahan-Starling form; equals (1 - es/2)/(1 - es)^3
    return 1.0 / (1.0 - es) + 1.5 * es / (1.0 - es) ** 2 + 0.5 * es ** 2 / (1.0 - es) ** 3


def dg0_cs(es):
    return (2.5 - es) / (1.0 - es) ** 4


def g0_ma(es):
    x = min(es, 0.643)
    num = 1.0 + 2.5 * x + 4.5094 * x ** 2 + 4.515439 * x ** 3
    return num / (1.0 - (x / 0.64356) ** 3) ** 0.678021


def dg0_ma(es):
    if es > 0.643:
        return 0.0
    x = es
    num = 1.0 + 2.5 * x + 4.5094 * x ** 2 + 4.515439 * x ** 3
    dnum = 2.5 + 2 * 4.5094 * x + 3 * 4.515439 * x ** 2
    den = (1.0 - (x / 0.64356) ** 3) ** 0.678021
    dden = 0.678021 * (1.0 - (x / 0.64356) ** 3) ** (0.678021 - 1.0) * (-3.0 * x ** 2 / 0.64356 ** 3)
    return (dnum * den - num * dden) / den ** 2


# ---- §2.2 Lun et al. (1984) as MFIX codes it ----------------------------------------
def kinetic(es, th, g0, dga):
    """dga = None: dry (rho_g = 0); else drag per unit solids fraction F_gs/eps_s."""
    xi = es * g0
    p = RHO_S * es * th * (1.0 + 4.0 * ETA * xi)
    mu0 = 5.0 / 96.0 * RHO_S * D_P * math.sqrt(PI * th)
    mub = 256.0 / (5.0 * PI) * mu0 * es * xi
    if dga is None:
        mus = mu0
    elif th < SMALL:
        mus = 0.0
    else:
        f_gs = es * dga
        mus = RHO_S * es * g0 * th * mu0 / (RHO_S * xi * th + 2.0 * f_gs * mu0 / (RHO_S * es))
    mu = (2.0 + ALPHA) / 3.0 * (
        mus / (ETA * (2.0 - ETA) * g0) * (1.0 + 8.0 / 5.0 * ETA * xi)
        * (1.0 + 8.0 / 5.0 * ETA * (3.0 * ETA - 2.0) * xi) + 3.0 / 5.0 * ETA * mub)
    lam = ETA * mub - 2.0 / 3.0 * mu
    k0 = 75.0 * RHO_S * D_P * math.sqrt(PI * th) / (48.0 * ETA * (41.0 - 33.0 * ETA))
    if dga is None:
        ks = k0
    elif th < SMALL:
        ks = 0.0
    else:
        f_gs = es * dga
        ks = RHO_S * es * g0 * th * k0 / (RHO_S * xi * th + 6.0 / 5.0 * f_gs * k0 / (RHO_S * es))
    kappa = ks / g0 * ((1.0 + 12.0 / 5.0 * ETA * xi) * (1.0 + 12.0 / 5.0 * ETA ** 2 * (4.0 * ETA - 3.0) * xi)
                       + 64.0 / (25.0 * PI) * (41.0 - 33.0 * ETA) * ETA ** 2 * xi ** 2)
    # dissipation, second form of spec §1.3
    gamma = 12.0 * (1.0 - E ** 2) * RHO_S * es ** 2 * g0 * th ** 1.5 / (D_P * math.sqrt(PI))
    return dict(p_kin=p, mu_dilute=mu0, mu_bulk=mub, mu_star=mus, mu_kin=mu, lambda_kin=lam,
                kappa_dilute=k0, kappa_star=ks, kappa_kin=kappa, dissipation=gamma)


# ---- §2.4.2 Princeton ---------------------------------------------------------------
def p_c(es):
    at = EPS_MAX - DELTA
    if es > at:
        pc_at = FR * (at - EPS_MIN) ** N_PC / DELTA ** D_PC
        slope = FR * (N_PC * (at - EPS_MIN) ** (N_PC - 1) / DELTA ** D_PC
                      + D_PC * (at - EPS_MIN) ** N_PC / DELTA ** (D_PC + 1))
        return pc_at + slope * (es - at)
    return FR * (es - EPS_MIN) ** N_PC / (EPS_MAX - es) ** D_PC


def dp_c(es):
    at = EPS_MAX - DELTA
    if es > at:
        # constant slope P_c' of spec §2.4.2 step 2, written with delta
        return FR * (N_PC * (at - EPS_MIN) ** (N_PC - 1) / DELTA ** D_PC
                     + D_PC * (at - EPS_MIN) ** N_PC / DELTA ** (D_PC + 1))
    return FR * (N_PC * (es - EPS_MIN) ** (N_PC - 1) / (EPS_MAX - es) ** D_PC
                 + D_PC * (es - EPS_MIN) ** N_PC / (EPS_MAX - es) ** (D_PC + 1))


def princeton(es, th, trd, ss):
    zero = dict(p_c=0.0, n=0.0, zeta=0.0, pf_over_pc=0.0, p_fric=0.0, mu_fric=0.0, lambda_fric=0.0, k_cp=0.0)
    if not es > EPS_MIN:
        return zero
    # theta >= theta_small = 1e-12 in every MFIX cell (spec §1.3, adjust_theta.f); the
    # floor keeps zeta > 0 when there is neither strain nor fluctuation
    zeta = math.sqrt(max(th, 1e-12) / D_P ** 2 + ss)
    pc = p_c(es)
    n = math.sqrt(3.0) / (2.0 * SIN_PHI) if trd >= 0 else N_PF
    r = trd / (n * math.sqrt(2.0) * SIN_PHI * zeta)
    if r > 1.0:
        ratio = 0.0
    elif trd == 0.0:
        ratio = 1.0
    else:
        ratio = (1.0 - r) ** (n - 1.0)
    # K_cp (§2.5): cap always with N_Pf, applied in the general branch only
    ratio_k = ratio
    cap_pf = (N_PF / (N_PF - 1.0)) ** (N_PF - 1.0)
    if r <= 1.0 and trd != 0.0 and ratio_k > cap_pf:
        ratio_k = cap_pf
    k_cp = ratio_k * dp_c(es)
    pf = pc * ratio
    mf = math.sqrt(2.0) * pf * SIN_PHI * (n - (n - 1.0) * ratio ** (1.0 / (n - 1.0)))
    cap = (n / (n - 1.0)) ** (n - 1.0)
    if ratio > cap:
        ratio = cap
        pf = pc * cap
        mf = 0.0
    mu = mf / (2.0 * zeta)
    return dict(p_c=pc, n=n, zeta=zeta, pf_over_pc=ratio, p_fric=pf, mu_fric=mu,
                lambda_fric=-2.0 / 3.0 * mu, k_cp=k_cp)


# ---- §2.4.1 Schaeffer ---------------------------------------------------------------
def schaeffer(es, ss):
    eg, eg_star = 1.0 - es, 1.0 - EPS_MAX
    pstar = A_PSTAR * max(0.0, eg_star - eg) ** B_PSTAR
    # dPodEP_s of solids_pressure_mod.f: written with (eps_g* - eps_g) like P* itself
    dpstar = B_PSTAR * A_PSTAR * max(0.0, eg_star - eg) ** (B_PSTAR - 1)
    i2 = ss / 2.0   # I2D = S:S/2 (second invariant of the deviatoric strain rate)
    mu = pstar * SIN_PHI ** 2 / (math.sqrt(4.0 * SIN_PHI ** 2 * i2) + SMALL)
    mu = min(mu, MU_MAX)
    # INV_H: eps_g = eps_g* - (P*/A)^(1/10)
    eps_g_back = eg_star - (pstar / A_PSTAR) ** (1.0 / B_PSTAR)
    return dict(p_star=pstar, dp_star_deps=dpstar, mu_schaeffer=mu, eps_g_from_p_star=eps_g_back)


# ---- §2.6 drag ----------------------------------------------------------------------
def cd_sn(re):
    return 24.0 * (1.0 + 0.15 * re ** 0.687) / (re + SMALL) if re <= 1000.0 else 0.44


def dga_so(eg, v, c1=0.8, d1=2.65):
    if eg == 0.0:
        return 0.0
    re = D_P * v * RHO_G / MU_G
    if re == 0.0:
        return 0.0
    a = eg ** 4.14
    b = c1 * eg ** 1.28 if eg <= 0.85 else eg ** d1
    vr = 0.5 * (a - 0.06 * re + math.sqrt((0.06 * re) ** 2 + 0.12 * re * (2.0 * b - a) + a * a))
    return 0.75 * MU_G * eg * (0.63 * math.sqrt(re / vr) + 4.8) ** 2 / (vr * D_P ** 2)


def ergun(eg, v):
    return 150.0 * (1.0 - eg) * MU_G / (eg * D_P ** 2) + 1.75 * RHO_G * v / D_P


def wen_yu(eg, v):
    re = D_P * v * RHO_G * eg / MU_G
    if re == 0.0:
        return 0.0
    return 0.75 * cd_sn(re) * v * RHO_G * eg * eg ** -2.65 / D_P


def dga_gidaspow(eg, v):
    re = D_P * v * RHO_G * eg / MU_G
    if re == 0.0:
        return 0.0
    return ergun(eg, v) if eg <= 0.8 else wen_yu(eg, v)


def dga_blend(eg, v):
    re = D_P * v * RHO_G * eg / MU_G
    if re == 0.0:
        return 0.0
    psi = math.atan(262.5 * (eg - 0.8)) / PI + 0.5
    return (1.0 - psi) * ergun(eg, v) + psi * wen_yu(eg, v)


def dga_wall(eg, v):
    # spec §2.6 last bullet; strict Re < 1000 as in calc_grbdry.f
    if v == 0.0:
        return LARGE
    re = eg * RHO_G * D_P * v / MU_G
    cd = 24.0 / (re + SMALL) * (1.0 + 0.15 * re ** 0.687) if re < 1000.0 else 0.44
    return 0.75 * cd * RHO_G * eg * v / (D_P * eg ** 2.65)


def kt_dga(eg, v):
    # MFIX kintheory_mod.f KT_DGA: single-particle Wen-Yu (no eps_g^-2.65), used below DIL_EP_S
    if v == 0.0:
        return LARGE
    rop = RHO_G * eg
    re = D_P * v * rop / (MU_G + SMALL)
    cd = 24.0 / (re + SMALL) * (1.0 + 0.15 * re ** 0.687) if re <= 1000.0 else 0.44
    return 0.75 * cd * v * rop / D_P


# ---- §1.3 granular-energy sources ---------------------------------------------------
def j_slip(es, th, g0, v):
    return 81.0 * es * MU_G ** 2 * v ** 2 / (g0 * D_P ** 3 * RHO_S * math.sqrt(PI) * math.sqrt(th + SMALL))


def production(p, mu, lam, trd, ss):
    trd2 = ss + trd ** 2 / 3.0
    return -p * trd + 2.0 * mu * trd2 + lam * trd ** 2


def main():
    out = {"parameters": dict(d_p=D_P, rho_s=RHO_S, e=E, eps_s_max=EPS_MAX, eps_s_min=EPS_MIN,
                              phi_internal_deg=PHI_DEG, rho_g=RHO_G, mu_g=MU_G)}
    eps_list = [0.0, 0.01, 0.3, 0.55, 0.6, 0.645, 0.649]
    out["radial"] = [dict(eps_s=es, g0_cs=g0_cs(es), dg0_cs=dg0_cs(es), g0_ma=g0_ma(es), dg0_ma=dg0_ma(es))
                     for es in eps_list + [0.65]]

    kt = []
    for es, th in [(0.01, 0.5), (0.3, 0.5), (0.55, 0.1), (0.6, 0.01), (0.645, 1e-3), (0.649, 1e-4)]:
        g0 = g0_cs(es)
        v = 0.3
        dga = dga_so(1.0 - es, v)
        kt.append(dict(eps_s=es, theta=th, g0=g0, dga=None, **kinetic(es, th, g0, None)))
        kt.append(dict(eps_s=es, theta=th, g0=g0, dga=dga, **kinetic(es, th, g0, dga)))
    out["kinetic"] = kt

    pr = []
    for es in [0.4, 0.55, 0.6, 0.63, 0.64, 0.645, 0.649, 0.65, 0.66]:
        for th, trd, ss in [(0.01, 0.0, 100.0), (0.01, 0.5, 100.0), (1e-3, -0.5, 4.0), (1e-4, 50.0, 1.0),
                            (1e-2, -30.0, 0.0), (1e-6, -1000.0, 0.0), (0.0, 0.0, 0.0)]:
            pr.append(dict(eps_s=es, theta=th, tr_d=trd, s_ddot_s=ss, **princeton(es, th, trd, ss)))
    out["princeton"] = pr
    out["critical_pressure"] = [dict(eps_s=es, p_c=p_c(es), dp_c=dp_c(es))
                                for es in [0.51, 0.55, 0.6, 0.63, 0.64, 0.645, 0.649, 0.65, 0.66]]

    out["schaeffer"] = [dict(eps_s=es, s_ddot_s=ss, **schaeffer(es, ss))
                        for es in [0.01, 0.6, 0.645, 0.649, 0.65, 0.651, 0.655, 0.66] for ss in [0.0, 1e-6, 100.0]]

    dr = []
    for es in [0.01, 0.1, 0.2, 0.3, 0.6, 0.645, 0.649]:
        eg = 1.0 - es
        for v in [0.0, 1e-3, 0.5, 5.0, 200.0]:
            dr.append(dict(eps_s=es, slip=v, syamlal_obrien=dga_so(eg, v), syamlal_obrien_custom=dga_so(eg, v, 0.7, 3.0),
                           gidaspow=dga_gidaspow(eg, v), gidaspow_blend=dga_blend(eg, v), wen_yu=wen_yu(eg, v),
                           wall_wen_yu=dga_wall(eg, v), kt_dga=kt_dga(eg, v)))
    out["drag"] = dr

    en = []
    for es, th, v, trd, ss in [(0.01, 0.5, 0.5, 0.1, 10.0), (0.3, 0.5, 2.0, -1.0, 50.0), (0.6, 0.01, 0.1, 0.5, 100.0),
                               (0.645, 1e-3, 0.0, 0.0, 1.0), (0.649, 0.0, 0.2, -0.2, 4.0)]:
        g0 = g0_cs(es)
        f_gs = es * dga_so(1.0 - es, v)
        k = kinetic(es, th, g0, None)
        en.append(dict(eps_s=es, theta=th, slip=v, tr_d=trd, s_ddot_s=ss, g0=g0, f_gs=f_gs,
                       j_vis=3.0 * f_gs * th, j_slip=j_slip(es, th, g0, v),
                       p_kin=k["p_kin"], mu_kin=k["mu_kin"], lambda_kin=k["lambda_kin"],
                       production=production(k["p_kin"], k["mu_kin"], k["lambda_kin"], trd, ss)))
    out["energy"] = en

    # the full closure set of one cell with gas (Syamlal-O'Brien) and Princeton friction
    DIL_EP_S = 1e-4
    cells = []
    for es, th, v, trd, ss in [(5e-5, 0.5, 0.5, 0.1, 10.0), (0.01, 0.5, 0.0, 0.0, 0.0), (0.01, 0.5, 0.5, 0.1, 10.0),
                               (0.3, 0.5, 2.0, -1.0, 50.0), (0.6, 0.01, 0.3, -0.5, 100.0),
                               (0.645, 1e-3, 0.1, 0.5, 1.0), (0.649, 1e-4, 0.2, -0.2, 4.0)]:
        g0 = g0_cs(es)
        dga = dga_so(1.0 - es, v)
        dga_k = kt_dga(1.0 - es, v) if es < DIL_EP_S else dga
        k = kinetic(es, th, g0, dga_k)
        f = princeton(es, th, trd, ss)
        f_gs = es * dga
        cells.append(dict(eps_s=es, theta=th, slip=v, tr_d=trd, s_ddot_s=ss, g0=g0, dga=dga, f_gs=f_gs,
                          dga_kinetic=dga_k, mu_star=k["mu_star"], mu_kin=k["mu_kin"], kappa_kin=k["kappa_kin"],
                          p_s=k["p_kin"] + f["p_fric"], mu_s=k["mu_kin"] + f["mu_fric"],
                          lambda_s=k["lambda_kin"] + f["lambda_fric"], k_cp=f["k_cp"],
                          production=production(k["p_kin"], k["mu_kin"], k["lambda_kin"], trd, ss),
                          j_vis=3.0 * f_gs * th, j_slip=j_slip(es, th, g0, v)))
    out["cell"] = cells

    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "values.json")
    with open(path, "w") as f:
        json.dump(out, f, indent=1)
        f.write("\n")

    # echo the spec's printed check values (§2.2, §2.4.2) for the record
    for es, th in [(0.3, 0.5), (0.55, 0.1)]:
        k = kinetic(es, th, g0_cs(es), None)
        print(f"eps_s={es} theta={th}: g0={g0_cs(es):.6g} P={k['p_kin']:.6g} mu={k['mu_kin']:.6g} "
              f"mu_b={k['mu_bulk']:.6g} lambda={k['lambda_kin']:.6g} kappa={k['kappa_kin']:.6g} "
              f"gamma={k['dissipation']:.6g}")
    for es, trd in [(0.6, 0.0), (0.645, 0.5)]:
        p = princeton(es, 0.01, trd, 100.0)
        print(f"princeton eps_s={es} trD={trd}: P_f={p['p_fric']:.6g} mu_f={p['mu_fric']:.6g}")
    at = EPS_MAX - DELTA
    print(f"P_c,at={p_c(at):.6g} P_c'={dp_c(0.66):.6g}")


if __name__ == "__main__":
    main()
