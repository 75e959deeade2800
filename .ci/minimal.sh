#!/usr/bin/env bash
# The whole test suite on the other stack users have: CGAL 6.1.1 and Eigen 5.0.1 (the releases
# kept in ../shared/deps, or NP_DEPS_DIR), built without CHOLMOD and without TBB (the package's
# own Cholesky, one thread), in build-minimal; then run. The examples' programs, which the tests
# also run, are built too. Without those releases it says so and builds on the system's CGAL and
# Eigen instead (the rest of the configuration is the same).
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${NP_MINIMAL_DIR:-build-minimal}
deps=${NP_DEPS_DIR:-../shared/deps}
start=$SECONDS
stack=()
if [ -x "$deps/unpack.sh" ]; then
  stack=($("$deps/unpack.sh" "${NP_DEPS_UNPACK_DIR:-$PWD/$dir-deps}" | tail -1))
  rm -rf "$HOME/.cmake/packages/Eigen3" # configuring Eigen's sources registers its build tree there
else
  echo "minimal build: no CGAL 6.1.1 / Eigen 5.0.1 in $deps: building on the system's CGAL and Eigen" >&2
fi
configured=$(cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DNP_USE_CHOLMOD=OFF -DNP_USE_TBB=OFF \
                   -DNP_BUILD_BENCHMARKS=OFF -DNP_BUILD_PYTHON=OFF "${stack[@]}" 2>&1)
echo "$configured"
grep -q "CHOLMOD FALSE, TBB FALSE" <<< "$configured" || { echo "minimal build: CHOLMOD or TBB still on" >&2; exit 1; }
if [ ${#stack[@]} -gt 0 ]; then
  grep -q "CGAL 6.1.1 .*Eigen 5.0.1" <<< "$configured" || { echo "minimal build: not on CGAL 6.1.1 and Eigen 5.0.1" >&2; exit 1; }
fi
cmake --build "$dir" -j"${NP_JOBS:-2}"
echo "minimal build: $((SECONDS - start)) s"
start=$SECONDS
# The tests of the outputs in real clients (Blender, Chromium, the glTF validator) hold no code of
# the package's that the main build's run does not already test.
# The accuracy suite is left to the main build: the same solves give the same bits here (below).
ctest --test-dir "$dir" --output-on-failure -j2 -E "doxygen_reference|Accuracy|blender|viewer|gltf|glb"
echo "minimal tests: $((SECONDS - start)) s"
# The same bits on both stacks where the arithmetic is the package's: the main build's uvs
# (build/, CGAL 5.5 and Eigen 3.4 with CHOLMOD and TBB) against this build's, on meshes below
# CHOLMOD's threshold (above it the main build factors with CHOLMOD, this one with its own code).
if [ -x build/test/uv_bits ]; then
  for name in cow nefertiti mushroom camel elephant-with-holes cube_poly; do
    mesh="$dir/data/meshes/$name.off"
    if ! diff <(build/test/uv_bits "$mesh") <("$dir/test/uv_bits" "$mesh"); then
      echo "minimal build: $name's uvs differ from the main build's" >&2
      exit 1
    fi
  done
  echo "minimal build: the same uv bits as the main build on 6 meshes"
fi
