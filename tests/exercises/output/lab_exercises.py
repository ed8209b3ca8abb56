#!/usr/bin/env python3
"""`numlab lab exercises` says only what its own results back.

  lab_exercises.py NUMLAB WORKDIR

Runs the lab into WORKDIR and reads the results.json it wrote for each program it checked
(check-starter, check-correct, check-no-pivoting). Then: every check of the starter fails with
"not implemented" (none errors); the correct GEPP passes every check; the GEPP without pivoting
fails the pivot-trace check; and each count and each failing check the lab's text names is the
one in those files.
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
            expect(f"\"{test['name']}\" fails: {' '.join(first_line.split())}" in text,
                   f"the lab does not name the failing check '{test['name']}' with its message")

    if problems:
        print("\n".join(problems))
        print("--- lab output ---\n" + run.stdout)
        return 1
    print(f"starter: {len(starter)} fail; correct: {len(correct)} pass; no pivoting: {count(buggy, 'fail')} fail")
    return 0


if __name__ == "__main__":
    sys.exit(main())
