"""The linkage page's embedded numbers against the CLI's CSV, and the page's promises that need no browser.

Usage: test_linkage_page_data.py NUMLAB MODELS_DIR OUT_DIR

For every shipped model (the built-in jansen, jansen10, mustang; each file in MODELS_DIR) and the
four-bar with loads at 60 rpm:
 1. every CSV column is in the page's JSON with the same numbers (equal as doubles; nan/inf as null)
    and the same words (status, branch_kept, statics), pose for pose;
 2. the velocities the page adds to the built-ins (from the files' joint-coordinate models) agree with
    5-point central differences of the CSV's own positions (per radian of crank);
 3. the marks: the Mustang's two assembly limits just outside its first and last pose and its kite's
    change point at 43.15 deg (built-in and file); the isosceles slider-crank's crossings at 90, 270 deg;
 4. self-contained: no URL the page would fetch (no src/href/url() to http, no @import);
    without scripts: the static SVG and a table row per pose;
 5. the Jansen cycle's page is under 2 MB. Prints every page's size;
 6. the loads the page carries are the file's [[load]]s (kind, joint or link, force, a mass's weight
    (0, -m g) with the file's gravity, torque), none for a model without; and at every pose in
    equilibrium, from the page's own numbers, the reactions and loads balance: forces to 1e-9 of
    the sum of their sizes, moments about the origin (with a crank's driver torque, a slider
    driver's force along its line) to 1e-9 of theirs.
"""

import math
import pathlib
import re
import sys

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
from pages import file_loads, make_pages, model_file  # noqa: E402


def same(csv_cell, value):
    """A CSV cell and the JSON's value are the same number (or word)."""
    try:
        number = float(csv_cell)
    except ValueError:
        return value == csv_cell
    if not math.isfinite(number):
        return value is None
    return value is not None and not isinstance(value, str) and float(value) == number


def check_columns(case, data):
    assert data["csv_columns"] == case.header, f"{case.name}: the page's columns are not the CSV's"
    columns = data["columns"]
    compared = 0
    for name in case.header:
        values = columns[name]
        cells = case.column(name)
        assert len(values) == len(cells), f"{case.name}: {name} has {len(values)} values, the CSV {len(cells)}"
        for k, (cell, value) in enumerate(zip(cells, values)):
            assert same(cell, value), f"{case.name}: {name} at pose {k}: CSV {cell}, page {value}"
            compared += 1
    return compared


def check_loads(case, data, models_dir):
    """6. The page's loads against the description file's; returns the number of loads."""
    path = model_file(case, models_dir)
    expected = file_loads(path) if path else []
    names = [joint["name"] for joint in data["joints"]]
    loads = data["loads"]
    assert len(loads) == len(expected), f"{case.name}: the page has {len(loads)} loads, the file {len(expected)}"
    for load, want in zip(loads, expected):
        assert load["kind"] == want[0], (case.name, load, want)
        if want[0] == "torque":
            assert load["link"] == want[1] and load["torque"] == want[2], (case.name, load, want)
            assert len(load["joints"]) >= 2 and all(0 <= j < len(names) for j in load["joints"]), (case.name, load)
        else:
            assert names[load["joint"]] == want[1] and tuple(load["force"]) == want[2], (case.name, load, want)
            assert want[0] != "mass" or load["mass"] == want[3], (case.name, load, want)
    reactions = [c for c in data["csv_columns"] if c.startswith("reaction_")]
    assert bool(reactions) == bool(loads), f"{case.name}: {len(loads)} loads, reaction columns {reactions}"
    return len(loads)


