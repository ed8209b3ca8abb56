"""A lab's report.html steps through its traced solves in a real browser, and reads without scripts.

Usage: test_lab_report.py OUT_DIR NUMLAB LAB STEPPERS
  LAB: a lab name, or "default" for `numlab` with no arguments (the Jansen lab, in OUT_DIR/out/).
  STEPPERS: how many traced solves the report must let the reader step through.

For each stepper the page embeds (<div class="stepper"> holding its JSON), the test presses the
right arrow, the left arrow, clicks next, previous, last and first, and moves the slider; after each
it checks what the page shows against the embedded trace, computed here on its own: the printed
line (identical to the trace's text), GEPP's event, pivot row, pivot, multipliers and growth so far,
Gauss-Seidel's sweep, iterate and residual, Newton's iteration, ||f||, linear status, inner
iterations, lambda and block. No console error or uncaught exception is allowed. Then: printed
(print media) the steppers are hidden and the static trace shows; with prefers-reduced-motion no
transition runs; with JavaScript off the static tables and the printed trace are all there.
Screenshots of every stepper go to OUT_DIR.
"""

import html
import json
import math
import os
import pathlib
import re
import subprocess
import sys
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from browser import Browser  # noqa: E402

STEPPER = re.compile(r'<div class="stepper" data-kind="([a-z-]+)" data-caption="([^"]*)">\n'
                     r'<script type="application/json">(.*?)</script>', re.S)


def close(shown, expected, digits, what):
    """`shown` (text) is `expected` to `digits` significant digits, as the page rounds it."""
    value = float(shown)
    scale = max(abs(expected), 1e-300)
    assert math.isfinite(value) and abs(value - expected) <= 0.51 * 10 ** (1 - digits) * scale, \
        f"{what}: the page shows {shown}, the trace holds {expected!r}"


def sci(value):
    """C's %.4e, as the printed trace and the page write ||f|| and residuals."""
    return f"{value:.4e}"


def run_lab(out, numlab, lab):
    """Runs the lab and returns its report's path."""
    reports = out / "reports"
    reports.mkdir(parents=True, exist_ok=True)
    command = [numlab] if lab == "default" else [numlab, "lab", lab, "--out", str(reports)]
    started = time.monotonic()
    # The Python running this test imports numpy: first on PATH, for the labs that run Python.
    env = dict(os.environ, PATH=f"{pathlib.Path(sys.executable).parent}:{os.environ.get('PATH', '')}")
    run = subprocess.run(command, cwd=reports, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, timeout=600,
                         env=env)
    name = "jansen" if lab == "default" else lab
    report = reports / ("out" if lab == "default" else "") / f"lab-{name}" / "report.html"
    assert report.exists(), f"numlab {lab} wrote no report (exit {run.returncode}): {run.stderr[-2000:]}"
    print(f"{lab}: lab ran in {time.monotonic() - started:.1f} s (exit {run.returncode}); "
          f"report.html {report.stat().st_size / 1024:.0f} KiB")
    return report


def readouts(page, index):
    """Every [data-role] text of stepper `index`, by role."""
    return page.eval(f"""(() => {{
      const root = document.querySelectorAll('.stepper')[{index}];
      const found = {{}};
      root.querySelectorAll('[data-role]').forEach((e) => {{ found[e.dataset.role] = e.textContent; }});
      found.pivotCell = [...root.querySelectorAll('td.pivot')].map((e) => e.textContent);
      found.touched = [...root.querySelectorAll('.stepper-matrix tr')].map((r, i) => r.classList.contains('touched') ? i : -1).filter((i) => i >= 0);
      found.multipliers = [...root.querySelectorAll('td.multiplier')].map((e) => e.textContent);
      found.points = (root.querySelector('.stepper-curve') || {{getAttribute: () => ''}}).getAttribute('points').trim().split(/\\s+/).length;
      found.current = [...root.querySelectorAll('.block.current')].map((e) => e.textContent);
      return found;
    }})()""")


