# BUG: singular when |det| < 1e-12, an absolute threshold, instead of eps times the squared size of A
# CAUSE: absolute_singular_threshold
import math


def solve(request):
    (a, b), (c, d) = request["A"]
    m = max(abs(a), abs(b), abs(c), abs(d))
    if m == 0:
        return {"status": "singular"}
    k = math.frexp(m)[1]
    a, b, c, d = (math.ldexp(v, -k) for v in (a, b, c, d))
    det = a * d - b * c
    if abs(det) < 1e-12:
        return {"status": "singular"}
    return {"inverse": [[math.ldexp(d / det, -k), math.ldexp(-b / det, -k)],
                        [math.ldexp(-c / det, -k), math.ldexp(a / det, -k)]]}
