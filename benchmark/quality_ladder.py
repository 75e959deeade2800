#!/usr/bin/env python3
"""The quality ladder, measured in one run: Google Benchmark's `quality` benchmarks (the
whole-soup call at the draft, default and exact presets on the two subdivision series,
mushroom, a disk, and cow, closed, 1 to 3 Loop steps) beside one factorization + solve of the
same mesh's graph Laplacian (`laplacian`). For each preset: the time, its ratio to the
factorization, the excess of Eq. 3 over the exact mode's optimum, the largest distance of a
uv from the exact map's (texture space) and the solver's iterations.

Usage: quality_ladder.py BUILD_DIR   (the table goes to stdout)"""
import json
import os
import subprocess
import sys


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    bench = os.path.join(argv[1], "benchmark", "bench_norm_preserving")
    out = subprocess.run([bench, "--benchmark_filter=^(quality/(draft|default|exact)|laplacian)/(mushroom|cow)/[1-3]/",
                          "--benchmark_format=json"], check=True, capture_output=True, text=True).stdout
    rows = {}
    for b in json.loads(out)["benchmarks"]:
        # the name, without Google Benchmark's suffixes (/iterations:1/real_time)
        parts = [part for part in b["name"].split("/") if ":" not in part and part != "real_time"]
        rows[tuple(parts)] = b
    print("| mesh | vertices | preset | time (s) | / Laplacian f+s | above the optimum | largest uv distance | iterations |")
    print("|---|---|---|---|---|---|---|---|")
    for mesh in ("mushroom", "cow"):
        for steps in ("1", "2", "3"):
            laplacian = rows.get(("laplacian", mesh, steps))
            for preset in ("draft", "default", "exact"):
                b = rows.get(("quality", preset, mesh, steps))
                if b is None or laplacian is None:
                    continue
                print("| %s x%s | %d | %s | %.3g | %.1f | %.2g | %.2g | %d |" % (
                    mesh, steps, int(b["vertices"]), preset, b["real_time"], b["real_time"] / laplacian["real_time"],
                    max(b["excess"], 0.), b["uv_distance"], int(b["solver_iterations"])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
