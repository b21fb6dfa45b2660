"""The goals' table of docs/PERFORMANCE.md from a GPU kit run's benchmarks.json (the
benchmarks of bench/performance_docs.sh, keyed by its names rays, still, peel, map_build),
with bench/performance_goals.py's own rows, printed as Markdown. The sweeps, the viewer's drag
and the demo's cold start are not in the kit (they need the viewer's X server and the variants
scripts), so their rows are left out. A run of one repetition (run.sh --quick) has no medians:
its single figures stand in for them.
    python3 gpu_kit_goals.py benchmarks.json
"""
import json
import os
import re
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import performance_goals as goals  # noqa: E402

with open(sys.argv[1]) as f:
    runs = json.load(f)


class Figures(goals.Medians):
    def __init__(self, data, label):
        dict.__init__(self)
        self.path = label
        self.counters = {}
        entries = data.get("benchmarks", [])
        medians = [b for b in entries if b.get("aggregate_name") == "median"]
        for b in medians or [b for b in entries if b.get("run_type") == "iteration"]:
            name = re.sub(r"/iterations:\d+.*$", "", b["run_name"])
            scale = {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
            self[name] = b["real_time"] * scale
            self.counters[name] = b


rows = []
for name, make in (("rays", goals.rays_rows), ("still", goals.bundled_rows),
                   ("peel", goals.peel_rows), ("map_build", goals.map_rows)):
    try:
        rows += make(Figures(runs.get(name, {}), name))
    except SystemExit as missing:
        rows.append((f"({name})", f"not measured: {missing}", ""))
print("| goal | measured | |")
print("|---|---|---|")
for goal, measured, state in rows:
    print(f"| {goal} | {measured} | {state} |")
