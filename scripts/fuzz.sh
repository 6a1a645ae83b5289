#!/usr/bin/env bash
# Fuzzes iga's text readers with libFuzzer: the OBJ reader, the expression layer and the curve JSON of
# iga-knots (targets in tests/fuzz/). Usage: scripts/fuzz.sh [SECONDS_PER_TARGET]   (default 600)
# Installs clang and libclang-rt-14-dev if missing (the normal gcc build does not need them), configures
# ./build-fuzz (CC=clang CXX=clang++ -DIGA_FUZZ=ON), builds the three targets, runs each for the given time on a
# working copy of its seed corpus (build-fuzz/corpus/<target>, kept between runs; seeds in tests/fuzz/corpus/)
# and prints the executions per target. Exits non-zero if any target finds a crash, a sanitizer report, an
# escaped exception, a timeout (> 10 s for one input) or an out-of-memory (> 2048 MB); the input is saved in
# build-fuzz/artifacts/<target>/. Environment: IGA_FUZZ_BUILD_DIR (default <repo>/build-fuzz), IGA_JOBS.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${IGA_FUZZ_BUILD_DIR:-$root/build-fuzz}"
jobs="${IGA_JOBS:-$(nproc)}"
seconds="${1:-600}"
[[ "$seconds" =~ ^[0-9]+$ ]] || { echo "usage: scripts/fuzz.sh [SECONDS_PER_TARGET]" >&2; exit 2; }

packages=(clang libclang-rt-14-dev cmake libeigen3-dev nlohmann-json3-dev libmuparser-dev libginac-dev pkg-config)
# shellcheck source=scripts/packages.sh
source "$root/scripts/packages.sh"
install_packages fuzz "${packages[@]}"

if [[ ! -f "$build/CMakeCache.txt" ]]; then
  CC=clang CXX=clang++ cmake -S "$root" -B "$build" -DIGA_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build" -j "$jobs"

# target:max_len (bytes of one input)
targets=(obj:65536 expression:4096 curve_json:4096)
failed=0
summary=()
for entry in "${targets[@]}"; do
  target="${entry%%:*}"
  max_len="${entry##*:}"
  corpus="$build/corpus/$target"
  artifacts="$build/artifacts/$target"
  log="$build/fuzz_$target.log"
  mkdir -p "$corpus" "$artifacts"
  cp -n "$root/tests/fuzz/corpus/$target/"* "$corpus/"
  echo "fuzz: $target for ${seconds} s (log $log)" >&2
  status=0
  "$build/tests/fuzz/fuzz_$target" "$corpus" -max_total_time="$seconds" -max_len="$max_len" -rss_limit_mb=2048 \
    -timeout=10 -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1 || status=$?
  # libFuzzer 14 says number_of_executed_units (later versions: ..._runs)
  runs=$(sed -n 's/^stat::number_of_executed_\(units\|runs\): *//p' "$log" | tail -1)
  if ((status != 0)) || [[ -n "$(ls -A "$artifacts")" ]]; then
    failed=1
    summary+=("$target: FAILED (exit $status) after ${runs:-?} runs; see $log and $artifacts/")
  else
    summary+=("$target: ok, ${runs:-?} runs in ${seconds} s, corpus $(ls "$corpus" | wc -l) inputs")
  fi
done
printf 'fuzz: %s\n' "${summary[@]}"
exit "$failed"
