#!/usr/bin/env python3
"""Measures `numlab exercise check` on the corpus of buggy student solutions (issue 29 §1).

  measure.py NUMLAB [--prefix PREFIX] [--jobs N] [--min-catch-rate R] [--min-diagnosis-rate R]
             [--json FILE] [--keep DIR] [--include-pending]

Each corpus file, EXERCISE/NAME.py|.m|.cpp beside this script, is what a student wrote in place of
the starter's solve() stub (a line "# include: NAME" stands for shared/NAME, a correct part that
several files use unchanged), under a header naming the bug and its true cause:
  BUG: one sentence            CAUSE: a cause id, no_effect (a harmless slip) or none (correct)
  SET: a name (optional)       the set the file belongs to: "heldout" for files written after the
                               detectors, without looking at them; a file without SET is "tuning"
It becomes a whole program in the starter `NUMLAB exercise init EXERCISE DIR --lang LANG` writes now
(its stub replaced by the file), is run by `NUMLAB exercise check EXERCISE --format json`, two at a
time: Python by this Python, Octave by `octave-cli --no-gui --quiet`, C++ built once, in one CMake
project against numlab installed in PREFIX (without --prefix the C++ files are skipped).

Prints, per exercise and overall: caught (status not pass) and diagnosed (diagnosis_cause is the
CAUSE) out of the files whose CAUSE is a bug (not no_effect or none), the false failures (a
no_effect or none file that does not pass), and each miss with its expected and diagnosed cause;
then the same table for each SET. --include-pending also reads ../corpus-pending/EXERCISE/NAME
(files that would break the thresholds until the detectors are fixed; they count in every table).
Exit 1 when the whole corpus (every set) is below --min-catch-rate or --min-diagnosis-rate or on any
false failure; 77 (a skip) when all else holds but files were skipped (no octave-cli, no --prefix);
2 on bad input.
"""
import argparse
import concurrent.futures
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
PENDING = os.path.join(os.path.dirname(HERE), "corpus-pending")
LANGUAGES = {".py": "python", ".m": "octave", ".cpp": "cpp"}
HARMLESS = ("no_effect", "none")
# The stub each starter ships, replaced by the corpus file.
STUBS = {"python": r"^def solve\(request\):\n(?:    .*\n)+",
         "octave": r"^function reply = solve\(request\)\n(?:.*\n)*?end\n",
         "cpp": r"^json solve\(const json& request\) \{\n(?:.*\n)*?\}\n"}
# The cause ids of docs/exercises.md ("The corpus"): a typo in a header is bad input, not a miss.
NEWTON = {"x_never_updated", "step_sign", "trace_before_step", "stop_test", "one_iteration_too_many",
          "transposed_jacobian", "degrees_for_radians", "finite_difference_jacobian", "wrong_jacobian",
          "converged_when_stopped", "restart_from_seed_guess", "rounded_constants"}
JACOBIAN = {"transposed_jacobian", "transposed_pair", "degrees_for_radians", "finite_difference_jacobian",
            "derivative_sign", "wrong_angle_column", "wrong_link", "mislabelled_entries", "f_sign"}
CAUSES = {
    "gepp": {"no_pivoting", "signed_pivot", "inverted_multiplier", "swap_without_b", "partial_row_swap",
             "back_substitution", "absolute_singular_threshold", "no_singular_test"},
    "gauss-seidel": {"jacobi_sweep", "a_at_instead_of_at_a", "plain_when_normal_asked", "reverse_order",
                     "stop_test", "limit_reported_converged", "x_never_updated"},
    "inverse2x2": {"transposed", "determinant_sign", "no_scaling", "absolute_singular_threshold",
                   "no_singular_test"},
    "polyfit": {"powers_reversed", "degree_off_by_one", "missing_unscale", "interpolation",
                "unscaled_vandermonde", "normal_equations_wrong", "no_rank_check"},
    "jansen-jacobian": JACOBIAN, "jansen10-jacobian": JACOBIAN,
    "jansen-newton": NEWTON, "mustang-newton": NEWTON,
}


def bad_input(message):
    print(f"measure.py: error: {message}", file=sys.stderr)
    sys.exit(2)


