#!/usr/bin/env python3
"""Runs `numlab exercise check` on one solution and checks the verdict it gives.

  expect_verdict.py NUMLAB reference EXERCISE COMMAND...   every check passes (exit 0, status pass)
  expect_verdict.py NUMLAB mutant PATCH OUT_DIR [RUNNER...] the mutant is caught as its header says
  expect_verdict.py NUMLAB summary PATCH_DIR OUT_DIR       the catch rate, overall and by exercise
  expect_verdict.py NUMLAB tolerant PATCH OUT_DIR          a valid variant passes every check

A mutant is tests/exercises/mutants/EXERCISE/NAME.patch: a unified diff against the exercise's
Python reference, applied (apply_mutant.py) into OUT_DIR/EXERCISE/NAME.py before the check runs;
a patch that no longer applies fails, naming itself. An Octave mutant,
mutants/octave/EXERCISE/NAME.patch, is a diff against references/octave/EXERCISE.m: the mutant is
named as its '+++' line says (NAME.m) and run by RUNNER (octave-cli --no-gui --quiet; the default
RUNNER is this Python). A RUNNER or reference COMMAND that is not on PATH is a skip (exit 77,
"SKIPPED: ..."), not a failure. The mutant's header names the bug and the verdict:
  # BUG: what is wrong (and, for a seed's error, which seed)
  # EXPECT-CHECK: part of the name of a check that must FAIL (not error)
  # EXPECT-MESSAGE: part of that check's message (one line each; all must appear)
  # EXPECT-CAUSE: the run's diagnosis_cause (docs/exercises.md, "Diagnosis"); optional

A tolerant variant, tolerant/EXERCISE/NAME.patch, is a patch against a reference that keeps it
correct but writes its replies as a tolerant reader must accept them (13.0 for 13, blank lines
between replies, a slow start): every check must pass. Its header says what differs:
  # VARIANT: what the variant does differently
  # EXPECT-SECONDS-PER-REQUEST-BELOW: S  (optional) every check's time per request is below S
"""
import json
import os
import shutil
import subprocess
import sys

from apply_mutant import make_mutant


SKIP = 77  # ctest's SKIP_RETURN_CODE for these tests


def skip_unless_found(program):
    """Exits 77 (a skip) naming the program when it is not on PATH: Octave is optional (.ci/setup has it)."""
    if os.sep not in program and shutil.which(program) is None:
        hint = " (Debian: apt-get install octave)" if program.startswith("octave") else ""
        print(f"SKIPPED: {program} is not on PATH{hint}: this test needs it")
        sys.exit(SKIP)


def run_check(numlab, exercise, command):
    run = subprocess.run([numlab, "exercise", "check", exercise, "--format", "json", "--"] + command,
                         capture_output=True, text=True, timeout=600)
    try:
        results = json.loads(run.stdout)
    except json.JSONDecodeError:
        sys.exit(f"not JSON on stdout (exit {run.returncode}):\n{run.stdout}\n{run.stderr}")
    return run.returncode, results


def header(path):
    fields = {"BUG": [], "EXPECT-CHECK": [], "EXPECT-MESSAGE": [], "EXPECT-CAUSE": []}
    with open(path, encoding="utf-8") as source:
        for line in source:
            if not line.startswith("#"):
                continue
            key, _, value = line[1:].strip().partition(":")
            if key in fields:
                fields[key].append(value.strip())
    if len(fields["BUG"]) != 1 or len(fields["EXPECT-CHECK"]) != 1:
        sys.exit(f"{path}: the header needs one '# BUG:' and one '# EXPECT-CHECK:' line")
    return fields


def caught(results, fields):
    """The failing check the header names, or a reason why the mutant was not caught."""
    wanted = fields["EXPECT-CHECK"][0]
    named = [test for test in results["tests"] if wanted in test["name"]]
    if not named:
        return None, f"no check is named like '{wanted}'"
    failing = [test for test in named if test["status"] == "fail"]
    if not failing:
        return None, f"'{wanted}' gave " + ", ".join(test["status"] for test in named)
    for test in failing:
        message = test.get("message") or ""
        if all(part in message for part in fields["EXPECT-MESSAGE"]):
            return test, ""
    return None, "the message does not say " + " / ".join(fields["EXPECT-MESSAGE"]) + ":\n" + \
        "\n".join(test.get("message") or "" for test in failing)


def expect_reference(numlab, exercise, command):
    skip_unless_found(command[0])
    code, results = run_check(numlab, exercise, command)
    wrong = [test for test in results["tests"] if test["status"] != "pass"]
    for test in wrong:
        print(f"false failure: {test['name']}: {test['status']}: {test.get('message')}")
    if code != 0 or results["status"] != "pass" or wrong or not results["tests"]:
        sys.exit(f"the reference solution did not pass every check (exit {code}, status {results['status']})")
    print(f"{len(results['tests'])} checks pass")
    return results


