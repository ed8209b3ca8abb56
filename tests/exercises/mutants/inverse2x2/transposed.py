#!/usr/bin/env python3
# BUG: inverse transposed: [[d, -c], [-b, a]] / det
# EXPECT-CHECK: well-conditioned
# EXPECT-MESSAGE: inverse[0][1]
"""A mutant (the bug is named above) of the correct student solution of `numlab exercise` inverse2x2: the closed form with A scaled by a
power of two first, and the singular test |det| <= eps ||A||_F^2."""
import json
import math
import sys

EPS = 2.220446049250313e-16


def solve(request):
    (a, b), (c, d) = request["A"]
    largest = max(abs(a), abs(b), abs(c), abs(d))
    if largest == 0.0:
        return {"status": "singular"}
    _, exponent = math.frexp(largest)  # scaled entries below 1: a d and b c cannot overflow or underflow
    a, b, c, d = (math.ldexp(v, -exponent) for v in (a, b, c, d))
    det = a * d - b * c
    if abs(det) <= EPS * (a * a + b * b + c * c + d * d):
        return {"status": "singular"}
    # (A / s)^-1 = s A^-1, so A^-1 = (adjugate / det) / s
    inverse = [[d / det, -c / det], [-b / det, a / det]]  # the bug: transposed
    return {"inverse": [[math.ldexp(v, -exponent) for v in row] for row in inverse]}


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
        print(json.dumps(reply), flush=True)


if __name__ == "__main__":
    main()
