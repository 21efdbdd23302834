#!/usr/bin/env python3
"""Where a run that ends in a deposit spends its steps (issue 58; docs/studies/performance.md,
"The deposit phase's cost").

Usage:
    RUNOUT_LOG=runout_run=debug runout run CASE --fidelity coarse --out RUN 2> RUN.log
    python3 examples/deposit-cost.py RUN.log RUN/bulk.csv

Reads the run's step log (one `step` line per attempted step: time, dt, outer iterations,
converged) and its bulk.csv (the εs-weighted mean u_s), and splits the run at the times the
mean speed falls below 50 %, 10 % and 1 % of its peak (after the peak). For each phase it
prints the simulated time, the accepted and rejected steps, the mean Δt, the outer
iterations per accepted step, the phase's share of all outer iterations (the work) and of the
log's wall-clock time (noisy on a loaded machine).
"""
import csv
import re
import sys
from datetime import datetime

STEP = re.compile(
    r"^(\S+Z).*? step time=(\S+) dt=(\S+) iterations=(\d+) converged=(true|false)"
)
ANSI = re.compile(r"\x1b\[[0-9;]*m")


def read_steps(log_path):
    steps = []
    with open(log_path, encoding="utf-8") as f:
        for line in f:
            m = STEP.match(ANSI.sub("", line))
            if m:
                stamp = datetime.fromisoformat(m.group(1).replace("Z", "+00:00"))
                steps.append(
                    (stamp.timestamp(), float(m.group(2)), float(m.group(3)),
                     int(m.group(4)), m.group(5) == "true")
                )
    return steps


def phase_bounds(bulk_path):
    with open(bulk_path, encoding="utf-8") as f:
        rows = [(float(r["t"]), float(r["mean_u_s"])) for r in csv.DictReader(f)]
    peak_at, peak = max(rows, key=lambda r: r[1])
    bounds = [0.0, peak_at]
    for fraction in (0.5, 0.1, 0.01):
        later = [t for t, u in rows if t > bounds[-1] and u < fraction * peak]
        bounds.append(later[0] if later else rows[-1][0])
    bounds.append(float("inf"))
    names = ["to the peak speed", "peak to 50 %", "50 % to 10 %", "10 % to 1 %", "below 1 %"]
    return peak, list(zip(names, bounds[:-1], bounds[1:]))


def main():
    steps = read_steps(sys.argv[1])
    if not steps:
        sys.exit(f"{sys.argv[1]}: no `step` lines (run with RUNOUT_LOG=runout_run=debug)")
    peak, phases = phase_bounds(sys.argv[2])
    total_iterations = sum(s[3] for s in steps)
    total_wall = steps[-1][0] - steps[0][0]
    print(f"peak εs-weighted mean u_s {peak:.3f} m/s; {len(steps)} attempted steps, "
          f"{total_iterations} outer iterations, {total_wall:.0f} s in the log")
    print("| phase | t [s] | accepted | rejected | mean Δt [s] | outer it./step "
          "| share of outer it. | share of wall |")
    print("|---|---|---|---|---|---|---|---|")
    # a step's wall time is the gap to the next logged step (the last one's is unknown: 0)
    gaps = [b[0] - a[0] for a, b in zip(steps, steps[1:])] + [0.0]
    for name, t0, t1 in phases:
        inside = [i for i, s in enumerate(steps) if t0 <= s[1] < t1]
        if not inside:
            continue
        accepted = [steps[i] for i in inside if steps[i][4]]
        iterations = sum(steps[i][3] for i in inside)
        wall = sum(gaps[i] for i in inside)
        mean_dt = sum(s[2] for s in accepted) / max(len(accepted), 1)
        end = min(t1, steps[-1][1])
        print(f"| {name} | {t0:.2f}–{end:.2f} | {len(accepted)} | {len(inside) - len(accepted)} "
              f"| {mean_dt:.2e} | {iterations / max(len(accepted), 1):.1f} "
              f"| {iterations / total_iterations:.2f} | {wall / total_wall:.2f} |")


if __name__ == "__main__":
    main()
