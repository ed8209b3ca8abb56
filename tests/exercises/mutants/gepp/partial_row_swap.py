#!/usr/bin/env python3
# BUG: a swap of only part of the row: columns k ... n-2, the last column stays behind
# EXPECT-CHECK: random systems
# EXPECT-MESSAGE: x differs from GSL LU
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
        p = k + int(np.argmax(np.abs(a[k:, k])))  # the largest |a_pk|, the first on a tie
        a[[k, p], k:n - 1] = a[[p, k], k:n - 1]  # the bug: the last column is not swapped
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
