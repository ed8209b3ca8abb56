#!/usr/bin/env python3
# BUG: seed 003's rounded 4.698 for the chord |2 6| and 6.032 - 4.698 = 1.334 for |6 7| = 4/3
# EXPECT-CHECK: closed-form pose across
# EXPECT-MESSAGE: differs from the closed form
"""Reference solution of `numlab exercise mustang-newton`: full Newton-Raphson on seed 003's Mustang
roof linkage (angles A ... H), from the task's equations, with its trace."""
import json
import sys

import numpy as np

BEND = np.pi / 9.0
R = np.sqrt(0.5)
T = 4.0 / 3.0
CHORD = 4.698  # |2 6|, the seed's 4.698


def closure(theta, v):
    A, B, C, D, E, F, G, H = v
    sin, cos = np.sin, np.cos
    f = np.array([
        -2.5 * cos(theta) + 2 * cos(A) + 2 * cos(B),
        -1 - 2.5 * sin(theta) + 2 * sin(A) + 2 * sin(B),
        -R + CHORD * cos(theta + BEND) + T * cos(C) - 5 * cos(D),
        1 + R + CHORD * sin(theta + BEND) - T * sin(C) - 5 * sin(D),
        1.334 * cos(theta + BEND) + 4 * cos(C - BEND) - 4.5 * cos(E) - T * cos(F),
        1.334 * sin(theta + BEND) - 4 * sin(C - BEND) + 4.5 * sin(E) - T * sin(F),
        cos(C + BEND) + T * cos(F) - T * cos(G) + cos(H),
        -sin(C + BEND) + T * sin(F) + T * sin(G) - sin(H)])
    J = np.zeros((8, 8))
    J[0, 0], J[0, 1] = -2 * sin(A), -2 * sin(B)
    J[1, 0], J[1, 1] = 2 * cos(A), 2 * cos(B)
    J[2, 2], J[2, 3] = -T * sin(C), 5 * sin(D)
    J[3, 2], J[3, 3] = -T * cos(C), -5 * cos(D)
    J[4, 2], J[4, 4], J[4, 5] = -4 * sin(C - BEND), 4.5 * sin(E), T * sin(F)
    J[5, 2], J[5, 4], J[5, 5] = -4 * cos(C - BEND), 4.5 * cos(E), -T * cos(F)
    J[6, 2], J[6, 5], J[6, 6], J[6, 7] = -sin(C + BEND), -T * sin(F), T * sin(G), -sin(H)
    J[7, 2], J[7, 5], J[7, 6], J[7, 7] = -cos(C + BEND), T * cos(F), T * cos(G), -cos(H)
    return f, J


def newton(evaluate, x, tolerance, max_iterations):
    """Full Newton-Raphson: stop when max |f_i| <= tolerance; else J dx = -f, x <- x + dx."""
    trace = []
    f, J = evaluate(x)
    status, iterations = "max_iterations", 0
    while True:
        if np.max(np.abs(f)) <= tolerance:
            status = "converged"
            break
        if iterations >= max_iterations:
            break
        try:
            dx = np.linalg.solve(J, -f)
        except np.linalg.LinAlgError:
            status = "singular"
            break
        x = x + dx
        iterations += 1
        f, J = evaluate(x)
        trace.append({"residual_inf": float(np.max(np.abs(f))), "step_inf": float(np.max(np.abs(dx)))})
        if not np.all(np.isfinite(f)):
            status = "diverged"
            break
    return x, status, iterations, trace


def solve(request):
    theta = float(request["crank_angle"])
    angles, status, iterations, trace = newton(lambda v: closure(theta, v), np.array(request["guess"], dtype=float),
                                               float(request["tolerance"]), int(request["max_iterations"]))
    return {"angles": angles.tolist(), "status": status, "iterations": iterations, "trace": trace}


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = solve(request)
        except Exception as error:
            reply = {"error": str(error)}
        reply["id"] = request.get("id")
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
