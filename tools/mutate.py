#!/usr/bin/env python3
"""A mutation check of the test suite: does a deliberate physics mistake turn a test red?

    python3 tools/mutate.py [--work DIR] [--only ID[,ID...]] [--jobs 2] [--per-test-timeout 900]
                            [--report FILE] [--skip REGEX]

Makes a scratch copy of the committed tree (`git worktree` of HEAD in DIR/src, default
/tmp/ryushi_mutate) and a Release build of it in DIR/build (the first time: a full build), then
for each mutation of tools/mutations.json, one at a time: applies it (an exact, unique
replacement in one source file), rebuilds incrementally, and runs the tests cheapest first
(by the costs ctest recorded in the last full run of that build, or of build/ beside this script)
until the first failure; then restores the file. A mutation that builds and passes every test is
a survivor: a physics mistake the suite does not see. --skip leaves out the tests whose names
match (Python regex), e.g. '^access:' (its every-method run fails on any solver that stops
converging, before a physics test would say what broke).

Writes the report (default DIR/report.md): per mutation, the catching test, how many tests ran
before it, and the seconds (build and tests). Exit 0 when every mutation was caught, 1 with
survivors, 2 on a mutation that no longer applies (its text is not in the file once).
"""
import argparse
import json
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def run(cmd, cwd=None, timeout=None):
    return subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=timeout)


def test_names_by_cost(build):
    """Every ctest entry, cheapest first: the slow tests by the COST tests/slow_tests.cmake gives
    them (ctest's own CTestCostData.txt cuts names at their first space, so it cannot be read),
    the rest, quick, before them."""
    listing = json.loads(run(["ctest", "--show-only=json-v1"], cwd=build).stdout)
    costs = {}
    for t in listing["tests"]:
        cost = 1.0
        for prop in t.get("properties", []):
            if prop.get("name") == "COST":
                cost = float(prop["value"])
        costs[t["name"]] = cost
    return sorted(costs, key=lambda name: costs[name])


def cmake_regex(name):
    """An exact-match ctest -R pattern (CMake's regex syntax: no escaped spaces)."""
    return "^" + "".join("\\" + c if c in ".^$*+?()[]{}|\\" else c for c in name) + "$"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--work", default="/tmp/ryushi_mutate")
    ap.add_argument("--only", default="")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--per-test-timeout", type=int, default=900)
    ap.add_argument("--report", default=None)
    ap.add_argument("--skip", default="", help="leave out the tests whose names match this regex")
    a = ap.parse_args()
    mutations = json.load(open(os.path.join(HERE, "mutations.json")))
    if a.only:
        wanted = set(a.only.split(","))
        mutations = [m for m in mutations if m["id"] in wanted]
    src, build = os.path.join(a.work, "src"), os.path.join(a.work, "build")
    if not os.path.isdir(src):
        os.makedirs(a.work, exist_ok=True)
        r = run(["git", "worktree", "add", "--detach", src, "HEAD"], cwd=ROOT)
        if r.returncode != 0:
            sys.exit(f"mutate: git worktree add failed: {r.stderr.strip()}")
    head = run(["git", "rev-parse", "HEAD"], cwd=ROOT).stdout.strip()
    r = run(["git", "checkout", "--detach", head], cwd=src)  # the scratch copy follows HEAD
    if r.returncode != 0:
        sys.exit(f"mutate: {src}: git checkout {head} failed: {r.stderr.strip()}")
    for m in mutations:  # every mutation applies before any is run
        text = open(os.path.join(src, m["file"])).read()
        if text.count(m["old"]) != 1:
            print(f"mutate: {m['id']}: its text occurs {text.count(m['old'])} times in {m['file']} (not once)",
                  file=sys.stderr)
            sys.exit(2)
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        r = run(["cmake", "-S", src, "-B", build, "-DCMAKE_BUILD_TYPE=Release"])
        if r.returncode != 0:
            sys.exit(f"mutate: cmake failed: {r.stderr[-2000:]}")
    start = time.time()
    r = run(["cmake", "--build", build, f"-j{a.jobs}"])
    if r.returncode != 0:
        sys.exit(f"mutate: the unmutated tree does not build: {r.stdout[-2000:]}")
    print(f"mutate: unmutated build {time.time() - start:.0f} s", flush=True)
    tests = [t for t in test_names_by_cost(build) if not (a.skip and re.search(a.skip, t))]
    rows, survivors = [], 0
    for m in mutations:
        path = os.path.join(src, m["file"])
        original = open(path).read()
        open(path, "w").write(original.replace(m["old"], m["new"]))
        try:
            t0 = time.time()
            r = run(["cmake", "--build", build, f"-j{a.jobs}"])
            built = time.time() - t0
            if r.returncode != 0:
                rows.append((m, "does not compile", 0, built, 0.0))
                print(f"mutate: {m['id']}: does not compile (fix the mutation)", flush=True)
                continue
            t1, caught, ran = time.time(), None, 0
            for name in tests:
                ran += 1
                try:
                    t = run(["ctest", "-R", cmake_regex(name), "--timeout", str(a.per_test_timeout)],
                            cwd=build, timeout=a.per_test_timeout + 60)
                    if "No tests were found" in t.stdout + t.stderr:
                        sys.exit(f"mutate: ctest found no test for the pattern {cmake_regex(name)}")
                    failed = t.returncode != 0
                except subprocess.TimeoutExpired:
                    failed = True
                if failed:
                    caught = name
                    break
            tested = time.time() - t1
            survivors += caught is None
            rows.append((m, caught or "SURVIVED", ran, built, tested))
            print(f"mutate: {m['id']}: {caught or 'SURVIVED'} ({ran} tests, build {built:.0f} s, "
                  f"tests {tested:.0f} s)", flush=True)
        finally:
            open(path, "w").write(original)
    run(["cmake", "--build", build, f"-j{a.jobs}"])  # leave the build unmutated
    report = a.report or os.path.join(a.work, "report.md")
    with open(report, "w") as out:
        out.write("| mutation | file | caught by | tests run | build s | tests s |\n|---|---|---|---|---|---|\n")
        for m, caught, ran, built, tested in rows:
            out.write(f"| {m['description']} | {m['file']} | {caught} | {ran} | {built:.0f} | {tested:.0f} |\n")
    print(f"mutate: {len(rows)} mutations, {survivors} survived; report {report} "
          f"({time.time() - start:.0f} s in all)")
    sys.exit(1 if survivors or any(r[1] == "does not compile" for r in rows) else 0)


if __name__ == "__main__":
    main()
