#!/usr/bin/env python3
"""Fuzz `runout run` (issue 21): mutate the numbers of the shipped case files (scaled by
0.1-10, +1, 0, negated; 1-3 per file), `runout check` each mutant, and run every accepted
one at smoke fidelity to END_TIME; count panics (exit 101 or 'panicked'), hangs (no exit in
60 s) and other exit codes. The mutants live in a temporary copy of cases/ and examples/.

    cargo build --release -p runout-cli
    python3 examples/fuzz-run.py [SEED] [SECONDS] [END_TIME]    # e.g. 1 240 0.003

Mutants that panic or hang are kept in the temporary folder, whose path is printed.
"""
import pathlib
import random
import re
import shutil
import subprocess
import sys
import tempfile
import time

seed = int(sys.argv[1]) if len(sys.argv) > 1 else 1
budget = float(sys.argv[2]) if len(sys.argv) > 2 else 240.0
end_time = sys.argv[3] if len(sys.argv) > 3 else "0.003"
random.seed(seed)
root = pathlib.Path(__file__).resolve().parent.parent
runout = root / "target/release/runout"
work = pathlib.Path(tempfile.mkdtemp(prefix="runout-fuzz-run-"))
for tree in ("cases", "examples"):
    shutil.copytree(root / tree, work / tree, ignore=shutil.ignore_patterns("*.py", "*.sh", "slurm"))
files = [p for p in (work / "cases").rglob("*.ron") if "analytic" not in p.parts]
files += list((work / "examples").glob("*.ron"))
number = re.compile(r"(?<![\w.])(-?\d+\.?\d*(?:e-?\d+)?)(?![\w.])")
stats = dict(tried=0, accepted=0, panics=0, hangs=0, other=0)
started = time.time()
while time.time() - started < budget:
    original = random.choice(files)
    text = original.read_text()
    for _ in range(random.randint(1, 3)):
        found = list(number.finditer(text))
        if not found:
            break
        m = random.choice(found)
        v = float(m.group(1))
        new = random.choice([v * random.choice([0.1, 0.5, 0.9, 1.1, 2, 3, 10]), v + 1, 0.0, -v])
        text = text[: m.start()] + repr(new) + text[m.end():]
    mutant = original.parent / f"zz_fuzz_{stats['tried']}_{original.name}"
    mutant.write_text(text)
    stats["tried"] += 1
    keep = False
    try:
        check = subprocess.run([runout, "check", mutant], capture_output=True, timeout=60)
        if check.returncode == 101:
            stats["panics"] += 1
            keep = True
            continue
        if check.returncode != 0:
            continue
        stats["accepted"] += 1
        run = subprocess.run(
            [runout, "run", mutant, "--fidelity", "smoke", "--end-time", end_time,
             "--quiet", "--overwrite", "--out", work / "run"],
            capture_output=True, timeout=60)
        if run.returncode == 101 or b"panicked" in run.stderr:
            stats["panics"] += 1
            keep = True
        elif run.returncode not in (0, 1):
            stats["other"] += 1
            keep = True
    except subprocess.TimeoutExpired:
        stats["hangs"] += 1
        keep = True
    finally:
        if not keep:
            mutant.unlink()
print(f"seed {seed}, {budget:.0f} s, end time {end_time} s: {stats}")
if stats["panics"] or stats["hangs"] or stats["other"]:
    print(f"kept mutants: {work}")
    sys.exit(1)
shutil.rmtree(work)
