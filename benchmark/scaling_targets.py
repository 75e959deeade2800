#!/usr/bin/env python3
"""The scaling targets of doc/performance.md, measured in one run: Google Benchmark on the two
subdivision series (mushroom, a disk; cow, closed; 1 to 4 Loop steps), ours against one
factorization + solve of the mesh's graph Laplacian and against CGAL's LSCM (up to 3 steps:
at 4 it takes minutes), all in the same run; then the peak memory of ours at 4 steps (the
comparison harness, one process per mesh) and the one-thread / two-thread test.

Targets: ours at most 3x one Laplacian factorization + solve at ~150k and ~600k vertices;
time growing at most as n^1.2 from ~40k to ~740k vertices; peak memory under 2 GiB at ~600k;
one thread and two give the same bits.

Usage: scaling_targets.py BUILD_DIR   (the table goes to stdout)"""
import json
import math
import os
import subprocess
import sys
import tempfile


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    build = argv[1]
    bench = os.path.join(build, "benchmark", "bench_norm_preserving")
    out = subprocess.run([bench, "--benchmark_filter=^((ours|laplacian)/(mushroom|cow)/[1-4]|lscm/(mushroom|cow)/[1-3])/",
                          "--benchmark_format=json"], check=True, capture_output=True, text=True).stdout
    times, vertices, iterations = {}, {}, {}
    for b in json.loads(out)["benchmarks"]:
        method, mesh, steps = b["name"].split("/")[:3]
        times[(method, mesh, int(steps))] = b["real_time"]
        vertices[(mesh, int(steps))] = int(b["vertices"])
        if method == "ours":
            iterations[(mesh, int(steps))] = int(b["solver_iterations"])

    print("| mesh | vertices | ours (s) | ADMM iterations | Laplacian f+s (s) | ours / Laplacian | LSCM (s) | LSCM / ours |")
    print("|---|---|---|---|---|---|---|---|")
    for mesh in ("mushroom", "cow"):
        for steps in range(1, 5):
            ours, lap = times[("ours", mesh, steps)], times[("laplacian", mesh, steps)]
            lscm = times.get(("lscm", mesh, steps))
            print("| %s x%d | %d | %.3f | %d | %.3f | %.1f | %s | %s |" % (
                mesh, steps, vertices[(mesh, steps)], ours, iterations[(mesh, steps)], lap, ours / lap,
                "%.3f" % lscm if lscm else "not run", "%.2f" % (lscm / ours) if lscm else "-"))

    memory = peak_memory(build)
    same_bits = subprocess.run([os.path.join(build, "test", "norm_preserving_tests"),
                                "--gtest_filter=NormPreservingADMMSolver.GivesTheSameBitsOnOneThreadAsOnSeveral"],
                               capture_output=True, text=True).returncode == 0

    print()
    print("| target | measured | status |")
    print("|---|---|---|")
    for steps, size in ((3, "~150k"), (4, "~600k")):
        ratios = [times[("ours", m, steps)] / times[("laplacian", m, steps)] for m in ("mushroom", "cow")]
        print("| 2. at most 3x one Laplacian factor + solve at %s | mushroom x%d %.1fx, cow x%d %.1fx | %s |"
              % (size, steps, ratios[0], steps, ratios[1], "met" if max(ratios) <= 3 else "not met"))
    growth = []
    for mesh in ("mushroom", "cow"):
        n2, n4 = vertices[(mesh, 2)], vertices[(mesh, 4)]
        growth.append(math.log(times[("ours", mesh, 4)] / times[("ours", mesh, 2)]) / math.log(n4 / n2))
    print("| 2. time growing at most as n^1.2 from x2 to x4 | mushroom n^%.2f, cow n^%.2f | %s |"
          % (growth[0], growth[1], "met" if max(growth) <= 1.2 else "not met"))
    print("| 4. peak memory under 2 GiB at ~600k | %s | %s |" % (
        ", ".join("%s %.0f MiB" % (m, v) for m, v in memory.items()),
        "met" if memory and max(memory.values()) < 2048 else "not met"))
    print("| 4. one thread and two give the same bits | test GivesTheSameBitsOnOneThreadAsOnSeveral %s | %s |"
          % ("passed" if same_bits else "failed", "met" if same_bits else "not met"))
    return 0


def peak_memory(build):
    harness = os.path.join(build, "benchmark", "compare_parameterizers")
    csv_path = tempfile.mkstemp(suffix=".csv")[1]
    subprocess.run([harness, "--runs", "1", "--methods", "ours-xy", "--csv", csv_path, "mushroom*4", "cow*4"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    import csv
    return {row["mesh"]: float(row["peak MiB"]) for row in csv.DictReader(open(csv_path)) if row["status"] == "ok"}


if __name__ == "__main__":
    sys.exit(main(sys.argv))
