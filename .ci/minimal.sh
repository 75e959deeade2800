#!/usr/bin/env bash
# The whole test suite built without CHOLMOD and without TBB (Eigen's Cholesky, one thread),
# in build-minimal; then run. The examples' programs, which the tests also run, are built too.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${NP_MINIMAL_DIR:-build-minimal}
start=$SECONDS
configured=$(cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Release -DNP_USE_CHOLMOD=OFF -DNP_USE_TBB=OFF \
                   -DNP_BUILD_BENCHMARKS=OFF 2>&1)
echo "$configured"
grep -q "CHOLMOD FALSE, TBB FALSE" <<< "$configured" || { echo "minimal build: CHOLMOD or TBB still on" >&2; exit 1; }
cmake --build "$dir" -j"${NP_JOBS:-2}"
echo "minimal build: $((SECONDS - start)) s"
start=$SECONDS
ctest --test-dir "$dir" --output-on-failure -j2 -E "install_and_use|doxygen_reference"
echo "minimal tests: $((SECONDS - start)) s"
