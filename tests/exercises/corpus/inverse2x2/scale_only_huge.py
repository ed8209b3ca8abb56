# BUG: A is scaled only when its largest entry is above 1e100 (the student guarded the overflow of a d and forgot the underflow): at 1e-170 a d underflows to 0
# CAUSE: no_scaling
# SET: heldout
import math


def solve(request):
    a, b = (float(v) for v in request["A"][0])
    c, d = (float(v) for v in request["A"][1])
    big = max(abs(a), abs(b), abs(c), abs(d))
    shift = 0
    if big > 1e100:
        shift = math.frexp(big)[1]
        a, b, c, d = (math.ldexp(v, -shift) for v in (a, b, c, d))
    det = a * d - b * c
    if abs(det) <= 2.220446049250313e-16 * (a * a + b * b + c * c + d * d):
        return {"status": "singular"}
    rows = [[d / det, -b / det], [-c / det, a / det]]
    return {"inverse": [[math.ldexp(v, -shift) for v in row] for row in rows]}
