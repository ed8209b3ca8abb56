# BUG: no singular test: only a ZeroDivisionError (det exactly 0) is reported as singular, a determinant at rounding level gives a huge inverse
# CAUSE: no_singular_test
import math


def solve(request):
    (a, b), (c, d) = request["A"]
    m = max(abs(a), abs(b), abs(c), abs(d))
    if m == 0:
        return {"status": "singular"}
    p = math.frexp(m)[1]
    a, b, c, d = (math.ldexp(v, -p) for v in (a, b, c, d))
    try:
        r = 1.0 / (a * d - b * c)
    except ZeroDivisionError:
        return {"status": "singular"}
    return {"inverse": [[math.ldexp(d * r, -p), math.ldexp(-b * r, -p)],
                        [math.ldexp(-c * r, -p), math.ldexp(a * r, -p)]]}
