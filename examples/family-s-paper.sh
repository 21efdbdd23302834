#!/usr/bin/env bash
# Family S at the paper grid (cases/sensitivity/, 30 cases, 1000 × 90 cells to t = 1.536 s),
# one case at a time on one niced thread, each recorded in the ledger
# (docs/reports/results/ledger/paper.csv) as it finishes; a case whose run folder already has
# a summary.json is skipped, so a killed run resumes (the interrupted case from its
# checkpoint). About 8–16 min a case on this kind of machine.
# usage: examples/family-s-paper.sh [XTASK]
#   XTASK: an xtask binary to use throughout (e.g. a copy of target/release/xtask), so that
#   rebuilding the checkout meanwhile does not change the solver between cases; default
#   `cargo xtask`. A sweep reads every case file under cases/: a binary older than a change
#   of the case format refuses the newer files, so copy the binary after such a change.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
if [ -n "${1:-}" ]; then cmd=("$1"); else cmd=(cargo xtask); fi
cases=$("${cmd[@]}" sweep --fidelity paper --list 2>/dev/null | grep -o '^ *S-[^ ]*' | tr -d ' ')
for c in $cases; do
  # `--only` matches names containing CASE (S-PS-hu_hu=1 runs hu = 10 and 100 too); a
  # ledger row is replaced, so every finished case is recorded again after each sweep
  [ -f "runs/$c/paper/summary.json" ] ||
    RAYON_NUM_THREADS=1 nice -n 19 "${cmd[@]}" sweep --fidelity paper --only "$c" --jobs 1
  for d in $cases; do
    [ -f "runs/$d/paper/summary.json" ] && "${cmd[@]}" ledger add "runs/$d/paper" > /dev/null
  done
  echo "$(date -u +%H:%M) $c"
done
