#!/usr/bin/env python3
"""Reference solution of `numlab exercise jansen-jacobian`: seed 000's 8-equation Jansen closure f
and its Jacobian J, from the task's equations."""
import json
import sys

import numpy as np

LI, L1, L2, L3, L4, L5, L6, L7, L8 = 15.0, 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7
A_OFFSET, B_OFFSET = 7.8, 38.0
LENGTHS = [L1, L2, L3, L4, L5, L6, L7, L8]
# Each y row (0, 2, 4, 6) as (angle index, sign) terms; the x row below it has the same terms.
ROWS = [[(0, 1), (1, -1)],
        [(0, 1), (2, 1), (3, -1)],
        [(5, 1), (6, -1)],
        [(0, 1), (2, 1), (4, 1), (6, -1), (7, -1)]]


def closure(crank, theta):
    s, c = np.sin(theta), np.cos(theta)
    Y = LI * np.sin(crank) + A_OFFSET
    X = LI * np.cos(crank) + B_OFFSET
    f = np.zeros(8)
    J = np.zeros((8, 8))
    for pair, terms in enumerate(ROWS):
        f[2 * pair] = Y + sum(sign * LENGTHS[k] * s[k] for k, sign in terms)
        f[2 * pair + 1] = X + sum(sign * LENGTHS[k] * c[k] for k, sign in terms)
        for k, sign in terms:
            J[2 * pair, k] = sign * LENGTHS[k] * c[k]
            J[2 * pair + 1, k] = -sign * LENGTHS[k] * s[k]
    return f, J


def solve(request):
    f, J = closure(float(request["crank_angle"]), np.array(request["theta"], dtype=float))
    return {"f": f.tolist(), "J": J.tolist()}


def use_lengths(lengths):
    """The variant's link lengths (TASK.md, "Your variant") in place of seed 000's."""
    global LI, L1, L2, L3, L4, L5, L6, L7, L8, A_OFFSET, B_OFFSET
    LI, A_OFFSET, B_OFFSET = lengths["crank"], lengths["a"], lengths["b"]
    L1, L2, L3, L4, L5, L6, L7, L8 = LENGTHS[:] = [lengths["l%d" % k] for k in range(1, 9)]


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
