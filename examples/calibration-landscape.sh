#!/usr/bin/env bash
# Issue 62's miss: the misfit landscape of a calibration at a truth it was not built on.
# A copy of cases/mfix-slope/jj.ron with specularity TRUTH is run at coarse fidelity; its
# interpolated fronts at t = 0.2, 0.3, …, 1.0 s (the bulk.csv rows nearest) are the
# measurements with σ = 5 mm; `runout calibrate` then scans specularity on N log-spaced
# points over [0.01, 1] with no refinement (every evaluation printed), and evaluates the
# truth itself.
# usage: examples/calibration-landscape.sh OUT [TRUTH] [N]     e.g. OUT=/tmp/c62, 0.45, 20
set -euo pipefail
out=$(realpath -m "$1"); truth=${2:-0.45}; n=${3:-20}
root=$(cd "$(dirname "$0")/.." && pwd)
runout="$root/target/release/runout"
[ -x "$runout" ] || (cd "$root" && cargo build --release -p runout-cli)
mkdir -p "$out"
sed "s/specularity: 0.1,/specularity: $truth,/" "$root/cases/mfix-slope/jj.ron" > "$out/truth.ron"
grep -q "specularity: $truth," "$out/truth.ron"
[ -f "$out/truth-run/bulk.csv" ] || "$runout" run "$out/truth.ron" --fidelity coarse --out "$out/truth-run" > "$out/truth.log"
python3 - "$out" <<'PY'
import sys
out = sys.argv[1]
rows = [l.strip().split(',') for l in open(f"{out}/truth-run/bulk.csv")]
h, data = rows[0], [list(map(float, r)) for r in rows[1:]]
t, x = h.index('t'), h.index('front_x_interpolated')
lines = ["t,x"]
for target in [0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]:
    r = min(data, key=lambda r: abs(r[t] - target))
    lines.append(f"{r[t]},{r[x]}")
open(f"{out}/front.csv", "w").write("\n".join(lines) + "\n")
PY
cd "$out"
for start in 0.05 "$truth"; do
  "$runout" calibrate truth.ron --param "specularity=0.01:1:$start:log" --measurements front.csv \
    --sigma 0.005 --fidelity coarse --scan "$n" --refine 0 --profile 0 --jobs 1 --out "$out/cal" \
    2>&1 | grep "specularity =" || true
  n=1
done | sort -t= -k2 -g | uniq
