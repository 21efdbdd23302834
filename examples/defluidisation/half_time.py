"""The basal excess gas pressure's half time after the floor closes, against the rigid bed's
pore-pressure diffusion (examples/defluidisation/run.sh). usage: half_time.py RUN_DIR T_OFF"""
import glob, math, re, sys

MU, D_P, R, M, T = 1.8e-5, 8e-5, 8.314462618, 0.028965, 293.15


def array(xml, name):
    m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, xml, re.S)
    return [float(v) for v in m.group(1).split()]


def basal(tau):
    """p_base/p_0 of the rigid bed at τ = D t/H² (the Fourier series of the linear start)."""
    return sum(8 / ((2 * n + 1) ** 2 * math.pi ** 2)
               * math.exp(-((2 * n + 1) ** 2) * math.pi ** 2 * tau / 4) for n in range(200))


def tau_half():
    lo, hi = 0.0, 1.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if basal(mid) > 0.5 else (lo, mid)
    return 0.5 * (lo + hi)


run, t_off = sys.argv[1], float(sys.argv[2])
snaps = []
for f in sorted(glob.glob(run + "/fields_*.vtr")):
    xml = open(f).read()
    nx, ny = len(array(xml, "x")) - 1, len(array(xml, "y")) - 1
    dy = array(xml, "y")[1] - array(xml, "y")[0]
    p, eps = array(xml, "p_g"), array(xml, "eps_s")
    column = [sum(eps[i + nx * j] for i in range(nx)) / nx for j in range(ny)]
    snaps.append((array(xml, "TimeValue")[0], sum(p[:nx]) / nx, column))
p_end = snaps[-1][1]
at_off = [s for s in snaps if s[0] <= t_off + 1e-9][-1]
before = [s for s in snaps if s[0] <= t_off - 0.1 * (t_off - 0.2) + 1e-9][-1]
p0 = at_off[1] - p_end
bed = [e for e in at_off[2] if e > 0.3]
height = len(bed) * dy
eps_s = sum(bed) / len(bed)
eps_g = 1 - eps_s
beta = 150 * eps_s ** 2 * MU / (eps_g * D_P ** 2)
diffusivity = at_off[1] * eps_g / beta
rigid = tau_half() * height ** 2 / diffusivity
prev, measured = None, float("nan")
for s in snaps:
    if s[0] > t_off and s[1] - p_end <= 0.5 * p0:
        (t0, e0), (t1, e1) = (prev[0], prev[1] - p_end), (s[0], s[1] - p_end)
        measured = t0 + (0.5 * p0 - e0) * (t1 - t0) / (e1 - e0) - t_off
        break
    prev = s
settle = [e for e in snaps[-1][2] if e > 0.3]
print(f"H {height:.4f} m, bed εs {eps_s:.4f} (end {sum(settle) / len(settle):.4f}), β {beta:.4g} kg/m³/s, "
      f"D {diffusivity:.4g} m²/s; excess at shut-off {p0:.1f} Pa ({(before[1] - p_end) / p0:.4f} of it at 0.9 of the inflow time "
      f"); t½ {measured * 1e3:.2f} ms against the rigid bed's {rigid * 1e3:.2f} ms "
      f"(ratio {measured / rigid:.3f}); t½/H² {measured / height ** 2:.3f} s/m²")
