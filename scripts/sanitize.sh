#!/usr/bin/env bash
# Builds iga with AddressSanitizer + UndefinedBehaviorSanitizer (gcc; CMake option IGA_SANITIZE) in
# ./build-asan and runs its tests there, in a fixed priority order, until a deadline. Any sanitizer report fails
# the test that met it, and so this script (exit 1). Reaching the deadline is not a failure: what did not run is
# named in one line and the script exits 0.
# Needs the packages of scripts/setup.sh (run it first on a fresh machine).
# Environment:
#   IGA_DEADLINE        seconds since the epoch by which the stage ends (.ci/run sets it from what the normal
#                       stage left); unset: no deadline
#   IGA_ASAN_BUILD_DIR  default <repo>/build-asan
#   IGA_JOBS            default: the number of cores
#
# The order (README, "Tests, labels and CI"): a class runs before the next; inside a class the longest test first
# (times from the Release tree's ctest, when it has them), two at a time:
#   1. corpus    the hostile-input corpus (run_corpus.py on the sanitized programs, in three shares; see below);
#   2. parsers   the unit tests of the text readers: OBJ, expressions, curve and patch JSON, meshes;
#   3. numerics  every other unit test of the libraries (quadrature, basis, fem, refine, bem, io);
#   4. programs  the programs end to end, their conventions and the examples;
#   5. mpi       the distributed solver (label mpi), without LeakSanitizer (below);
# Never run here: label slow (as in the normal stage); label docs (the README's commands: their programs run here
# in their own tests and the corpus; its mpirun commands would need LeakSanitizer off as for label mpi, and it
# names the Google Benchmark program, which this tree does not build; measured: it failed on both, 2026-12-04);
# label install (external_consumer builds an outside
# project, without -fsanitize, against the instrumented libraries, which need the ASan runtime loaded first), and
# the corpus as a ctest (run_corpus.py gives every run an 8 GiB address-space limit, and ASan reserves terabytes
# of shadow memory at start-up, so every case would die before main: class 1 runs it with the limit raised past
# ASan's reservation and ASan's own max_allocation_size_mb=8192 in its place).
# Label mpi runs without LeakSanitizer: Open MPI keeps about 116 kB in 3,300 allocations past MPI_Finalize, most
# of them from its run-time plugins, which are unloaded by then, so their frames read "<unknown module>" and no
# suppression can name them (measured 2026-12-03). Address and undefined-behaviour checks stay on.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$(realpath -m "${IGA_ASAN_BUILD_DIR:-$root/build-asan}")"
jobs="${IGA_JOBS:-$(nproc)}"
deadline="${IGA_DEADLINE:-}"

minutes_left() { echo $(((deadline - $(date +%s)) / 60)); }
if [[ -n "$deadline" ]] && (($(date +%s) + 60 >= deadline)); then
  echo "sanitize: NOT RUN: less than a minute is left before the deadline (not a failure)" >&2
  exit 0
fi

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  # -O1 -g1 without NDEBUG: stack traces with file and line (-g1: line tables only, a quarter less compile
  # time than -g for the same traces), and Eigen's index assertions stay on.
  # The Google Benchmark micro-suite measures and is not a test: not built here.
  # -Wno-error=maybe-uninitialized: at -O1 with ASan, GCC 12 reports libstdc++'s own <regex> automaton
  # (std::function inside _State) as maybe uninitialized; the warning stays visible, the release build keeps -Werror.
  cmake -S "$root" -B "$build" -G Ninja -DIGA_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1 -Wno-error=maybe-uninitialized" -DCMAKE_DISABLE_FIND_PACKAGE_benchmark=ON
fi
SECONDS=0
if [[ -n "$deadline" ]]; then
  status=0
  timeout --kill-after=20 "$((deadline - $(date +%s)))" cmake --build "$build" -j "$jobs" || status=$?
  if ((status == 124 || status == 137)); then
    echo "sanitize: NOT RUN: the sanitizer build did not finish by the deadline (after $((SECONDS / 60)) min);" \
         "no sanitizer test ran (not a failure)" >&2
    exit 0
  fi
  ((status == 0)) || exit "$status"
else
  cmake --build "$build" -j "$jobs"
fi
echo "sanitize: build done in $((SECONDS / 60)) min $((SECONDS % 60)) s" >&2

# halt_on_error: the first report ends the program (non-zero exit), so the test fails.
# allocator_may_return_null: an impossible allocation throws std::bad_alloc as without ASan (the programs
# answer it with one line) instead of ASan aborting on it.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:allocator_may_return_null=1"
# Passive OpenMP waiting, as the ctest properties give every test (tests/CMakeLists.txt): two tests share two cores.
export OMP_WAIT_POLICY=PASSIVE
# Leaks of third-party libraries that no frame of ours can name (scripts/lsan.supp says which and why).
export LSAN_OPTIONS="suppressions=$root/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:report_error_type=1"

corpus="env ASAN_OPTIONS=$ASAN_OPTIONS:max_allocation_size_mb=8192 /usr/bin/python3 $root/tests/bad_input/run_corpus.py --memory-limit-mb 100000000"
for p in benchmarks/iga-poisson benchmarks/iga-biharmonic benchmarks/iga-elasticity benchmarks/iga-shell benchmarks/iga-bem benchmarks/iga-quadrature tools/iga-geometry tools/iga-knots \
         tools/iga-fit-quadrature; do
  corpus+=" --exe $(basename "$p")=$build/$p"
done
parsers='^test_(obj_reader|obj_writer|poly_mesh|data_meshes|expression|expression_text|curve_json|patches|iga_knots)$'
programs='^(test_iga_(poisson|bem|quadrature|geometry)|test_bench_.*|test_determinism|test_study|program_conventions)$'
corpus_shares=()
for k in 1 2 3; do corpus_shares+=(--extra-test "bad_input_corpus_asan_${k}of3=$corpus --shard $k/3"); done
[[ -n "$deadline" ]] || deadline=$(($(date +%s) + 100 * 24 * 3600))
echo "sanitize: the tests under ASan/UBSan, $(minutes_left) min before the deadline" >&2
exec /usr/bin/python3 "$root/scripts/run_with_deadline.py" --tag sanitize --build-dir "$build" --jobs "$jobs" \
  --deadline "$deadline" --costs-from "${IGA_BUILD_DIR:-$root/build}" \
  --exclude-labels '^(slow|install|corpus|docs)$' \
  "${corpus_shares[@]}" \
  --class 'corpus=^bad_input_corpus_asan_' --class "parsers=$parsers" \
  --class 'mpi=^mpi$' --class "programs=$programs|^examples$" --class 'numerics=*' \
  --order corpus,parsers,numerics,programs,mpi \
  --env "mpi:ASAN_OPTIONS=${ASAN_OPTIONS/detect_leaks=1/detect_leaks=0}"