def balance(data, i):
    """Pose i's net force and moment about the origin, from the page's numbers, each over the sum of
    its terms' sizes: the supports' reactions, the loads, and the driver's load where it is external
    (a crank's torque; a slider driver's force along its line; an actuator's or motor's acts between
    members, inside the reactions)."""
    columns, names = data["columns"], [joint["name"] for joint in data["joints"]]
    fx = fy = moment = force_size = moment_size = 0.0

    def add(x, y, at):
        nonlocal fx, fy, moment, force_size, moment_size
        px, py = columns["x_" + at][i], columns["y_" + at][i]
        fx, fy, moment = fx + x, fy + y, moment + px * y - py * x
        force_size += math.hypot(x, y)
        moment_size += math.hypot(px, py) * math.hypot(x, y)
    for name in data["csv_columns"]:
        if name.startswith("reaction_") and name.endswith("_x"):
            support = name[len("reaction_"):-2]
            add(columns[name][i], columns[f"reaction_{support}_y"][i], support)
    for load in data["loads"]:
        if load["kind"] == "torque":
            moment, moment_size = moment + load["torque"], moment_size + abs(load["torque"])
        else:
            add(load["force"][0], load["force"][1], names[load["joint"]])
    driver = data["driver"]
    if driver["kind"] == "crank":
        torque = columns["driver_torque"][i]
        moment, moment_size = moment + torque, moment_size + abs(torque)
    elif driver["kind"] == "slider":
        angle = math.radians(data["sliders"][driver["slider"]]["angle_deg"])
        force = columns["driver_force"][i]
        add(force * math.cos(angle), force * math.sin(angle), names[driver["joint"]])
    return math.hypot(fx, fy) / force_size, abs(moment) / moment_size


def check_balance(case, data):
    """6. Every pose in equilibrium balances (1e-9); returns the poses checked and the worst ratios."""
    poses, worst_force, worst_moment = 0, 0.0, 0.0
    for i, statics in enumerate(data["columns"]["statics"]):
        if statics != "equilibrium":
            continue
        force, moment = balance(data, i)
        assert force <= 1e-9 and moment <= 1e-9, f"{case.name} pose {i}: net force {force:.2e}, moment {moment:.2e} of their terms"
        poses, worst_force, worst_moment = poses + 1, max(worst_force, force), max(worst_moment, moment)
    return poses, worst_force, worst_moment


def check_builtin_velocities(case, data):
    """vx_J, vy_J (per radian) against central differences of x_J, y_J over the 1-degree steps.

    The 5-point stencil errs by h^4/30 times the fifth derivative, the 3-point one by h^2/6 times the
    third, some 100 times more at h = 1 deg: a right velocity is nearer the 5-point value than the
    two stencils are to each other. Each pose is allowed half their largest spread over the poses within
    3 steps (where the third derivative passes zero the spread alone is no measure) plus 1e-6 of the
    motion's scale (rounding: 1e-16 / h). Returns the worst |v - d5| over the scale."""
    columns = data["columns"]
    drivers = [float(d) for d in case.column("crank_deg")]
    step = drivers[1] - drivers[0]
    h = math.radians(step)
    checks = []
    for joint in data["joints"]:
        series = []
        name = joint["name"]
        for axis in ("x", "y"):
            p = [float(x) for x in case.column(f"{axis}_{name}")]
            velocity = columns[f"v{axis}_{name}"]
            for i in range(2, len(p) - 2):
                if abs(drivers[i + 2] - drivers[i - 2] - 4 * step) > 1e-9:
                    continue
                d5 = (-p[i + 2] + 8 * p[i + 1] - 8 * p[i - 1] + p[i - 2]) / (12 * h)
                d3 = (p[i + 1] - p[i - 1]) / (2 * h)
                assert velocity[i] is not None, f"{case.name}: no velocity of {name} at pose {i}"
                series.append((abs(velocity[i] - d5), abs(d3 - d5), f"v{axis}_{name} at pose {i}"))
            for k, (error, _, where) in enumerate(series):
                spread = max(s for _, s, _ in series[max(0, k - 3):k + 4])
                checks.append((error, spread, where))
            series = []
    scale = max(abs(v) for name, column in columns.items() if name.startswith("v") for v in column if v is not None)
    assert scale > 0 and len(checks) > 100, (case.name, scale, len(checks))
    for error, spread, where in checks:
        assert error <= 0.5 * spread + 1e-6 * scale, f"{case.name}: {where}: |v - d5| {error:.3g}, stencils' spread {spread:.3g}"
    return max(error for error, _, _ in checks) / scale


