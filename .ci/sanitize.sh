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
      -DNP_BUILD_EXAMPLES=ON -DNP_BUILD_BENCHMARKS=OFF -DNP_BUILD_PYTHON=OFF
# The tool and the programs its tests read its outputs with, not the other examples.
cmake --build "$dir" -j"${NP_JOBS:-2}" --target norm_preserving_tests texture_mesh image_probe page_probe uv_bits
echo "sanitizer build: $((SECONDS - start)) s"
start=$SECONDS
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# install_and_use, doxygen_reference and the guides' snippets hold no code of ours to sanitize that
# the suite does not run; the other examples and the client tests' programs are not built; the
# accuracy suite repeats under the sanitizers, many times slower, solves the suite already runs;
# the large Klein bottle (over 2 minutes here) runs the code of the large Moebius strip, which stays.
ctest --test-dir "$dir" --output-on-failure -j2 \
      -E "install_and_use|doxygen_reference|guide_snippets|Accuracy|LargeIsTextured/klein_bottle|example_(simple_parameterization|closed_mesh|polygon_mesh|seam_mesh|custom_mesh|initial_guess_and_solver|compare_with_lscm_arap)|texture_mesh_(outputs|viewer|glb|ply_strips)|blender|python"
echo "sanitizer tests: $((SECONDS - start)) s"
