#!/usr/bin/env python3
"""Runs a build tree's ctest tests in a fixed priority order until a deadline, and never past it.

The sanitizer stage of CI (scripts/sanitize.sh) runs under what the normal stage left of CI's time. ctest alone
cannot do that: a test cut at `--stop-time` counts as failed. This runner takes the tests from
`ctest --show-only=json-v1` (names, commands, labels, environments, timeouts, working folders, fixtures), orders
them by the priority classes given with --class (first class first; inside a class the longest known test
first, from ctest's own CTestCostData.txt, so the two workers finish together), and runs them --jobs at a time.

At the deadline it stops: no new test starts, a test still running is ended, and both are listed as "not run
(deadline)" in one line. That is never a failure. A test that fails, crashes or exceeds its own TIMEOUT before the
deadline is a failure (exit 1), its output printed as ctest would. A test whose last measured time does not fit in
what is left is not started (listed the same way): starting it would only waste the rest.

The closing line is the plain 'N passed, N failed, N skipped' (skipped: not run for the deadline, or skipped by
the test itself, as ctest's SKIP_REGULAR_EXPRESSION or SKIP_RETURN_CODE says).
"""
import argparse
import json
import os
import re
import shlex
import signal
import subprocess
import sys
import threading
import time


def parse_args():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("--build-dir", required=True, help="the ctest build tree")
    p.add_argument("--jobs", type=int, default=os.cpu_count() or 1)
    p.add_argument("--deadline", type=float, required=True, help="seconds since the epoch at which to stop")
    p.add_argument("--exclude-labels", default="", help="regex: tests with a matching label are not run")
    p.add_argument("--exclude", default="", help="regex: tests with a matching name are not run")
    p.add_argument("--class", dest="classes", action="append", default=[], metavar="NAME=REGEX",
                   help="a priority class: tests whose name, executable or a label matches REGEX "
                        "(re.search); the first class that matches a test takes it. REGEX '*' takes the tests "
                        "no other class takes, at its place in the order (without it they run last)")
    p.add_argument("--order", default="", metavar="NAME,NAME,...",
                   help="the order in which the classes run, when it differs from the order in which they "
                        "take tests (e.g. a narrow class that must take its tests before a wide one, yet run "
                        "after it); every class once")
    p.add_argument("--extra-test", action="append", default=[], metavar="NAME=COMMAND",
                   help="a command to run as one more test (split as a shell would, run without a shell), "
                        "with the environment of this runner and its TIMEOUT of 1500 s")
    p.add_argument("--env", action="append", default=[], metavar="LABEL:VAR=VALUE",
                   help="set VAR=VALUE for the tests with label LABEL (after the test's own ENVIRONMENT)")
    p.add_argument("--costs-from", default="", metavar="DIR",
                   help="another build tree whose CTestCostData.txt orders the tests inside a class when this "
                        "tree has no time for them yet (e.g. the Release tree for a fresh sanitizer tree)")
    p.add_argument("--tag", default="run", help="the word that starts every line this runner prints")
    p.add_argument("--dry-run", action="store_true", help="print the order and the classes, run nothing")
    return p.parse_args()


def load_tests(build_dir):
    out = subprocess.run(["ctest", "--test-dir", build_dir, "--show-only=json-v1"], check=True,
                         capture_output=True, text=True).stdout
    tests = []
    for t in json.loads(out)["tests"]:
        props = {p["name"]: p["value"] for p in t.get("properties", [])}
        if props.get("DISABLED"):
            continue
        labels = props.get("LABELS", [])
        env = {}
        for item in props.get("ENVIRONMENT", []):
            k, _, v = item.partition("=")
            env[k] = v
        tests.append({
            "name": t["name"],
            "command": t.get("command", []),
            "labels": labels if isinstance(labels, list) else [labels],
            "env": env,
            "timeout": float(props.get("TIMEOUT", 1500)),
            "cwd": props.get("WORKING_DIRECTORY") or build_dir,
            "requires": props.get("FIXTURES_REQUIRED", []),
            "after": props.get("DEPENDS", []),
            "sets_up": props.get("FIXTURES_SETUP", []),
            "will_fail": bool(props.get("WILL_FAIL", False)),
            "skip_regex": [re.compile(rx) for rx in props.get("SKIP_REGULAR_EXPRESSION", [])],
            "skip_code": props.get("SKIP_RETURN_CODE"),
        })
    return tests


def load_costs(build_dir):
    """ctest's own record of each test's average time (Testing/Temporary/CTestCostData.txt)."""
    costs = {}
    path = os.path.join(build_dir, "Testing", "Temporary", "CTestCostData.txt")
    try:
        with open(path, encoding="utf-8") as f:
            for line in f:
                if line.startswith("---"):
                    break
                parts = line.split()
                if len(parts) == 3:
                    costs[parts[0]] = float(parts[2])
    except OSError:
        pass
    return costs


