"""The linkage pages the tests make: every shipped model (the built-in jansen, jansen10 and mustang,
and each file in mechanisms/models) over a sweep, plus the four-bar with loads and a crank speed.

    for case in make_pages(numlab, models_dir, out_dir): case.name, case.page, case.csv_rows, ...

Each case runs `numlab mechanism NAME --sweep S --html PAGE` and, separately, the same solve with
`--format csv`: the CSV is the reference the page's numbers are checked against.
"""

import csv
import io
import json
import pathlib
import re
import subprocess

# docs/linkage-files.md's complete example of loads: the shipped four-bar with one load of each kind.
FOUR_BAR_LOADS = """[linkage]
name = "four-bar-loads"
title = "Grashof crank-rocker four-bar with loads"

[ground]
O = [0.0, 0.0]
Q = [4.5, 0.0]

[joints]
A = [0.75, 1.3]
B = [4.0, 3.5]

[[link]]
joints = ["O", "A"]
length = 1.5

[[link]]
joints = ["A", "B"]
length = 4.0

[[link]]
name = "rocker"
joints = ["Q", "B"]
length = 3.5

[driver]
type = "crank"
pivot = "O"
joint = "A"
angle = 60.0

[[load]]
link = "rocker"
torque = -10.0

[[load]]
joint = "B"
mass = 2.0

[[load]]
joint = "A"
force = [3.0, -4.0]
"""

PARALLELOGRAM_LOAD = """
[[load]]
joint = "B"
mass = 1.0
"""


def model_file(case, models_dir):
    """The description file of a page's model, or None for a built-in (jansen, jansen10, mustang)."""
    mechanism = case.args[2]
    if mechanism.endswith(".toml"):
        path = pathlib.Path(mechanism)
        return path if path.is_absolute() else pathlib.Path(models_dir) / mechanism
    path = pathlib.Path(models_dir) / (mechanism + ".toml")
    return path if case.name not in ("jansen", "jansen10", "mustang") and path.is_file() else None


def file_loads(path):
    """The loads of a description file as the page should carry them: (kind, joint name or link name,
    force (Fx, Fy) in N or torque), a mass's force its weight (0, -m g) with the file's gravity."""
    import tomllib
    model = tomllib.loads(path.read_text())
    gravity = model.get("linkage", {}).get("gravity", 9.80665)
    loads = []
    for load in model.get("load", []):
        if "torque" in load:
            loads.append(("torque", load["link"], load["torque"]))
        elif "mass" in load:
            loads.append(("mass", load["joint"], (0.0, -load["mass"] * gravity), load["mass"]))
        else:
            loads.append(("force", load["joint"], tuple(load["force"])))
    return loads


class Case:
    def __init__(self, name, args, page, csv_text, exit_code):
        self.name, self.args, self.page, self.exit_code = name, args, page, exit_code
        reader = csv.reader(io.StringIO(csv_text))
        self.header = next(reader)
        self.rows = [row for row in reader if row]

    def column(self, name):
        k = self.header.index(name)
        return [row[k] for row in self.rows]

    def html(self):
        return self.page.read_text(encoding="utf-8")

    def data(self):
        """The JSON embedded in the page (<script type="application/json" id="linkage-data">)."""
        match = re.search(r'<script type="application/json" id="linkage-data">(.*?)</script>', self.html(), re.S)
        assert match, f"{self.name}: no embedded linkage-data"
        return json.loads(match.group(1))


def driver_sweep(toml):
    """A crank's whole turn, 0:359:1; for another driver (slider, actuator) 121 poses within 30% of the
    file's reference value (the [driver]'s travel or length; +-1 about a reference of 0)."""
    driver = toml.read_text().split("[driver]", 1)[1].split("\n[", 1)[0]
    kind = re.search(r'^type\s*=\s*"(\w+)"', driver, re.M)
    if kind is None or kind.group(1) in ("crank", "motor"):
        return "0:359:1"
    value = re.search(r"^(?:travel|length)\s*=\s*([-+0-9.eE]+)", driver, re.M)
    reference = float(value.group(1)) if value else 0.0
    half = 0.3 * abs(reference) or 1.0
    return f"{reference - half:.6g}:{reference + half:.6g}:{2 * half / 120:.6g}"


def sweeps(models_dir):
    """(name, mechanism argument, extra arguments) for every shipped model."""
    cases = [("jansen", "jansen", ["--sweep", "0:359:1"]),
             ("jansen10", "jansen10", ["--sweep", "0:359:1"]),
             ("mustang", "mustang", ["--sweep", "-90:90:0.5"])]
    for toml in sorted(pathlib.Path(models_dir).glob("*.toml")):
        # jansen and mustang name the built-ins: their files go by their file names
        name = toml.stem if toml.stem not in ("jansen", "mustang") else toml.name
        cases.append((toml.name, name, ["--sweep", driver_sweep(toml)]))
    return cases


def make_pages(numlab, models_dir, out_dir):
    out = pathlib.Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    loads = out / "four-bar-loads.toml"
    loads.write_text(FOUR_BAR_LOADS)
    # The statics where they are not in equilibrium: the parallelogram with a mass at B is singular at
    # its change points (0 and 180 deg); the boom past its stroke does not assemble (no_pose).
    parallelogram = out / "parallelogram-loads.toml"
    parallelogram.write_text((pathlib.Path(models_dir) / "parallelogram.toml").read_text() + PARALLELOGRAM_LOAD)
    todo = sweeps(models_dir) + [("four-bar-loads", str(loads), ["--sweep", "0:359:1", "--speed", "60rpm"]),
                                 ("parallelogram-loads", str(parallelogram), ["--sweep", "0:359:1"]),
                                 ("hydraulic-boom-past-stroke", "hydraulic-boom", ["--sweep", "0.4:3.2:0.1"])]
    cases = []
    for name, mechanism, extra in todo:
        page = out / (name.replace(".toml", "") + ("-file" if name.endswith(".toml") else "") + ".html")
        args = [numlab, "mechanism", mechanism] + extra
        made = subprocess.run(args + ["--html", str(page)], capture_output=True, text=True)
        table = subprocess.run(args + ["--format", "csv"], capture_output=True, text=True)
        assert made.returncode in (0, 1), f"{name}: exit {made.returncode}: {made.stderr}"
        assert made.returncode == table.returncode, f"{name}: --html exit {made.returncode}, --format csv {table.returncode}"
        assert page.is_file(), f"{name}: no page written"
        cases.append(Case(name, args, page, table.stdout, made.returncode))
    return cases
