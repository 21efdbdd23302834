#!/usr/bin/env bash
# Defluidisation against pore-pressure diffusion (issue 60 item 3, exploration): cases/gas/
# defluidisation.ron at gas pressures P and bed heights H (domain 1.5 H,
# 2.5 mm cells). The bed settles for 0.2 s, air enters through the floor for
# max(1 s, 3 H²/D) (D the rigid bed's diffusivity, below), and the floor is closed for
# max(0.4 s, 6 k half times) more, k = 8 at 1 atm and 1.5 below (the compaction's slowing). `half_time.py` then gives the basal excess
# pressure's half time after the floor closes against the rigid bed's t½ = 0.1967 H²/D,
# D = P εg/β (Gidaspow's Ergun branch at the bed's mean εs), and t½/H².
# At 1 kPa the gas stores ~10× more per pascal than the bed's frictional compaction does, so
# the bed is nearly rigid; at 1 atm the compaction dominates.
# usage: examples/defluidisation/run.sh OUT [P:H ...]   (default 101325:0.05 101325:0.1
#   101325:0.2, minutes on one thread; at 1000 Pa the time step collapses to ~1e-5 s — 0.56 M
#   steps for 1000:0.05 — with a constant density as with the ideal gas: not understood yet)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
out=$(mkdir -p "$1" && cd "$1" && pwd)
runout=${RUNOUT:-"$root/target/release/runout"}
py() { python3 -c "print($1)"; }
out_runs=("${@:2}")
[ ${#out_runs[@]} -gt 0 ] || out_runs=(101325:0.05 101325:0.1 101325:0.2)
for run in "${out_runs[@]}"; do
  p=${run%%:*}; h=${run##*:}
  # D ≈ P εg/β with εg ≈ 0.42, β ≈ 3.4e5 kg/m³/s; t½ ≈ 0.2 H²/D
  d=$(py "$p * 0.42 / 3.4e5"); half=$(py "0.2 * $h * $h / $d")
  k=$(py "8 if $p > 5e4 else 1.5")
  off=$(py "round(0.2 + max(1.0, 3 * $h * $h / $d), 4)")
  end=$(py "round($off + max(0.4, 6 * $k * $half), 4)")
  # air at 0.1 mm/s (1 kPa) or 2 mm/s (1 atm): an excess of a few % of P, below fluidisation
  u=$(py "1e-4 if $p < 5e4 else 2e-3")
  rho=$(py "round($p * 0.028965 / (8.314462618 * 293.15), 6)")
  name="p$p-h$h"
  sed -e "s/Uniform(length: 0.15, cells: 60)/Uniform(length: $(py "1.5 * $h"), cells: $(py "round(1.5 * $h / 0.0025)"))/" \
      -e "s/y: (0.0, 0.1), solids/y: (0.0, $h), solids/" \
      -e "s/density: 1.2041,/density: $rho,/" \
      -e "s/reference_pressure: 101325.0,/reference_pressure: $p.0,/" \
      -e "s/Hydrostatic(101325.0)/Hydrostatic($p.0)/" \
      -e "s/rate: Velocity(0.002), from: 0.2, until: 1.2/rate: Velocity($u), from: 0.2, until: $off/" \
      -e "s/end_time: 1.5/end_time: $end/g" \
      -e "s/max: 2e-4,/max: $(py "$half / 200"),/" \
      -e "s/min: 1e-8,/min: $(py "2e-9 * $end"),/" \
      -e "s/output_interval: 1e-3,/output_interval: $(py "$half / 50"),/" \
      -e "s/name: \"defluidisation\"/name: \"defluidisation-$name\"/" \
      "$root/cases/gas/defluidisation.ron" > "$out/$name.ron"
  [ -f "$out/$name/summary.json" ] ||
    RAYON_NUM_THREADS=1 "$runout" run "$out/$name.ron" --fidelity coarse --out "$out/$name" | tail -1
  echo "$name $off" >> "$out/shut-off-times"
done
sort -u "$out/shut-off-times" | while read -r name off; do
  printf '%s: ' "$name"; python3 "$here/half_time.py" "$out/$name" "$off"
done
