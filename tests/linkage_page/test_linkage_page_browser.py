"""The linkage page in headless Chromium, for every shipped model (tests/browser/browser.py drives it).

Usage: test_linkage_page_browser.py OUT_DIR NUMLAB MODELS_DIR

For each page (pages.py: the built-in jansen, jansen10, mustang, every file in MODELS_DIR, the
four-bar with loads at 60 rpm):
 0. at every pose that assembled, the joints' names by their boxes (getBBox): no two overlap, none
    covers a joint's circle, each inside the frame and within 12 units of its joint's circle;
 1. the slider scrubbed to poses across the sweep (first, thirds, last, and a pose that did not
    assemble if any): the readout's joint coordinates, velocities, driver value and status equal
    the CSV row's (the full value in data-value exactly, the text to its 8 digits), and the drawn
    joint circles stand at the CSV's x, -y;
 2. the keys on the slider (ArrowRight, Home, End), the buttons (previous, first, next) and the
    page's own keys on no control (ArrowRight, End, ArrowLeft) move one pose, or to the ends;
 3. no console error or uncaught exception; a screenshot per page (OUT_DIR/NAME.png);
 4. a model with loads (whitworth, inverted-slider-crank, hydraulic-boom, the four-bar with loads,
    the parallelogram with a mass, the boom past its stroke), at poses across the sweep and every
    pose not in equilibrium: each reaction arrow starts at its support and its vector (SVG ends
    times the page's newtons per unit) is the CSV's reaction_S_x, _y (to 1e-12 of the largest force);
    none where statics is not `equilibrium`, and a sentence naming the status; each load arrow is
    the file's force (a mass's weight) at its joint, a torque's arc turns its way; the readout's
    reactions and |F|; the reactions, the loads (and a crank's torque) balance in force and moment
    from the page's numbers (1e-9); the checkbox hides and shows them (a click, then Space); the
    stated scale and largest force. A model without loads has no force control at all.
Then on particular pages: the Jansen cycle's frame time over 200 slider moves (median under 16 ms:
the input event handled, style and layout done), the page with scripts off (the static SVG and the
table of 360 rows), printed (no controls), with reduced motion (Play's rate says so); Play at the
real crank speed of --speed 60rpm; the Mustang's limit and kite-crossing marks take the slider there.
Last, the pages the labs jansen and mustang write beside their report (leg.html, mustang.html):
they open without errors, their readout shows their own embedded numbers, and their names keep
apart at every pose as in 0.
"""

import json
import math
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
sys.path.insert(0, str(HERE.parent / "browser"))
from browser import Browser  # noqa: E402
from pages import file_loads, make_pages, model_file  # noqa: E402


def shown_cells(page):
    """Every readout cell with a column: {column: (text, data-value)}."""
    return page.eval("Object.fromEntries([...document.querySelectorAll('#readout [data-col]')]"
                     ".map(e => [e.getAttribute('data-col'), [e.textContent, e.getAttribute('data-value')]]))")


def last_digit(text):
    """Half a unit in the last digit the text shows (e.g. 0.005 for '12.34', 5e-9 for '1.5e-8')."""
    mantissa, _, exponent = text.lower().partition("e")
    decimals = len(mantissa.partition(".")[2])
    return 0.5 * 10.0 ** (-decimals + (int(exponent) if exponent else 0)) * (1 + 1e-9)


