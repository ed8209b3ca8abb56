#!/usr/bin/env python3
# BUG: the coefficients come out highest power first (numpy.polyfit's order), the powers reversed
# EXPECT-CHECK: Small fits
# EXPECT-MESSAGE: powers reversed
"""Reference solution of `numlab exercise polyfit`: least squares by SVD (numpy.linalg.lstsq) of
the Vandermonde matrix with unit-length columns, coefficients lowest power first."""
import json
import sys

import numpy as np


def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    degree = int(request["degree"])
    if len(np.unique(x)) < degree + 1:
        return {"status": "singular"}
    V = np.vander(x, degree + 1, increasing=True)
    scale = np.linalg.norm(V, axis=0)
    b = np.linalg.lstsq(V / scale, y, rcond=None)[0] / scale
    return {"coefficients": b[::-1].tolist()}


def main():
    for line in sys.stdin:
        if not line.strip():
            continue
        request = json.loads(line)
        try:
            reply = solve(request)
        except Exception as error:  # the checker reports it as this request's failure
            reply = {"error": str(error)}
        reply["id"] = request.get("id")
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
