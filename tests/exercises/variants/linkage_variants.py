#!/usr/bin/env python3
"""The linkage exercise under variants (docs/exercises.md, "A variant per student"), through numlab.

  linkage_variants.py NUMLAB WORK_DIR MODEL[,MODEL...] ID[,ID...]

For each shipped MODEL:
1. Without a variant, the file's model as the requests carry it (recorded by file_numbers.py).
2. Under each ID the generic reference (references/python/linkage.py) passes every check and
   results.json names the variant; every request carries one model, the same for the same ID run
   twice and another for another ID; each link length, body coefficient... differs from the file's:
   every distance or crank length within 3% of the file's and not equal to it; the sweep's drivers
   are the file's (the same range); the variant assembles over it, checked here apart from numlab:
   numpy Newton on the variant's equations from q0, pose after pose, ||f||_inf <= the tolerance.
3. TASK.md of `init --variant ID` writes the equations with the variant's lengths, not the file's.
4. A solution with the file's model in place of the request's (file_numbers.py use) fails with
   diagnosis wrong_link.
5. Each linkage mutant (linkage/mutants/*.patch) on the first model its '# MODELS:' line names is
   caught under the first ID with its EXPECT-CAUSE.
"""
import json
import os
import re
import shutil
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
EXERCISES = os.path.dirname(HERE)
sys.path.insert(0, EXERCISES)
sys.path.insert(0, os.path.join(EXERCISES, "references", "python"))
from apply_mutant import make_mutant  # noqa: E402
import linkage  # noqa: E402

PYTHON = sys.executable
REFERENCE = os.path.join(EXERCISES, "references", "python", "linkage.py")
failures = []


def fail(text):
    failures.append(text)
    print("FAIL: " + text)


def check(numlab, model, program, variant=None):
    words = [numlab, "exercise", "check", "linkage", "--model", model, "--format", "json"]
    words += ["--variant", variant] if variant else []
    done = subprocess.run(words + ["--"] + program, capture_output=True, text=True, timeout=600)
    try:
        return done.returncode, json.loads(done.stdout)
    except json.JSONDecodeError:
        fail(f"{model} {variant}: not JSON (exit {done.returncode}): {done.stdout[:300]} {done.stderr[:300]}")
        return done.returncode, {"tests": [], "status": "error"}


def requests_of(numlab, model, variant, log):
    """The requests numlab sends the reference under `variant`, and the check's results."""
    if os.path.exists(log):
        os.remove(log)
    tee = [PYTHON, os.path.join(HERE, "variants_cli.py"), "tee", log, PYTHON, REFERENCE]
    code, results = check(numlab, model, tee, variant)
    with open(log, encoding="utf-8") as lines:
        requests = [json.loads(line) for line in lines if line.strip()]
    for request in requests:
        request.pop("id", None)
    return code, results, requests


def lengths(model):
    return [e["length"] for e in model["equations"] if "length" in e]


def lengths_line(model):
    """TASK.md's line of the lengths, as the model states them (17 significant digits)."""
    named = [f"{e['name']} {e['length']:.17g}" for e in model["equations"] if "length" in e]
    return "The lengths: " + "; ".join(named) + "."


def assembles(model, sweep):
    """numpy Newton on the model's equations from q0 over the sweep's drivers: every pose converges."""
    solver = linkage.Linkage(model)
    q = np.array(sweep["q0"], dtype=float)
    for driver in sweep["drivers"]:
        try:
            q, _ = solver.newton(q, solver.t(driver), sweep["tolerance"], sweep["max_iterations"])
        except (RuntimeError, np.linalg.LinAlgError) as error:
            return f"no pose at driver {driver}: {error}"
    return ""


