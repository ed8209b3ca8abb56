#!/usr/bin/env python3
"""The watch on forbidden library calls (docs/exercises.md, "Library calls"), end to end.

  check_forbidden.py NUMLAB caught PATCH OUT_DIR [RUNNER...]
      The solution PATCH makes breaks its exercise's rule: the run fails with diagnosis_cause
      library_call, the rule check fails quoting TASK.md, and the diagnosis names each
      FORBIDDEN-CALL of the header with the number of calls the solution itself counted. PATCH is
      python/NAME.patch or octave/NAME.patch, a diff against a reference like a mutant's (made into
      OUT_DIR/NAME.py or .m; RUNNER: this Python, or octave-cli --no-gui --quiet).
  check_forbidden.py NUMLAB watched EXERCISE COMMAND...
      a reference: the watch was loaded (the rule check is there) and every check passes.
  check_forbidden.py NUMLAB chained EXERCISE OUT_DIR COMMAND...
      the same, with a sitecustomize.py of the user's on PYTHONPATH: the watch hides it and must
      run it too.

A solution's header (lines starting with '#' or '%'):
  EXERCISE: the exercise;  FORBIDDEN-CALL: a function it calls (one line each);
  OTHERS-PASS: yes when every other check passes (only the watch can tell);
  NEEDS-MODULE: a module the runner must import, else the test is a skip.
The solution appends one line per forbidden call to $FORBIDDEN_CALLS_MADE: the count to compare.
"""
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from apply_mutant import make_mutant  # noqa: E402
from expect_verdict import mutant_suffix  # noqa: E402

SKIP = 77
RULE_CHECK = "uses no forbidden library function (TASK.md rule)"


def run(numlab, exercise, command, env=None):
    done = subprocess.run([numlab, "exercise", "check", exercise, "--format", "json", "--"] + command,
                          capture_output=True, text=True, timeout=600, env=env)
    try:
        return done.returncode, json.loads(done.stdout)
    except json.JSONDecodeError:
        sys.exit(f"not JSON on stdout (exit {done.returncode}):\n{done.stdout}\n{done.stderr}")


def skip(why):
    print(f"SKIPPED: {why}")
    sys.exit(SKIP)


def header(path):
    fields = {"EXERCISE": [], "FORBIDDEN-CALL": [], "OTHERS-PASS": [], "NEEDS-MODULE": []}
    with open(path, encoding="utf-8") as source:
        for line in source:
            if line[:1] in "#%":
                key, _, value = line.lstrip("#% ").partition(":")
                if key in fields:
                    fields[key].append(value.strip())
    if len(fields["EXERCISE"]) != 1 or not fields["FORBIDDEN-CALL"]:
        sys.exit(f"{path}: the header needs one EXERCISE and at least one FORBIDDEN-CALL line")
    return fields


def times(count):
    return {1: "once", 2: "twice"}.get(count, f"{count} times")


def flat(text):
    return " ".join(text.split())


def rule_check(results):
    found = [test for test in results["tests"] if test["name"] == RULE_CHECK]
    if len(found) != 1:
        sys.exit(f"{len(found)} checks named '{RULE_CHECK}' (the watch was not loaded?)")
    return found[0]


def caught(numlab, patch, out_dir, runner):
    if os.sep not in runner[0] and shutil.which(runner[0]) is None:
        skip(f"{runner[0]} is not on PATH")
    path = os.path.join(out_dir, os.path.splitext(os.path.basename(patch))[0] + mutant_suffix(patch))
    make_mutant(patch, path)
    fields = header(path)
    for module in fields["NEEDS-MODULE"]:
        if subprocess.run(runner + ["-c", f"import {module}"], capture_output=True).returncode != 0:
            skip(f"{runner[0]} cannot import {module}")
    exercise = fields["EXERCISE"][0]
    made = os.path.join(out_dir, os.path.basename(path) + ".calls")
    open(made, "w").close()
    code, results = run(numlab, exercise, runner + [os.path.abspath(path)], dict(os.environ, FORBIDDEN_CALLS_MADE=made))
    with open(made, encoding="utf-8") as lines:
        counted = [line.strip() for line in lines if line.strip()]
    problems = []
    if code == 0 or results["status"] != "fail":
        problems.append(f"the run passed (exit {code}, status {results['status']})")
    if results.get("diagnosis_cause") != "library_call":
        problems.append(f"diagnosis_cause is {results.get('diagnosis_cause')!r}: {results.get('diagnosis')!r}")
    diagnosis = results.get("diagnosis") or ""
    for name in fields["FORBIDDEN-CALL"]:
        expected = f"{name} {times(counted.count(name))}"
        if not counted or expected not in diagnosis:
            problems.append(f"the diagnosis does not say '{expected}' (counted by the solution): {diagnosis!r}")
    rule = rule_check(results)
    quoted = re.search(r'TASK\.md: "([^"]+)"', rule.get("message") or "")
    task = subprocess.run([numlab, "exercise", "show", exercise], capture_output=True, text=True).stdout
    if rule["status"] != "fail" or quoted is None or flat(quoted[1]) not in flat(task):
        problems.append(f"the rule check does not fail quoting TASK.md: {rule['status']}: {rule.get('message')!r}")
    if fields["OTHERS-PASS"] == ["yes"]:
        others = [test for test in results["tests"] if test is not rule and test["status"] != "pass"]
        problems += [f"'{test['name']}' did not pass: {test.get('message')}" for test in others]
    if problems:
        sys.exit("\n".join(problems))
    print(f"caught: {diagnosis}\nrule check: {rule['message']}")


def watched(numlab, exercise, command, env=None):
    if os.sep not in command[0] and shutil.which(command[0]) is None:
        skip(f"{command[0]} is not on PATH")
    code, results = run(numlab, exercise, command, env)
    rule = rule_check(results)
    wrong = [f"{test['name']}: {test['status']}: {test.get('message')}" for test in results["tests"]
             if test["status"] != "pass"]
    if code != 0 or wrong:
        sys.exit(f"exit {code}:\n" + "\n".join(wrong))
    print(f"{len(results['tests'])} checks pass, '{rule['name']}' among them")


def chained(numlab, exercise, out_dir, command):
    site = os.path.join(out_dir, "site")
    os.makedirs(site, exist_ok=True)
    ran = os.path.join(site, "ran")
    if os.path.exists(ran):
        os.remove(ran)
    with open(os.path.join(site, "sitecustomize.py"), "w", encoding="utf-8") as user_site:
        user_site.write(f"with open({ran!r}, 'a') as ran:\n    ran.write('ran\\n')\n")
    watched(numlab, exercise, command, dict(os.environ, PYTHONPATH=site))
    if not os.path.exists(ran):
        sys.exit("the user's sitecustomize.py did not run: the watch hid it")
    print("the user's sitecustomize.py ran too")


if __name__ == "__main__":
    numlab, mode, rest = sys.argv[1], sys.argv[2], sys.argv[3:]
    if mode == "caught":
        caught(numlab, rest[0], rest[1], rest[2:] or [sys.executable])
    elif mode == "watched":
        watched(numlab, rest[0], rest[1:])
    elif mode == "chained":
        chained(numlab, rest[0], rest[1], rest[2:])
    else:
        sys.exit(f"unknown mode {mode}")
