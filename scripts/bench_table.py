#!/usr/bin/env python3
"""Print criterion results (target/criterion/**/new/estimates.json) as ns per element.

Usage: python3 scripts/bench_table.py [GROUP_PREFIX]
Reads the median point estimate and the throughput recorded in benchmark.json.
"""
import json
import sys
from pathlib import Path

root = Path(__file__).resolve().parent.parent / "target" / "criterion"
prefix = sys.argv[1] if len(sys.argv) > 1 else ""
rows = []
for est in sorted(root.glob("**/new/estimates.json")):
    bench = json.loads((est.parent / "benchmark.json").read_text())
    name = bench["full_id"]
    if not name.startswith(prefix):
        continue
    median = json.loads(est.read_text())["median"]["point_estimate"]
    tp = bench.get("throughput") or {}
    elems = tp.get("Elements") or tp.get("Bytes") or 1
    rows.append((name, median / elems))
width = max((len(n) for n, _ in rows), default=10)
for name, ns in rows:
    print(f"{name:<{width}}  {ns:10.3f} ns/elem")
