#!/usr/bin/env bash
# Issue 58's relaxation regression: one family-S case run with the shipped numerics and with
# one setting changed at a time (MFIX's relaxation 0.5/0.5/0.8; MFIX's pooled momentum
# residual, with family S's and with MFIX's relaxation; an outer-iteration tolerance of
# 1e-4; the conservative momentum form, docs/model.md §4.3, with family S's and with MFIX's
# relaxation), each a copy of cases/sensitivity/{base,SWEEP}.ron with `numerics`/`run.tolerances`
# edited; prints each variant's floor front (εs ≥ 0.01) at the station time and at 1.3, 1.4
# and 1.5 s (bulk.csv's interpolated front), max u_s, steps and outer iterations.
# usage: [VARIANTS="shipped conservative ..."] examples/relaxation-check.sh FIDELITY OUT [SWEEP] [ONLY]
#   e.g. examples/relaxation-check.sh coarse /tmp/r58            (S-JEN-d, d = 0.5 mm)
set -euo pipefail
fidelity=$1; out=$(realpath -m "$2"); sweep=${3:-S-JEN-d}; only=${4:-d=0.0005}
root=$(cd "$(dirname "$0")/.." && pwd)
runout="$root/target/release/runout"
[ -x "$runout" ] || (cd "$root" && cargo build --release -p runout-cli)
edit() {  # variant, sed expression on base.ron
  mkdir -p "$out/$1"
  cp "$root/cases/sensitivity/base.ron" "$root/cases/sensitivity/$sweep.ron" "$out/$1/"
  [ -z "$2" ] || sed -i "$2" "$out/$1/base.ron"
}
edit shipped ""
edit mfix-relaxation 's/relaxation: (velocity: 0.7, theta: 1.0, pressure: 1.0,/relaxation: (velocity: 0.5, theta: 0.5, pressure: 0.8,/'
pooled='s/tolerances: (residual: 1e-3,/tolerances: (momentum_residual: Pooled, residual: 1e-3,/'
edit pooled "$pooled"
edit pooled-mfix-relaxation "$pooled;s/relaxation: (velocity: 0.7, theta: 1.0, pressure: 1.0,/relaxation: (velocity: 0.5, theta: 0.5, pressure: 0.8,/"
edit tolerance-1e-4 's/tolerances: (residual: 1e-3,/tolerances: (residual: 1e-4,/'
conservative='s/dilute_cells: FrozenWhenCycling,/dilute_cells: FrozenWhenCycling, momentum_form: Conservative,/'
edit conservative "$conservative"
edit conservative-mfix-relaxation "$conservative;s/relaxation: (velocity: 0.7, theta: 1.0, pressure: 1.0,/relaxation: (velocity: 0.5, theta: 0.5, pressure: 0.8,/"
edit conservative-tolerance-1e-4 "$conservative;s/tolerances: (residual: 1e-3,/tolerances: (residual: 1e-4,/"
edit conservative-mfix-relaxation-1e-4 "$conservative;s/tolerances: (residual: 1e-3,/tolerances: (residual: 1e-4,/;s/relaxation: (velocity: 0.7, theta: 1.0, pressure: 1.0,/relaxation: (velocity: 0.5, theta: 0.5, pressure: 0.8,/"
variants=${VARIANTS:-shipped mfix-relaxation pooled pooled-mfix-relaxation tolerance-1e-4 conservative conservative-mfix-relaxation}
for v in $variants; do
  RAYON_NUM_THREADS=${RAYON_NUM_THREADS:-1} "$runout" sweep "$out/$v/$sweep.ron" --only "$only" \
    --fidelity "$fidelity" --out "$out/$v/out" --jobs 1 > "$out/$v.log" 2>&1
  dir=$(ls -d "$out/$v/out/runs/"*"/$fidelity")
  metrics=$("$runout" post "$dir" 2>/dev/null)
  front=$(echo "$metrics" | grep -m1 '"front_x"' | tr -dc '0-9.')
  umax=$(echo "$metrics" | grep -m1 '"max_u_s"' | tr -dc '0-9.')
  hist=$(awk -F, 'NR>1 && (($1>=1.2995 && $1<1.3045) || ($1>=1.3995 && $1<1.4045) || ($1>=1.4995 && $1<1.5045)) {printf " %.2f s: %.3f m", $1, $5}' "$dir/bulk.csv")
  wall=$(grep -o '[0-9.]* s wall' "$out/$v.log" | head -1)
  its=$(grep -o '"outer_iterations": *[0-9]*' "$dir/summary.json" | tr -dc '0-9')
  steps=$(grep -o '"steps": *[0-9]*' "$dir/summary.json" | tr -dc '0-9')
  echo "$v: front at the station $front m, max u_s $umax m/s;$hist; $steps steps, $its outer iterations ($wall)"
done
