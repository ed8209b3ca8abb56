# BUG: none: scaled by a power of two with frexp/ldexp, relative singular test (a check against false failures)
# CAUSE: none
import math

EPS = 2.220446049250313e-16


def solve(request):
    (p, q), (r, s) = request["A"]
    top = max(abs(p), abs(q), abs(r), abs(s))
    if top == 0.0:
        return {"status": "singular"}
    _, e = math.frexp(top)
    p, q, r, s = (math.ldexp(v, -e) for v in (p, q, r, s))
    det = p * s - q * r
    if abs(det) <= EPS * (p * p + q * q + r * r + s * s):
        return {"status": "singular"}
    return {"inverse": [[math.ldexp(s / det, -e), math.ldexp(-q / det, -e)],
                        [math.ldexp(-r / det, -e), math.ldexp(p / det, -e)]]}
