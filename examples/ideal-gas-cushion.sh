#!/usr/bin/env bash
# The paper's air-cushion cases (S-JJ-phi, φ = 1 and 0.1) with air as an ideal gas beside the
# shipped constant density (issue 60 item 1; docs/model.md §1.4): a copy of
# cases/sensitivity/base.ron whose gas is `IdealGas(molar_mass: 0.028965, temperature:
# 294.15)` (1.2000 kg/m³ at 101 325 Pa, the shipped density), both run by the same binary,
# then the station numbers of `runout post` side by side.
# usage: examples/ideal-gas-cushion.sh OUT [FIDELITY]   (FIDELITY: coarse (default) or wall)
#   coarse: four runs of 250 × 23 cells, minutes each on one niced thread
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(mkdir -p "$1" && cd "$1" && pwd)
fidelity=${2:-coarse}
runout=${RUNOUT:-"$root/target/release/runout"}
mkdir -p "$out/cases"
sed 's/^    gas: (density: 1.2, viscosity: 1.8e-5, reference_pressure: 101325.0),$/    gas: (density: 1.2, viscosity: 1.8e-5, reference_pressure: 101325.0, law: IdealGas(molar_mass: 0.028965, temperature: 294.15)),/' \
  "$root/cases/sensitivity/base.ron" > "$out/cases/base-ideal.ron"
grep -q 'law: IdealGas' "$out/cases/base-ideal.ron" || { echo "base.ron's gas line changed: edit this script" >&2; exit 1; }
cp "$root/cases/sensitivity/base.ron" "$out/cases/base.ron"
for law in constant ideal; do
  base=base.ron; [ "$law" = ideal ] && base=base-ideal.ron
  cat > "$out/cases/S-JJ-phi-$law.ron" <<RON
Sweep(
    name: "S-JJ-phi-$law",
    base: "$base",
    set: [SolidsWalls([JohnsonJackson(specularity: 0.1, wall_restitution: 0.7, wall_friction_angle: 11.0)]), Diameter([5e-4])],
    vary: [Specularity([1.0, 0.1])],
)
RON
done
# the two sweep files only (the folder would run its bases too)
for law in constant ideal; do
  RAYON_NUM_THREADS=1 nice -n 19 "$runout" sweep "$out/cases/S-JJ-phi-$law.ron" --fidelity "$fidelity" --jobs 1 --out "$out"
done
printf '| case | gas | air cushion | cushion thickness [m] | floor εs | flow thickness [m] | max u_s [m/s] | front at the station [m] | mean u_s there [m/s] | steps | outer iterations | wall time [s] |\n|---|---|---|---|---|---|---|---|---|---|---|---|\n'
for phi in 1 0.1; do
  for law in constant ideal; do
    dir="$out/runs/S-JJ-phi-${law}_phi=$phi/$fidelity"
    "$runout" post "$dir" 2>/dev/null | python3 -c "
import json, sys
m = json.load(sys.stdin); f = m['flow']; s = m['summary']
print('| φ = $phi | $law | {} | {:.4f} | {:.6f} | {:.4f} | {:.6f} | {:.4f} | {:.6f} | {} | {} | {:.0f} |'.format(
    f['air_cushion'], f['cushion_thickness'], f['floor_eps_s'], f['flow_thickness'], f['max_u_s'],
    m['front_x'], m['mean_u_s'], s['steps'], s['outer_iterations'], s['wall_time']))"
  done
done
