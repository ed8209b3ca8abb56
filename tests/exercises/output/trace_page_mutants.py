#!/usr/bin/env python3
"""The student's trace beside numlab's (docs/exercises.md, "Your trace beside numlab's"), end to end:

  trace_page_mutants.py NUMLAB OUT_DIR

Three shipped mutants are checked with --out: gepp/no_pivoting, gauss-seidel/jacobi_sweep and
jansen-newton/minus_dx. Each fails its trace check, and OUT/trace.html is written whole (no temporary
left, the page ends with </html>), embeds the failing test's "trace" of results.json number for number,
and names the first parting step, found here apart from numlab: for GEPP by elimination without
pivoting (numpy) on the request of the replay file, the first column whose largest |a_ik| is not on
the diagonal; for Gauss-Seidel by a Jacobi sweep and a Gauss-Seidel sweep (numpy) from the request's
x0; for Newton by the Python reference solution run on the same request (its trace against the
mutant's). report.html links the page. Then the reference solution is checked into the same folder:
no trace check fails, so trace.html is removed and neither results.json nor report.html mention it.
Last, `exercise grade` of a class of two (the no-pivoting mutant, the reference) writes trace.html
for the first only, embedding her results.json's trace.
"""
import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, ".."))
from apply_mutant import make_mutant  # noqa: E402

REFERENCES = os.path.join(HERE, "..", "references", "python")
problems = []


def fail(message):
    problems.append(message)
    print("FAIL:", message)


def check(numlab, exercise, solution, out):
    run = subprocess.run([numlab, "exercise", "check", exercise, "--out", out, "--", sys.executable, solution],
                         capture_output=True, text=True, timeout=600)
    return run.returncode, json.load(open(os.path.join(out, "results.json"), encoding="utf-8"))


def embedded(page):
    found = re.search(r'<script type="application/json" id="trace-data">(.*?)</script>', page, re.S)
    return json.loads(found.group(1)) if found else None


