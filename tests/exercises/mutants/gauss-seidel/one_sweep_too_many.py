#!/usr/bin/env python3
# BUG: the loop runs max_iterations + 1 sweeps
# EXPECT-CHECK: max_iterations after exactly
# EXPECT-MESSAGE: after 26 sweeps
"""A mutant (the bug is named above) of the correct student solution of `numlab exercise` gauss-seidel: Gauss-Seidel sweeps by hand
(numpy only for arrays) of M x = c, M = A or A^T A, the stop test with abs, and the sweep trace."""
import json
import sys

import numpy as np


def solve(request):
    m = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        m, c = m.T @ m, m.T @ c
    x = np.array(request["x0"], dtype=float)
    tolerance = request["tolerance"]
    max_iterations = request["max_iterations"]
    n = len(x)
    trace = []
    status = "max_iterations"
    first_update = 0.0
    sweep = 0
    while sweep <= max_iterations:  # the bug: one sweep too many
        sweep += 1
        old = x.copy()
        for i in range(n):
            others = m[i, :i] @ x[:i] + m[i, i + 1:] @ x[i + 1:]
            x[i] = (c[i] - others) / m[i, i]
        update = float(np.max(np.abs(x - old)))
        if sweep == 1:
            first_update = update
        trace.append({"x": x.tolist(), "update_inf": update})
        if update <= tolerance * max(1.0, float(np.max(np.abs(x)))):
            status = "converged"
            break
        if update > 1e8 * max(first_update, tolerance):
            status = "diverged"
            break
    return {"x": x.tolist(), "status": status, "iterations": sweep, "trace": trace}


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = solve(request)
        except Exception as error:  # the checker reports it as this check's failure
            reply = {"error": f"{type(error).__name__}: {error}"}
        reply["id"] = request.get("id")
        print(json.dumps(reply, default=float), flush=True)


if __name__ == "__main__":
    main()
