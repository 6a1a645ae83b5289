#!/usr/bin/python3
"""Runs the commands README.md shows for this project's programs and fails naming the README line of any that
exits non-zero (or runs past --timeout seconds).

Which commands run (the rule):
  - a command runs a program of this project when it contains build/benchmarks/, build/tools/ or build/examples/
    (a pipeline into one counts: echo ... | build/tools/iga-knots -);
  - a fenced code block without a language or with sh/bash/console (```cmake blocks are not commands) runs
    whole, every command in order (lines joined at a trailing backslash or inside a '...' string that spans
    lines, '#' comment lines skipped), when at least one of its commands runs a program of this project: a helper
    line that writes an input file runs too;
  - an inline code span runs when it is such a command;
  - everything else is skipped, by rule: ./scripts/*.sh (setup.sh installs packages and builds, test.sh and
    run.sh run setup.sh and then the whole suite or a benchmark, fuzz.sh and sanitize.sh build and run separate
    clang/ASan trees for minutes to hours), cmake --install (writes outside the build tree), CMake snippets.
How they run: build/ (or ./build/) is rewritten to --build-dir; every fenced block, and every paragraph's inline
spans, runs in a fresh temporary folder holding a symlink data -> <source>/data, so data/meshes/... resolves and
every output (result.vtu, net.obj, ...) lands there; the commands of one block or paragraph run in order in the
same folder (a later one may read what an earlier one wrote), through bash -o pipefail.
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from shard import add_shard_option, take_share  # noqa: E402  (tests/support/shard.py)

# The README's mpirun commands as a user types them: Open MPI's own switches for running as root (CI does) and for
# more ranks than cores, set through its environment instead of the command line.
MPI_ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")

PROGRAM = re.compile(r"(?<![\w./-])(?:\./)?build/(benchmarks|tools|examples)/")


def commands(readme_lines):
    """[(group, line_number, command)], group = the block or paragraph the command belongs to."""
    out = []
    fence = None  # language of the open fenced block, None outside
    group = 0
    pending, pending_line = "", 0
    for number, line in enumerate(readme_lines, start=1):
        stripped = line.strip()
        if stripped.startswith("```"):
            if fence is None:
                fence = stripped[3:].strip()
                group += 1
            else:
                fence = None
                group += 1
            continue
        if fence is not None:
            if fence not in ("", "sh", "bash", "console"):
                continue
            if not pending and (not stripped or stripped.startswith("#")):
                continue
            if not pending:
                pending_line = number
            if stripped.endswith("\\"):
                pending += stripped[:-1] + " "
                continue
            if (pending + stripped).count("'") % 2:  # a quoted string that goes on to the next line
                pending += stripped + "\n"
                continue
            out.append((group, pending_line, pending + stripped, True))
            pending = ""
            continue
        if not stripped:
            group += 1  # a blank line ends a paragraph
            continue
        for span in re.findall(r"`([^`]+)`", line):
            out.append((group, number, span.strip(), False))
    runs = {g for g, _, c, _ in out if PROGRAM.search(c)}
    return [(g, n, c) for g, n, c, fenced in out if g in runs and (fenced or PROGRAM.search(c))]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--readme", required=True)
    ap.add_argument("--source-dir", required=True, help="the repository (its data/ is linked into each folder)")
    ap.add_argument("--build-dir", required=True, help="what build/ in the README stands for")
    ap.add_argument("--timeout", type=float, default=120, help="seconds per command")
    ap.add_argument("--list", action="store_true", help="print the commands that would run and exit")
    add_shard_option(ap, "command groups (a group's commands share a folder, so a group is never split)")
    args = ap.parse_args()
    build = os.path.abspath(args.build_dir)
    name = os.path.basename(args.readme)
    with open(args.readme, encoding="utf-8") as f:
        found = commands(f.read().splitlines())
    groups = sorted({g for g, _, _ in found}, key=lambda g: min(num for gg, num, _ in found if gg == g))
    mine = set(take_share(ap, args.shard, groups))
    found = [c for c in found if c[0] in mine]
    if args.list:
        for _, number, command in found:
            print(f"{name}:{number}: {command}")
        return 0
    if not found:
        print(f"{name}: no commands of this project found", file=sys.stderr)
        return 1
    failures = []
    folders = {}
    with tempfile.TemporaryDirectory(prefix="iga-readme-") as scratch:
        for group, number, command in found:
            if group not in folders:
                folders[group] = os.path.join(scratch, f"block{len(folders):02d}")
                os.makedirs(folders[group])
                os.symlink(os.path.join(os.path.abspath(args.source_dir), "data"), os.path.join(folders[group], "data"))
            run = PROGRAM.sub(lambda m: f"{build}/{m.group(1)}/", command)
            start = time.monotonic()
            try:
                r = subprocess.run(["bash", "-o", "pipefail", "-c", run], cwd=folders[group], capture_output=True,
                                   text=True, timeout=args.timeout, stdin=subprocess.DEVNULL, env=MPI_ENV)
                rc, err = r.returncode, r.stderr.strip().splitlines()
            except subprocess.TimeoutExpired:
                rc, err = "timeout", [f"still running after {args.timeout:g} s"]
            seconds = time.monotonic() - start
            status = "ok" if rc == 0 else f"FAILED ({rc})"
            print(f"{name}:{number}: {status} in {seconds:.1f} s: {command}", flush=True)
            if rc != 0:
                failures.append(f"{name}:{number}: exit {rc}: {command}\n    " + (err[-1] if err else "(no stderr)"))
    if failures:
        print(f"\n{len(failures)} of {len(found)} commands of {name} failed:", file=sys.stderr)
        for f in failures:
            print(f, file=sys.stderr)
        return 1
    print(f"all {len(found)} commands of {name} passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
