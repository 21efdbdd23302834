#!/usr/bin/env bash
# How long pore pressure lasts (docs/guide/gas.md): `runout pore-pressure` for glass beads
# (2500 kg/m3, Gidaspow drag, Princeton's stiffness under the bed's own weight) in air at
# 1 atm, packed at εs 0.58 and dilated to 0.50, over grain sizes and layer heights; prints
# the guide's markdown table.
# Usage: examples/gas-matters.sh [RUNOUT]   (default target/release/runout; ~1 s)
set -euo pipefail
RUNOUT=${1:-target/release/runout}
HEIGHTS=0.03,0.3,3
FORMAT='
import json, sys
v = json.load(sys.stdin)
def t(x):
    return "%.3g ms" % (x * 1e3) if x < 1 else "%.3g s" % x
def row(key):
    return " / ".join(t(h[key]) for h in v["heights"])
cells = ["%g µm" % (v["inputs"]["material"]["diameter"] * 1e6),
         "%.3g" % v["bed"]["u_mf"], "%.3g" % v["diffusivity"]["rigid"],
         row("half_time_rigid"), row("half_time_self_weight"), row("settling_time")]
print("| " + " | ".join(cells) + " |")
'
echo "| d | U_mf [m/s] | D rigid [m²/s] | t½ rigid (3 cm / 0.3 m / 3 m) | t½ under its own weight | settling from εs 0.50 |"
echo "|---|---|---|---|---|---|"
for d in 4e-5 8e-5 1.6e-4 5e-4 2e-3; do
  "$RUNOUT" pore-pressure --eps-s 0.58 --dilated-eps-s 0.5 --heights "$HEIGHTS" \
    --diameter "$d" --density 2500 --gas-density 1.2041 --drag gidaspow | python3 -c "$FORMAT"
done