def check_gepp(data, k, shown):
    record = data["trace"][k]
    column = record["column"]
    assert shown["event"] == record["event"].replace("_", " "), (shown["event"], record["event"])
    assert shown["column"] == str(column)
    states = [data["start"]] + [r["augmented"] for r in data["trace"][:k + 1] if "augmented" in r]
    before = ([data["start"]] + [r["augmented"] for r in data["trace"][:k] if "augmented" in r])[-1]
    after = states[-1]
    if record["event"] == "row_swap":
        assert shown["pivot-row"] == str(record["swapped_with_row"])
        close(shown["pivot"], record["pivot"], 6, "pivot")
        assert sorted(shown["touched"]) == sorted({column - 1, record["swapped_with_row"] - 1})
    elif record["event"] == "elimination":
        assert shown["pivot-row"] == str(column)
        close(shown["pivot"], record["pivot"], 6, "pivot")
        close(shown["pivotCell"][0], after[column - 1][column - 1], 6, "the highlighted pivot cell")
        rows_below = list(range(column, len(after)))
        assert shown["touched"] == rows_below, (shown["touched"], rows_below)
        multipliers = [m for m in shown["multipliers"] if m]
        assert len(multipliers) == len(rows_below)
        for text, i in zip(multipliers, rows_below):
            close(text.split("=")[1], before[i][column - 1] / record["pivot"], 6, f"multiplier l_{i + 1}{column}")
    else:
        close(shown["value"], record["value"], 6, f"x{column}")
    # Growth so far: max |a_ij| over the current upper triangle over max |a_ij| of A.
    scale = max(abs(v) for row in data["start"] for v in row[:-1])
    largest = max(abs(v) for r, row in enumerate(after) for v in row[r:-1])
    close(shown["growth"], largest / scale, 6, "growth factor so far")


def check_sweeps(data, k, shown):
    record = data["trace"][k]
    assert shown["sweep"] == str(record["sweep"])
    assert shown["residual"] == sci(record["residual_inf"]) and shown["residual"] in shown["line"]
    assert shown["step"] == sci(record["step_inf"]) and shown["step"] in shown["line"]
    if "x" in record:
        values = shown["x"].split()
        assert len(values) == len(record["x"])
        for text, value in zip(values, record["x"]):
            close(text, value, 6, "iterate")
    assert shown["points"] == k + 1, f"the residual history shows {shown['points']} sweeps at sweep {k + 1}"


def check_newton(data, k, shown):
    record = data["trace"][k]
    assert shown["iteration"] == str(record["iteration"])
    assert shown["fnorm"] == sci(record["residual_inf"]) and shown["fnorm"] in shown["line"]
    assert shown["step"] == sci(record["step_inf"])
    assert shown["status"] == record.get("linear_status", "-")
    assert shown["inner"] == str(record.get("linear_iterations", "-"))
    close(shown["lambda"].split()[0], record["damping"], 6, "lambda")
    assert ("damped" in shown["lambda"]) == (record["damping"] < 1)
    if "block" in record:
        assert shown["block"] == str(record["block"]) and shown["current"] == [f"block {record['block']}"]
    assert shown["points"] == k + 1


def check_closed_form(data, k, shown):
    record, first = data["trace"][k], data["trace"][0]
    assert shown["event"] == record["event"]
    close(shown["det"], first["determinant"], 6, "det A")
    close(shown["kappa"], first["condition_number"], 6, "kappa_2(A)")
    if record["event"] == "solution":
        values = shown["x"].split()
        assert len(values) == 2
        for text, value in zip(values, record["x"]):
            close(text, value, 6, "x")
    # det A is a d - b c of the matrix shown first, computed here.
    (a, b, _), (c, d, _) = first["augmented"]
    assert abs(first["determinant"] - (a * d - b * c)) <= 1e-15 * max(abs(a * d), abs(b * c))


CHECKS = {"gepp": check_gepp, "sweeps": check_sweeps, "newton": check_newton, "closed-form": check_closed_form}


def check_step(page, index, kind, data, k):
    shown = readouts(page, index)
    count = len(data["trace"])
    assert shown["position"] == f"step {k + 1} of {count}", (shown["position"], k + 1)
    assert shown["line"] == data["lines"][k], f"printed line {shown['line']!r} != trace text {data['lines'][k]!r}"
    assert shown["header"] == data["header"].rstrip("\n")
    CHECKS[kind](data, k, shown)


