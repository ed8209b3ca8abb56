#!/usr/bin/env python3
"""The C++ starter as a student uses it, against numlab installed by the test fixture.

  cpp_starter.py PREFIX WORKDIR

Runs PREFIX/bin/numlab exercise init gepp WORKDIR/gepp --lang cpp, configures the starter with
-DCMAKE_PREFIX_PATH=PREFIX (find_package(numlab)), builds it, and checks it with
`numlab exercise check gepp --format json`: exit 1, and every check fails (none errors) with
"not implemented". Exits 77 (skipped) only when this numlab has no `exercise` command or no
`gepp` exercise yet.
"""
import json
import os
import shutil
import subprocess
import sys


def run(command, **options):
    print("$ " + " ".join(command), flush=True)
    return subprocess.run(command, capture_output=True, text=True, timeout=600, **options)


def main():
    prefix, workdir = sys.argv[1], sys.argv[2]
    numlab = os.path.join(prefix, "bin", "numlab")
    listing = run([numlab, "exercise", "list"])
    if listing.returncode != 0 or "gepp" not in listing.stdout:
        print(f"SKIPPED: {numlab} has no `exercise list` with gepp yet:\n{listing.stdout}{listing.stderr}")
        return 77

    starter = os.path.join(workdir, "gepp")
    shutil.rmtree(workdir, ignore_errors=True)
    os.makedirs(workdir)
    steps = [
        [numlab, "exercise", "init", "gepp", starter, "--lang", "cpp"],
        ["cmake", "-S", starter, "-B", os.path.join(starter, "build"), f"-DCMAKE_PREFIX_PATH={prefix}"],
        ["cmake", "--build", os.path.join(starter, "build")],
    ]
    for step in steps:
        done = run(step)
        if done.returncode != 0:
            print(f"failed (exit {done.returncode}):\n{done.stdout}\n{done.stderr}")
            return 1
    for name in ("TASK.md", "CMakeLists.txt", "solution.cpp"):
        if not os.path.isfile(os.path.join(starter, name)):
            print(f"exercise init wrote no {name}")
            return 1

    check = run([numlab, "exercise", "check", "gepp", "--format", "json", "--",
                 os.path.join(starter, "build", "solution")], cwd=starter)
    try:
        results = json.loads(check.stdout)
    except json.JSONDecodeError:
        print(f"not JSON (exit {check.returncode}):\n{check.stdout}\n{check.stderr}")
        return 1
    problems = []
    if check.returncode != 1:
        problems.append(f"exit {check.returncode}, expected 1 (some check fails)")
    if results.get("status") != "fail":
        problems.append(f"status {results.get('status')!r}, expected 'fail'")
    if not results.get("tests"):
        problems.append("no tests in results.json")
    for test in results.get("tests", []):
        message = test.get("message") or ""
        if test["status"] != "fail" or "not implemented" not in message:
            problems.append(f"{test['name']}: {test['status']}: {message}")
    if problems:
        print("the C++ starter does not fail honestly:\n  " + "\n  ".join(problems))
        return 1
    print(f"all {len(results['tests'])} checks fail with 'not implemented'")
    return 0


if __name__ == "__main__":
    sys.exit(main())
