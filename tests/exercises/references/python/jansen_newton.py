#!/usr/bin/env python3
"""Reference solution of `numlab exercise jansen-newton`: full Newton-Raphson on seed 000's
8-equation Jansen closure (from the task's equations), with its trace."""
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
    crank = float(request["crank_angle"])
    theta, status, iterations, trace = newton(lambda t: closure(crank, t), np.array(request["theta0"], dtype=float),
                                              float(request["tolerance"]), int(request["max_iterations"]))
    return {"theta": theta.tolist(), "status": status, "iterations": iterations, "trace": trace}


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
