#!/usr/bin/env python3
"""Reference solution of `numlab exercise mustang-newton`: full Newton-Raphson on seed 003's Mustang
roof linkage (angles A ... H), from the task's equations, with its trace."""
import json
import sys

import numpy as np

BEND = np.pi / 9.0
R = np.sqrt(0.5)
# Seed 003's lengths |a b| as l_a_b; a request with a variant carries its own as "lengths".
SEED = {"l1_3": 2.0, "l3_4": 2.0, "l2_4": 2.5, "l0_5": 5.0, "l5_6": 4 / 3, "l6_7": 4 / 3, "l6_8": 4.0,
        "l8_9": 1.0, "l7_10": 4.5, "l10_8": 4 / 3, "l10_11": 4 / 3, "l9_11": 1.0}


def closure(theta, v, lengths=SEED):
    A, B, C, D, E, F, G, H = v
    sin, cos = np.sin, np.cos
    l13, l34, l24, l05, l56, l67, l68, l89, l710, l108, l1011, l911 = (lengths[name] for name in SEED)
    CHORD = 2.0 * l24 * np.cos(BEND)  # |2 6|, the seed's 4.698
    f = np.array([
        -l24 * cos(theta) + l13 * cos(A) + l34 * cos(B),
        -1 - l24 * sin(theta) + l13 * sin(A) + l34 * sin(B),
        -R + CHORD * cos(theta + BEND) + l56 * cos(C) - l05 * cos(D),
        1 + R + CHORD * sin(theta + BEND) - l56 * sin(C) - l05 * sin(D),
        l67 * cos(theta + BEND) + l68 * cos(C - BEND) - l710 * cos(E) - l108 * cos(F),
        l67 * sin(theta + BEND) - l68 * sin(C - BEND) + l710 * sin(E) - l108 * sin(F),
        l89 * cos(C + BEND) + l108 * cos(F) - l1011 * cos(G) + l911 * cos(H),
        -l89 * sin(C + BEND) + l108 * sin(F) + l1011 * sin(G) - l911 * sin(H)])
    J = np.zeros((8, 8))
    J[0, 0], J[0, 1] = -l13 * sin(A), -l34 * sin(B)
    J[1, 0], J[1, 1] = l13 * cos(A), l34 * cos(B)
    J[2, 2], J[2, 3] = -l56 * sin(C), l05 * sin(D)
    J[3, 2], J[3, 3] = -l56 * cos(C), -l05 * cos(D)
    J[4, 2], J[4, 4], J[4, 5] = -l68 * sin(C - BEND), l710 * sin(E), l108 * sin(F)
    J[5, 2], J[5, 4], J[5, 5] = -l68 * cos(C - BEND), l710 * cos(E), -l108 * cos(F)
    J[6, 2], J[6, 5], J[6, 6], J[6, 7] = -l89 * sin(C + BEND), -l108 * sin(F), l1011 * sin(G), -l911 * sin(H)
    J[7, 2], J[7, 5], J[7, 6], J[7, 7] = -l89 * cos(C + BEND), l108 * cos(F), l1011 * cos(G), -l911 * cos(H)
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
    theta, lengths = float(request["crank_angle"]), request.get("lengths", SEED)
    angles, status, iterations, trace = newton(lambda v: closure(theta, v, lengths), np.array(request["guess"], dtype=float),
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
