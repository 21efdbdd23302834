"""The floor's excess gas pressure under a released column, over the weight of the solids above it
(issue 60 item 4's exploration, examples/fluidised-release/). usage: pore_pressure.py RUN_DIR
For each snapshot from the gate's opening on and stations x = 0.05 (the reservoir), 0.15, 0.3,
0.5, 0.7 m: W = Σ εs ρs g Δy of the column above the floor cell [Pa], the floor cell's gas
pressure less the top row's and the gas's hydrostatic column, and their ratio r (1: the gas
carries the whole weight)."""
import glob, re, sys

RHO_S, G, RHO_G = 2500.0, 9.81, 1.2


def array(xml, name):
    m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, xml, re.S)
    return [float(v) for v in m.group(1).split()]


for f in sorted(glob.glob(sys.argv[1] + "/fields_*.vtr")):
    xml = open(f).read()
    t = array(xml, "TimeValue")[0]
    if t < 0.5 - 1e-9:
        continue
    xs, ys = array(xml, "x"), array(xml, "y")
    nx, ny, dx, dy = len(xs) - 1, len(ys) - 1, xs[1] - xs[0], ys[1] - ys[0]
    eps, p = array(xml, "eps_s"), array(xml, "p_g")
    cells = []
    for x in [0.05, 0.15, 0.3, 0.5, 0.7]:
        i = int(x / dx)
        w = sum(eps[i + nx * j] for j in range(ny)) * RHO_S * G * dy
        excess = p[i] - p[i + nx * (ny - 1)] - RHO_G * G * (ny - 1) * dy
        ratio = f"{excess / w:.2f}" if w > 1.0 else "-"
        cells.append(f"x {x}: W {w:6.1f} Pa, excess {excess:6.1f} Pa, r {ratio}")
    print(f"t {t:.2f} s | " + " | ".join(cells))
