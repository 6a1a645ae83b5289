#!/usr/bin/env bash
# Sets up (dependencies, build) and runs the default benchmark: Poisson on the embedded quarter annulus,
# writing result.vtu (open it in ParaView) and result.json in the current directory.
# Extra arguments go to iga-poisson, e.g. ./scripts/run.sh --degree 2 --refine 6.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
"$root/scripts/setup.sh"
"${IGA_BUILD_DIR:-$root/build}/benchmarks/iga-poisson" --vtu result.vtu --json result.json "$@"
