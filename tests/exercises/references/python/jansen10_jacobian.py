#!/usr/bin/env python3
"""Reference solution of `numlab exercise jansen10-jacobian`: seed 001's 10-equation Jansen closure
f and its Jacobian J, from the task's equations."""
import json
import sys

import numpy as np

LI, A_OFFSET, B_OFFSET = 15.0, 7.8, 38.0
# |r3| ... |r12|: the lengths of the links whose directions are theta3 ... theta12.
R3, R4, R5, R6, R7, R8, R9, R10, R11, R12 = 50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49.0, 65.7
LENGTHS = [R3, R4, R5, R6, R7, R8, R9, R10, R11, R12]
# Each loop: whether it starts with P1->A, and its (angle index, sign) terms. Row 2p is the loop's
# x component (cosines), row 2p + 1 its y component (sines).
LOOPS = [(True, [(0, 1), (1, 1)]),
         (False, [(1, -1), (2, 1), (3, 1)]),
         (False, [(3, 1), (4, -1), (5, 1), (6, -1)]),
         (True, [(5, -1), (7, -1)]),
         (False, [(6, 1), (8, 1), (9, 1)])]


def closure(crank, theta):
    s, c = np.sin(theta), np.cos(theta)
    X = B_OFFSET + LI * np.cos(crank)
    Y = A_OFFSET + LI * np.sin(crank)
    f = np.zeros(10)
    J = np.zeros((10, 10))
    for loop, (from_crank, terms) in enumerate(LOOPS):
        x_row, y_row = 2 * loop, 2 * loop + 1
        f[x_row] = (X if from_crank else 0.0) + sum(sign * LENGTHS[k] * c[k] for k, sign in terms)
        f[y_row] = (Y if from_crank else 0.0) + sum(sign * LENGTHS[k] * s[k] for k, sign in terms)
        for k, sign in terms:
            J[x_row, k] = -sign * LENGTHS[k] * s[k]
            J[y_row, k] = sign * LENGTHS[k] * c[k]
    return f, J


def solve(request):
    f, J = closure(float(request["crank_angle"]), np.array(request["theta"], dtype=float))
    return {"f": f.tolist(), "J": J.tolist()}


def use_lengths(lengths):
    """The variant's link lengths (TASK.md, "Your variant") in place of seed 000's: |r3| ... |r12| are
    l1, l2, l3, l4, l5, l7, l8, l6, l9, l10."""
    global LI, A_OFFSET, B_OFFSET, R3, R4, R5, R6, R7, R8, R9, R10, R11, R12
    LI, A_OFFSET, B_OFFSET = lengths["crank"], lengths["a"], lengths["b"]
    R3, R4, R5, R6, R7, R8, R9, R10, R11, R12 = LENGTHS[:] = [lengths[name] for name in (
        "l1", "l2", "l3", "l4", "l5", "l7", "l8", "l6", "l9", "l10")]


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        if "lengths" in request:
            use_lengths(request["lengths"])
        try:
            reply = solve(request)
        except Exception as error:
            reply = {"error": str(error)}
        reply["id"] = request.get("id")
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