def mutant_exercise(path):
    return os.path.basename(os.path.dirname(os.path.abspath(path)))


def mutant_suffix(patch):
    """The mutant's file suffix, from the patch's '+++' line: .py, or .m for an Octave mutant."""
    with open(patch, encoding="utf-8") as text:
        for line in text:
            if line.startswith("+++ "):
                return os.path.splitext(line[4:].split("\t")[0].strip())[1] or ".py"
    return ".py"


def mutant_from_patch(patch, out_dir):
    """OUT_DIR/EXERCISE/NAME.py (or .m), made from mutants/[octave/]EXERCISE/NAME.patch (exits if it does not apply)."""
    exercise = os.path.basename(os.path.dirname(os.path.abspath(patch)))
    name = os.path.splitext(os.path.basename(patch))[0] + mutant_suffix(patch)
    path = os.path.join(out_dir, exercise, name)
    make_mutant(patch, path)
    return path


def expect_mutant(numlab, patch, out_dir, runner):
    skip_unless_found(runner[0])
    path = mutant_from_patch(patch, out_dir)
    fields = header(path)
    _, results = run_check(numlab, mutant_exercise(path), runner + [os.path.abspath(path)])
    test, why = caught(results, fields)
    if test is None:
        sys.exit(f"{patch} ({fields['BUG'][0]}) was not caught: {why}")
    print(f"caught by '{test['name']}':\n{test['message']}")
    for cause in fields["EXPECT-CAUSE"]:
        if results.get("diagnosis_cause") != cause:
            sys.exit(f"{patch}: the diagnosis is {results.get('diagnosis_cause')!r} "
                     f"({results.get('diagnosis')!r}), not {cause!r}")
        print(f"diagnosed as {cause}: {results['diagnosis']}")


def expect_tolerant(numlab, patch, out_dir):
    path = mutant_from_patch(patch, out_dir)
    fields = {"VARIANT": [], "EXPECT-SECONDS-PER-REQUEST-BELOW": []}
    with open(path, encoding="utf-8") as source:
        for line in source:
            key, _, value = line[1:].strip().partition(":")
            if line.startswith("#") and key in fields:
                fields[key].append(value.strip())
    if len(fields["VARIANT"]) != 1:
        sys.exit(f"{path}: the header needs one '# VARIANT:' line")
    print(f"variant: {fields['VARIANT'][0]}")
    results = expect_reference(numlab, mutant_exercise(path), [sys.executable, os.path.abspath(path)])
    for limit in fields["EXPECT-SECONDS-PER-REQUEST-BELOW"]:
        # The library-call rule (docs/exercises.md, "Library calls") sends no request: it has no time.
        times = {test["name"]: (test.get("timing") or {}).get("you") for test in results["tests"]
                 if not test["name"].startswith("uses no forbidden library function")}
        slow = {name: seconds for name, seconds in times.items() if seconds is None or seconds >= float(limit)}
        for name, seconds in slow.items():
            print(f"time per request {seconds} s (not below {limit} s): {name}")
        if slow:
            sys.exit(f"{len(slow)} checks timed the program's start-up, or not at all")
        print(f"every check's time per request is below {limit} s (the slowest {max(times.values()):.3g} s)")


def summary(numlab, folder, out_dir):
    counts = {}
    for exercise in sorted(os.listdir(folder)):
        directory = os.path.join(folder, exercise)
        if not os.path.isdir(directory):
            continue
        for name in sorted(os.listdir(directory)):
            if not name.endswith(".patch"):
                continue
            path = mutant_from_patch(os.path.join(directory, name), out_dir)
            _, results = run_check(numlab, exercise, [sys.executable, path])
            test, why = caught(results, header(path))
            flagged = any(t["status"] == "fail" for t in results["tests"])
            total, hit, pointed = counts.get(exercise, (0, 0, 0))
            counts[exercise] = (total + 1, hit + flagged, pointed + (test is not None))
            print(f"{exercise}/{name}: {'caught' if test else 'MISSED: ' + why}")
    grand = [sum(values) for values in zip(*counts.values())]
    for exercise, (total, hit, pointed) in counts.items():
        print(f"{exercise}: flagged {hit}/{total}, at the named check {pointed}/{total}")
    print(f"all: flagged {grand[1]}/{grand[0]}, at the named check {grand[2]}/{grand[0]}")


if __name__ == "__main__":
    numlab, mode = sys.argv[1], sys.argv[2]
    if mode == "reference":
        expect_reference(numlab, sys.argv[3], sys.argv[4:])
    elif mode == "mutant":
        expect_mutant(numlab, sys.argv[3], sys.argv[4], sys.argv[5:] or [sys.executable])
    elif mode == "tolerant":
        expect_tolerant(numlab, sys.argv[3], sys.argv[4])
    elif mode == "summary":
        summary(numlab, sys.argv[3], sys.argv[4])
    else:
        sys.exit(f"unknown mode {mode}")
