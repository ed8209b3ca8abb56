# BUG: the adjugate is written [[d, -c], [-b, a]]: the off-diagonal entries are swapped (the transpose of the inverse)
# CAUSE: transposed
import math


def solve(request):
    (a, b), (c, d) = request["A"]
    big = max(abs(a), abs(b), abs(c), abs(d))
    if big == 0:
        return {"status": "singular"}
    e = math.frexp(big)[1]
    a, b, c, d = [math.ldexp(t, -e) for t in (a, b, c, d)]
    det = a * d - b * c
    if abs(det) <= 2.220446049250313e-16 * (a * a + b * b + c * c + d * d):
        return {"status": "singular"}
    inv = [[d / det, -c / det], [-b / det, a / det]]
    return {"inverse": [[math.ldexp(t, -e) for t in row] for row in inv]}
