#!/usr/bin/python3
"""The conventions every iga-* program keeps (README, "Conventions of every program"), checked from one table.

For each program: --help and --version (exit 0, the version of CMakeLists.txt and the git revision on stdout),
an unknown option (exit 2, one line "PROGRAM: error: ..." on stderr), bad input (exit 1, one line; a --config or
--mesh file that is not there is bad input too), a quick
successful run that writes nothing but what it is asked for ("none" writes nothing; stdout stays empty unless
'-' asks for it), --quiet (stderr empty on success); for programs with a JSON report: '--json -' puts exactly
the report on stdout with program, version, git_revision, schema_version and settings; and --export-config
followed by --config reproduces the report bit for bit apart from timings.

Usage: conventions.py --source-dir DIR --version X.Y.Z --exe NAME=PATH ...
"""
import argparse
import json
import os
import re
import shlex
import subprocess
import sys
import tempfile

# program: (quick successful arguments that write nothing by themselves, bad-input arguments, JSON report option
# or None). {data} is the source tree's data folder, {bad} an OBJ whose face names a vertex that does not exist,
# {curve} a valid B-spline curve JSON.
PROGRAMS = {
    "iga-poisson": ("--degree 2 --refine 1 --vtu none --json none", "--basis cc --mesh {bad} --vtu none --json none", "--json"),
    "iga-biharmonic": ("--geometry square --refine 2 --vtu none --json none", "--basis cc --mesh {bad} --vtu none --json none",
                       "--json"),
    "iga-elasticity": ("--refine 1 --vtu none --json none", "--basis cc --mesh {bad} --vtu none --json none", "--json"),
    "iga-bem": ("--refine 1 --vtu none --boundary-vtu none --json none", "--basis cc --mesh {bad} --vtu none --json none",
                "--json"),
    "iga-quadrature": ("--mesh {data}/meshes/square_evs.obj --quantity area --json none", "--mesh {bad}", "--json"),
    "iga-geometry": ("--mesh {data}/meshes/square_evs.obj --json none", "--mesh {bad}", "--json"),
    "iga-knots": ("{curve} --out none", "{bad}", None),
    "iga-fit-quadrature": ("--rank --min-valence 5 --max-valence 5 --output none", "--min-valence 6 --max-valence 5", None),
}

CURVE = {"degree": 2, "knots": [0, 0, 0, 0.5, 1, 1, 1], "control_points": [[0, 0], [1, 2], [2, 0], [3, 1]]}


