#!/usr/bin/env python3
"""`numlab exercise grade` on a small class (docs/exercises.md, "Grading a class").

  grade_class.py NUMLAB EXERCISES_SOURCE WORK [INSTALL_PREFIX]

The class: the Python reference, a mutant (rows of A swapped without b), the untouched starter, an
empty folder, a syntax error and, when INSTALL_PREFIX (numlab installed) is given and cmake is on
PATH, the C++ reference built from the C++ starter's CMakeLists.txt. It is graded with --jobs 1 and
--jobs 2: the gradebooks must be the same but for the seconds, each row and each student's
results.json and report.html what that submission deserves. Then bad input: one line, exit 2,
nothing overwritten.
"""
import csv
import json
import os
import shutil
import subprocess
import sys

numlab, source, work = sys.argv[1:4]
prefix = sys.argv[4] if len(sys.argv) > 4 else ""
failures = []


def expect(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def run(*args, env=None):
    return subprocess.run([numlab, *args], capture_output=True, text=True, env=env, timeout=600)


shutil.rmtree(work, ignore_errors=True)
subs = os.path.join(work, "subs")
os.makedirs(subs)
reference = os.path.join(source, "references", "python", "gepp.py")
os.makedirs(os.path.join(subs, "ref"))
shutil.copy(reference, os.path.join(subs, "ref", "solution.py"))
os.makedirs(os.path.join(subs, "mutant"))
subprocess.run([sys.executable, os.path.join(source, "apply_mutant.py"),
                os.path.join(source, "mutants", "gepp", "swap_without_b.patch"),
                os.path.join(subs, "mutant", "solution.py")], check=True)
os.makedirs(os.path.join(subs, "empty"))
os.makedirs(os.path.join(subs, "syntax"))
with open(os.path.join(subs, "syntax", "solution.py"), "w") as f:
    f.write("import json\ndef solve(request:\n    return {}\n")
subprocess.run([numlab, "exercise", "init", "gepp", os.path.join(subs, "starter")], check=True, capture_output=True)
os.makedirs(os.path.join(subs, ".hidden"))  # not a student

env = dict(os.environ)
with_cpp = bool(prefix) and shutil.which("cmake") is not None
if with_cpp:
    cpp = os.path.join(subs, "cpp")
    subprocess.run([numlab, "exercise", "init", "gepp", cpp, "--lang", "cpp"], check=True, capture_output=True)
    with open(os.path.join(source, "references", "cpp", "gepp.cpp")) as f:
        text = f.read()
    text = text.replace('"../../batteries/linear/gepp_solution.hpp"', '"gepp_solution.hpp"')
    with open(os.path.join(cpp, "solution.cpp"), "w") as f:
        f.write(text)
    shutil.copy(os.path.join(source, "batteries", "linear", "gepp_solution.hpp"), cpp)
    env["CMAKE_PREFIX_PATH"] = prefix
else:
    print("note: no C++ submission (no install prefix given or cmake not on PATH)")

books = {}
for jobs in ("1", "2"):
    out = os.path.join(work, "out" + jobs)
    done = run("exercise", "grade", "gepp", "--submissions", subs, "--out", out, "--jobs", jobs, env=env)
    print(done.stdout, done.stderr, end="")
    expect(done.returncode == 1, f"--jobs {jobs}: exit 1 (some fail), got {done.returncode}")
    with open(os.path.join(out, "gradebook.csv"), newline="") as f:
        books[jobs] = list(csv.reader(f))
    rows = {row[0]: row for row in books[jobs][1:]}
    names = [row[0] for row in books[jobs][1:]]
    expect(books[jobs][0] == ["student", "exercise", "variant", "passed", "total", "diagnosis", "seconds"], "header")
    expect(names == sorted(names) and ".hidden" not in names, f"rows in name order, no hidden folder: {names}")
    expect(set(names) == {"ref", "mutant", "empty", "syntax", "starter"} | ({"cpp"} if with_cpp else set()), names)
    for row in books[jobs][1:]:
        expect(row[1] == "gepp" and row[2] == "" and float(row[6]) >= 0, f"exercise, variant, seconds: {row}")
    # 9 checks, and the library-call rule for a watched (Python) program (docs/exercises.md, "Library calls").
    expect(rows["ref"][3:6] == ["10", "10", ""], f"ref passes all: {rows['ref']}")
    expect(int(rows["mutant"][3]) < int(rows["mutant"][4]) and rows["mutant"][5] != "",
           f"mutant fails with a diagnosis: {rows['mutant']}")
    expect(rows["empty"][3] == "0" and rows["empty"][5].startswith("no starter file"), f"empty: {rows['empty']}")
    expect(rows["syntax"][3] == "0" and "exited with code 1" in rows["syntax"][5], f"syntax: {rows['syntax']}")
    expect(rows["starter"][3] == "0" and "not implemented" in rows["starter"][5], f"starter: {rows['starter']}")
    if with_cpp:
        expect(rows["cpp"][3:6] == ["9", "9", ""], f"C++ reference passes all: {rows['cpp']}")
        expect(os.path.isfile(os.path.join(out, "cpp", "build", "solution")), "C++ built into OUT/cpp/build")
    for student in names:
        for name in ("results.json", "report.html"):
            expect(os.path.isfile(os.path.join(out, student, name)), f"{student}/{name} written")
    with open(os.path.join(out, "ref", "results.json")) as f:
        expect(json.load(f)["status"] == "pass", "ref results.json: pass")
    with open(os.path.join(out, "mutant", "results.json")) as f:
        expect(json.load(f)["status"] == "fail", "mutant results.json: fail")
    with open(os.path.join(out, "empty", "results.json")) as f:
        result = json.load(f)
        expect(result["status"] == "error" and "no starter file" in result["message"], f"empty results.json: {result}")
    with open(os.path.join(out, "mutant", "report.html")) as f:
        html = f.read()
        expect("gepp" in html and "random systems" in html, "the mutant's report names the exercise and its failing check")

strip = lambda book: [row[:6] for row in book]
expect(strip(books["1"]) == strip(books["2"]), "--jobs 1 and --jobs 2: the same gradebook but for the seconds")

# Bad input: one line on stderr, exit 2, nothing written or overwritten.
out1 = os.path.join(work, "out1")
with open(os.path.join(out1, "gradebook.csv"), "rb") as f:
    before = f.read()
a_file = os.path.join(work, "a-file")
open(a_file, "w").close()
os.makedirs(os.path.join(work, "nobody"))
bad = {
    "no such DIR": ["--submissions", os.path.join(work, "missing"), "--out", os.path.join(work, "o1")],
    "OUT holds a gradebook": ["--submissions", subs, "--out", out1],
    "OUT not writable": ["--submissions", subs, "--out", os.path.join(a_file, "out")],
    "--jobs 0": ["--submissions", subs, "--out", os.path.join(work, "o2"), "--jobs", "0"],
    "no sub-folder": ["--submissions", os.path.join(work, "nobody"), "--out", os.path.join(work, "o3")],
    "bad timeout": ["--submissions", subs, "--out", os.path.join(work, "o4"), "--timeout", "0"],
}
for what, args in bad.items():
    done = run("exercise", "grade", "gepp", *args)
    lines = done.stderr.strip().splitlines()
    expect(done.returncode == 2 and len(lines) == 1, f"{what}: exit 2 and one line, got {done.returncode}: {done.stderr}")
    print(f"{what}: {done.stderr.strip()}")
done = run("exercise", "grade", "no-such-exercise", "--submissions", subs, "--out", os.path.join(work, "o5"))
expect(done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, f"unknown exercise: {done.stderr}")
print(f"unknown exercise: {done.stderr.strip()}")
with open(os.path.join(out1, "gradebook.csv"), "rb") as f:
    expect(f.read() == before, "the existing gradebook is untouched")
for name in ("o1", "o2", "o4", "o5"):
    expect(not os.path.exists(os.path.join(work, name)), f"nothing made for bad input ({name})")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
