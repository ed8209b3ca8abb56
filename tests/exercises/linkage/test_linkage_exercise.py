#!/usr/bin/env python3
"""numlab exercise linkage --model FILE|NAME, end to end (docs/exercises.md, "Any linkage as an exercise").

  test_linkage_exercise.py NUMLAB MODELS_DIR WORK_DIR

1. Every shipped model (MODELS_DIR/*.toml): `exercise init linkage DIR --model NAME` writes a Python
   starter whose TASK.md names the model's unknowns and equations; as written, every check fails
   "not implemented"; filled in with the generic reference (references/python/linkage.py), every
   check passes.
2. An instructor's own file (norton_crank_rocker.toml, not shipped): init copies it as model.toml,
   the check command in TASK.md runs from the starter's folder and passes, and the reference's pose
   at 40 deg is Norton's, B from the circle-circle intersection computed here.
3. Each mutant, mutants/NAME.patch (against the reference), on each model its '# MODELS:' line names:
   the check its header names fails, and results.json's diagnosis_cause is its EXPECT-CAUSE.
4. `exercise grade linkage --model`: a class of the reference and a mutant.
5. Bad input: one line and exit 2.
"""
import glob
import json
import math
import os
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from apply_mutant import make_mutant  # noqa: E402

PYTHON = sys.executable  # has numpy (tests/python_with_numpy.cmake)
REFERENCE = os.path.join(os.path.dirname(HERE), "references", "python", "linkage.py")
failures = []


def fail(text):
    failures.append(text)
    print("FAIL: " + text)


def run(args, cwd=None, env=None):
    return subprocess.run(args, capture_output=True, text=True, timeout=300, cwd=cwd, env=env)


def check(numlab, model, program, cwd=None):
    done = run([numlab, "exercise", "check", "linkage", "--model", model, "--format", "json", "--"] + program, cwd)
    try:
        return done.returncode, json.loads(done.stdout)
    except json.JSONDecodeError:
        fail(f"check --model {model}: not JSON (exit {done.returncode}): {done.stdout[:300]} {done.stderr[:300]}")
        return done.returncode, {"tests": [], "status": "error"}


def filled_in(starter):
    """The starter with its stub replaced by a call of the reference's solve()."""
    with open(starter, encoding="utf-8") as source:
        text = source.read()
    start = text.index("def solve(request):\n")
    end = text.index("\ndef to_json(value):")
    body = ("def solve(request):\n"
            f"    sys.path.insert(0, {os.path.dirname(REFERENCE)!r})\n"
            "    import linkage\n"
            "    return linkage.solve(request)\n\n")
    return text[:start] + body + text[end:]


TWO_DRIVERS = {"five-bar"}


def shipped_models(numlab, models_dir, work):
    names = sorted(os.path.splitext(os.path.basename(path))[0] for path in glob.glob(os.path.join(models_dir, "*.toml")))
    if len(names) < 10:
        fail(f"only {len(names)} shipped models in {models_dir}")
    for name in names:
        folder = os.path.join(work, "starters", name)
        done = run([numlab, "exercise", "init", "linkage", folder, "--model", name])
        if name in TWO_DRIVERS:  # refused: a request gives one driver value
            if done.returncode != 2 or "has two drivers" not in done.stderr or os.path.exists(folder):
                fail(f"init --model {name}: a two-driver model must be refused (exit 2, nothing written): "
                     f"exit {done.returncode}: {done.stderr}")
            continue
        if done.returncode != 0:
            fail(f"init --model {name}: exit {done.returncode}: {done.stderr}")
            continue
        with open(os.path.join(folder, "TASK.md"), encoding="utf-8") as task:
            text = task.read()
        explain = json.loads(run([numlab, "mechanism", os.path.join(models_dir, name + ".toml"), "--explain", "--format", "json"]).stdout)
        unknowns = "q = (" + ", ".join(explain["unknowns"]) + ")"
        if unknowns not in text:
            fail(f"{name}: TASK.md does not state the unknowns {unknowns}")
        for k, equation in enumerate(explain["equations"]):
            if f"{k + 1}. f[{k}] = `" not in text:
                fail(f"{name}: TASK.md lacks equation {k + 1} ({equation})")
        if f"numlab exercise check linkage --model {name} -- python3 solution.py" not in text:
            fail(f"{name}: TASK.md's check command does not pass --model {name}")
        starter = os.path.join(folder, "solution.py")
        code, results = check(numlab, name, [PYTHON, starter])
        stubs = [t for t in results["tests"] if t["status"] == "fail" and "not implemented" in (t["message"] or "")]
        if code != 1 or len(results["tests"]) != 4 or len(stubs) != 4:
            fail(f"{name}: the starter as written: exit {code}, {len(stubs)} of {len(results['tests'])} 'not implemented'")
        solution = filled_in(starter)
        with open(starter, "w", encoding="utf-8") as source:
            source.write(solution)
        code, results = check(numlab, name, [PYTHON, starter])
        wrong = [f"{t['name']}: {t['status']}: {t['message']}" for t in results["tests"] if t["status"] != "pass"]
        if code != 0 or wrong or len(results["tests"]) != 4:
            fail(f"{name}: the reference does not pass every check (exit {code}): {wrong}")
        else:
            print(f"{name}: starter fails 4 of 4 'not implemented'; reference passes 4 of 4")
    return names


