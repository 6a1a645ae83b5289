#!/usr/bin/env bash
# Sets up (dependencies, build) and runs the default test suite with ctest (slow studies excluded).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
ctest --test-dir "${IGA_BUILD_DIR:-$root/build}" --output-on-failure -j "${IGA_JOBS:-$(nproc)}" -LE slow
