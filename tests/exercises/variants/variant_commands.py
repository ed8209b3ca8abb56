#!/usr/bin/env python3
"""The commands' --variant (docs/exercises.md, "Variants"): init, check, replay and grade.

  variant_commands.py NUMLAB EXERCISES_SOURCE WORK

- `init --variant ID`: TASK.md names the variant and its check command (and the starter's) says
  --variant ID; an empty ID, or one with a control character, is one line and exit 2.
- `check --variant ID --out DIR`: results.json's "variant" is ID (null without --variant), the text and
  report.html name it, each replay line carries it, and `exercise replay` sends the same requests again
  (no "Note:") and fails the mutant, passes the reference.
- `grade --variant-from-folder`: each row's variant is its folder's name, in the gradebook and in each
  results.json, the same with --jobs 1 and 2 (but for the seconds); `grade --variant ID` gives every row
  ID; the two together, or a folder name that cannot be an ID, are one line and exit 2.
"""
import csv
import glob
import json
import os
import shutil
import subprocess
import sys

numlab, source, work = sys.argv[1:4]
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def run(*args):
    return subprocess.run([numlab, *args], capture_output=True, text=True, timeout=600)


def bad_input(result, what):
    lines = result.stderr.strip().splitlines()
    expect(result.returncode == 2 and len(lines) == 1 and lines[0].startswith("numlab: error:"),
           f"{what}: exit {result.returncode}, stderr {result.stderr!r}")


def mutant(patch, path):
    subprocess.run([sys.executable, os.path.join(source, "apply_mutant.py"), os.path.join(source, "mutants", patch),
                    path], check=True)


shutil.rmtree(work, ignore_errors=True)
os.makedirs(work)
reference = os.path.join(source, "references", "python", "gepp.py")

# init
starter = os.path.join(work, "starter")
init = run("exercise", "init", "gepp", starter, "--variant", "s1234567 b")
expect(init.returncode == 0, f"init --variant: exit {init.returncode}: {init.stderr}")
task = open(os.path.join(starter, "TASK.md"), encoding="utf-8").read()
expect("## Your variant" in task and "`s1234567 b`" in task, "TASK.md names the variant")
expect("numlab exercise check gepp --variant 's1234567 b' -- python3 solution.py" in task,
       "TASK.md's check command says --variant (shell-quoted)")
solution = open(os.path.join(starter, "solution.py"), encoding="utf-8").read()
expect("numlab exercise check gepp --variant 's1234567 b' -- python3 solution.py" in solution,
       "the starter's own check command says --variant")
bad_input(run("exercise", "init", "gepp", os.path.join(work, "empty-id"), "--variant", ""), "init --variant ''")
expect(not os.path.exists(os.path.join(work, "empty-id")), "init --variant '' wrote nothing")
bad_input(run("exercise", "init", "gepp", os.path.join(work, "tab-id"), "--variant", "a\tb"), "init --variant TAB")

# check, the reports and the replay
buggy = os.path.join(work, "swap_without_b.py")
mutant(os.path.join("gepp", "swap_without_b.patch"), buggy)
out = os.path.join(work, "out")
check = run("exercise", "check", "gepp", "--variant", "s1234567", "--out", out, "--", sys.executable, buggy)
expect(check.returncode == 1, f"check of the mutant under a variant: exit {check.returncode}")
expect("numlab exercise gepp (variant s1234567):" in check.stdout, "the text output names the variant")
results = json.load(open(os.path.join(out, "results.json"), encoding="utf-8"))
expect(results.get("variant") == "s1234567", f"results.json variant {results.get('variant')!r}")
expect("Variant: <code>s1234567</code>" in open(os.path.join(out, "report.html"), encoding="utf-8").read(),
       "report.html names the variant")
replays = sorted(glob.glob(os.path.join(out, "replay", "*.jsonl")))
expect(bool(replays), "a replay file for the failing check")
for path in replays[:1]:
    lines = [json.loads(line) for line in open(path, encoding="utf-8") if line.strip()]
    expect(all(line.get("variant") == "s1234567" for line in lines), "each replay line carries the variant")
    again = run("exercise", "replay", path, "--", sys.executable, buggy)
    expect(again.returncode == 1 and "Note:" not in again.stdout,
           f"the replay sends the variant's requests again and fails the mutant: exit {again.returncode}\n{again.stdout}")
    fixed = run("exercise", "replay", path, "--", sys.executable, reference)
    expect(fixed.returncode == 0 and "Note:" not in fixed.stdout, f"the replay passes the reference: {fixed.stdout}")
