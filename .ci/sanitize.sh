#!/usr/bin/env bash
# The whole test suite and the command-line tool built with AddressSanitizer and UndefinedBehaviorSanitizer, without
# recovery (the first report fails the run), and with CGAL's and Eigen's assertions on
# (no NDEBUG), in build-sanitize; then run.
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${NP_SANITIZE_DIR:-build-sanitize}
# GCC's -Wmaybe-uninitialized misfires at -O1 with the sanitizers, in CGAL's property_map.h.
flags="-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -Wno-maybe-uninitialized"
start=$SECONDS
cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCMAKE_CXX_FLAGS="$flags" \
      -DNP_BUILD_EXAMPLES=ON -DNP_BUILD_BENCHMARKS=OFF
cmake --build "$dir" -j"${NP_JOBS:-2}" --target norm_preserving_tests texture_mesh # the tool, not the other examples
echo "sanitizer build: $((SECONDS - start)) s"
start=$SECONDS
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# install_and_use and doxygen_reference hold no code of ours to sanitize; the other examples are not built.
ctest --test-dir "$dir" --output-on-failure -j2 \
      -E "install_and_use|doxygen_reference|example_(simple_parameterization|closed_mesh|polygon_mesh|seam_mesh|custom_mesh|initial_guess_and_solver|compare_with_lscm_arap)"
echo "sanitizer tests: $((SECONDS - start)) s"