def one_model(numlab, work, name, ids):
    file_json = os.path.join(work, name + ".file.json")
    code, results = check(numlab, name, [PYTHON, os.path.join(HERE, "file_numbers.py"), "record", file_json])
    if code != 0:
        return fail(f"{name} without a variant: exit {code}")
    with open(file_json, encoding="utf-8") as saved:
        file_model = json.load(saved)
    _, _, plain = requests_of(numlab, name, None, os.path.join(work, name + ".plain.jsonl"))
    plain_sweep = next(r for r in plain if r["task"] == "sweep")
    models = {}
    for variant in ids:
        code, results, requests = requests_of(numlab, name, variant, os.path.join(work, f"{name}.{variant}.jsonl"))
        bad = [f"{t['name']}: {t['message']}" for t in results["tests"] if t["status"] != "pass"]
        if code != 0 or bad or results.get("variant") != variant:
            fail(f"{name} under {variant}: the reference: exit {code}, variant {results.get('variant')!r}, {bad}")
        _, _, again = requests_of(numlab, name, variant, os.path.join(work, f"{name}.{variant}.again.jsonl"))
        if again != requests:
            fail(f"{name} under {variant}: another run sent other requests")
        varied = {json.dumps(r["model"], sort_keys=True) for r in requests}
        if len(varied) != 1:
            fail(f"{name} under {variant}: {len(varied)} models in its requests, not one")
        model = requests[0]["model"]
        models[variant] = model
        for got, file_length in zip(lengths(model), lengths(file_model)):
            if got == file_length or abs(got / file_length - 1.0) > 0.03:
                fail(f"{name} under {variant}: length {got} against the file's {file_length}")
        if len(lengths(model)) != len(lengths(file_model)):
            fail(f"{name} under {variant}: other equations than the file's")
        sweep = next(r for r in requests if r["task"] == "sweep")
        if sweep["drivers"] != plain_sweep["drivers"]:
            fail(f"{name} under {variant}: the sweep's drivers are not the file's")
        why = assembles(model, sweep)
        if why:
            fail(f"{name} under {variant}: the variant does not assemble over the checked range: {why}")
        # TASK.md: the variant's lengths, not the file's.
        folder = os.path.join(work, f"{name}.{variant}.starter")
        shutil.rmtree(folder, ignore_errors=True)
        done = subprocess.run([numlab, "exercise", "init", "linkage", folder, "--model", name, "--variant", variant],
                              capture_output=True, text=True, timeout=300)
        with open(os.path.join(folder, "TASK.md"), encoding="utf-8") as task:
            text = task.read()
        if done.returncode != 0 or lengths_line(model) not in text or lengths_line(file_model) in text:
            fail(f"{name} under {variant}: TASK.md's equations are not written with the variant's lengths "
                 f"('{lengths_line(model)}')")
        # The file's numbers where the variant's belong: wrong_link.
        code, results = check(numlab, name, [PYTHON, os.path.join(HERE, "file_numbers.py"), "use", file_json], variant)
        if results["status"] != "fail" or results.get("diagnosis_cause") != "wrong_link":
            fail(f"{name} under {variant}: the file's numbers get {results['status']}, diagnosis "
                 f"{results.get('diagnosis_cause')!r} ({results.get('diagnosis')!r}), not wrong_link")
    if len({json.dumps(m, sort_keys=True) for m in models.values()}) != len(ids):
        fail(f"{name}: two IDs got the same linkage")
    print(f"{name}: the reference passes under {len(ids)} variants, each its own linkage over the file's range; "
          "the file's numbers get wrong_link")


def mutants(numlab, work, variant):
    folder = os.path.join(EXERCISES, "linkage", "mutants")
    caught = 0
    for patch in sorted(p for p in os.listdir(folder) if p.endswith(".patch")):
        path = os.path.join(work, patch.replace(".patch", ".py"))
        make_mutant(os.path.join(folder, patch), path)
        with open(path, encoding="utf-8") as source:
            fields = dict(re.findall(r"^# ([A-Z-]+): (.*)$", source.read(), re.M))
        model = fields["MODELS"].split()[0]
        _, results = check(numlab, model, [PYTHON, path], variant)
        named = [t for t in results["tests"] if fields["EXPECT-CHECK"] in t["name"]]
        if not any(t["status"] == "fail" for t in named) or results.get("diagnosis_cause") != fields["EXPECT-CAUSE"]:
            fail(f"mutant {patch} on {model} under {variant}: {[t['status'] for t in named]}, diagnosis "
                 f"{results.get('diagnosis_cause')!r}, not {fields['EXPECT-CAUSE']!r}")
        else:
            caught += 1
    print(f"{caught} linkage mutants caught under {variant!r} with their EXPECT-CAUSE")


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    numlab, work, names, ids = sys.argv[1], sys.argv[2], sys.argv[3].split(","), sys.argv[4].split(",")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name in names:
        one_model(numlab, work, name, ids)
    mutants(numlab, work, ids[0])
    if failures:
        sys.exit(f"{len(failures)} failures")


if __name__ == "__main__":
    main()
