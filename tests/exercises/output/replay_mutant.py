#!/usr/bin/env python3
"""A failure a student can replay (docs/exercises.md, "Replaying a failure"), end to end:

  replay_mutant.py NUMLAB PATCH OUT_DIR

The mutant PATCH makes (tests/exercises/mutants/EXERCISE/NAME.patch) is checked with --out: the
report leads with "Fix first:" and the replay command, each failing check has its replay file (one
JSON line per request: the request numlab sent, numlab's expected reply or property beside it,
the mutant's reply); the replay command reproduces the failure against the mutant (exit 1, the same
message), passes against the Python reference (exit 0), and refuses a file that is not a replay (exit 2).
"""
import json
import os
import shlex
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from apply_mutant import make_mutant  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def run(args):
    return subprocess.run(args, capture_output=True, text=True, timeout=600)


def main(numlab, patch, out_dir):
    exercise = os.path.basename(os.path.dirname(os.path.abspath(patch)))
    name = os.path.splitext(os.path.basename(patch))[0]
    mutant = os.path.join(out_dir, exercise, name + ".py")
    make_mutant(patch, mutant)
    reference = os.path.join(HERE, "..", "references", "python", exercise.replace("-", "_") + ".py")
    verdict = os.path.join(out_dir, exercise, name + "-verdict")
    problems = []

    check = run([numlab, "exercise", "check", exercise, "--out", verdict, "--", sys.executable, mutant])
    if check.returncode != 1:
        sys.exit(f"check exit {check.returncode}, expected 1:\n{check.stdout}\n{check.stderr}")
    results = json.load(open(os.path.join(verdict, "results.json"), encoding="utf-8"))
    failing = [(k, test) for k, test in enumerate(results["tests"], 1) if test["status"] != "pass"]
    lines_out = check.stdout.splitlines()
    if results.get("diagnosis"):  # the report leads with the run's diagnosis, then the failure to fix first
        if lines_out[0] != "Diagnosis: " + results["diagnosis"]:
            problems.append(f"the text does not lead with the diagnosis: {lines_out[0]!r}")
        lines_out = lines_out[1:]
    first_line, second_line = lines_out[:2]
    first = failing[0][1]
    if not first_line.startswith(f"Fix first: {first['name']} — "):
        problems.append(f"the text does not lead with the first failure: {first_line!r}")
    if not second_line.startswith("Replay it: numlab exercise replay "):
        problems.append(f"no replay command under it: {second_line!r}")
    html = open(os.path.join(verdict, "report.html"), encoding="utf-8").read()
    if "Fix first:" not in html or "numlab exercise replay" not in html:
        problems.append("report.html lacks 'Fix first:' or the replay command")

    files = sorted(os.listdir(os.path.join(verdict, "replay")))
    if len(files) != len(failing) or not all(f.startswith(f"{k:02}-") for f, (k, _) in zip(files, failing)):
        problems.append(f"replay files {files} do not match the failing checks {[k for k, _ in failing]}")
    path = os.path.join(verdict, "replay", files[0])
    lines = [json.loads(line) for line in open(path, encoding="utf-8")]
    for line in lines:
        for key in ("check", "inputs", "request", "expected", "property"):
            if key not in line:
                problems.append(f"{files[0]}: a line without \"{key}\"")
        if line["check"] != first["name"] or line["request"].get("exercise") != exercise:
            problems.append(f"{files[0]}: a line of another check or exercise")
    if not any(line["expected"] is not None or line["property"] != line["check"] for line in lines):
        problems.append(f"{files[0]}: no line says what numlab expected")

    # The command the report gives, run as the student would.
    command = shlex.split(second_line[len("Replay it: "):])
    if command[:3] != ["numlab", "exercise", "replay"]:
        problems.append(f"the replay command is {command}")
    replay = run([numlab] + command[1:])
    message_start = first["message"].splitlines()[0][:60]
    if replay.returncode != 1 or message_start not in replay.stdout:
        problems.append(f"replay against the mutant: exit {replay.returncode} (expected 1), message "
                        f"{'found' if message_start in replay.stdout else 'missing'}:\n{replay.stdout}{replay.stderr}")
    for key in ("  sent:", "  yours:", "  expected:", "  checked:"):
        if key not in replay.stdout:
            problems.append(f"replay prints no '{key.strip()}' line")
    fixed = run([numlab, "exercise", "replay", path, "--", sys.executable, reference])
    if fixed.returncode != 0 or "Note:" in fixed.stdout:
        problems.append(f"replay against the reference: exit {fixed.returncode} (expected 0):\n{fixed.stdout}{fixed.stderr}")

    # Not a replay file: one line, exit 2.
    bad = os.path.join(out_dir, exercise, name + "-bad.jsonl")
    with open(bad, "w", encoding="utf-8") as out:
        out.write("{\"request\": 1}\n")
    refused = run([numlab, "exercise", "replay", bad, "--", sys.executable, reference])
    if refused.returncode != 2 or "not a replay line" not in refused.stderr or refused.stderr.count("\n") != 1:
        problems.append(f"a bad file: exit {refused.returncode}, stderr {refused.stderr!r}")

    if problems:
        sys.exit("\n".join(problems))
    print(f"{len(failing)} failing checks, {len(files)} replay files; replayed {files[0]}: "
          f"fails against the mutant, passes against the reference")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3])
