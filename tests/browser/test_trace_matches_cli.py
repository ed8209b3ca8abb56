"""The traces a lab report embeds for its steppers are the CLI's own: page and terminal cannot disagree.

Usage: test_trace_matches_cli.py OUT_DIR NUMLAB
Runs labs gauss, seidel, inverse2x2 and newton, takes each embedded stepper's JSON, runs the same solve with
`numlab solve ... --trace --format json` and `--trace` (text), and checks that the embedded "trace"
equals the CLI's "trace" record for record (every number bit for bit; only Newton's time_s, a
clock reading, is left out) and that the embedded "header" and "lines" are the text --trace prints
(Newton's time column masked). The 3x3 system lab gauss traces is written to a --matrix file.
"""

import json
import pathlib
import re
import subprocess
import sys

STEPPER = re.compile(r'<div class="stepper" data-kind="([a-z-]+)" data-caption="[^"]*">\n'
                     r'<script type="application/json">(.*?)</script>', re.S)


def embedded(numlab, out, lab):
    subprocess.run([numlab, "lab", lab, "--out", str(out)], check=True, stdout=subprocess.DEVNULL, timeout=300)
    text = (out / f"lab-{lab}" / "report.html").read_text()
    return [json.loads(data) for kind, data in STEPPER.findall(text)]


def cli(numlab, arguments):
    """The CLI's JSON trace and its --trace text (stderr) for one solve."""
    as_json = subprocess.run([numlab, *arguments, "--trace", "--format", "json"], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, timeout=120)
    as_text = subprocess.run([numlab, *arguments, "--trace"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                             text=True, timeout=120)
    return json.loads(as_json.stdout)["trace"], as_text.stderr


def without_time(records):
    return [{key: value for key, value in record.items() if key != "time_s"} for record in records]


def mask_time(text):
    """Newton's printed lines with the time column (the 8th number after k) blanked."""
    return re.sub(r"\d\.\d{3}e[+-]\d\d(\s*)$", r"TIME\1", text, flags=re.M)


def compare(name, page, arguments, numlab, newton=False):
    trace, text = cli(numlab, arguments)
    page_text = page["header"] + "".join(line + "\n" for line in page["lines"])
    if newton:
        assert without_time(page["trace"]) == without_time(trace), f"{name}: the embedded trace differs from the CLI's"
        assert mask_time(page_text) == mask_time(text), f"{name}: printed lines differ:\n{page_text}\n---\n{text}"
    else:
        assert page["trace"] == trace, f"{name}: the embedded trace differs from the CLI's"
        assert page_text == text, f"{name}: printed lines differ:\n{page_text}\n---\n{text}"
    print(f"{name}: {len(trace)} records equal to `numlab {' '.join(arguments)} --trace [--format json]`")


def main(out_dir, numlab):
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    # 1. Lab gauss: GEPP on its 3x3 system, given to the CLI as an augmented matrix file.
    (gepp,) = embedded(numlab, out, "gauss")
    matrix = out / "gauss-3x3.txt"
    matrix.write_text("".join(" ".join(repr(v) for v in row) + "\n" for row in gepp["start"]))
    compare("lab gauss, step 1", gepp, ["solve", "linear", "--method", "gepp", "--matrix", str(matrix)], numlab)

    # 2. Lab seidel: its three traced runs.
    dominant, plain, normal = embedded(numlab, out, "seidel")
    compare("lab seidel, diagonally dominant", dominant,
            ["solve", "linear", "--method", "gauss-seidel-plain", "--generate", "diag-dominant:5", "--max-iter", "100"], numlab)
    compare("lab seidel, diverging", plain,
            ["solve", "linear", "--method", "gauss-seidel-plain", "--generate", "gs-diverge:3", "--max-iter", "100"], numlab)
    compare("lab seidel, normal equations", normal,
            ["solve", "linear", "--method", "gauss-seidel", "--generate", "gs-diverge:3", "--max-iter", "1000"], numlab)

    # 3. Lab inverse2x2: the closed form on A = [4 3; 6 3], b = A (1, 1), as an augmented matrix file.
    (closed,) = embedded(numlab, out, "inverse2x2")
    matrix = out / "inverse2x2.txt"
    matrix.write_text("".join(" ".join(repr(v) for v in row) + "\n" for row in closed["trace"][0]["augmented"]))
    compare("lab inverse2x2, step 1", closed, ["solve", "linear", "--method", "inverse2x2", "--matrix", str(matrix)], numlab)

    # 4. Lab newton: Rosenbrock from its standard start, tolerance 1e-10, at most 100 iterations.
    rosenbrock = embedded(numlab, out, "newton")[0]
    compare("lab newton, Rosenbrock", rosenbrock,
            ["solve", "nonlinear", "--problem", "rosenbrock", "--method", "newton", "--tol", "1e-10", "--max-iter", "100"],
            numlab, newton=True)


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