def header(path, exercise):
    """BUG, CAUSE and SET ("tuning" when absent) from the file's comment header (#, % or //)."""
    fields = {}
    with open(path, encoding="utf-8") as source:
        for line in source:
            match = re.match(r"\s*(?:#|%|//)\s*(BUG|CAUSE|SET):\s*(.+?)\s*$", line)
            if match:
                fields.setdefault(match.group(1), []).append(match.group(2))
    if len(fields.get("BUG", [])) != 1 or len(fields.get("CAUSE", [])) != 1:
        bad_input(f"{path}: the header needs one 'BUG:' line and one 'CAUSE:' line")
    sets = fields.get("SET", ["tuning"])
    if len(sets) != 1 or not re.fullmatch(r"[a-z0-9_-]+", sets[0]):
        bad_input(f"{path}: at most one 'SET:' line, a name of a-z, 0-9, _ and -")
    cause = fields["CAUSE"][0]
    if cause not in CAUSES[exercise] | {"library_call", *HARMLESS}:
        bad_input(f"{path}: CAUSE {cause!r} is not a cause id of {exercise} (nor library_call, no_effect, none)")
    return fields["BUG"][0], cause, sets[0]


def corpus_files(include_pending):
    """Every file of the corpus (and of corpus-pending with include_pending), named EXERCISE/NAME
    (corpus-pending/EXERCISE/NAME for a pending one)."""
    files = []
    roots = [(HERE, "")] + ([(PENDING, "corpus-pending/")] if include_pending and os.path.isdir(PENDING) else [])
    for root, label in roots:
        for exercise in sorted(os.listdir(root)):
            folder = os.path.join(root, exercise)
            if not os.path.isdir(folder) or exercise.startswith(".") or exercise == "shared":
                continue
            if exercise not in CAUSES:
                bad_input(f"{folder}: not an exercise of the corpus ({', '.join(CAUSES)})")
            for name in sorted(os.listdir(folder)):
                language = LANGUAGES.get(os.path.splitext(name)[1])
                if language:
                    path = os.path.join(folder, name)
                    bug, cause, part = header(path, exercise)
                    files.append({"exercise": exercise, "file": f"{label}{exercise}/{name}", "path": path,
                                  "language": language, "bug": bug, "cause": cause, "set": part})
    if not files:
        bad_input(f"no corpus files under {HERE}")
    return files


def starter_text(numlab, exercise, language, work, cache={}):
    """The program `exercise init` writes for EXERCISE in LANGUAGE (made once per pair)."""
    key = (exercise, language)
    if key not in cache:
        folder = os.path.join(work, "starters", f"{language}-{exercise}")
        os.makedirs(os.path.dirname(folder), exist_ok=True)
        subprocess.run([numlab, "exercise", "init", exercise, folder, "--lang", language],
                       check=True, capture_output=True, timeout=60)
        name = {"python": "solution.py", "octave": "solution.m", "cpp": "solution.cpp"}[language]
        with open(os.path.join(folder, name), encoding="utf-8") as text:
            cache[key] = text.read()
    return cache[key]


def shared_part(name, user):
    """corpus/shared/NAME: a correct part several files use unchanged (their bug is elsewhere)."""
    path = os.path.join(HERE, "shared", name)
    if not os.path.isfile(path):
        bad_input(f"{user}: includes {name}, which is not in {os.path.dirname(path)}")
    with open(path, encoding="utf-8") as text:
        return text.read().rstrip("\n") + "\n"


def whole_program(numlab, entry, work):
    """The starter with its solve() stub replaced by the corpus file, written under WORK."""
    starter = starter_text(numlab, entry["exercise"], entry["language"], work)
    with open(entry["path"], encoding="utf-8") as text:
        student = re.sub(r"^(?:#|%|//) include: (\S+)\n", lambda m: shared_part(m.group(1), entry["path"]), text.read(),
                         flags=re.M).rstrip("\n") + "\n"
    program, replaced = re.subn(STUBS[entry["language"]], lambda _: student, starter, count=1, flags=re.M)
    if replaced != 1:
        bad_input(f"the {entry['language']} starter of {entry['exercise']} has no solve() stub to replace")
    stem = os.path.splitext(entry["file"])[0].replace("/", "__").replace("-", "_")
    path = os.path.join(work, "programs", stem + os.path.splitext(entry["path"])[1])
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as out:
        out.write(program)
    return path, stem


