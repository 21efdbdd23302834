#!/usr/bin/env bash
# Issue 20's behaviour-preserving check: runs the smoke sweep, family M against MFIX and the
# stability suite in one checkout and collects their outputs without wall times, so that two
# checkouts (before and after a change) can be compared with `diff -r OUT_BEFORE OUT_AFTER`.
# usage: examples/constraint-check.sh CHECKOUT OUT   (CHECKOUT builds in CHECKOUT/target)
set -euo pipefail
co=$(realpath "$1"); out=$(realpath -m "$2")
cd "$co"
export CARGO_TARGET_DIR="$co/target"
rm -rf runs/*/smoke results/summary.csv
mkdir -p "$out"
cargo xtask sweep --fidelity smoke > "$out/sweep.log" 2>&1
cargo xtask verify mfix-slope --skip-variants > "$out/mfix.log" 2>&1
cargo xtask stability --fidelity smoke > "$out/stability.log" 2>&1
git checkout docs/   # the two verify commands rewrite their committed pages
grep '^| 1 ' "$out/mfix.log" | cut -d'|' -f2-8 > "$out/mfix-row.txt"          # steps, rejected, outer it.
grep '^| ST' "$out/stability.log" | cut -d'|' -f2-10 > "$out/stability-rows.txt"
grep ',smoke,' results/summary.csv | cut -d, -f1-3,5- | sort > "$out/summary-smoke.csv"
python3 - "$co/runs" "$out/runs" <<'PY'
import json, os, shutil, sys
runs, out = os.path.realpath(sys.argv[1]), sys.argv[2]
n = 0
for root, _, files in os.walk(runs):
    rel = os.path.relpath(root, runs)
    if 'smoke' not in rel.split(os.sep):
        continue
    for f in files:
        src, dst = os.path.join(root, f), os.path.join(out, rel, f)
        if not f.endswith(('.csv', '.vtr', '.json', '.txt')):
            continue
        os.makedirs(os.path.dirname(dst), exist_ok=True)
        if f == 'summary.json':  # drop what depends on the machine's speed
            d = {k: v for k, v in json.load(open(src)).items()
                 if not any(w in k for w in ('wall', 'profile', 'time_s', 'cpu'))}
            json.dump(d, open(dst, 'w'), indent=1, sort_keys=True)
        else:
            shutil.copy(src, dst)
        n += 1
print('collected', n, 'files')
PY