def classify(tests, classes, costs, other_costs):
    """Each test's class (the index of the first class that takes it) and cost. The cost is this
    tree's own measured time, else the other tree's (only for the order: the fit against the deadline uses this
    tree's own times alone)."""
    compiled = [(i, re.compile(rx)) for i, (_, rx) in enumerate(classes) if rx != "*"]
    rest = next((i for i, (_, rx) in enumerate(classes) if rx == "*"), len(classes))

    def klass(t):
        keys = [t["name"], os.path.basename(t["command"][0]) if t["command"] else ""] + t["labels"]
        for i, rx in compiled:
            if any(rx.search(k) for k in keys):
                return i
        return rest

    for t in tests:
        t["class"] = klass(t)
        t["own_cost"] = costs.get(t["name"])
        t["cost"] = t["own_cost"] if t["own_cost"] is not None else other_costs.get(t["name"])
    return tests


class Runner:
    def __init__(self, args, tests, label_env):
        self.args, self.queue, self.label_env = args, list(tests), label_env
        self.lock = threading.Lock()
        self.done_fixtures_ok, self.failed_fixtures = set(), set()
        self.running = {}   # name -> Popen
        self.passed, self.failed, self.not_run, self.skipped = [], [], [], []
        self.stopping = False

    def remaining(self):
        return self.args.deadline - time.time()

    def environment(self, t):
        env = dict(os.environ)
        env.update(t["env"])
        for label, var, value in self.label_env:
            if label in t["labels"]:
                env[var] = value
        return env

    def next_test(self):
        """The first queued test whose fixtures are ready; None when none is ready yet; 'end' when none is left."""
        with self.lock:
            running_setups = {f for name in self.running for f in self._setups.get(name, [])}
            i = 0
            while i < len(self.queue):
                t = self.queue[i]
                needs = set(t["requires"])
                if needs & self.failed_fixtures:
                    self.queue.pop(i)
                    self.failed.append((t["name"], "the setup of its fixture failed"))
                    continue
                if needs - self.done_fixtures_ok and (
                        any(needs & set(q["sets_up"]) for q in self.queue) or needs & running_setups):
                    i += 1  # its setup has yet to finish
                    continue
                if any(q["name"] in t["after"] for q in self.queue) or set(t["after"]) & set(self.running):
                    i += 1  # a test it DEPENDS on has yet to finish
                    continue
                if t["own_cost"] is not None and t["own_cost"] > self.remaining():
                    self.queue.pop(i)  # its last measured time does not fit in what is left
                    self.not_run.append(t["name"])
                    continue
                self.running[t["name"]] = None  # started from now on (its process follows)
                return self.queue.pop(i)
            return None if self.queue else "end"

    def run_one(self, t):
        left = self.remaining()
        limit = min(t["timeout"], left)
        start = time.time()
        try:
            proc = subprocess.Popen(t["command"], cwd=t["cwd"], env=self.environment(t), stdout=subprocess.PIPE,
                                    stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL, start_new_session=True)
        except OSError as e:
            with self.lock:
                self.running.pop(t["name"], None)
            return "failed", f"could not start: {e}", 0.0
        with self.lock:
            self.running[t["name"]] = proc
        try:
            out, _ = proc.communicate(timeout=limit)
            text = (out or b"").decode("utf-8", "replace")
            status = "passed" if (proc.returncode == 0) != t["will_fail"] else "failed"
            if (t["skip_code"] is not None and proc.returncode == int(t["skip_code"])) or \
                    any(rx.search(text) for rx in t["skip_regex"]):
                status = "skipped"  # as ctest: the test said it could not run here (e.g. no ../shared)
            detail = f"exit code {proc.returncode}"
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            out, _ = proc.communicate()
            if limit < t["timeout"]:
                status, detail = "deadline", "ended at the deadline"
            else:
                status, detail = "failed", f"its own TIMEOUT of {t['timeout']:.0f} s"
        finally:
            with self.lock:
                self.running.pop(t["name"], None)
        if self.stopping and status not in ("passed", "skipped"):
            status = "deadline"
        if status == "failed":
            lines = (out or b"").decode("utf-8", "replace").splitlines()
            detail = "\n".join(lines[-400:] + [f"({detail})"])
        return status, detail, time.time() - start

    def worker(self):
        while True:
            if self.remaining() <= 0:
                return
            t = self.next_test()
            if t == "end":
                return
            if t is None:
                time.sleep(0.2)
                continue
            status, detail, seconds = self.run_one(t)
            with self.lock:
                if status == "skipped":
                    self.skipped.append(t["name"])
                    self.done_fixtures_ok.update(t["sets_up"])
                    print(f"{self.args.tag}: skipped {t['name']} (the test said so)", flush=True)
                elif status == "passed":
                    self.passed.append(t["name"])
                    self.done_fixtures_ok.update(t["sets_up"])
                    print(f"{self.args.tag}: passed  {t['name']} ({seconds:.1f} s)", flush=True)
                elif status == "deadline":
                    self.not_run.append(t["name"])
                    print(f"{self.args.tag}: stopped at the deadline: {t['name']} ({seconds:.1f} s)", flush=True)
                else:
                    self.failed.append((t["name"], detail))
                    self.failed_fixtures.update(t["sets_up"])
                    print(f"{self.args.tag}: FAILED  {t['name']} ({seconds:.1f} s)\n{detail.rstrip()}", flush=True)

    def run(self):
        self._setups = {t["name"]: t["sets_up"] for t in self.queue}
        workers = [threading.Thread(target=self.worker) for _ in range(max(1, self.args.jobs))]
        for w in workers:
            w.start()
        try:
            while any(w.is_alive() for w in workers):
                if self.remaining() <= 0 and not self.stopping:
                    self.stopping = True
                    with self.lock:
                        for proc in self.running.values():
                            try:
                                if proc is not None:
                                    os.killpg(proc.pid, signal.SIGKILL)
                            except ProcessLookupError:
                                pass
                time.sleep(0.2)
        finally:
            for w in workers:
                w.join()
        with self.lock:
            self.not_run.extend(t["name"] for t in self.queue)
            self.queue.clear()