def build_cpp(entries, prefix, work):
    """Builds every C++ program in one CMake project against PREFIX; sets each entry's command."""
    project = os.path.join(work, "cpp")
    lines = ["cmake_minimum_required(VERSION 3.16)", "project(numlab_corpus LANGUAGES CXX)",
             "find_package(numlab REQUIRED)"]
    for entry in entries:
        lines.append(f"add_executable({entry['stem']} {entry['program']})")
        lines.append(f"target_link_libraries({entry['stem']} PRIVATE numlab::exercise_protocol)")
        entry["command"] = [os.path.join(project, "build", entry["stem"])]
    os.makedirs(project, exist_ok=True)
    with open(os.path.join(project, "CMakeLists.txt"), "w") as out:
        out.write("\n".join(lines) + "\n")
    for step in (["cmake", "-S", project, "-B", os.path.join(project, "build"), f"-DCMAKE_PREFIX_PATH={prefix}",
                  "-DCMAKE_BUILD_TYPE=Release"],
                 ["cmake", "--build", os.path.join(project, "build"), "-j2"]):
        done = subprocess.run(step, capture_output=True, text=True, timeout=900)
        if done.returncode != 0:
            print(done.stdout[-3000:], done.stderr[-3000:])
            sys.exit(f"the C++ corpus does not build: {' '.join(step)} exited with {done.returncode}")


def check(numlab, entry):
    run = subprocess.run([numlab, "exercise", "check", entry["exercise"], "--format", "json", "--"]
                         + entry["command"], capture_output=True, text=True, timeout=900)
    try:
        results = json.loads(run.stdout)
    except json.JSONDecodeError:
        return {"status": "no JSON", "got": None, "diagnosis": f"exit {run.returncode}: {run.stderr.strip()[:300]}"}
    failing = [test for test in results.get("tests", []) if test["status"] != "pass"]
    first = f"{failing[0]['name']}: {(failing[0].get('message') or '').splitlines()[0:1]}" if failing else ""
    return {"status": results.get("status"), "got": results.get("diagnosis_cause"),
            "diagnosis": results.get("diagnosis") or (f"(no diagnosis) {first}" if failing else "")}


def rate(part, whole):
    return part / whole if whole else 1.0


def table(entries):
    """Per exercise and overall: bugs, caught, diagnosed, harmless files, false failures."""
    rows = {}
    for entry in entries:
        for key in (entry["exercise"], "all"):
            row = rows.setdefault(key, {"bugs": 0, "caught": 0, "diagnosed": 0, "harmless": 0, "false_failures": 0})
            if entry["cause"] in HARMLESS:
                row["harmless"] += 1
                row["false_failures"] += entry["status"] != "pass"
            else:
                row["bugs"] += 1
                row["caught"] += entry["status"] != "pass"
                row["diagnosed"] += entry["got"] == entry["cause"]
    for row in rows.values():
        row["catch_rate"], row["diagnosis_rate"] = rate(row["caught"], row["bugs"]), rate(row["diagnosed"], row["bugs"])
    return rows


def print_table(title, rows):
    """One table of table(): a row per exercise, then "all"."""
    print(f"\n{title + ':':<20}{'caught':>10}{'diagnosed':>12}{'false failures':>17}")
    for name, row in sorted(rows.items(), key=lambda item: (item[0] == "all", item[0])):
        print(f"{name:<20}{row['caught']:>5}/{row['bugs']:<4}{row['diagnosed']:>7}/{row['bugs']:<4}"
              f"{row['false_failures']:>11}/{row['harmless']}")
    whole = rows.get("all")
    if whole:
        print(f"{'':<20}catch rate {whole['catch_rate']:.3f}, diagnosis rate {whole['diagnosis_rate']:.3f}")