def check_pose(page, case, i):
    """The readout and the drawing at pose i against the CSV's row i."""
    assert page.eval("numlabLinkage.shown()") == i, (case.name, i, page.eval("numlabLinkage.shown()"))
    row = dict(zip(case.header, case.rows[i]))
    cells = shown_cells(page)
    checked = 0
    for column, (text, value) in cells.items():
        if column not in row:
            continue  # a column the page adds (the built-ins' velocities): checked against differences elsewhere
        cell = row[column]
        try:
            number = float(cell)
        except ValueError:
            assert text == cell and value == cell, f"{case.name} pose {i}: {column} shows {text!r}, the CSV {cell!r}"
            checked += 1
            continue
        if not math.isfinite(number):
            assert value == "", f"{case.name} pose {i}: {column} is {cell} in the CSV, {value!r} on the page"
        else:
            assert float(value) == number, f"{case.name} pose {i}: {column} data-value {value}, the CSV {cell}"
            assert abs(float(text) - number) <= last_digit(text), f"{case.name} pose {i}: {column} shows {text}, the CSV {cell}"
        checked += 1
    joints = [c[2:] for c in case.header if c.startswith("x_")]
    assert all(f"x_{j}" in cells and f"y_{j}" in cells for j in joints), f"{case.name}: a joint missing from the readout"
    if row.get("status") == "converged":
        drawn = page.eval("Object.fromEntries([...document.querySelectorAll('#scene circle.joint')]"
                          ".map(c => [c.getAttribute('data-joint'), [+c.getAttribute('cx'), +c.getAttribute('cy')]]))")
        for j in joints:
            x, y = float(row[f"x_{j}"]), float(row[f"y_{j}"])
            assert drawn[j][0] == x and drawn[j][1] == -y, f"{case.name} pose {i}: {j} drawn at {drawn[j]}, the CSV ({x}, {y})"
    return checked