def instructor_file(numlab, work):
    source = os.path.join(HERE, "norton_crank_rocker.toml")
    folder = os.path.join(work, "norton")
    done = run([numlab, "exercise", "init", "linkage", folder, "--model", source])
    if done.returncode != 0:
        return fail(f"init --model {source}: exit {done.returncode}: {done.stderr}")
    with open(os.path.join(folder, "model.toml"), encoding="utf-8") as copy, open(source, encoding="utf-8") as original:
        if copy.read() != original.read():
            fail("init did not copy the instructor's file as model.toml")
    with open(os.path.join(folder, "TASK.md"), encoding="utf-8") as task:
        text = task.read()
    for wanted in ["norton-crank-rocker", "q = (x_A, y_A, x_B, y_B)", "link A-B 120", "link O4-B 80", "crank O2-A 40",
                   "numlab exercise check linkage --model model.toml -- python3 solution.py"]:
        if wanted not in text:
            fail(f"the instructor's TASK.md lacks '{wanted}'")
    starter = os.path.join(folder, "solution.py")
    solution = filled_in(starter)
    with open(starter, "w", encoding="utf-8") as out:
        out.write(solution)
    code, results = check(numlab, "model.toml", [PYTHON, "solution.py"], cwd=folder)
    if code != 0 or results["status"] != "pass":
        fail(f"the instructor's file: exit {code}, {[(t['name'], t['message']) for t in results['tests']]}")
    # Norton's open configuration at 40 deg, B from the two circles, against the reference's own pose.
    sys.path.insert(0, os.path.dirname(REFERENCE))
    import linkage as reference  # noqa: E402
    A = (40 * math.cos(math.radians(40)), 40 * math.sin(math.radians(40)))
    d = math.hypot(100 - A[0], -A[1])
    a = (120 ** 2 - 80 ** 2 + d * d) / (2 * d)
    h = math.sqrt(120 ** 2 - a * a)
    e = ((100 - A[0]) / d, -A[1] / d)
    B = (A[0] + a * e[0] - h * e[1], A[1] + a * e[1] + h * e[0])
    theta3 = math.degrees(math.atan2(B[1] - A[1], B[0] - A[0]))
    theta4 = math.degrees(math.atan2(B[1], B[0] - 100))
    if abs(theta3 - 20.30) > 0.01 or abs(theta4 - 57.32) > 0.01:
        fail(f"Norton's angles: theta3 {theta3}, theta4 {theta4}")
    solved = reference.Linkage({
        "joints": [{"name": "O2", "ground": True, "position": [0, 0]}, {"name": "O4", "ground": True, "position": [100, 0]},
                   {"name": "A", "ground": False, "position": [30.6, 25.7]},
                   {"name": "B", "ground": False, "position": [143.0, 67.0]}],
        "driver": {"type": "crank"},
        "equations": [{"kind": "distance", "rows": 1, "joints": ["A", "B"], "length": 120.0},
                      {"kind": "distance", "rows": 1, "joints": ["O4", "B"], "length": 80.0},
                      {"kind": "crank", "rows": 2, "joints": ["O2", "A"], "length": 40.0, "offset": 0.0}]})
    import numpy as np
    q, _ = solved.newton(np.array([30.6, 25.7, 143.0, 67.0]), math.radians(40), 1e-12, 50)
    if max(abs(q[2] - B[0]), abs(q[3] - B[1])) > 1e-9:
        fail(f"the reference's B at 40 deg is {q[2:]}, Norton's {B}")
    else:
        print(f"instructor's file: passes; B at 40 deg = ({q[2]:.6f}, {q[3]:.6f}), Norton theta3 {theta3:.2f}, theta4 {theta4:.2f}")


