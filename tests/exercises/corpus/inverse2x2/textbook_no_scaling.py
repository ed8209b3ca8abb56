# BUG: the textbook formula on A as given, no scaling by a power of two: a d underflows at 1e-170 and overflows at 1e170
# CAUSE: no_scaling
def solve(request):
    a, b = request["A"][0]
    c, d = request["A"][1]
    det = a * d - b * c
    if abs(det) <= 2.220446049250313e-16 * (a * a + b * b + c * c + d * d):
        return {"status": "singular"}
    return {"inverse": [[d / det, -b / det], [-c / det, a / det]]}
