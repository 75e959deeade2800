#!/usr/bin/env python3
"""How the draft preset's tolerance was chosen: the default solver at a ladder of tolerances,
through the Python module, on each mesh: Eq. 3 above the exact preset's certified optimum
(relative) and the time of the call. Prints a table per mesh, then for each tolerance the median
and largest excess and the median speed-up over the default tolerance (2.5e-5).

Usage: tolerance_sweep.py BUILD_DIR mesh...   (a name of CGAL's collection, as extracted into
BUILD_DIR/data/meshes, or a path; the tables go to stdout)"""
import os
import statistics
import sys

TOLERANCES = (2.5e-5, 1e-3, 3e-3, 1e-2, 3e-2, 1e-1)


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    sys.path.insert(0, os.path.join(argv[1], "python"))
    import norm_preserving

    print("| mesh | vertices | exact (s) | " + " | ".join("%g: above / s" % t for t in TOLERANCES) + " |")
    print("|---|---|---|" + "---|" * len(TOLERANCES))
    excess = {t: [] for t in TOLERANCES}
    speedup = {t: [] for t in TOLERANCES}
    for mesh in argv[2:]:
        path = mesh if os.path.exists(mesh) else os.path.join(argv[1], "data", "meshes", mesh + ".off")
        vertices, faces = norm_preserving.read_mesh(path)
        _, exact = norm_preserving.texture(vertices, faces, quality="exact")
        cells = []
        seconds = {}
        for t in TOLERANCES:
            _, report = norm_preserving.texture(vertices, faces, tolerance=t)
            above = max(report.objective - exact.objective, 0.) / exact.objective if exact.objective > 0 else 0.
            excess[t].append(above)
            seconds[t] = report.seconds
            cells.append("%.2g / %.3f" % (above, report.seconds))
        for t in TOLERANCES:
            if seconds[TOLERANCES[0]] >= 0.01: # below, the times are the clock's noise
                speedup[t].append(seconds[TOLERANCES[0]] / seconds[t])
        print("| %s | %d | %.3f | %s |" % (os.path.basename(mesh), len(vertices), exact.seconds, " | ".join(cells)))
    print("\n| tolerance | median above the optimum | largest | median speed-up over 2.5e-5 (meshes over 10 ms) |")
    print("|---|---|---|---|")
    for t in TOLERANCES:
        print("| %g | %.2g | %.2g | %.2f |" % (t, statistics.median(excess[t]), max(excess[t]), statistics.median(speedup[t])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
