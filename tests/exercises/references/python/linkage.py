#!/usr/bin/env python3
"""Reference solution of `numlab exercise linkage --model FILE|NAME`: any linkage, generic.

It reads the model every request carries (`model`: joints, unknowns, driver, equations in row
order; TASK.md), writes f and J of the closure in the joint coordinates, and sweeps the driver by
its own Newton-Raphson from the pose before, with the velocity from J qdot = -dPhi/dt. numpy only."""
import json
import math
import sys

import numpy as np


def perp(v):
    return np.array([-v[1], v[0]])


class Linkage:
    def __init__(self, model):
        self.equations = model["equations"]
        self.crank = model["driver"]["type"] in ("crank", "motor")  # an angle in degrees
        self.fixed = {}  # ground joint -> position
        self.column = {}  # moving joint -> column of its x
        for joint in model["joints"]:
            if joint["ground"]:
                self.fixed[joint["name"]] = np.array(joint["position"], dtype=float)
            else:
                self.column[joint["name"]] = 2 * len(self.column)
        self.n = 2 * len(self.column)
        self.m = sum(equation["rows"] for equation in self.equations)

    def t(self, driver):
        """The driver in the equations' units: radians for a crank (the request gives degrees)."""
        return math.radians(driver) if self.crank else driver

    def p(self, q, name):
        if name in self.fixed:
            return self.fixed[name]
        k = self.column[name]
        return q[k:k + 2]

    def put(self, J, rows, name, block):
        """d(rows)/d(joint name's x, y) += block (nothing for a ground joint)."""
        if name in self.column:
            k = self.column[name]
            J[rows, k:k + 2] += block

    def closure(self, q, t):
        f = np.zeros(self.m)
        J = np.zeros((self.m, self.n))
        row = 0
        for e in self.equations:
            names = e["joints"]
            if e["kind"] == "distance":
                L = e["length"]
                d = self.p(q, names[0]) - self.p(q, names[1])
                f[row] = (d @ d - L * L) / (2 * L)
                self.put(J, slice(row, row + 1), names[0], (d / L)[None, :])
                self.put(J, slice(row, row + 1), names[1], (-d / L)[None, :])
            elif e["kind"] == "body_point":
                a, b = e["coefficients"]
                base = self.p(q, names[1]) - self.p(q, names[0])
                f[row:row + 2] = self.p(q, names[2]) - self.p(q, names[0]) - a * base - b * perp(base)
                # d/d base of -(a base + b perp(base)) = -(a I + b R), R = d perp / d v
                R = np.array([[0.0, -1.0], [1.0, 0.0]])
                M = a * np.eye(2) + b * R
                rows = slice(row, row + 2)
                self.put(J, rows, names[2], np.eye(2))
                self.put(J, rows, names[0], -np.eye(2) + M)
                self.put(J, rows, names[1], -M)
            elif e["kind"] == "slider_line":
                u, P = np.array(e["direction"]), np.array(e["point"])
                offset = self.p(q, names[0]) - P
                f[row] = u[0] * offset[1] - u[1] * offset[0]
                self.put(J, slice(row, row + 1), names[0], np.array([[-u[1], u[0]]]))
            elif e["kind"] == "crank":
                r, angle = e["length"], t + e["offset"]
                f[row:row + 2] = self.p(q, names[1]) - self.p(q, names[0]) - r * np.array([math.cos(angle), math.sin(angle)])
                self.put(J, slice(row, row + 2), names[1], np.eye(2))
                self.put(J, slice(row, row + 2), names[0], -np.eye(2))
            elif e["kind"] == "slider_travel":
                u, P = np.array(e["direction"]), np.array(e["point"])
                f[row] = u @ (self.p(q, names[0]) - P) - t
                self.put(J, slice(row, row + 1), names[0], u[None, :])
            elif e["kind"] == "slider_on_line":
                # A in the slot along B -> C: (d x r)/|d| - offset, d = C - B, r = A - B
                A, B, C = (self.p(q, name) for name in names)
                d, r = C - B, A - B
                L, side = math.hypot(*d), d[0] * r[1] - d[1] * r[0]
                f[row] = side / L - e["offset"]
                dA = perp(d) / L
                dC = -perp(r) / L - side * d / L**3
                for name, g in ((names[0], dA), (names[1], -dA - dC), (names[2], dC)):
                    self.put(J, slice(row, row + 1), name, g[None, :])
            elif e["kind"] == "actuator":
                d = self.p(q, names[0]) - self.p(q, names[1])
                f[row] = math.hypot(*d) - t
                self.put(J, slice(row, row + 1), names[0], (d / math.hypot(*d))[None, :])
                self.put(J, slice(row, row + 1), names[1], (-d / math.hypot(*d))[None, :])
            elif e["kind"] == "motor":
                # l sin(phi - t), phi the angle from u = B - A to v = C - A
                A, B, C = (self.p(q, name) for name in names)
                u, v, l = B - A, C - A, e["length"]
                psi = math.atan2(u[0] * v[1] - u[1] * v[0], u @ v) - t
                f[row] = l * math.sin(psi)
                gB = -l * math.cos(psi) * perp(u) / (u @ u)
                gC = l * math.cos(psi) * perp(v) / (v @ v)
                for name, g in ((names[0], -gB - gC), (names[1], gB), (names[2], gC)):
                    self.put(J, slice(row, row + 1), name, g[None, :])
            else:
                raise ValueError(f"unknown equation kind {e['kind']}")
            row += e["rows"]
        return f, J

    def phi_t(self, t):
        """dPhi/dt: only the driver's rows depend on t."""
        g = np.zeros(self.m)
        row = 0
        for e in self.equations:
            if e["kind"] == "actuator":
                g[row] = -1.0
            elif e["kind"] == "motor":  # a motor's depends on the pose too: the one Newton solved last
                A, B, C = (self.p(self.solved, name) for name in e["joints"])
                u, v = B - A, C - A
                g[row] = -e["length"] * math.cos(math.atan2(u[0] * v[1] - u[1] * v[0], u @ v) - t)
            if e["kind"] == "crank":
                angle = t + e["offset"]
                g[row:row + 2] = e["length"] * np.array([math.sin(angle), -math.cos(angle)])
            elif e["kind"] == "slider_travel":
                g[row] = -1.0
            row += e["rows"]
        return g

    def newton(self, q, t, tolerance, max_iterations):
        for _ in range(max_iterations + 1):
            f, J = self.closure(q, t)
            if np.max(np.abs(f)) <= tolerance:
                self.solved = q
                return q, J
            q = q + np.linalg.solve(J, -f)
        raise RuntimeError(f"Newton did not converge at t = {t} in {max_iterations} iterations")


def solve(request):
    linkage = Linkage(request["model"])
    if request["task"] == "closure":
        f, J = linkage.closure(np.array(request["q"], dtype=float), linkage.t(request["driver"]))
        return {"f": f, "J": J}
    q = np.array(request["q0"], dtype=float)
    positions, velocities = [], []
    for driver in request["drivers"]:
        t = linkage.t(driver)
        q, J = linkage.newton(q, t, request["tolerance"], request["max_iterations"])
        positions.append(q.tolist())
        velocities.append(np.linalg.solve(J, -linkage.phi_t(t)).tolist())
    return {"positions": positions, "velocities": velocities}


def to_json(value):
    if isinstance(value, np.ndarray):
        return value.tolist()
    if isinstance(value, np.generic):
        return value.item()
    raise TypeError(f"cannot send a {type(value).__name__} as JSON")


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = dict(solve(request))
            reply["id"] = request.get("id")
            text = json.dumps(reply, default=to_json)
        except Exception as error:
            text = json.dumps({"id": request.get("id"), "error": f"{type(error).__name__}: {error}"})
        print(text, flush=True)


if __name__ == "__main__":
    main()
