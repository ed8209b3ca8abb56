#!/usr/bin/env python3
"""trace.html in a real browser (headless Chromium, tests/browser/browser.py):

  browser_trace_page.py OUT_DIR NUMLAB MUTANT     (MUTANT: gepp/no_pivoting, ...)

The shipped mutant is checked with --out; its trace.html is opened from file://. With scripts on the
stepper shows at step 1; the test walks every step with the right arrow key and checks, at each, the
position line, the current row of the table, and every number of the side-by-side table against
results.json's "trace" (as JavaScript prints a double: it reads back exactly); the left arrow,
Home, End, the buttons and the slider move it too. At the parting step (reached by the slider and by
"Where they part") the current row is the one marked parting, the sentence shown is results.json's,
the parting cell is marked, and for GEPP numlab's pivot row and the student's are marked among the
candidates. No console error or uncaught exception. With prefers-reduced-motion the table does not
scroll smoothly; printed, the stepper is hidden; with scripts off the stepper stays hidden and the
static table shows every step with the parting row marked. Screenshots go to OUT_DIR.
"""

import json
import os
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent.parent / "browser"))
sys.path.insert(0, str(HERE.parent))
from apply_mutant import make_mutant  # noqa: E402
from browser import Browser, find_chromium  # noqa: E402


def cells(page):
    """The side-by-side table of the current step: [label, yours, numlab's] per row."""
    return page.eval("Array.from(document.querySelectorAll('#step-table tbody tr'))"
                     ".map(r => Array.from(r.children).map(c => c.textContent))")


def expected_rows(trace, k):
    """What the side-by-side table must hold at step k (0-based), from results.json."""
    names = {"pivot_row": "pivot row", "residual_inf": "||f||_inf", "step_inf": "||dx||_inf"}
    yours = trace["yours"][k] if k < len(trace["yours"]) else {}
    numlab = trace["numlab"][k] if k < len(trace["numlab"]) else {}
    rows = []
    for field in trace["fields"]:
        a, b = yours.get(field), numlab.get(field)
        if isinstance(a, list) or isinstance(b, list):
            count = max(len(a) if isinstance(a, list) else 0, len(b) if isinstance(b, list) else 0)
            for i in range(count):
                rows.append((f"{field}[{i}]", a[i] if isinstance(a, list) and i < len(a) else None,
                             b[i] if isinstance(b, list) and i < len(b) else None))
        else:
            rows.append((names.get(field, field), a, b))
    return rows


def same(shown, value, what):
    if value is None:
        assert shown == "\u2014", f"{what}: the page shows {shown!r} where the trace has nothing"
    else:
        assert float(shown) == float(value), f"{what}: the page shows {shown}, results.json holds {value!r}"


def check_step(page, trace, k, steps):
    assert page.eval("document.getElementById('stepper').dataset.step") == str(k + 1)
    position = page.text("#position")
    assert position.startswith(f"Step {k + 1} of {steps} ({trace['step_name']} {k + trace['first_number']})"), position
    assert page.eval("document.querySelector('#trace-table tr.current').id") == f"step-{k + 1}"
    assert page.eval("document.querySelectorAll('#trace-table tr.current').length") == 1
    shown = cells(page)
    expected = expected_rows(trace, k)
    assert len(shown) == len(expected), f"step {k + 1}: {len(shown)} rows shown, {len(expected)} in the trace"
    for (label, mine, theirs), (name, a, b) in zip(shown, expected):
        assert label == name, f"step {k + 1}: row {label!r}, expected {name!r}"
        same(mine, a, f"step {k + 1} {name} (yours)")
        same(theirs, b, f"step {k + 1} {name} (numlab's)")
    # Newton's ||f|| (Gauss-Seidel's update) drawn for both traces up to this step.
    plotted = next((f for f in ("residual_inf", "update_inf") if f in trace["fields"]), None)
    if plotted:
        for side in ("yours", "numlab"):
            drawn = page.eval(f"document.querySelector('#trace-plot polyline.plot-{side}').dataset.points")
            expected = sum(1 for step in trace[side][:k + 1] if isinstance(step.get(plotted), (int, float)) and step[plotted] > 0)
            assert drawn == str(expected), f"step {k + 1}: {drawn} points of {side} drawn, {expected} expected"


