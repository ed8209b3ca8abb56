#!/usr/bin/env python3
# BUG: no pivoting: row k is always the pivot row
# EXPECT-CHECK: pivot choices (trace)
# EXPECT-MESSAGE: you pivoted on row
"""A mutant (the bug is named above) of the correct student solution of `numlab exercise` gepp: Gaussian elimination with partial
pivoting by hand (numpy only for arrays), its singular test and its pivot trace."""
import json
import sys

import numpy as np

EPS = np.finfo(float).eps


def solve(request):
    a = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    negligible = n * EPS * np.max(np.abs(a))
    trace = []
    for k in range(n):
        p = k  # the bug: no pivoting
        a[[k, p], :] = a[[p, k], :]
        b[[k, p]] = b[[p, k]]
        if abs(a[k, k]) <= negligible:
            return {"status": "singular", "trace": trace}
        trace.append({"column": k, "pivot_row": p, "pivot": a[k, k]})
        for i in range(k + 1, n):
            l = a[i, k] / a[k, k]
            a[i, k:] -= l * a[k, k:]
            b[i] -= l * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - a[i, i + 1:] @ x[i + 1:]) / a[i, i]
    return {"x": x.tolist(), "trace": trace}


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
