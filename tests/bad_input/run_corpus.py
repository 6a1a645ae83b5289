#!/usr/bin/python3
"""Runs the hostile-input corpus (tests/bad_input/cases/*.ini) against the built programs.

Every case is one run of one program. It passes when
- the program exits with the expected code (never killed by a signal, never past its timeout),
- standard error is exactly the expected lines (one line for a refusal: the error and nothing else),
- nothing on either stream looks like a crash (terminate, sanitizer reports, 'Segmentation fault'),
- and, for runs expected to succeed, the JSON report holds the expected values.

A case (INI section; values are read after placeholder substitution):
    [name]
    class = 7                         # the class of issue 14 (1..10) it belongs to
    run = iga-poisson --mesh {in}/bom.obj --vtu none --json none --quiet
    exit = 1                          # expected exit code
    stderr = iga-poisson: error: ...  # expected standard error, exactly; several lines: indent continuations
    stderr_regex = ...                # instead of stderr: one line matching this regular expression (for
                                      #   figures that depend on the machine, such as the memory available)
    stdin = {in}/curve.json           # optional: file fed to standard input (default: none)
    timeout = 60                      # optional, seconds
    json = {tmp}/r.json               # optional: report to check (exit 0 runs)
    json_checks = domain_measure 1 1e-12   # optional: lines 'key value tolerance' (key a JSON pointer
                                      #   without the leading '/', value a number, or a string with tolerance -)
    absent = {tmp}/none               # optional: paths that must not exist after the run (one per line)
Placeholders: {in} = tests/bad_input/inputs, {data} = the repository's data/, {tmp} = a fresh temporary folder
per case, {src} = the repository root.

Usage: run_corpus.py --exe iga-poisson=PATH [--exe ...] [--memory-limit-mb N] [--only SUBSTRING] [--counts]
Programs not given with --exe make their cases fail (a case that cannot run is not a pass).
Every run gets an address-space limit (default 8 GiB) so that a program that does not check sizes before
allocating fails inside its own std::bad_alloc handler instead of taking the machine.
"""
import argparse
import configparser
import json
import os
import re
import resource
import shlex
import subprocess
import sys
import tempfile
from collections import defaultdict

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
from shard import add_shard_option, take_share  # noqa: E402  (tests/support/shard.py)

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(os.path.dirname(HERE))
CRASH = re.compile(r"terminate called|Segmentation fault|AddressSanitizer|runtime error:|LeakSanitizer|"
                   r"Aborted|core dumped|std::bad_alloc$|what\(\):")


def load_cases(only):
    cases = []
    folder = os.path.join(HERE, "cases")
    for name in sorted(os.listdir(folder)):
        if not name.endswith(".ini"):
            continue
        parser = configparser.ConfigParser(interpolation=None, strict=True, empty_lines_in_values=False)
        parser.optionxform = str
        with open(os.path.join(folder, name), encoding="utf-8") as f:
            parser.read_file(f)
        for section in parser.sections():
            if only and only not in section and only not in name:
                continue
            cases.append((name, section, dict(parser[section])))
    return cases


def substitute(text, tmp):
    return (text.replace("{in}", os.path.join(HERE, "inputs")).replace("{data}", os.path.join(SRC, "data"))
            .replace("{tmp}", tmp).replace("{src}", SRC))


def json_value(report, pointer):
    value = report
    for part in pointer.split("/"):
        if isinstance(value, list):
            value = value[int(part)]
        else:
            value = value[part]
    return value


def check_json(case, tmp):
    problems = []
    path = substitute(case["json"], tmp)
    try:
        with open(path, encoding="utf-8") as f:
            report = json.load(f)
    except (OSError, ValueError) as e:
        return [f"report {path} unreadable: {e}"]
    for line in case.get("json_checks", "").strip().splitlines():
        key, value, tol = line.split()
        try:
            got = json_value(report, key)
        except (KeyError, IndexError, ValueError):
            problems.append(f"report has no {key}")
            continue
        if tol == "-":
            if (got if isinstance(got, str) else json.dumps(got)) != value:
                problems.append(f"{key} = {got!r}, expected {value!r}")
        elif not isinstance(got, (int, float)) or abs(got - float(value)) > float(tol):
            problems.append(f"{key} = {got!r}, expected {value} ± {tol}")
    return problems


