#!/usr/bin/env python3
"""Compare builds of examples/halton_interleaved (e.g. two versions of qmckit) on a noisy machine.

Usage:

    python3 scripts/halton_versions.py [--reps R] [--rounds K] BIN [BIN ...]

Each BIN is a copy of `target/release/examples/halton_interleaved` built from some version
of the code (build, then `cp` it away before switching versions). The binaries run one after
another, R times in turn (default 4), each with K interleaved rounds (default 40); every run
times qmckit and the `halton` crate in alternation itself, so each row's ratio peer / qmckit
comes from one process. The table gives, per binary and row, the ratio of the best times
over all its runs ("best") and the median of the per-run ratios ("median"), per coordinate
and per point for random access, `fill` (u32) and f64 (`fill_as`, or `fill` + a conversion pass in older builds) for sequential rows (the
radical-inverse rows have one qmckit figure).
"""
import argparse
import re
import subprocess
from collections import defaultdict

HALTON = re.compile(
    r"halton d=(\d+)\s+(\w+)\s+per coordinate\s+([\d.]+)\s+per point\s+([\d.]+)\s+peer\s+([\d.]+)"
)
RADICAL = re.compile(r"radical inverse base (\d+)\s+(\w+)\s+qmckit\s+([\d.]+)\s+peer\s+([\d.]+)")
SEQUENTIAL = re.compile(
    r"sequential halton d=(\d+)\s+fill\s+([\d.]+)\s+(?:fill\+f64|f64)\s+([\d.]+)\s+peer\s+([\d.]+)"
)


def rows(text):
    """(row label, [qmckit A, qmckit B, peer]) for each result line: A, B = per coordinate,
    per point (random access) or fill, fill + f64 (sequential)."""
    for line in text.splitlines():
        m = HALTON.match(line)
        if m:
            yield f"Halton d={m[1]} {m[2]}", [float(m[3]), float(m[4]), float(m[5])]
            continue
        m = RADICAL.match(line)
        if m:
            yield f"radical inverse base {m[1]} {m[2]}", [float(m[3]), float(m[3]), float(m[4])]
            continue
        m = SEQUENTIAL.match(line)
        if m:
            yield f"sequential Halton d={m[1]}", [float(m[2]), float(m[3]), float(m[4])]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--reps", type=int, default=4)
    ap.add_argument("--rounds", type=int, default=40)
    ap.add_argument("bins", nargs="+")
    a = ap.parse_args()
    best = defaultdict(lambda: [float("inf")] * 3)
    ratios = defaultdict(list)
    for _ in range(a.reps):
        for b in a.bins:
            out = subprocess.run([b, str(a.rounds)], capture_output=True, text=True, check=True)
            for label, v in rows(out.stdout):
                best[b, label] = [min(x, y) for x, y in zip(best[b, label], v)]
                ratios[b, label].append((v[2] / v[0], v[2] / v[1]))
    labels = sorted({k[1] for k in best}, key=lambda s: (s.split()[-1], s))
    print("| row | " + " | ".join(f"{b}: best / median" for b in a.bins) + " |")
    print("|---|" + "---|" * len(a.bins))
    for label in labels:
        cells = []
        for b in a.bins:
            q1, q2, p = best[b, label]
            rs = ratios[b, label]
            m1 = sorted(r[0] for r in rs)[len(rs) // 2]
            m2 = sorted(r[1] for r in rs)[len(rs) // 2]
            if label.startswith("radical"):
                cells.append(f"{p / q1:.2f}x / {m1:.2f}x")
            else:
                cells.append(f"{p / q1:.2f}x, {p / q2:.2f}x / {m1:.2f}x, {m2:.2f}x")
        print(f"| {label} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
