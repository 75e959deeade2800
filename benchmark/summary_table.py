#!/usr/bin/env python3
"""Condenses the CSV of compare_parameterizers into the headline table of doc/benchmarks.md:
per mesh, the time and the Euclidean edge-length error of ours (XY-MinMax guess, default
solver), of the exact interior-point solve, of CGAL's LSCM and ARAP, and the time ratios.

Usage: summary_table.py comparison.csv > table.md"""
import csv
import sys

rows = {}
for row in csv.DictReader(open(sys.argv[1])):
    rows.setdefault(row["mesh"], {})[row["method"]] = row

def cell(by_method, method, column):
    row = by_method.get(method)
    if row is None:
        return "-"
    return row[column] if row["status"] == "ok" else row["status"]

def ratio(by_method, method):
    ours, other = by_method.get("ours-xy"), by_method.get(method)
    if not ours or not other or ours["status"] != "ok" or other["status"] != "ok":
        return "-"
    return "%.1fx" % (float(other["seconds"]) / float(ours["seconds"]))

print("| mesh | vertices | topology | ours (s) | ours error | exact QP (s) | LSCM (s) | LSCM error "
      "| ARAP (s) | ARAP error | LSCM / ours | ARAP / ours |")
print("|" + "---|" * 12)
for mesh, m in rows.items():
    first = next(iter(m.values()))
    print("| " + " | ".join([
        mesh, first["vertices"], first["topology"],
        cell(m, "ours-xy", "seconds"), cell(m, "ours-xy", "edge error"), cell(m, "ours-exact", "seconds"),
        cell(m, "lscm", "seconds"), cell(m, "lscm", "edge error"),
        cell(m, "arap", "seconds"), cell(m, "arap", "edge error"),
        ratio(m, "lscm"), ratio(m, "arap")]) + " |")
