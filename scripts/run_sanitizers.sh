#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer run (issue 17): builds the
# Boost.Test suites and optimize_seams into BUILD_DIR (default build-asan)
# with -fsanitize=address,undefined -O1 -g1 and runs every test_* suite and
# the CLI tests that stay quick under ASan (all but one). Any sanitizer
# report fails the run (halt_on_error, exit code of the suites and ctest).
#   bash scripts/run_sanitizers.sh [BUILD_DIR]
#
# Time budget: the instrumented build is the slow part (each translation unit
# takes several times its Release time), and CI stops at 90 minutes. With
# SMSO_SANITIZER_DEADLINE set (seconds since the epoch), the build and the
# suites (cheapest first, the CLI tests last) stop at the deadline; what did
# not finish is listed as "not run" (not a failure: the Release run of the
# same tests has already passed). Without it, everything runs.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
build=${1:-build-asan}
deadline=${SMSO_SANITIZER_DEADLINE:-0}
san="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"

# Built on its own after the rest, run last: instrumented, it takes 7.7 GB
# to compile with -g1 (9.8 with -g), test_optimize_seams 10.5 GB (14.4), and
# side by side they were killed for memory on a 24 GB machine. (A compile-time suite: under ASan it adds
# little that the others do not run.)
alone="test_named_parameters"

start=$(date +%s)
# RelWithDebInfo with its flags replaced: CGAL's CMake accepts the build
# type, and nothing appends -O2/-O3 after -O1. -g1 (line tables: reports
# still give file and line): with -g, compiling test_named_parameters took
# 9.8 GB, and two such units side by side were killed for memory on 24 GB.
mkdir -p "$build"
build=$(cd "$build" && pwd) # absolute: the filtered suites below run from their own folder
cmake -S . -B "$build" -DBUILD_TESTING=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DSMSO_BUILD_EXAMPLES=OFF -DSMSO_BUILD_BENCHMARKS=OFF -DSMSO_BUILD_DOC=OFF -DSMSO_INSTALL=OFF \
  -DSMSO_SUITES_NOT_IN_ALL="$alone" \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 $san" \
  -DCMAKE_EXE_LINKER_FLAGS="$san" >"$build/cmake.log" 2>&1 || { cat "$build/cmake.log"; exit 1; }

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1

# Cases that take minutes under ASan are left out, each 5-8 times slower
# under ASan (native, 2026-11-28: 11, 5, 7, 31 and 8 s of
# test_optimize_seams' 87 s; 11 and 7 s of test_topology's 18 s; 15 s of
# test_minimize_distortion's 30 s). What they run is covered by quicker
# cases: the third start by the_free_run_forks_from_the_first_start_...,
# the coarse start by the_coarse_to_fine_start_reaches_the_minimum_...
declare -A slow_cases=(
  [test_optimize_seams]="results_are_deterministic,the_scaffold_prevents_overlaps,the_bound_is_met_on_small_meshes,a_carried_map_that_keeps_a_fold_gives_way_to_the_direct_run,a_third_start_cutting_without_the_scaffold_first_shortens_the_seams"
  [test_topology]="cgal_sample_meshes_meet_the_bound,shared_meshes_meet_the_bound"
  [test_minimize_distortion]="minimize_distortion_starts_large_meshes_from_coarser_ones")
# CLI tests that take minutes under ASan (measured on 2 busy cores:
# cli_energy_threads_repair 285 s, five runs on the cat that the other tests
# already cover; all other CLI tests 0-60 s).
slow_cli="energy_threads_repair"
# Run order: cheapest first, the CLI tests last.
suites=(test_energy test_core test_io test_topology test_initial_parameterization
  test_minimize_distortion test_optimize_seams)

rc=0
not_run=()
remaining() { if ((deadline > 0)); then echo $((deadline - $(date +%s))); else echo 1000000; fi; }
# bounded CMD...: runs CMD within the time left; 124 when the deadline cut it.
bounded() {
  local left
  left=$(remaining)
  ((left > 60)) || return 124
  timeout --kill-after=30 "$left" "$@"
}

# One build of everything the run needs: the default target with only the
# tests and the CLI configured (CMake's Makefiles build several --target
# goals one after the other, on one core).
bst=0
bounded cmake --build "$build" -j2 || bst=$?
if ((bst != 0 && bst != 124)); then echo "sanitizers: build failed" >&2; rc=1; fi
built=$(date +%s)

run_suite() {
  local suite=$1 exe="$build/test/Surface_mesh_seam_optimization/$1" src=0
  if [[ ! -x $exe ]]; then not_run+=("$suite (not built)"); return; fi
  local filter=()
  [[ -n "${slow_cases[$suite]:-}" ]] && filter=("--run_test=!${slow_cases[$suite]}")
  echo "== $suite${slow_cases[$suite]:+ without ${slow_cases[$suite]}}"
  (cd "$(dirname "$exe")" && bounded "$exe" --log_level=test_suite "${filter[@]}") || src=$?
  if ((src == 124)); then not_run+=("$suite (cut at the deadline)"); elif ((src != 0)); then rc=1; fi
}
for suite in "${suites[@]}"; do run_suite "$suite"; done
if [[ -x $build/cli/optimize_seams ]]; then
  echo "== CLI tests but cli_$slow_cli"
  src=0
  bounded ctest --test-dir "$build" --output-on-failure --timeout 900 -R "^cli_" -E "^cli_($slow_cli)\$" || src=$?
  if ((src == 124)); then not_run+=("CLI tests (cut at the deadline)"); elif ((src != 0)); then rc=1; fi
else
  not_run+=("CLI tests (optimize_seams not built)")
fi
for suite in $alone; do
  bst=0
  bounded cmake --build "$build" --target "$suite" || bst=$?
  if ((bst != 0 && bst != 124)); then echo "sanitizers: build of $suite failed" >&2; rc=1; fi
  run_suite "$suite"
done

end=$(date +%s)
if ((${#not_run[@]} > 0)); then
  echo "sanitizers: not run within the time budget (SMSO_SANITIZER_DEADLINE):"
  printf '  %s\n' "${not_run[@]}"
fi
echo "sanitizers: build $((built - start)) s, tests $((end - built)) s, exit code $rc"
exit "$rc"
