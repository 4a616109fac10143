#!/usr/bin/env python3
"""The tables of scripts/utk_compare.sh from its stats.tsv and times.tsv (standard library only).

usage: utk_compare_table.py OUT_DIR N UTK_COMMIT

Statistics: mean over the sets, with the standard error of the mean in parentheses (in
units of the last digit shown is not attempted: the error is printed as a number). Times:
the median over the rounds of the whole wall time, per point, and qmckit/UTK.
"""

import csv
import statistics
import sys


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def fmt(v, se, digits):
    v, se = float(v), float(se)
    if se != se:  # NaN: a single set
        return f"{v:.{digits}f}"
    return f"{v:.{digits}f} ±{se:.{digits}f}"


def ns(seconds, points):
    t = seconds / points * 1e9
    return f"{t:.3g}" if t < 1000 else f"{t:,.0f}"


def main():
    out, n, commit = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    stats = read(f"{out}/stats.tsv")
    times = read(f"{out}/times.tsv")
    labels = list(dict.fromkeys(r["label"] for r in stats + times))
    by = {(r["label"], r["tool"]): r for r in stats}

    print(f"UTK commit {commit}; N = {n} (Poisson disk: about N); qmckit | UTK in each cell.\n")
    print("| sampler | sets | star discrepancy D* | mean NN distance x N^(1/d) "
          "| low band P, 1 <= r <= sqrt(N)/2 | band sqrt(N)/2 < r <= sqrt(N) |")
    print("|---|---|---|---|---|---|")
    for lab in labels:
        q, u = by.get((lab, "qmckit")), by.get((lab, "utk"))
        if not q or not u:
            continue
        cells = []
        for key, d in (("star", 5), ("nn", 4), ("low", 4), ("mid", 3)):
            cells.append(f"{fmt(q[key], q[key + '_se'], d)} \\| {fmt(u[key], u[key + '_se'], d)}")
        print(f"| {lab} | {q['sets']} | " + " | ".join(cells) + " |")

    try:
        with open(f"{out}/refused.tsv") as f:
            refused = [line.rstrip("\n").split("\t") for line in f if line.strip()]
    except FileNotFoundError:
        refused = []
    for lab, tool, why in refused:
        print(f"\n{lab}: no statistics for {tool}: {why}")

    print("\nTime per point in ns (median of the rounds; whole process wall time, text output "
          "included), and qmckit/UTK (below 1: qmckit faster).\n")
    print("| sampler | sets x N: qmckit | UTK | ratio | one large set: N | qmckit | UTK | ratio |")
    print("|---|---|---|---|---|---|---|---|")
    for lab in labels:
        rows = [r for r in times if r["label"] == lab]
        cells = []
        for big in (False, True):
            sel = [r for r in rows if (r["sets"] == "1" and int(r["n"]) != n) == big]
            if not sel:
                cells.append("| | | |" if big else "| | |")
                continue
            pts = int(sel[0]["sets"]) * int(sel[0]["n"])
            med = {}
            for tool in ("qmckit", "utk"):
                v = [float(r["seconds"]) for r in sel if r["tool"] == tool]
                med[tool] = statistics.median(v) if v else float("nan")
            ratio = med["qmckit"] / med["utk"] if med["utk"] > 0 else float("nan")
            c = f"{ns(med['qmckit'], pts)} | {ns(med['utk'], pts)} | {ratio:.2f}"
            cells.append((f"{int(sel[0]['n'])} | " if big else "") + c)
        print(f"| {lab} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()
