#!/usr/bin/env python3
"""`--variant` end to end (docs/exercises.md, "Variants"), through the numlab executable.

  variants_cli.py unchanged NUMLAB REFERENCES GOLDEN OUT
      Without --variant every exercise sends, request for request, what numlab sent before variants
      existed: GOLDEN holds the digest of each request the Python references (REFERENCES/NAME.py)
      received from numlab f22073f (SHA-256 of the request without its id, 16 hex digits), in order,
      and they must all come again, in that order; requests of checks added since may come between.
  variants_cli.py references NUMLAB EXERCISE ID[,ID...] COMMAND...
      COMMAND passes every check of EXERCISE under each variant ID, and results.json names the variant.
  variants_cli.py mutants NUMLAB MUTANTS OUT ID[,ID...]
      Every Python mutant (MUTANTS/EXERCISE/NAME.patch) is still caught under each ID: the check its
      header names fails, with the header's diagnosis (EXPECT-CAUSE) when it gives one.
  variants_cli.py tee LOG COMMAND...
      (internal) passes stdin to COMMAND and its replies back, appending every request line to LOG.
"""
import hashlib
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from expect_verdict import caught, header, mutant_from_patch, skip_unless_found  # noqa: E402

EXERCISES = ["gepp", "gauss-seidel", "inverse2x2", "polyfit", "jansen-jacobian", "jansen10-jacobian",
             "jansen-newton", "mustang-newton"]


def tee(log, command):
    child = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True, bufsize=1)
    with open(log, "a", encoding="utf-8") as out:
        for line in sys.stdin:
            out.write(line)
            out.flush()
            child.stdin.write(line)
            child.stdin.flush()
            sys.stdout.write(child.stdout.readline())
            sys.stdout.flush()
    child.stdin.close()
    sys.exit(child.wait())


def digests(log):
    """The digest of each request in LOG, in order: SHA-256 of the request without its id (16 hex
    digits); a request sent twice in a row (the warm-up that leaves out start-up) counted once."""
    found, last = [], None
    with open(log, encoding="utf-8") as text:
        for raw in text:
            if raw == last:
                continue
            last = raw
            request = json.loads(raw)
            request.pop("id", None)
            canonical = json.dumps(request, sort_keys=True, separators=(",", ":"))
            found.append(hashlib.sha256(canonical.encode()).hexdigest()[:16])
    return found


def missing_from(expected, got):
    """The first of `expected` that does not come in `got` in order (None when all do)."""
    rest = iter(got)
    for k, digest in enumerate(expected):
        if not any(digest == other for other in rest):
            return k
    return None


def check(numlab, exercise, command, variant=None, out=None):
    words = [numlab, "exercise", "check", exercise, "--format", "json"]
    words += ["--variant", variant] if variant is not None else []
    words += ["--out", out] if out else []
    run = subprocess.run(words + ["--"] + command, capture_output=True, text=True, timeout=600)
    try:
        return run.returncode, json.loads(run.stdout)
    except json.JSONDecodeError:
        sys.exit(f"not JSON on stdout (exit {run.returncode}):\n{run.stdout}\n{run.stderr}")


def unchanged(numlab, references, golden, out_dir):
    expected = {}
    with open(golden, encoding="utf-8") as text:
        for line in text:
            if line.strip() and not line.startswith("#"):
                name, *found = line.split()
                expected[name] = found
    os.makedirs(out_dir, exist_ok=True)
    wrong = []
    for exercise in EXERCISES:
        log = os.path.join(out_dir, exercise + ".requests.jsonl")
        if os.path.exists(log):
            os.remove(log)
        reference = os.path.join(references, exercise.replace("-", "_") + ".py")
        code, results = check(numlab, exercise, [sys.executable, os.path.abspath(__file__), "tee", log,
                                                 sys.executable, reference])
        got = digests(log)
        lost = missing_from(expected[exercise], got)
        print(f"{exercise}: {len(got)} requests, the {len(expected[exercise])} of before "
              f"{'all sent, in order' if lost is None else f'not all sent: request {lost + 1} is missing'} "
              f"(status {results['status']}, variant {results.get('variant')!r})")
        if lost is not None or results.get("variant") is not None or code != 0:
            wrong.append(exercise)
    if wrong:
        sys.exit("without --variant these exercises no longer send the requests of before: " + ", ".join(wrong))


def references(numlab, exercise, ids, command):
    skip_unless_found(command[0])
    start = time.monotonic()
    for variant in ids:
        code, results = check(numlab, exercise, command, variant)
        bad = [t for t in results["tests"] if t["status"] != "pass"]
        for test in bad:
            print(f"false failure under variant {variant!r}: {test['name']}: {test['status']}: {test['message']}")
        if code != 0 or bad or results.get("variant") != variant:
            sys.exit(f"{exercise} under variant {variant!r}: exit {code}, status {results['status']}, "
                     f"results.json variant {results.get('variant')!r}")
        print(f"variant {variant!r}: {len(results['tests'])} checks pass")
    print(f"{len(ids)} variants in {time.monotonic() - start:.1f} s")


def caught_under_variant(results, fields):
    """"" when the check the header names fails (not errors) and the diagnosis is the header's cause,
    else why not. The header's EXPECT-MESSAGE lines quote the inputs without a variant (a label, an
    entry's place), so under a variant they are shown, not required."""
    wanted = fields["EXPECT-CHECK"][0]
    named = [test for test in results["tests"] if wanted in test["name"]]
    if not any(test["status"] == "fail" for test in named):
        return f"'{wanted}' gave " + (", ".join(test["status"] for test in named) or "no such check")
    for cause in fields["EXPECT-CAUSE"]:
        if results.get("diagnosis_cause") != cause:
            return f"the diagnosis is {results.get('diagnosis_cause')!r} ({results.get('diagnosis')!r}), not {cause!r}"
    test, _ = caught(results, fields)
    if test is None:
        print(f"(the message differs from the header's, as a variant's inputs do: {wanted})")
    return ""


def mutants(numlab, folder, out_dir, ids):
    start, count, missed = time.monotonic(), 0, []
    for exercise in sorted(os.listdir(folder)):
        directory = os.path.join(folder, exercise)
        if exercise == "octave" or not os.path.isdir(directory):
            continue
        for name in sorted(n for n in os.listdir(directory) if n.endswith(".patch")):
            path = mutant_from_patch(os.path.join(directory, name), out_dir)
            fields = header(path)
            for variant in ids:
                count += 1
                _, results = check(numlab, exercise, [sys.executable, path], variant)
                why = caught_under_variant(results, fields)
                if why:
                    missed.append(f"{exercise}/{name} under {variant!r}: {why}")
    for line in missed:
        print("MISSED: " + line)
    print(f"{count - len(missed)} of {count} mutant runs caught under variants {ids} "
          f"in {time.monotonic() - start:.1f} s")
    if missed or count == 0:
        sys.exit(f"{len(missed)} mutant runs not caught under a variant")


if __name__ == "__main__":
    mode = sys.argv[1]
    if mode == "tee":
        tee(sys.argv[2], sys.argv[3:])
    elif mode == "unchanged":
        unchanged(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5])
    elif mode == "references":
        references(sys.argv[2], sys.argv[3], sys.argv[4].split(","), sys.argv[5:])
    elif mode == "mutants":
        mutants(sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5].split(","))
    else:
        sys.exit(f"unknown mode {mode}")