def main(out_dir, numlab, mutant):
    if find_chromium() is None:
        print("SKIP: no chromium on PATH (apt-get install chromium)")
        sys.exit(77)
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    exercise, name = mutant.split("/")
    solution = out / f"{exercise}-{name}.py"
    make_mutant(str(HERE.parent / "mutants" / f"{mutant}.patch"), str(solution))
    verdict = out / f"{exercise}-{name}"
    subprocess.run([numlab, "exercise", "check", exercise, "--out", str(verdict), "--", sys.executable, str(solution)],
                   capture_output=True, text=True, timeout=600)
    results = json.load(open(verdict / "results.json", encoding="utf-8"))
    trace = next(test["trace"] for test in results["tests"] if "trace" in test)
    steps = max(len(trace["yours"]), len(trace["numlab"]))
    parting = trace["parting"]
    page_path = verdict / "trace.html"
    shot = f"{exercise}-{name}"

    with Browser(out) as browser:
        # 1. Scripts on: the stepper at step 1, every step by the right arrow, back by the left.
        page = browser.open(page_path)
        assert page.eval("document.getElementById('stepper').hidden") is False
        check_step(page, trace, 0, steps)
        for k in range(1, steps):
            page.press("ArrowRight")
            check_step(page, trace, k, steps)
        page.press("ArrowRight")  # past the last step: stays
        check_step(page, trace, steps - 1, steps)
        page.screenshot(f"{shot}-last.png")
        page.press("ArrowLeft")
        check_step(page, trace, steps - 2, steps)
        page.press("Home")
        check_step(page, trace, 0, steps)
        assert page.eval("document.getElementById('previous').disabled") is True
        page.press("End")
        check_step(page, trace, steps - 1, steps)
        page.click("#first")
        check_step(page, trace, 0, steps)
        page.click("#next")
        check_step(page, trace, min(1, steps - 1), steps)
        page.click("#last")
        check_step(page, trace, steps - 1, steps)
        page.click("#previous")
        check_step(page, trace, max(steps - 2, 0), steps)

        # 2. The parting step, by the slider and by its button: the marked row, the sentence.
        page.set_range("#slider", parting + 1)
        check_step(page, trace, parting, steps)
        page.click("#last")
        page.click("#to-parting")
        check_step(page, trace, parting, steps)
        current = page.eval("document.querySelector('#trace-table tr.current').className")
        assert "parting" in current.split(), f"the current row at the parting step is '{current}'"
        assert page.text("#step-sentence") == trace["sentence"], page.text("#step-sentence")
        assert trace["sentence"] in page.text("#parting-sentence")
        if trace["parting_field"]:
            marked = page.eval("Array.from(document.querySelectorAll('#step-table td.differs')).length")
            assert marked == 1, f"{marked} cells marked as parting in the side-by-side table"
        if exercise == "gepp":
            numlab_row = trace["numlab"][parting]["pivot_row"]
            your_row = trace["yours"][parting]["pivot_row"]
            assert "numlab's pivot" in page.text(f"#candidate-{numlab_row}")
            assert "your pivot" in page.text(f"#candidate-{your_row}")
            # numlab's multipliers: each other row's a_ik over numlab's pivot, none for the pivot row
            pivot = trace["numlab"][parting]["pivot"]
            context = trace["context"][parting]
            for j, a in enumerate(context["candidates"]):
                row = context["first_row"] + j
                shown = page.text(f"#candidate-{row} td.multiplier")
                if row == numlab_row:
                    assert shown == "\u2014", f"row {row}: a multiplier {shown} for numlab's pivot row"
                else:
                    assert abs(float(shown) - a / pivot) <= 1e-15 * abs(a / pivot), f"row {row}: l = {shown}, a/pivot = {a / pivot}"
        page.check_no_errors()

        # 3. Reduced motion: no smooth scrolling (without the preference, smooth); the parting step's
        # row scrolled to at once, in view in the table when the screenshot is taken.
        assert page.eval("getComputedStyle(document.getElementById('trace-table')).scrollBehavior") == "smooth"
        calm = browser.open(page_path, reduced_motion="reduce")
        assert calm.eval("getComputedStyle(document.getElementById('trace-table')).scrollBehavior") == "auto"
        calm.click("#last")
        calm.click("#to-parting")
        check_step(calm, trace, parting, steps)
        assert calm.eval("(t => { const r = document.querySelector('#trace-table tr.current');"
                         " return r.offsetTop >= t.scrollTop && r.offsetTop + r.offsetHeight <= t.scrollTop + t.clientHeight; })"
                         "(document.getElementById('trace-table'))"), "the parting row is not scrolled into the table's view"
        calm.screenshot(f"{shot}-parting.png", full_page=True)
        calm.check_no_errors()

        # 4. Printed: the stepper hidden, the table whole.
        printed = browser.open(page_path, media="print")
        assert printed.eval("getComputedStyle(document.getElementById('stepper')).display") == "none"
        printed.check_no_errors()

        # 5. Scripts off: no stepper, the static table with every step and the parting row marked.
        static = browser.open(page_path, scripts=False)
        assert static.eval("getComputedStyle(document.getElementById('stepper')).display") == "none"
        assert static.eval("document.querySelectorAll('#trace-table tbody tr').length") == steps
        assert static.eval("document.querySelector('#trace-table tr.parting').id") == f"step-{parting + 1}"
        assert static.eval("document.querySelectorAll('#trace-table tr.current').length") == 0
        assert trace["sentence"] in static.text("#parting-sentence")
        static.screenshot(f"{shot}-no-scripts.png", full_page=True)
        static.check_no_errors()
    print(f"{mutant}: {steps} steps walked, parting at step {parting + 1}: {trace['sentence']}")


if __name__ == "__main__":
    main(*sys.argv[1:])