def numbers(text):
    return [float(n) for n in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?", text)]


def agrees(printed, value):
    """A number printed with a few significant digits is value rounded to them."""
    return abs(printed - value) <= 5e-3 * abs(value) + 1e-300


def failing_request(out, results, index):
    """The last request of the failing check (the one it failed on), from its replay file."""
    prefix = f"{index + 1:02}-"
    name = next(f for f in sorted(os.listdir(os.path.join(out, "replay"))) if f.startswith(prefix))
    lines = [json.loads(line) for line in open(os.path.join(out, "replay", name), encoding="utf-8")]
    return lines[-1]["request"]


def gepp_parting(request, trace):
    """Elimination without pivoting until the largest |a_ik| is off the diagonal."""
    a = np.array(request["A"], dtype=float)
    n = len(a)
    for k in range(n):
        p = k + int(np.argmax(np.abs(a[k:, k])))
        if p != k:
            return k, f"step {k + 1} (column {k}): you took row {k} as the pivot, numlab row {p} (|a| = ", \
                (abs(a[p, k]), abs(a[k, k]))
        a[k + 1:, k:] -= np.outer(a[k + 1:, k] / a[k, k], a[k, k:])
    return None, "", ()


def sweeps(request):
    A, b = np.array(request["A"], dtype=float), np.array(request["b"], dtype=float)
    M, c = (A.T @ A, A.T @ b) if request["normal_equations"] else (A, b)
    x0 = np.array(request["x0"], dtype=float)
    jacobi = (c - (M - np.diag(np.diag(M))) @ x0) / np.diag(M)
    seidel = x0.copy()
    for i in range(len(seidel)):
        seidel[i] = (c[i] - M[i, :i] @ seidel[:i] - M[i, i + 1:] @ seidel[i + 1:]) / M[i, i]
    return jacobi, seidel


def reference_trace(request):
    """The Python reference solution's reply to the request (numpy Newton, apart from numlab)."""
    run = subprocess.run([sys.executable, os.path.join(REFERENCES, "jansen_newton.py")], input=json.dumps(request) + "\n",
                         capture_output=True, text=True, timeout=60)
    return json.loads(run.stdout.splitlines()[0])["trace"]


def main(numlab, out_dir):
    for mutant in ("gepp/no_pivoting", "gauss-seidel/jacobi_sweep", "jansen-newton/minus_dx"):
        exercise, name = mutant.split("/")
        solution = os.path.join(out_dir, exercise, name + ".py")
        make_mutant(os.path.join(HERE, "..", "mutants", mutant + ".patch"), solution)
        out = os.path.join(out_dir, exercise, name + "-out")
        code, results = check(numlab, exercise, solution, out)
        traced = [(k, t) for k, t in enumerate(results["tests"]) if "trace" in t]
        if code != 1 or len(traced) != 1 or traced[0][1]["status"] != "fail":
            fail(f"{mutant}: exit {code}, {len(traced)} tests with a trace (expected 1 failing trace check)")
            continue
        index, test = traced[0]
        trace = test["trace"]
        page_path = os.path.join(out, "trace.html")
        if not os.path.isfile(page_path):
            fail(f"{mutant}: no trace.html")
            continue
        leftovers = [f for f in os.listdir(out) if ".tmp-" in f]
        if leftovers:
            fail(f"{mutant}: temporaries left beside trace.html: {leftovers}")
        page = open(page_path, encoding="utf-8").read()
        if not page.endswith("</html>\n"):
            fail(f"{mutant}: trace.html is not whole")
        data = embedded(page)
        if data is None or data.pop("check", None) != test["name"] or data != trace:
            fail(f"{mutant}: the traces embedded in trace.html are not results.json's")
        report = open(os.path.join(out, "report.html"), encoding="utf-8").read()
        if '<a href="trace.html">trace.html</a>' not in report:
            fail(f"{mutant}: report.html does not link trace.html")
        parting, sentence = trace["parting"], trace["sentence"]
        if f'<tr id="step-{parting + 1}" class="parting">' not in page or page.count('class="parting"') != 1:
            fail(f"{mutant}: the page does not mark step {parting + 1} (alone) as the parting row")
        request = failing_request(out, results, index)

        if exercise == "gepp":
            k, start, sizes = gepp_parting(request, trace)
            printed = numbers(sentence[len(start):]) if sentence.startswith(start) else []
            if parting != k or not sentence.startswith(start) or len(printed) != 2 or \
                    not all(agrees(p, v) for p, v in zip(printed, sizes)):
                fail(f"{mutant}: parting {parting}, sentence {sentence!r}; by numpy column {k}: {start}{sizes}")
        elif exercise == "gauss-seidel":
            jacobi, seidel = sweeps(request)
            i = int(np.argmax(np.abs(jacobi - seidel)))
            start = f"step 1 (sweep 1): your x[{i}] = "
            printed = numbers(sentence[len(start):])[:2] if sentence.startswith(start) else []
            if parting != 0 or len(printed) != 2 or not agrees(printed[0], jacobi[i]) or not agrees(printed[1], seidel[i]):
                fail(f"{mutant}: parting {parting}, sentence {sentence!r}; by numpy sweep 1 parts at x[{i}]: "
                     f"Jacobi {jacobi[i]}, Gauss-Seidel {seidel[i]}")
            if np.max(np.abs(np.array(trace["yours"][0]["x"]) - jacobi)) > 1e-12 or \
                    np.max(np.abs(np.array(trace["numlab"][0]["x"]) - seidel)) > 1e-12:
                fail(f"{mutant}: sweep 1 of the traces is not Jacobi's (yours) and Gauss-Seidel's (numlab's)")
        else:
            correct = reference_trace(request)
            yours = trace["yours"]
            k = next((k for k, (a, b) in enumerate(zip(yours, correct))
                      if abs(a["residual_inf"] - b["residual_inf"]) > 1e-6 * b["residual_inf"] + 1e-9), None)
            start = f"step {k + 1} (iteration {k + 1}): your ||f||_inf = " if k is not None else "?"
            printed = numbers(sentence[len(start):])[:2] if sentence.startswith(start) else []
            if parting != k or len(printed) != 2 or not agrees(printed[0], yours[k]["residual_inf"]) or \
                    not agrees(printed[1], correct[k]["residual_inf"]):
                fail(f"{mutant}: parting {parting}, sentence {sentence!r}; by the Python reference iteration {k}")
        print(f"{mutant}: {sentence}")

        # The reference into the same folder: no failing trace check, no page, no link.
        reference = os.path.join(REFERENCES, exercise.replace("-", "_") + ".py")
        code, results = check(numlab, exercise, reference, out)
        if code != 0 or os.path.exists(page_path) or any("trace" in t for t in results["tests"]) or \
                "trace.html" in open(os.path.join(out, "report.html"), encoding="utf-8").read():
            fail(f"{mutant}: after the reference passed (exit {code}), trace.html or a mention of it is left")
    # `exercise grade` writes the page per student too: the no-pivoting mutant gets one, the reference none.
    submissions = os.path.join(out_dir, "class")
    for student, source in (("ada", os.path.join(out_dir, "gepp", "no_pivoting.py")),
                            ("bob", os.path.join(REFERENCES, "gepp.py"))):
        os.makedirs(os.path.join(submissions, student), exist_ok=True)
        with open(source, encoding="utf-8") as f, open(os.path.join(submissions, student, "solution.py"), "w") as g:
            g.write(f.read())
    graded = os.path.join(out_dir, "graded")
    shutil.rmtree(graded, ignore_errors=True)
    run = subprocess.run([numlab, "exercise", "grade", "gepp", "--submissions", submissions, "--out", graded, "--jobs", "1"],
                         capture_output=True, text=True, timeout=600, env=dict(os.environ, PATH=os.path.dirname(sys.executable)
                                                                                + os.pathsep + os.environ.get("PATH", "")))
    ada = os.path.join(graded, "ada")
    if run.returncode != 1 or not os.path.isfile(os.path.join(ada, "trace.html")) or \
            os.path.exists(os.path.join(graded, "bob", "trace.html")):
        fail(f"grade: exit {run.returncode}; ada's trace.html {os.path.isfile(os.path.join(ada, 'trace.html'))}, "
             f"bob's {os.path.exists(os.path.join(graded, 'bob', 'trace.html'))} (expected only ada's)\n{run.stderr}")
    else:
        results = json.load(open(os.path.join(ada, "results.json"), encoding="utf-8"))
        test = next(t for t in results["tests"] if "trace" in t)
        data = embedded(open(os.path.join(ada, "trace.html"), encoding="utf-8").read())
        if data is None or data.pop("check", None) != test["name"] or data != test["trace"]:
            fail("grade: ada's trace.html does not embed her results.json's trace")
    if problems:
        sys.exit(f"{len(problems)} problems")
    print("trace pages: 3 mutants, each parting where numpy or the Python reference says")


if __name__ == "__main__":
    main(*sys.argv[1:])
