#!/usr/bin/env python3
"""Turns the CSV of compare_parameterizers --methods ours-xy,ours-combination,ours-graph into
the table of doc/guesses.md: per mesh, each guess's final objective (Eq. 3), L1 and Euclidean
edge-length errors and flipped faces, the guess of lowest Eq. 3, and the counts of wins.

Usage: guess_table.py guesses.csv > table.md"""
import csv
import sys
from collections import Counter

GUESSES = {"ours-xy": "XY-MinMax", "ours-combination": "Combination", "ours-graph": "Graph-based"}
MEASURES = [("Eq. 3", "Eq. 3"), ("L1 err", "L1 edge error"), ("L2 err", "edge error"), ("flipped", "flipped")]

rows = {}
for row in csv.DictReader(open(sys.argv[1])):
    if row["method"] in GUESSES:
        rows.setdefault(row["mesh"], {})[row["method"]] = row

header = ["mesh", "vertices", "topology"]
header += ["%s %s" % (short, GUESSES[g].split("-")[0]) for short, _ in MEASURES for g in GUESSES] + ["lowest Eq. 3"]
print("| " + " | ".join(header) + " |")
print("|" + "---|" * len(header))
wins = {column: Counter() for _, column in MEASURES}
for mesh, by_guess in rows.items():
    ok = {g: r for g, r in by_guess.items() if r["status"] == "ok"}
    cells = [mesh, next(iter(by_guess.values()))["vertices"], next(iter(by_guess.values()))["topology"]]
    for _, column in MEASURES:
        cells += [ok[g][column] if g in ok else by_guess.get(g, {}).get("status", "-") for g in GUESSES]
        if ok:
            wins[column][GUESSES[min(ok, key=lambda g: float(ok[g][column]))]] += 1
    cells.append(GUESSES[min(ok, key=lambda g: float(ok[g]["Eq. 3"]))] if ok else "-")
    print("| " + " | ".join(cells) + " |")
print()
for short, column in MEASURES:
    print("Lowest %s: %s (of %d meshes)." % (short, ", ".join("%s %d" % kv for kv in wins[column].most_common()), len(rows)))
