#!/usr/bin/env python3
"""`numlab lab exercises` says only what its own results back.

  lab_exercises.py NUMLAB WORKDIR

Runs the lab into WORKDIR and reads the results.json it wrote for each program it checked
(check-starter, check-correct, check-no-pivoting). Then: every check of the starter fails with
"not implemented" (none errors); the correct GEPP passes every check; the GEPP without pivoting
fails the pivot-trace check; and each count and each failing check the lab's text names is the
one in those files. Without a python3 that imports numpy (a stand-in python3 first on PATH), the
lab says so and exits 1.
"""
import json
import os
import re
import shutil
import subprocess
import sys


def count_of(count, total):
    if count == 0:
        return f"none of the {total}"
    if count == total:
        return f"all {total}"
    return f"{count} of {total}"


def main():
    numlab, workdir = sys.argv[1], sys.argv[2]
    shutil.rmtree(workdir, ignore_errors=True)
    run = subprocess.run([numlab, "lab", "exercises", "--out", workdir], capture_output=True, text=True, timeout=900)
    text = re.sub(r"\s+", " ", run.stdout)
    problems = []
    if run.returncode != 0:
        problems.append(f"exit {run.returncode}: {run.stderr}")

    def results(name):
        with open(os.path.join(workdir, "lab-exercises", name, "results.json"), encoding="utf-8") as file:
            return json.load(file)["tests"]

    def expect(condition, what):
        if not condition:
            problems.append(what)

    def count(tests, status):
        return sum(test["status"] == status for test in tests)

    starter = results("check-starter")
    expect(starter and all(t["status"] == "fail" and "not implemented" in t["message"] for t in starter),
           "the starter's checks do not all fail with 'not implemented'")
    expect(f"{count_of(len(starter), len(starter))} checks fail with the stub's \"not implemented\", and "
           f"{count_of(count(starter, 'error'), len(starter))} give an error" in text,
           "the starter's sentence does not match its results")

    correct = results("check-correct")
    expect(count(correct, "pass") == len(correct), "the correct GEPP does not pass every check: " +
           "; ".join(t["name"] + ": " + (t["message"] or "") for t in correct if t["status"] != "pass"))
    expect(f"{count_of(count(correct, 'pass'), len(correct))} checks pass." in text,
           "the correct solution's sentence does not match its results")

    timed = sorted((t for t in correct if t["timing"]["you"] is not None and len(t["timing"]) > 1),
                   key=lambda t: t["timing"]["you"])
    if timed:
        median = timed[len(timed) // 2]
        you_ms = f"{median['timing']['you'] * 1e3:.3g}"
        expect(f"On the check of median time, \"{median['name']}\", the Python solution took {you_ms} ms per request"
               in text, "the speed sentence is not about the check of median time")

    buggy = results("check-no-pivoting")
    expect(any(t["status"] == "fail" and "trace" in t["name"] for t in buggy),
           "the GEPP without pivoting does not fail the trace check")
    n = len(buggy)
    expect(f"{count_of(count(buggy, 'fail'), n)} checks fail, {count_of(count(buggy, 'error'), n)} give an error, "
           f"and {count_of(count(buggy, 'pass'), n)} pass." in text,
           "the buggy solution's sentence does not match its results")
    for test in buggy:
        if test["status"] == "fail":
            first_line = test["message"].split("\n")[0]
            expect(f"\"{test['name']}\" fails. The message: {' '.join(first_line.split())}." in text,
                   f"the lab does not name the failing check '{test['name']}' with its message")

    # A python3 without numpy: the lab says what it needs and exits 1 (not 2: nothing was wrong with the command).
    fake = os.path.join(workdir, "python-without-numpy")
    os.makedirs(fake)
    with open(os.path.join(fake, "python3"), "w", encoding="utf-8") as stand_in:
        stand_in.write("#!/bin/sh\necho \"ModuleNotFoundError: No module named 'numpy'\" >&2\nexit 1\n")
    os.chmod(os.path.join(fake, "python3"), 0o755)
    environment = dict(os.environ, PATH=fake + os.pathsep + os.environ.get("PATH", ""))
    without = subprocess.run([numlab, "lab", "exercises", "--out", os.path.join(workdir, "without")],
                             capture_output=True, text=True, timeout=300, env=environment)
    expect(without.returncode == 1, f"without numpy the lab exits {without.returncode}, not 1")
    expect("python3 with numpy is needed" in re.sub(r"\s+", " ", without.stdout),
           "without numpy the lab does not say that python3 with numpy is needed")

    if problems:
        print("\n".join(problems))
        print("--- lab output ---\n" + run.stdout)
        return 1
    print(f"starter: {len(starter)} fail; correct: {len(correct)} pass; no pivoting: {count(buggy, 'fail')} fail")
    return 0


if __name__ == "__main__":
    sys.exit(main())