def header(path):
    fields = {}
    with open(path, encoding="utf-8") as source:
        for line in source:
            if line.startswith("# ") and ":" in line:
                key, _, value = line[2:].partition(":")
                fields.setdefault(key.strip(), []).append(value.strip())
    return fields


def mutants(numlab, work):
    caught = 0
    for patch in sorted(glob.glob(os.path.join(HERE, "mutants", "*.patch"))):
        name = os.path.splitext(os.path.basename(patch))[0]
        path = os.path.join(work, "mutants", name + ".py")
        make_mutant(patch, path)
        fields = header(path)
        for model in fields["MODELS"][0].split():
            _, results = check(numlab, model, [PYTHON, path])
            named = [t for t in results["tests"] if fields["EXPECT-CHECK"][0] in t["name"]]
            failing = [t for t in named if t["status"] == "fail"
                       and all(part in (t["message"] or "") for part in fields["EXPECT-MESSAGE"])]
            cause = results.get("diagnosis_cause")
            if not failing:
                fail(f"{name} on {model}: '{fields['EXPECT-CHECK'][0]}' did not fail as expected: "
                     f"{[(t['status'], t['message']) for t in named]}")
            elif cause != fields["EXPECT-CAUSE"][0]:
                fail(f"{name} on {model}: diagnosis {cause!r} ({results.get('diagnosis')!r}), not {fields['EXPECT-CAUSE'][0]}")
            else:
                caught += 1
                print(f"{name} on {model}: caught, {cause}: {results['diagnosis']}")
    return caught


def grade(numlab, work):
    submissions = os.path.join(work, "class")
    for student, source in [("ada", REFERENCE), ("bob", os.path.join(work, "mutants", "transposed_jacobian.py"))]:
        os.makedirs(os.path.join(submissions, student))
        shutil.copy(source, os.path.join(submissions, student, "solution.py"))
    out = os.path.join(work, "graded")
    done = run([numlab, "exercise", "grade", "linkage", "--model", "four-bar", "--submissions", submissions, "--out", out,
                "--jobs", "2"],
               env=dict(os.environ, PATH=os.path.dirname(PYTHON) + os.pathsep + os.environ.get("PATH", "")))
    with open(os.path.join(out, "gradebook.csv"), encoding="utf-8") as book:
        rows = book.read().splitlines()
    ada, bob = rows[1].split(","), rows[2].split(",")
    if done.returncode != 1 or ada[:5] != ["ada", "linkage", "", "4", "4"] or bob[:2] != ["bob", "linkage"] \
            or bob[3] == "4" or "transposed" not in rows[2]:
        fail(f"grade: exit {done.returncode}, gradebook {rows}, {done.stderr}")
    else:
        print(f"grade --model four-bar: {rows[1]} / {rows[2]}")


def bad_input(numlab, work):
    broken = os.path.join(work, "broken.toml")
    with open(broken, "w", encoding="utf-8") as out:
        out.write('[linkage]\nname = "x"\n\n[joints]\nA = [1, 2, 3]\n')
    cases = [
        (["exercise", "check", "linkage", "--", "true"], "linkage needs --model"),
        (["exercise", "init", "linkage", os.path.join(work, "none")], "linkage needs --model"),
        (["exercise", "check", "gepp", "--model", "four-bar", "--", "true"], "--model applies to the linkage exercise only"),
        (["exercise", "check", "linkage", "--model", "no-such-model", "--", "true"], "neither a file nor a shipped model"),
        (["exercise", "check", "linkage", "--model", broken, "--", "true"], broken + ":5:5: the position of joint 'A'"),
        (["exercise", "grade", "linkage", "--submissions", work, "--out", os.path.join(work, "g2")], "linkage needs --model"),
    ]
    for args, wanted in cases:
        done = run([numlab] + args)
        lines = done.stderr.strip().splitlines()
        if done.returncode != 2 or len(lines) != 1 or wanted not in lines[0]:
            fail(f"{' '.join(args)}: exit {done.returncode}, stderr {done.stderr!r}, wanted '{wanted}'")
    print(f"bad input: {len(cases)} cases exit 2 with one line")


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    numlab, models_dir, work = sys.argv[1:]
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, "starters"))
    names = shipped_models(numlab, models_dir, work)
    instructor_file(numlab, work)
    caught = mutants(numlab, work)
    grade(numlab, work)
    bad_input(numlab, work)
    if failures:
        sys.exit(f"{len(failures)} failures")
    print(f"{len(names)} shipped models and an instructor's file pass; {caught} mutant runs caught with their cause")


if __name__ == "__main__":
    main()
