#!/usr/bin/env python3
"""How close each quality preset comes to the optimum, through the Python module: for every mesh,
the draft and default presets' Eq. 3 above the exact preset's certified optimum (relative), beside
the certified bound each call reports (`optimality_gap`), and the exact preset's own bound. The
figures are the solver's arithmetic only: they do not depend on the machine's speed or load.

Usage: preset_accuracy.py BUILD_DIR mesh...   (a name of CGAL's collection, as extracted into
BUILD_DIR/data/meshes, or a path; the table goes to stdout)"""
import os
import statistics
import sys


def main(argv):
    if len(argv) < 3:
        print(__doc__)
        return 2
    build = argv[1]
    sys.path.insert(0, os.path.join(build, "python"))
    import norm_preserving

    print("| mesh | vertices | draft: above the optimum | draft: certified bound | default: above the optimum "
          "| default: certified bound | exact: certified bound |")
    print("|---|---|---|---|---|---|---|")
    excess = {"draft": [], "default": []}
    looseness = {"draft": [], "default": []}
    for mesh in argv[2:]:
        path = mesh if os.path.exists(mesh) else os.path.join(build, "data", "meshes", mesh + ".off")
        vertices, faces = norm_preserving.read_mesh(path)
        result = {}
        for quality in ("draft", "default", "exact"):
            _, report = norm_preserving.texture(vertices, faces, quality=quality)
            if report.status != norm_preserving.ErrorCode.OK:
                raise SystemExit("%s, %s: %s" % (mesh, quality, report.message))
            result[quality] = report
        optimum = result["exact"].objective
        cells = []
        for quality in ("draft", "default"):
            above = max(result[quality].objective - optimum, 0.) / optimum if optimum > 0 else 0.
            bound = result[quality].optimality_gap
            excess[quality].append(above)
            if above > 0:
                looseness[quality].append(bound / above)
            cells += ["%.2g" % above, "%.2g" % bound]
        print("| %s | %d | %s | %.2g |" % (os.path.basename(mesh), len(vertices), " | ".join(cells),
                                         result["exact"].optimality_gap))
    for quality in ("draft", "default"):
        print("\n%s: above the optimum, median %.2g, largest %.2g; certified bound / distance, median %.0f (%.0f to %.0f)" % (
            quality, statistics.median(excess[quality]), max(excess[quality]), statistics.median(looseness[quality]),
            min(looseness[quality]), max(looseness[quality])))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