def main(numlab, models_dir, out_dir):
    cases = make_pages(numlab, models_dir, out_dir)
    names = [case.name for case in cases]
    assert {"jansen", "jansen10", "mustang", "four-bar.toml", "jansen.toml", "mustang.toml"} <= set(names), names
    for case in cases:
        data = case.data()
        compared = check_columns(case, data)
        html = case.html()
        # 4. Nothing fetched from anywhere; the page without scripts.
        for pattern in (r'src\s*=\s*"(?!data:)', r'href\s*=\s*"http', r'url\(\s*["\']?http', r'@import', r'<link\b'):
            assert not re.search(pattern, html), f"{case.name}: the page refers to something outside it ({pattern})"
        static = re.search(r'<figure id="static-scene">\s*(.*?)</figure>', html, re.S)
        assert static and "<svg" in static.group(1), f"{case.name}: no static SVG for a reader without scripts"
        table = re.search(r'<table id="pose-table">(.*?)</table>', html, re.S)
        assert table and table.group(1).count("<tr>") == len(case.rows) + 1, f"{case.name}: the table is not a row per pose"
        note = ""
        if check_loads(case, data, models_dir):
            poses, force, moment = check_balance(case, data)
            assert poses > 0, f"{case.name}: no pose in equilibrium"
            note = f", loads the file's; {poses} poses balance (force {force:.1e}, moment {moment:.1e} of their terms)"
        if case.name in ("jansen", "jansen10", "mustang"):
            assert {"vx_F" if "jansen" in case.name else "vx_P12", "condition"} <= set(data["columns"]), case.name
            note += f", velocity vs 5-point difference {check_builtin_velocities(case, data):.1e} of its scale"
        size = case.page.stat().st_size
        print(f"{case.name:28} {len(case.rows):4} poses  {size / 1e6:6.3f} MB  {compared} numbers equal to the CSV's{note}")
        if case.name == "jansen":
            assert len(case.rows) == 360 and size < 2e6, f"jansen: {len(case.rows)} poses, {size} bytes"
    by_name = {case.name: case for case in cases}
    # 3. The marks.
    mustang = by_name["mustang"]
    limits = sorted(m["driver"] for m in mustang.data()["marks"] if m["kind"] == "limit")
    first, last = float(mustang.rows[0][0]), float(mustang.rows[-1][0])
    assert len(limits) == 2 and first - 0.5 <= limits[0] <= first + 1e-9 and last - 1e-9 <= limits[1] <= last + 0.5, (limits, first, last)
    # The kite's change point, 43.15 deg (test_mustang_file.cpp's bisection), lies between two of the
    # built-in's 0.5-deg poses; the file's own sweep puts it there too.
    kite = [m["driver"] for m in mustang.data()["marks"] if m["kind"] == "crossing"]
    assert len(kite) == 1 and abs(kite[0] - 43.15) <= 0.25, kite
    file_kite = [m["driver"] for m in by_name["mustang.toml"].data()["marks"] if m["kind"] == "crossing"]
    assert len(file_kite) == 1 and abs(file_kite[0] - 43.15) <= 0.01, file_kite
    crossings = sorted(m["driver"] for m in by_name["isosceles-slider-crank.toml"].data()["marks"] if m["kind"] == "crossing")
    assert len(crossings) == 2 and abs(crossings[0] - 90) < 1e-3 and abs(crossings[1] - 270) < 1e-3, crossings
    loads = by_name["four-bar-loads"].data()
    assert "driver_torque" in loads["columns"] and abs(loads["speed_rad_s"] - 2 * math.pi) < 1e-12, loads["speed_rad_s"]
    statics = {name: by_name[name].column("statics") for name in ("parallelogram-loads", "hydraulic-boom-past-stroke")}
    assert statics["parallelogram-loads"].count("singular") == 2 and "no_pose" in statics["hydraulic-boom-past-stroke"], statics
    print(f"{len(cases)} pages: numbers equal to the CSV's, marks, self-contained, static fallback, loads the files'")


if __name__ == "__main__":
    main(*sys.argv[1:4])