def scrub(page, case):
    n = len(case.rows)
    statuses = case.column("status")
    poses = {0, n // 3, n // 2, 2 * n // 3, n - 1}
    failed = [k for k, s in enumerate(statuses) if s != "converged"]
    if failed:
        poses.add(failed[len(failed) // 2])
    checked = 0
    for i in sorted(poses):
        page.set_range("#pose-slider", i)
        checked += check_pose(page, case, i)
        if statuses[i] != "converged":
            assert "not assembled" in page.text("#scene-pose"), page.text("#scene-pose")
    # Keys on the slider, then the buttons.
    page.set_range("#pose-slider", n // 2)
    page.press("ArrowRight", "#pose-slider")
    checked += check_pose(page, case, n // 2 + 1)
    page.press("Home", "#pose-slider")
    checked += check_pose(page, case, 0)
    page.press("End", "#pose-slider")
    checked += check_pose(page, case, n - 1)
    page.click("#pose-previous")
    checked += check_pose(page, case, n - 2)
    page.click("#pose-first")
    checked += check_pose(page, case, 0)
    page.click("#pose-next")
    checked += check_pose(page, case, 1)
    page.eval("document.activeElement.blur()")  # the page's own keys, on no control
    page.press("ArrowRight")
    checked += check_pose(page, case, 2)
    page.press("End")
    checked += check_pose(page, case, n - 1)
    page.press("ArrowLeft")
    checked += check_pose(page, case, n - 2)
    return checked


FORCES = """(() => {
  const g = document.getElementById('forces');
  const line = e => ['x1', 'y1', 'x2', 'y2'].map(a => +e.getAttribute(a));
  const shown = e => getComputedStyle(e).display !== 'none';
  return {
    layer: shown(g), npu: +g.getAttribute('data-newtons-per-unit'), note: document.getElementById('force-note').textContent,
    reactions: Object.fromEntries([...g.querySelectorAll('line.reaction')].map(e => [e.getAttribute('data-support'), [shown(e), line(e)]])),
    loads: [...g.querySelectorAll('.load, .torque-load')].map(e => [+e.getAttribute('data-load'), e.getAttribute('class'),
      e.tagName === 'line' ? line(e) : e.getAttribute('d'), e.getAttribute('data-torque')]),
    magnitudes: [...document.querySelectorAll('#reaction-table tbody tr')].map(r =>
      [r.querySelector('td').getAttribute('data-col'), r.querySelector('td.magnitude').getAttribute('data-value')]),
    values: Object.fromEntries([...document.querySelectorAll('#readout [data-col]')].map(e => [e.getAttribute('data-col'), e.getAttribute('data-value')]))
  };
})()"""


def check_forces(page, case, models_dir):
    """4. The force arrows and the reactions' readout at poses across the sweep; the checkbox. Returns
    the arrows checked and the worst imbalance (force, moment) over their terms' sizes."""
    n = len(case.rows)
    statics = case.column("statics")
    supports = [c[len("reaction_"):-2] for c in case.header if c.startswith("reaction_") and c.endswith("_x")]
    expected = file_loads(model_file(case, models_dir))
    data = page.eval("numlabLinkage.data")
    names = [joint["name"] for joint in data["joints"]]
    largest = max([math.hypot(*load[2]) for load in expected if load[0] != "torque"] +
                  [math.hypot(float(row[case.header.index(f"reaction_{s}_x")]), float(row[case.header.index(f"reaction_{s}_y")]))
                   for row, st in zip(case.rows, statics) if st == "equilibrium" for s in supports])
    text = page.text("#force-scale")
    stated = [float(v) for v in text.split("stands for ")[1].split(" N")[:1] + text.split("the largest force of the sweep, ")[1].split(" N")[:1]]
    found = page.eval(FORCES)
    assert found["layer"] and found["npu"] > 0 and abs(stated[0] - found["npu"]) <= 1e-5 * found["npu"], (case.name, text, found["npu"])
    assert abs(stated[1] - largest) <= 1e-5 * largest, (case.name, text, largest)
    poses = {0, n // 3, n // 2, 2 * n // 3, n - 1} | {i for i, st in enumerate(statics) if st != "equilibrium"}
    arrows, worst = 0, [0.0, 0.0]
    for i in sorted(poses):
        page.set_range("#pose-slider", i)
        check_pose(page, case, i)
        found = page.eval(FORCES)
        row = dict(zip(case.header, case.rows[i]))
        npu, tol = found["npu"], 1e-12 * largest
        assert set(found["reactions"]) == set(supports), (case.name, found["reactions"].keys(), supports)
        if statics[i] != "equilibrium":
            assert not any(shown for shown, _ in found["reactions"].values()), f"{case.name} pose {i}: a reaction drawn at {statics[i]}"
            assert statics[i] in found["note"] and "No reactions" in found["note"], (case.name, i, found["note"])
        else:
            assert found["note"] == "", (case.name, i, found["note"])
            force = [0.0, 0.0]
            for s in supports:
                shown, (x1, y1, x2, y2) = found["reactions"][s]
                rx, ry = float(row[f"reaction_{s}_x"]), float(row[f"reaction_{s}_y"])
                assert shown == (math.hypot(rx, ry) > 0), (case.name, i, s)
                assert (x1, y1) == (float(row[f"x_{s}"]), -float(row[f"y_{s}"])), f"{case.name} pose {i}: {s}'s reaction starts at {x1, y1}"
                vx, vy = (x2 - x1) * npu, -(y2 - y1) * npu
                assert abs(vx - rx) <= tol and abs(vy - ry) <= tol, f"{case.name} pose {i}: {s}'s arrow is ({vx}, {vy}) N, the CSV ({rx}, {ry})"
                arrows += 1
        assert len(found["loads"]) == len(expected), (case.name, found["loads"], expected)
        drawn_at = i if row["status"] == "converged" else None
        for (k, kind, shape, torque), want in zip(found["loads"], expected):
            if want[0] == "torque":
                assert kind == "torque-load" and float(torque) == want[2], (case.name, kind, torque, want)
                flags = shape.split(" A ")[1].split()
                assert flags[3:5] == ["1", "0" if want[2] >= 0 else "1"], f"{case.name}: the torque's arc {shape} for {want[2]}"
                continue
            x1, y1, x2, y2 = shape
            vx, vy = (x2 - x1) * npu, -(y2 - y1) * npu
            assert kind == "load" and abs(vx - want[2][0]) <= tol and abs(vy - want[2][1]) <= tol, (case.name, i, kind, (vx, vy), want)
            if drawn_at is not None:
                assert (x1, y1) == (float(row[f"x_{want[1]}"]), -float(row[f"y_{want[1]}"])), (case.name, i, want, x1, y1)
            arrows += 1
        # The readout's |F| and the balance from the page's numbers (its readout, its loads).
        for column, magnitude in found["magnitudes"]:
            s = column[len("reaction_"):-2]
            rx, ry = float(row[f"reaction_{s}_x"]), float(row[f"reaction_{s}_y"])
            if not (math.isfinite(rx) and math.isfinite(ry)):
                assert magnitude == "", (case.name, i, s, magnitude)
            else:  # the browser's Math.hypot and Python's may differ in the last bit
                assert abs(float(magnitude) - math.hypot(rx, ry)) <= 4e-16 * math.hypot(rx, ry), (case.name, i, s, magnitude)
        if statics[i] == "equilibrium":
            values = {c: float(v) for c, v in found["values"].items() if v not in ("", None) and c != "status" and c != "statics"
                      and c != "branch_kept"}
            fx = fy = moment = fsize = msize = 0.0
            terms = [(values[f"reaction_{s}_x"], values[f"reaction_{s}_y"], s) for s in supports]
            terms += [(want[2][0], want[2][1], want[1]) for want in expected if want[0] != "torque"]
            for x, y, at in terms:
                px, py = values[f"x_{at}"], values[f"y_{at}"]
                fx, fy, moment = fx + x, fy + y, moment + px * y - py * x
                fsize, msize = fsize + math.hypot(x, y), msize + math.hypot(px, py) * math.hypot(x, y)
            for want in expected:
                if want[0] == "torque":
                    moment, msize = moment + want[2], msize + abs(want[2])
            if data["driver"]["kind"] == "crank":
                moment, msize = moment + values["driver_torque"], msize + abs(values["driver_torque"])
            elif data["driver"]["kind"] == "slider":
                angle = math.radians(data["sliders"][data["driver"]["slider"]]["angle_deg"])
                x, y, at = values["driver_force"] * math.cos(angle), values["driver_force"] * math.sin(angle), names[data["driver"]["joint"]]
                fx, fy, moment = fx + x, fy + y, moment + values[f"x_{at}"] * y - values[f"y_{at}"] * x
                fsize, msize = fsize + abs(values["driver_force"]), msize + math.hypot(values[f"x_{at}"], values[f"y_{at}"]) * abs(values["driver_force"])
            imbalance = [math.hypot(fx, fy) / fsize, abs(moment) / msize]
            assert imbalance[0] <= 1e-9 and imbalance[1] <= 1e-9, f"{case.name} pose {i}: the page's forces do not balance: {imbalance}"
            worst = [max(worst[0], imbalance[0]), max(worst[1], imbalance[1])]
    # The checkbox: a click hides the forces (the names placed again), Space on it shows them.
    page.click("#show-forces")
    assert page.eval("getComputedStyle(document.getElementById('forces')).display") == "none", case.name
    assert not page.eval("document.getElementById('show-forces').checked"), case.name
    page.press(" ", "#show-forces")
    assert page.eval("getComputedStyle(document.getElementById('forces')).display") != "none", case.name
    assert page.eval("document.getElementById('show-forces').checked"), case.name
    return arrows, worst


# Every pose of the page (the slider's every value that assembled): each joint's name, by its box
# (getBBox, in the drawing's units), against every other name's box, every joint's circle (its radius
# plus half its stroke), the frame (the SVG's viewBox) and its own joint. What the page script's
# label placement promises (labs/linkage_page/label_placement.js).
LABEL_BOXES = """(() => {
  const svg = document.getElementById('scene'), frame = svg.viewBox.baseVal;
  const u = +getComputedStyle(svg).getPropertyValue('--u');
  const names = [...svg.querySelectorAll('g.names text')], circles = [...svg.querySelectorAll('circle.joint')];
  const n = +document.getElementById('pose-slider').max + 1;
  const result = {poses: 0, names: names.length, u: u, pairs: [], circles: [], outside: [], far: [], farthest: 0, bad: []};
  for (let i = 0; i < n; ++i) {
    numlabLinkage.show(i);
    if (svg.classList.contains('stale')) continue;
    result.poses++;
    const boxes = names.map(t => t.getBBox());
    const discs = circles.map(c => [+c.getAttribute('cx'), +c.getAttribute('cy'), +c.getAttribute('r') + 0.5 * +c.getAttribute('stroke-width')]);
    boxes.forEach((p, a) => {
      if (![p.x, p.y, p.width, p.height].every(Number.isFinite) || !(p.width > 0 && p.height > 0)) result.bad.push([i, names[a].textContent]);
      for (let b = a + 1; b < boxes.length; ++b) {
        const q = boxes[b];
        const wide = Math.min(p.x + p.width, q.x + q.width) - Math.max(p.x, q.x);
        const high = Math.min(p.y + p.height, q.y + q.height) - Math.max(p.y, q.y);
        if (wide > 0 && high > 0) result.pairs.push([i, names[a].textContent, names[b].textContent, wide / u, high / u]);
      }
      discs.forEach((d, j) => {
        const gap = Math.hypot(Math.max(p.x - d[0], 0, d[0] - p.x - p.width), Math.max(p.y - d[1], 0, d[1] - p.y - p.height)) - d[2];
        if (!(gap >= 0)) result.circles.push([i, names[a].textContent, circles[j].getAttribute('data-joint'), gap / u]);
        if (j === a) {
          result.farthest = Math.max(result.farthest, gap / u);
          if (!(gap <= 12 * u)) result.far.push([i, names[a].textContent, gap / u]);
        }
      });
      if (!(p.x >= frame.x && p.y >= frame.y && p.x + p.width <= frame.x + frame.width && p.y + p.height <= frame.y + frame.height)) {
        result.outside.push([i, names[a].textContent]);
      }
    });
  }
  return result;
})()"""


def check_labels(page, name):
    """No two names overlap at any assembled pose, none covers a joint's circle, each stays in the frame
    and within 12 units (12% of the frame's larger side) of its joint's circle. Returns the number of
    poses checked and the farthest name's gap from its joint's circle (in units)."""
    found = page.eval(LABEL_BOXES)
    data = page.eval("(d => [d.columns[d.driver_column], d.columns.status, d.joints.length])(numlabLinkage.data)")
    drivers, statuses, joints = data
    assembled = sum(1 for s in statuses if s == "converged")
    assert found["poses"] == assembled > 0 and found["names"] == joints > 0, (name, found["poses"], assembled, found["names"])
    assert found["u"] > 0 and not found["bad"], (name, found["u"], found["bad"][:5])

    def at(entries):  # the first few, with the driver value of their pose
        return [[drivers[e[0]]] + [round(v, 2) if isinstance(v, float) else v for v in e[1:]] for e in entries[:6]]
    assert not found["pairs"], (f"{name}: names overlap at {len(set(e[0] for e in found['pairs']))} poses "
                                f"(driver, name, name, overlap wide and high in units): {at(found['pairs'])}")
    assert not found["circles"], f"{name}: a name on a joint's circle at {len(found['circles'])} (pose, name): {at(found['circles'])}"
    assert not found["outside"], f"{name}: a name outside the frame: {at(found['outside'])}"
    assert not found["far"], f"{name}: a name over 12 units from its joint: {at(found['far'])}"
    return found["poses"], found["farthest"]


FRAME_TIME = """(async () => {
  const slider = document.getElementById('pose-slider'), scene = document.getElementById('scene');
  const n = +slider.max + 1, work = [], frames = [];
  for (let k = 0; k < 200; ++k) {
    const t0 = performance.now();
    slider.value = String((k * 7 + 1) % n);
    slider.dispatchEvent(new Event('input', {bubbles: true}));
    scene.getBoundingClientRect();
    document.body.offsetHeight;  // style and layout now, as the frame would
    const t1 = performance.now();
    await new Promise(done => requestAnimationFrame(() => done()));
    work.push(t1 - t0);
    frames.push(performance.now() - t0);
  }
  const median = a => { const s = a.slice().sort((x, y) => x - y); return (s[99] + s[100]) / 2; };
  const p95 = a => a.slice().sort((x, y) => x - y)[189];
  return {moves: work.length, median_ms: median(work), p95_ms: p95(work), max_ms: Math.max(...work),
          median_to_next_frame_ms: median(frames)};
})()"""


def sleep_js(ms):
    return f"new Promise(done => setTimeout(done, {ms}))"


def main(out_dir, numlab, models_dir):
    out = pathlib.Path(out_dir)
    cases = make_pages(numlab, models_dir, out / "pages")
    by_name = {case.name: case for case in cases}
    total = 0
    force_pages, force_arrows, imbalance = [], 0, [0.0, 0.0]
    label_poses, farthest = 0, 0.0
    with Browser(out, width=1300, height=1000) as browser:
        for case in cases:
            page = browser.open(case.page)
            assert page.eval("getComputedStyle(document.getElementById('static-scene')).display") == "none", case.name
            poses, far = check_labels(page, case.name)
            assert poses == case.column("status").count("converged"), (case.name, poses)
            label_poses, farthest = label_poses + poses, max(farthest, far)
            total += scrub(page, case)
            if "statics" in case.header:
                arrows, worst = check_forces(page, case, models_dir)
                force_pages.append(case.name)
                force_arrows, imbalance = force_arrows + arrows, [max(a, b) for a, b in zip(imbalance, worst)]
            else:
                assert not any(page.exists(s) for s in ("#show-forces", "#force-scale", "#reaction-table", "#forces *")), \
                    f"{case.name}: force controls on a model without loads"
            page.set_range("#pose-slider", len(case.rows) // 3)
            page.eval("window.scrollTo(0, 0)")
            page.screenshot(case.page.stem + ".png")
            page.check_no_errors()
        # Where names overlapped before they were placed per pose (whitworth.toml's A over B from crank
        # 28 deg, the Mustang's P1 over P11 at -41 deg, mustang.toml's P9 over P11 at 24 deg): screenshots.
        for name, driver in (("whitworth.toml", 30), ("mustang", -41), ("mustang.toml", 24)):
            case = by_name[name]
            pose = [float(v) for v in case.column(case.header[0])].index(driver)
            page = browser.open(case.page)
            page.set_range("#pose-slider", pose)
            page.eval("document.getElementById('scene').scrollIntoView()")
            page.screenshot(f"names-{case.page.stem}-at-{driver}.png")
            page.check_no_errors()
        # The forces at two poses of whitworth.toml (crank 30 and 200 deg) and hydraulic-boom.toml (its
        # 11th and 101st pose): screenshots of the scene and the readout.
        for name, poses in (("whitworth.toml", (30, 200)), ("hydraulic-boom.toml", (10, 100))):
            case = by_name[name]
            page = browser.open(case.page)
            for pose in poses:
                page.set_range("#pose-slider", pose)
                page.eval("document.getElementById('scene').scrollIntoView()")
                page.screenshot(f"forces-{case.page.stem}-at-{case.rows[pose][0]}.png")
            page.check_no_errors()
        # The Jansen cycle: frame time, scripts off, print, reduced motion.
        jansen = by_name["jansen"]
        page = browser.open(jansen.page)
        timing = page.eval(FRAME_TIME)
        (out / "frame_time.json").write_text(json.dumps(timing, indent=2) + "\n")
        print(f"jansen, 360 poses: {timing['moves']} slider moves, update + style + layout median "
              f"{timing['median_ms']:.2f} ms, 95th percentile {timing['p95_ms']:.2f} ms, max {timing['max_ms']:.2f} ms; "
              f"to the next frame median {timing['median_to_next_frame_ms']:.2f} ms")
        assert timing["median_ms"] < 16, timing
        page.check_no_errors()
        page = browser.open(jansen.page, scripts=False)
        assert page.eval("getComputedStyle(document.getElementById('static-scene')).display") != "none"
        assert page.exists("#static-scene svg") and not page.exists("#pose-slider")
        assert page.eval("document.querySelectorAll('#pose-table tbody tr').length") == 360
        page.screenshot("jansen-no-scripts.png")
        page = browser.open(jansen.page, media="print")
        assert page.eval("getComputedStyle(document.querySelector('.controls')).display") == "none"
        assert page.eval("getComputedStyle(document.getElementById('scene')).display") != "none"
        page.screenshot("jansen-print.png")
        page.check_no_errors()
        page = browser.open(jansen.page, reduced_motion="reduce")
        assert "reduced motion" in page.text("#play-rate"), page.text("#play-rate")
        page.check_no_errors()
        # Play at --speed 60rpm: 360 deg/s, 1-degree poses: about 90 poses in 250 ms.
        loads = by_name["four-bar-loads"]
        page = browser.open(loads.page)
        assert "6.28319 rad/s (60 rpm)" in page.text("#play-rate"), page.text("#play-rate")
        assert "driver_torque" in shown_cells(page)
        page.click("#pose-first")
        moved = page.eval("(async () => { document.getElementById('pose-play').click(); const t0 = performance.now();"
                          f" await {sleep_js(250)}; document.getElementById('pose-play').click();"
                          " return [numlabLinkage.shown(), performance.now() - t0]; })()")
        expected = 360 * moved[1] / 1000
        assert 0.5 * expected <= moved[0] <= 1.5 * expected + 2, (moved, expected)
        print(f"play at 60 rpm: {moved[0]} poses in {moved[1]:.0f} ms (the crank's speed gives {expected:.0f})")
        page.check_no_errors()
        # The Mustang's limits: two marks; each "go to" shows the pose nearest the limit.
        mustang = by_name["mustang"]
        page = browser.open(mustang.page)
        assert page.eval("document.querySelectorAll('.marks .tick.limit').length") == 2
        page.click("#mark-list li.limit:first-child button")
        assert page.eval("numlabLinkage.shown()") == 0
        page.click("#mark-list li.limit:nth-child(2) button")
        assert page.eval("numlabLinkage.shown()") == len(mustang.rows) - 1
        page.eval("window.scrollTo(0, 0)")
        page.screenshot("mustang-at-upper-limit.png")
        assert page.eval("document.querySelectorAll('.marks .tick.crossing').length") == 1
        page.click("#mark-list li.crossing button")
        assert abs(float(mustang.rows[page.eval("numlabLinkage.shown()")][0]) - 43.15) <= 0.5
        page.eval("window.scrollTo(0, 0)")
        page.screenshot("mustang-at-kite-crossing.png")
        page.check_no_errors()
        # The labs' pages.
        for lab, name in (("jansen", "leg.html"), ("mustang", "mustang.html")):
            folder = out / "labs"
            run = subprocess.run([numlab, "lab", lab, "--out", str(folder)], capture_output=True, text=True)
            assert run.returncode == 0, f"lab {lab}: exit {run.returncode}: {run.stderr}"
            path = folder / f"lab-{lab}" / name
            assert name in (folder / f"lab-{lab}" / "report.html").read_text(), f"lab {lab}: the report does not name {name}"
            page = browser.open(path)
            data = page.eval("numlabLinkage.data.columns")
            for i in (0, len(data["crank_deg"]) // 2, len(data["crank_deg"]) - 1):
                page.set_range("#pose-slider", i)
                cells = shown_cells(page)
                joint = "F" if lab == "jansen" else "P12"
                for column in ("crank_deg", f"x_{joint}", f"vx_{joint}", "condition"):
                    assert data[column][i] is not None and float(cells[column][1]) == data[column][i], \
                        (lab, column, i, cells[column], data[column][i])
            poses, far = check_labels(page, f"lab {lab} {name}")
            label_poses, farthest = label_poses + poses, max(farthest, far)
            page.eval("window.scrollTo(0, 0)")
            page.screenshot(f"lab-{lab}-{name}.png")
            page.check_no_errors()
    assert {"whitworth.toml", "inverted-slider-crank.toml", "hydraulic-boom.toml", "four-bar-loads", "parallelogram-loads",
            "hydraulic-boom-past-stroke"} <= set(force_pages), force_pages
    print(f"forces on {len(force_pages)} pages: {force_arrows} arrows equal to the CSV's reactions and the files' loads; "
          f"the page's numbers balance to {imbalance[0]:.1e} (force) and {imbalance[1]:.1e} (moment) of their terms")
    print(f"{len(cases)} pages scrubbed in Chromium: {total} shown numbers and words equal to the CSV's, no page errors")
    print(f"joint names at {label_poses} assembled poses: no two overlap, none on a joint's circle, all in the frame, "
          f"the farthest {farthest:.1f} units from its joint")


if __name__ == "__main__":
    main(*sys.argv[1:4])
