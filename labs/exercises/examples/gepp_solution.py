#!/usr/bin/env python3
"""numlab exercise gepp: a correct solution, the one `numlab lab exercises` runs.

Gaussian elimination with partial pivoting, by hand, on numpy arrays: for each column k,
  1. the pivot: the row p >= k with the largest |a_pk|;
  2. swap rows k and p (of A and b, whole rows);
  3. eliminate below the pivot;
then back substitution. A pivot that is negligible against the matrix's scale
(|a_kk| <= n * eps * max|a_ij|) means the matrix is singular to working precision.
The trace has one entry per column: {column, pivot_row, pivot} (0-based indices).
"""
import json
import sys

import numpy as np


def gepp(A, b):
    A = np.array(A, dtype=float)
    b = np.array(b, dtype=float)
    n = len(b)
    negligible = n * np.finfo(float).eps * np.max(np.abs(A))
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(A[k:, k])))  # 1. the largest |a_pk| on or below the diagonal
        trace.append({"column": k, "pivot_row": p, "pivot": float(A[p, k])})
        if abs(A[p, k]) <= negligible:
            return {"status": "singular", "trace": trace}
        if p != k:  # 2. swap whole rows
            A[[k, p], :] = A[[p, k], :]
            b[[k, p]] = b[[p, k]]
        for i in range(k + 1, n):  # 3. eliminate below the pivot
            m = A[i, k] / A[k, k]
            A[i, k:] -= m * A[k, k:]
            b[i] -= m * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):  # back substitution, last unknown first
        x[i] = (b[i] - A[i, i + 1:] @ x[i + 1:]) / A[i, i]
    return {"x": x.tolist(), "trace": trace}


def serve(method):
    """The protocol loop: one request per stdin line, one reply per stdout line, the id echoed."""
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = method(request["A"], request["b"])
        except Exception as error:
            reply = {"error": f"{type(error).__name__}: {error}"}
        reply["id"] = request.get("id")
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    serve(gepp)