def main():
    args = parse_args()
    classes = []
    for c in args.classes:
        name, sep, rx = c.partition("=")
        if not sep:
            sys.exit(f"{args.tag}: --class needs NAME=REGEX, got '{c}'")
        classes.append((name, rx))
    label_env = []
    for e in args.env:
        label, sep, assignment = e.partition(":")
        var, sep2, value = assignment.partition("=")
        if not sep or not sep2:
            sys.exit(f"{args.tag}: --env needs LABEL:VAR=VALUE, got '{e}'")
        label_env.append((label, var, value))

    tests = load_tests(args.build_dir)
    xl = re.compile(args.exclude_labels) if args.exclude_labels else None
    xn = re.compile(args.exclude) if args.exclude else None
    tests = [t for t in tests if not (xl and any(xl.search(label) for label in t["labels"]))
             and not (xn and xn.search(t["name"]))]
    for e in args.extra_test:
        name, sep, command = e.partition("=")
        if not sep or not command.strip():
            sys.exit(f"{args.tag}: --extra-test needs NAME=COMMAND, got '{e}'")
        tests.append({"name": name, "command": shlex.split(command), "labels": [], "env": {}, "timeout": 1500.0,
                      "cwd": args.build_dir, "requires": [], "after": [], "sets_up": [], "will_fail": False,
                      "skip_regex": [], "skip_code": None})
    other = load_costs(args.costs_from) if args.costs_from else {}
    tests = classify(tests, classes, load_costs(args.build_dir), other)
    names = [c[0] for c in classes]
    run_order = args.order.split(",") if args.order else names
    if sorted(run_order) != sorted(names):
        sys.exit(f"{args.tag}: --order must name every class once: {', '.join(names)}")
    rank = {names.index(n): r for r, n in enumerate(run_order)}
    rank[len(names)] = len(names)  # the tests no class took, when no class is '*'
    for t in tests:
        t["class"] = rank[t["class"]]
    tests.sort(key=lambda t: (t["class"], -(t["cost"] or 0.0), t["name"]))
    names = run_order + ([] if any(rx == "*" for _, rx in classes) else ["rest"])
    counts = [sum(1 for t in tests if t["class"] == i) for i in range(len(names))]
    print(f"{args.tag}: {len(tests)} tests in priority order: " +
          ", ".join(f"{n} {c}" for n, c in zip(names, counts)) +
          f"; {max(0, args.deadline - time.time()) / 60:.1f} min until the deadline", flush=True)
    if args.dry_run:
        for t in tests:
            cost = f"{t['cost']:.1f} s" if t["cost"] is not None else "?"
            print(f"{names[t['class']]}\t{cost}\t{t['name']}")
        return 0

    runner = Runner(args, tests, label_env)
    runner.run()
    if runner.failed:
        print(f"{args.tag}: the failed tests: " + ", ".join(n for n, _ in runner.failed), flush=True)
    if runner.not_run:
        print(f"{args.tag}: NOT RUN, the deadline came first ({len(runner.not_run)} tests; not a failure): " +
              ", ".join(sorted(runner.not_run)), flush=True)
    skipped = len(runner.not_run) + len(runner.skipped)
    print(f"{args.tag}: {len(runner.passed)} passed, {len(runner.failed)} failed, {skipped} skipped", flush=True)
    return 1 if runner.failed else 0


if __name__ == "__main__":
    sys.exit(main())