plain = run("exercise", "check", "gepp", "--format", "json", "--", sys.executable, reference)
expect(plain.returncode == 0 and json.loads(plain.stdout)["variant"] is None, "without --variant, variant is null")
bad_input(run("exercise", "check", "gepp", "--variant", "", "--", sys.executable, reference), "check --variant ''")
bad_input(run("exercise", "check", "gepp", "--variant", "a\nb", "--", sys.executable, reference), "check --variant LF")

# grade
subs = os.path.join(work, "subs")
for student in ["s1111111", "s2222222"]:
    os.makedirs(os.path.join(subs, student))
    shutil.copy(reference, os.path.join(subs, student, "solution.py"))
os.makedirs(os.path.join(subs, "s3333333"))
mutant(os.path.join("gepp", "no_pivoting.patch"), os.path.join(subs, "s3333333", "solution.py"))


def grade(name, *options):
    folder = os.path.join(work, name)
    result = run("exercise", "grade", "gepp", "--submissions", subs, "--out", folder, *options)
    expect(result.returncode == 1, f"grade {options}: exit {result.returncode}: {result.stderr}")
    with open(os.path.join(folder, "gradebook.csv"), newline="", encoding="utf-8") as text:
        rows = list(csv.DictReader(text))
    for row in rows:
        row_results = json.load(open(os.path.join(folder, row["student"], "results.json"), encoding="utf-8"))
        expect(row_results.get("variant") == (row["variant"] or None),
               f"{name}/{row['student']}: results.json variant {row_results.get('variant')!r}, row {row['variant']!r}")
    return [{key: value for key, value in row.items() if key != "seconds"} for row in rows]


one = grade("graded-jobs1", "--variant-from-folder", "--jobs", "1")
two = grade("graded-jobs2", "--variant-from-folder", "--jobs", "2")
expect(one == two, f"--jobs 1 and 2 differ:\n{one}\n{two}")
expect([row["variant"] for row in one] == ["s1111111", "s2222222", "s3333333"], f"variants {one}")
expect([row["passed"] == row["total"] for row in one] == [True, True, False], f"verdicts {one}")
same = grade("graded-same", "--variant", "s9")
expect([row["variant"] for row in same] == ["s9"] * 3, f"--variant s9: {same}")
none = grade("graded-none")
expect([row["variant"] for row in none] == [""] * 3, f"without a variant: {none}")
both = run("exercise", "grade", "gepp", "--submissions", subs, "--out", os.path.join(work, "both"), "--variant", "x",
           "--variant-from-folder")
bad_input(both, "grade --variant and --variant-from-folder")
expect(not os.path.exists(os.path.join(work, "both")), "grade with both wrote nothing")
dash = os.path.join(work, "dash")  # an ID that starts with '-' reaches the worker as the ID, not an option
os.makedirs(os.path.join(dash, "-s4"))
shutil.copy(reference, os.path.join(dash, "-s4", "solution.py"))
graded = run("exercise", "grade", "gepp", "--submissions", dash, "--out", os.path.join(work, "dash-out"),
             "--variant-from-folder")
dash_json = json.load(open(os.path.join(work, "dash-out", "-s4", "results.json"), encoding="utf-8"))
expect(graded.returncode == 0 and dash_json.get("variant") == "-s4", f"folder -s4: exit {graded.returncode}, "
       f"variant {dash_json.get('variant')!r}: {graded.stderr}")
odd = os.path.join(work, "odd")
os.makedirs(os.path.join(odd, "a\x01b"))
bad_input(run("exercise", "grade", "gepp", "--submissions", odd, "--out", os.path.join(work, "odd-out"),
              "--variant-from-folder"), "a folder name with a control character")

if failures:
    sys.exit(f"{len(failures)} failures")
print("init, check, replay and grade name and use the variant")