def run_case(case, exes, memory_mb):
    tmp = tempfile.mkdtemp(prefix="iga-bad-input-")
    argv = shlex.split(substitute(case["run"], tmp))
    program = argv[0]
    if program not in exes:
        return [f"program {program} not given (--exe {program}=PATH)"], ""
    argv[0] = exes[program]
    stdin = subprocess.DEVNULL
    if "stdin" in case:
        stdin = open(substitute(case["stdin"], tmp), "rb")

    def limit():
        limit_bytes = memory_mb * 1024 * 1024
        resource.setrlimit(resource.RLIMIT_AS, (limit_bytes, limit_bytes))

    env = dict(os.environ, OMP_NUM_THREADS=os.environ.get("OMP_NUM_THREADS", "2"))
    try:
        p = subprocess.run(argv, stdin=stdin, capture_output=True, timeout=float(case.get("timeout", 60)),
                           preexec_fn=limit, cwd=tmp, env=env)
    except subprocess.TimeoutExpired:
        return [f"no answer within {case.get('timeout', 60)} s (a hang)"], ""
    except OSError as e:
        return [f"cannot run {argv[0]}: {e}"], ""
    finally:
        if stdin is not subprocess.DEVNULL:
            stdin.close()
    err = p.stderr.decode("utf-8", "replace")
    out = p.stdout.decode("utf-8", "replace")
    problems = []
    if p.returncode < 0:
        problems.append(f"killed by signal {-p.returncode}")
    expected_exit = int(case["exit"])
    if p.returncode != expected_exit:
        problems.append(f"exit {p.returncode}, expected {expected_exit}")
    if CRASH.search(err) or CRASH.search(out):
        problems.append("crash output")
    expected = [line.strip() for line in substitute(case.get("stderr", ""), tmp).strip().splitlines()]
    got = [line for line in err.rstrip("\n").split("\n")] if err.strip() else []
    if "stderr_ignore" in case:  # lines of a successful run that are results, not messages (iga-quadrature's value)
        ignore = re.compile(substitute(case["stderr_ignore"], tmp).strip())
        got = [line for line in got if not ignore.fullmatch(line)]
    if "stderr_regex" in case:
        pattern = substitute(case["stderr_regex"], tmp).strip()
        if len(got) != 1 or not re.fullmatch(pattern, got[0]):
            problems.append("stderr does not match:\n      pattern: " + pattern + "\n      got:     " +
                            "\n               ".join(got))
    elif got != expected:
        problems.append("stderr differs:\n      expected: " + "\n                ".join(expected) +
                        "\n      got:      " + "\n                ".join(got))
    for path in substitute(case.get("absent", ""), tmp).split():
        if os.path.exists(path):
            problems.append(f"{path} was written")
    if expected_exit == 0 and "json" in case:
        problems += check_json(case, tmp)
    if expected_exit != 0 and "nan" in err.lower().split() and "nan" not in case.get("stderr", "").lower():
        problems.append("a NaN in a refusal that does not expect one")
    return problems, err


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", action="append", default=[], help="NAME=PATH of a program")
    ap.add_argument("--memory-limit-mb", type=int, default=8192)
    ap.add_argument("--only", default="")
    ap.add_argument("--counts", action="store_true", help="print the number of cases per program and class")
    add_shard_option(ap, "cases, in the order of the case files")
    args = ap.parse_args()
    exes = {name: os.path.abspath(path) for name, path in (e.split("=", 1) for e in args.exe)}
    cases = load_cases(args.only)
    if args.counts:
        table = defaultdict(lambda: defaultdict(int))
        for _, _, case in cases:
            table[shlex.split(case["run"])[0]][case.get("class", "?")] += 1
        classes = sorted({c for row in table.values() for c in row}, key=lambda c: (len(c), c))
        print("| program | " + " | ".join(f"class {c}" for c in classes) + " | all |")
        print("|---" * (len(classes) + 2) + "|")
        for program in sorted(table):
            row = table[program]
            print(f"| {program} | " + " | ".join(str(row.get(c, 0)) for c in classes) + f" | {sum(row.values())} |")
        print(f"| all | " + " | ".join(str(sum(r.get(c, 0) for r in table.values())) for c in classes) +
              f" | {len(cases)} |")
        return 0
    cases = take_share(ap, args.shard, cases)
    failed = 0
    for file, name, case in cases:
        problems, _ = run_case(case, exes, args.memory_limit_mb)
        if problems:
            failed += 1
            print(f"FAIL {file} [{name}]")
            for p in problems:
                print("    " + p)
        else:
            print(f"ok   {file} [{name}]")
    print(f"{len(cases) - failed} passed, {failed} failed")
    return 1 if failed or not cases else 0


if __name__ == "__main__":
    sys.exit(main())