class Checker:
    def __init__(self, exes, version, data):
        self.exes, self.version, self.data = exes, version, data
        self.failures = []
        self.checks = 0

    def run(self, program, args, cwd):
        argv = [self.exes[program]] + shlex.split(args)
        env = dict(os.environ, OMP_NUM_THREADS="1")
        p = subprocess.run(argv, capture_output=True, cwd=cwd, timeout=300, env=env)
        return p.returncode, p.stdout.decode("utf-8", "replace"), p.stderr.decode("utf-8", "replace")

    def expect(self, program, what, ok, detail=""):
        self.checks += 1
        if not ok:
            self.failures.append(f"{program}: {what}" + (f"\n    {detail}" if detail else ""))

    def one_error_line(self, program, what, result, code):
        rc, out, err = result
        lines = err.rstrip("\n").split("\n") if err.strip() else []
        self.expect(program, f"{what}: exit {code}", rc == code, f"exit {rc}, stderr {err!r}")
        self.expect(program, f"{what}: one line '{program}: error: ...' on stderr",
                    len(lines) == 1 and lines[0].startswith(program + ": error: "), repr(err))
        self.expect(program, f"{what}: nothing on stdout", out == "", repr(out[:200]))

    def check(self, program, tmp):
        ok_args, bad_args, json_option = PROGRAMS[program]
        fill = {"data": self.data, "bad": os.path.join(tmp, "bad.obj"), "curve": os.path.join(tmp, "curve.json")}
        ok_args, bad_args = ok_args.format(**fill), bad_args.format(**fill)
        work = os.path.join(tmp, program)
        os.mkdir(work)

        rc, out, err = self.run(program, "--help", work)
        self.expect(program, "--help: exit 0 with the options on stdout", rc == 0 and "--version" in out, err)
        rc, out, err = self.run(program, "--version", work)
        pattern = re.escape(program) + " " + re.escape(self.version) + r" \(git ([0-9a-f]{12}(-dirty)?|unknown)\)\n"
        self.expect(program, "--version: exit 0, 'PROGRAM VERSION (git REVISION)' on stdout",
                    rc == 0 and re.fullmatch(pattern, out) is not None and err == "", repr(out) + " " + repr(err))
        self.one_error_line(program, "an unknown option", self.run(program, "--no-such-option", work), 2)
        self.one_error_line(program, "bad input", self.run(program, bad_args, work), 1)
        missing = os.path.join(tmp, "no_such_file.toml")
        self.one_error_line(program, "a --config file that is not there (bad input)", self.run(program, f"--config {missing}", work), 1)
        if "--mesh" in bad_args:
            self.one_error_line(program, "a --mesh file that is not there (bad input)",
                                self.run(program, bad_args.replace(fill["bad"], os.path.join(tmp, "no_such.obj")), work), 1)

        rc, out, err = self.run(program, ok_args, work)
        self.expect(program, f"a quick run ({ok_args}): exit 0", rc == 0, err)
        self.expect(program, "a quick run: stdout empty (a report goes there only with '-')", out == "", repr(out[:200]))
        self.expect(program, "'none' writes nothing", os.listdir(work) == [], repr(os.listdir(work)))
        rc, out, err = self.run(program, ok_args + " --quiet", work)
        self.expect(program, "--quiet: exit 0 and nothing on stderr", rc == 0 and err == "", repr(err))
        if json_option:
            self.check_report(program, ok_args, json_option, work)
        self.check_config(program, ok_args, json_option, work)

    def check_report(self, program, ok_args, json_option, work):
        rc, out, err = self.run(program, ok_args.replace(f"{json_option} none", f"{json_option} -"), work)
        try:
            report = json.loads(out)
        except ValueError:
            self.expect(program, f"{json_option} -: the report on stdout", False, repr(out[:200]) + " " + err)
            return
        self.expect(program, f"{json_option} -: exit 0", rc == 0, err)
        for key, want in (("program", program), ("version", self.version), ("schema_version", 1)):
            self.expect(program, f"report: {key} = {want!r}", report.get(key) == want, repr(report.get(key)))
        self.expect(program, "report: git_revision and settings", isinstance(report.get("git_revision"), str)
                    and isinstance(report.get("settings"), dict), repr(report.get("settings"))[:200])

    def check_config(self, program, ok_args, json_option, work):
        """--export-config writes the options; --config with that file alone runs the same."""
        cfg = os.path.join(work, "run.toml")
        args = ok_args.replace(f"{json_option} none", f"{json_option} report.json") if json_option else ok_args
        rc, out, err = self.run(program, args + f" --export-config {cfg} --quiet", work)
        self.expect(program, "--export-config: exit 0", rc == 0 and os.path.exists(cfg), err)
        if rc != 0 or not os.path.exists(cfg):
            return
        first = open(os.path.join(work, "report.json")).read() if json_option else None
        rc, out2, err = self.run(program, f"--config {cfg} --quiet", work)
        self.expect(program, "--config FILE (exported): exit 0", rc == 0, err)
        if json_option and rc == 0:
            a, b = strip_timings(json.loads(first)), strip_timings(json.load(open(os.path.join(work, "report.json"))))
            self.expect(program, "--config reproduces the report (timings aside) bit for bit", a == b,
                        json.dumps(diff(a, b))[:400])
        for name in os.listdir(work):
            os.remove(os.path.join(work, name))


def strip_timings(j):
    if isinstance(j, dict):
        return {k: strip_timings(v) for k, v in j.items() if "seconds" not in k}
    if isinstance(j, list):
        return [strip_timings(v) for v in j]
    return j


def diff(a, b, at=""):
    if isinstance(a, dict) and isinstance(b, dict):
        out = {}
        for k in set(a) | set(b):
            d = diff(a.get(k), b.get(k), at + "/" + k)
            if d:
                out.update(d)
        return out
    return {} if a == b else {at: [a, b]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--exe", action="append", default=[])
    ap.add_argument("--version", required=True)
    ap.add_argument("--source-dir", required=True)
    args = ap.parse_args()
    exes = dict(e.split("=", 1) for e in args.exe)
    missing = set(PROGRAMS) - set(exes)
    if missing:
        sys.exit(f"conventions.py: no --exe for {', '.join(sorted(missing))}")
    checker = Checker(exes, args.version, os.path.join(args.source_dir, "data"))
    with tempfile.TemporaryDirectory(prefix="iga-conventions-") as tmp:
        with open(os.path.join(tmp, "bad.obj"), "w") as f:
            f.write("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3 9\n")
        with open(os.path.join(tmp, "curve.json"), "w") as f:
            json.dump(CURVE, f)
        for program in PROGRAMS:
            checker.check(program, tmp)
    for f in checker.failures:
        print("FAILED " + f)
    print(f"{checker.checks - len(checker.failures)} passed, {len(checker.failures)} failed")
    return 1 if checker.failures else 0


if __name__ == "__main__":
    sys.exit(main())