def counts(entries, field):
    found = {}
    for entry in entries:
        found[entry[field]] = found.get(entry[field], 0) + 1
    return ", ".join(f"{key} {value}" for key, value in sorted(found.items()))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("numlab")
    parser.add_argument("--prefix", help="numlab installed here (find_package) builds the C++ files")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--min-catch-rate", type=float, default=0.0)
    parser.add_argument("--min-diagnosis-rate", type=float, default=0.0)
    parser.add_argument("--json", help="write the table and every file's verdict here")
    parser.add_argument("--keep", help="write the whole programs here (to run one by hand) and keep them")
    parser.add_argument("--include-pending", action="store_true",
                        help="also measure ../corpus-pending (files left out until the detectors catch them)")
    options = parser.parse_args()
    options.numlab = os.path.abspath(options.numlab)
    options.prefix = options.prefix and os.path.abspath(options.prefix)
    if not os.access(options.numlab, os.X_OK):
        bad_input(f"{options.numlab} is not an executable numlab")
    if options.jobs < 1:
        bad_input("--jobs must be at least 1")
    started = time.monotonic()
    entries = corpus_files(options.include_pending)
    octave = shutil.which("octave-cli")
    work = options.keep or tempfile.mkdtemp(prefix="numlab-corpus-")
    skipped = []
    try:
        runnable = []
        for entry in entries:
            if entry["language"] == "octave" and not octave:
                skipped.append((entry, "octave-cli is not on PATH"))
                continue
            if entry["language"] == "cpp" and not (options.prefix and shutil.which("cmake")):
                skipped.append((entry, "no --prefix (or no cmake) to build it"))
                continue
            entry["program"], entry["stem"] = whole_program(options.numlab, entry, work)
            entry["command"] = {"python": [sys.executable, entry["program"]],
                                "octave": [octave or "octave-cli", "--no-gui", "--quiet", entry["program"]]}.get(
                                    entry["language"], [])
            runnable.append(entry)
        cpp = [entry for entry in runnable if entry["language"] == "cpp"]
        if cpp:
            build_cpp(cpp, options.prefix, work)
        with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
            for entry, verdict in zip(runnable, pool.map(lambda e: check(options.numlab, e), runnable)):
                entry.update(verdict)
    finally:
        if not options.keep:
            shutil.rmtree(work, ignore_errors=True)
    seconds = time.monotonic() - started

    print(f"corpus: {len(entries)} files; by language: {counts(entries, 'language')}; by set: {counts(entries, 'set')}")
    print(f"by cause: {counts(entries, 'cause')}")
    for entry, why in skipped:
        print(f"SKIPPED {entry['file']}: {why}")
    rows = table(runnable)
    print_table("whole corpus", rows)
    sets = {name: table([e for e in runnable if e["set"] == name]) for name in sorted({e["set"] for e in runnable})}
    for name, set_rows in sets.items():
        print_table(f"set {name}", set_rows)
    overall = rows.get("all", {"catch_rate": 1.0, "diagnosis_rate": 1.0, "false_failures": 0})
    print(f"\ncatch rate {overall['catch_rate']:.3f}, diagnosis rate {overall['diagnosis_rate']:.3f}, "
          f"false failures {overall['false_failures']}; {len(runnable)} checked in {seconds:.1f} s")
    misses = [e for e in runnable if (e["status"] != "pass" if e["cause"] in HARMLESS else e["got"] != e["cause"])]
    for entry in misses:
        what = "FALSE FAILURE" if entry["cause"] in HARMLESS else ("NOT CAUGHT" if entry["status"] == "pass" else "misdiagnosed")
        print(f"{what}: {entry['file']} ({entry['language']}, set {entry['set']}): expected {entry['cause']}, got {entry['got']} "
              f"[{entry['status']}]: {entry['diagnosis']}")
    if options.json:
        with open(options.json, "w", encoding="utf-8") as out:
            json.dump({"seconds": seconds, "table": rows, "sets": sets, "skipped": [e["file"] for e, _ in skipped],
                       "files": [{key: e.get(key) for key in ("file", "language", "set", "bug", "cause", "status", "got",
                                                              "diagnosis")} for e in runnable]}, out, indent=1)
    failed = []
    if overall["catch_rate"] < options.min_catch_rate:
        failed.append(f"catch rate {overall['catch_rate']:.3f} below {options.min_catch_rate}")
    if overall["diagnosis_rate"] < options.min_diagnosis_rate:
        failed.append(f"diagnosis rate {overall['diagnosis_rate']:.3f} below {options.min_diagnosis_rate}")
    if overall["false_failures"]:
        failed.append(f"{overall['false_failures']} valid solutions fail")
    if failed:
        sys.exit("FAILED: " + "; ".join(failed))
    if skipped:
        print(f"SKIPPED: {len(skipped)} files not run (above); the rest hold")
        sys.exit(77)


if __name__ == "__main__":
    main()
