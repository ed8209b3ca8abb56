#!/usr/bin/env python3
"""Deterministic verdicts (issue 29 §3): the same solution gets the same results.json every run.

  same_verdict.py NUMLAB OUT_DIR [RUNS]

Runs `numlab exercise check --format json` RUNS times (default 3) on every Python reference
(references/python/*.py but linkage.py, which needs --model) and every Python mutant
(mutants/EXERCISE/NAME.patch, made into OUT_DIR) and fails naming each solution whose results differ
between runs in anything but the times (each test's "timing"). Then it prints the margins it can
read from the failing messages, "by X ... allowed Y": the mutant nearest to passing (largest
allowed/error).
"""
import concurrent.futures
import json
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
EXERCISES = os.path.dirname(HERE)
sys.path.insert(0, EXERCISES)
from expect_verdict import mutant_from_patch  # noqa: E402

NUMBER = r"([0-9]+(?:\.[0-9]+)?(?:e[-+]?[0-9]+)?)"
BY_ALLOWED = re.compile(r"by " + NUMBER + r"\b[^;\n]*?allowed (?:\|error\| )?" + NUMBER)


def verdict(numlab, exercise, command):
    """results.json without the times; the raw one for the margins."""
    done = subprocess.run([numlab, "exercise", "check", exercise, "--format", "json", "--"] + command,
                          capture_output=True, text=True, timeout=600)
    try:
        results = json.loads(done.stdout)
    except json.JSONDecodeError:  # shown as a difference, with what came instead
        return done.returncode, f"not JSON: {done.stdout[:300]!r} {done.stderr[:300]!r}", {"tests": []}
    for test in results["tests"]:
        test.pop("timing", None)
    return done.returncode, json.dumps(results, sort_keys=True), results


def solutions(out_dir):
    """(label, exercise, command) for every Python reference and mutant."""
    found = []
    references = os.path.join(EXERCISES, "references", "python")
    for name in sorted(os.listdir(references)):
        if name.endswith(".py") and name != "linkage.py":
            found.append((f"reference {name}", name[:-3].replace("_", "-"),
                          [sys.executable, os.path.join(references, name)]))
    mutants = os.path.join(EXERCISES, "mutants")
    for exercise in sorted(os.listdir(mutants)):
        folder = os.path.join(mutants, exercise)
        if exercise == "octave" or not os.path.isdir(folder):
            continue
        for name in sorted(os.listdir(folder)):
            if name.endswith(".patch"):
                path = mutant_from_patch(os.path.join(folder, name), out_dir)
                found.append((f"mutant {exercise}/{name}", exercise, [sys.executable, path]))
    return found


def main(numlab, out_dir, runs):
    os.makedirs(out_dir, exist_ok=True)
    todo = solutions(out_dir)
    jobs = [(label, exercise, command) for label, exercise, command in todo for _ in range(runs)]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        outcomes = list(pool.map(lambda job: verdict(numlab, job[1], job[2]), jobs))
    differing, margins = [], []
    for k, (label, _, _) in enumerate(todo):
        mine = outcomes[k * runs:(k + 1) * runs]
        if len({(code, text) for code, text, _ in mine}) != 1:
            differing.append(label)
            print(f"DIFFERS between runs: {label}")
            for code, text, _ in mine:
                print(f"  exit {code}: {text[:400]}")
        for test in mine[0][2]["tests"]:
            for error, allowed in BY_ALLOWED.findall(test.get("message") or ""):
                if float(error) > 0:
                    margins.append((float(allowed) / float(error), label, test["name"]))
    print(f"{len(todo)} solutions, {runs} runs each: {len(todo) - len(differing)} gave the same results every run")
    if margins:
        ratio, label, check = max(margins)
        print(f"the mutant nearest to passing: {label}, '{check}': allowed/error = {ratio:.3g} "
              f"({len(margins)} failing messages read)")
    if differing:
        sys.exit(f"{len(differing)} solutions got different results in different runs")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]) if len(sys.argv) > 3 else 3)
