#!/bin/bash
# Kill-and-restart check of one run (issue 21): runs CASE uninterrupted, then again with a
# SIGTERM after KILL_AFTER seconds of wall time and a `--restart`, and compares the two:
# the summaries' steps, rejected steps, outer iterations and Δt statistics, and every
# monitor and field file byte for byte.
#
#   cargo build --release -p runout-cli
#   examples/restart-check.sh cases/mfix-slope/jj.ron paper 20     # family M at MFIX's grid
#
# Arguments: CASE (a case file) FIDELITY (smoke|coarse|paper) KILL_AFTER (seconds);
# the runs go to runs/restart-check/{whole,killed}.
set -euo pipefail
case_file=${1:?case file}
fidelity=${2:-paper}
kill_after=${3:-20}
bin=target/release/runout
dir=runs/restart-check
rm -rf "$dir"
mkdir -p "$dir"
echo "uninterrupted run"
$bin run "$case_file" --fidelity "$fidelity" --out "$dir/whole" --quiet
echo "run to be killed after $kill_after s"
$bin run "$case_file" --fidelity "$fidelity" --out "$dir/killed" --quiet &
pid=$!
sleep "$kill_after"
kill -TERM "$pid"
status=0
wait "$pid" || status=$?
echo "exit status $status (130: interrupted with a checkpoint)"
grep -E '"(status|simulated_time|steps)"' "$dir/killed/summary.json"
echo "restart"
$bin run "$case_file" --fidelity "$fidelity" --restart "$dir/killed" --quiet
python3 - "$dir" <<'PY'
import json, sys, pathlib
d = pathlib.Path(sys.argv[1])
a = json.loads((d / "whole/summary.json").read_text())
b = json.loads((d / "killed/summary.json").read_text())
keys = ["status", "simulated_time", "steps", "rejected_steps", "outer_iterations", "dt",
        "solids_mass_change", "max_eps_s"]
for k in keys:
    print(f"{k:20} uninterrupted {a[k]!s:60} restarted {b[k]!s} {'same' if a[k] == b[k] else 'DIFFERENT'}")
print(f"{'wall_time':20} uninterrupted {a['wall_time']:.1f} s, restarted (both parts) {b['wall_time']:.1f} s")
files = sorted(p.name for p in (d / "whole").iterdir() if p.is_file() and p.name not in ("summary.json",))
diff = [f for f in files if (d / "whole" / f).read_bytes() != (d / "killed" / f).read_bytes()]
print(f"{len(files)} files compared byte for byte: {'all equal' if not diff else 'DIFFERENT: ' + ', '.join(diff)}")
sys.exit(1 if diff or any(a[k] != b[k] for k in keys) else 0)
PY
