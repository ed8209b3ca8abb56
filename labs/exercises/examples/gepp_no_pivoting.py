#!/usr/bin/env python3
"""numlab exercise gepp: a buggy solution, the one `numlab lab exercises` runs after the correct one.

BUG: no pivoting. Each column is eliminated with its diagonal entry a_kk as the pivot, whatever
sits below it (the rows are never swapped). On a matrix whose diagonal holds a small entry the
multipliers a_ik / a_kk are huge and the rounding errors they carry swamp the answer; on a
diagonal entry negligible against the scale of A it says "singular" although A is regular.
Everything else is as in gepp_solution.py, whose protocol loop it uses.
"""
import sys

import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ beside the examples (an installed folder may be read-only)

from gepp_solution import serve


def gepp(A, b):
    A = np.array(A, dtype=float)
    b = np.array(b, dtype=float)
    n = len(b)
    negligible = n * np.finfo(float).eps * np.max(np.abs(A))
    trace = []
    for k in range(n):
        p = k  # BUG: the diagonal entry, not the row with the largest |a_pk|
        trace.append({"column": k, "pivot_row": p, "pivot": float(A[p, k])})
        if abs(A[p, k]) <= negligible:
            return {"status": "singular", "trace": trace}
        for i in range(k + 1, n):
            m = A[i, k] / A[k, k]
            A[i, k:] -= m * A[k, k:]
            b[i] -= m * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - A[i, i + 1:] @ x[i + 1:]) / A[i, i]
    return {"x": x.tolist(), "trace": trace}


if __name__ == "__main__":
    serve(gepp)