def step_through(page, index, kind, data, out, lab):
    """Keys, buttons and the slider on stepper `index`, checking the page after each."""
    sel = f"document.querySelectorAll('.stepper')[{index}]"
    count = len(data["trace"])
    page.eval(f"{sel}.id = 'stepper-under-test'; {sel}.scrollIntoView({{block: 'start'}})")
    check_step(page, index, kind, data, 0)
    expected = 0

    def act(action, target):
        nonlocal expected
        action()
        expected = target
        check_step(page, index, kind, data, expected)

    root = "#stepper-under-test"
    act(lambda: page.press("ArrowRight", root), min(1, count - 1))
    act(lambda: page.press("ArrowRight", root), min(2, count - 1))
    act(lambda: page.press("ArrowLeft", root), max(expected - 1, 0))
    if count > 1:
        act(lambda: page.click(f"{root} [data-action=next]"), min(expected + 1, count - 1))
        act(lambda: page.click(f"{root} [data-action=previous]"), expected - 1)
        act(lambda: page.click(f"{root} [data-action=last]"), count - 1)
        page.eval(f"document.querySelector('{root}').scrollIntoView({{block: 'start'}})")
        page.screenshot(f"{lab}-stepper{index + 1}-last.png")
        act(lambda: page.press("Home", root), 0)
        act(lambda: page.press("End", root), count - 1)
        act(lambda: page.click(f"{root} [data-action=first]"), 0)
        assert page.eval(f"document.querySelector('{root} [data-action=previous]').disabled")
    middle = count // 2
    act(lambda: page.set_range(f"{root} input[type=range]", middle), middle)
    if count - 1 - middle >= 3:
        # Play advances one step each 0.7 s, and pauses on a second press where it is (before the end).
        page.click(f"{root} [data-action=play]")
        time.sleep(1.6)
        page.click(f"{root} [data-action=play]")
        now = int(page.eval(f"document.querySelector('{root}').dataset.step"))
        assert middle < now <= min(middle + 3, count - 1), f"play moved from step {middle + 1} to {now + 1}"
        assert page.eval(f"document.querySelector('{root} [data-action=play]').getAttribute('aria-label')") == "Play"
        check_step(page, index, kind, data, now)
        act(lambda: page.set_range(f"{root} input[type=range]", middle), middle)
    page.eval(f"document.querySelector('{root}').scrollIntoView({{block: 'start'}})")
    page.screenshot(f"{lab}-stepper{index + 1}-middle.png")
    # Every control is a labelled button or slider (keyboard and screen readers).
    labels = page.eval(f"[...document.querySelectorAll('{root} button, {root} input')].map((e) => e.getAttribute('aria-label'))")
    assert len(labels) == 6 and all(labels), labels
    page.eval(f"document.querySelector('{root}').removeAttribute('id')")


def main(out_dir, numlab, lab, steppers):
    out = pathlib.Path(out_dir)
    started = time.monotonic()
    report = run_lab(out, numlab, lab)
    text = report.read_text()
    embedded = [(kind, html.unescape(caption), json.loads(data)) for kind, caption, data in STEPPER.findall(text)]
    assert len(embedded) == steppers, f"{lab}: {len(embedded)} steppers embedded, expected {steppers}"
    name = "numlab" if lab == "default" else lab
    with Browser(out) as browser:
        # 1. Scripts on: each stepper steps, and shows what its trace holds.
        page = browser.open(report)
        page.check_no_errors()
        assert page.eval("document.querySelectorAll('.stepper.stepper-ready').length") == steppers
        for index, (kind, caption, data) in enumerate(embedded):
            assert data["trace"] and len(data["lines"]) == len(data["trace"]), caption
            step_through(page, index, kind, data, out, name)
        page.check_no_errors()

        # 2. Printed: no controls, the static trace instead; reduced motion: no transitions.
        printed = browser.open(report, media="print", reduced_motion="reduce")
        if steppers:
            assert printed.eval("[...document.querySelectorAll('.stepper')].every((e) => getComputedStyle(e).display === 'none')")
            durations = printed.eval("[...document.querySelectorAll('.stepper-matrix td')].map((e) => getComputedStyle(e).transitionDuration)")
            assert all(d == "0s" for d in durations), durations
        printed.screenshot(f"{name}-print.png")
        printed.check_no_errors()

        # 3. Scripts off: today's static report, every table and the printed trace of every solve.
        static = browser.open(report, scripts=False)
        assert static.eval("document.querySelectorAll('.stepper-ready, .stepper-controls').length") == 0
        tables = text.count("<table>")
        assert static.eval("document.querySelectorAll('table').length") == tables
        pre = static.eval("[...document.querySelectorAll('pre')].map((e) => e.textContent).join('\\n')")
        for kind, caption, data in embedded:
            if kind != "sweeps":  # the Seidel lab prints a shortened table of its own
                for line in data["lines"]:
                    assert line in pre, f"{caption}: the static report lacks the printed line {line!r}"
        assert static.eval("[...document.querySelectorAll('.stepper')].every((e) => getComputedStyle(e).display === 'none')")
        static.eval("window.scrollTo(0, 0)")
        static.screenshot(f"{name}-no-scripts.png")
    print(f"{lab}: {steppers} steppers checked step by step, print and no-script views; "
          f"{time.monotonic() - started:.1f} s in all")


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]))
