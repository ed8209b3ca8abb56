# BUG: none: GEPP with plain Python loops, the singular test after the swap and the trace (a check against false failures)
# CAUSE: none
def solve(request):
    a = [[float(v) for v in row] for row in request["A"]]
    b = [float(v) for v in request["b"]]
    n = len(b)
    small = n * 2.220446049250313e-16 * max(abs(v) for row in a for v in row)
    trace = []
    for k in range(n):
        p = k
        for i in range(k + 1, n):
            if abs(a[i][k]) > abs(a[p][k]):
                p = i
        a[k], a[p] = a[p], a[k]
        b[k], b[p] = b[p], b[k]
        if abs(a[k][k]) <= small:
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": a[k][k]})
        for i in range(k + 1, n):
            l = a[i][k] / a[k][k]
            for j in range(k, n):
                a[i][j] -= l * a[k][j]
            b[i] -= l * b[k]
    x = [0.0] * n
    for i in range(n - 1, -1, -1):
        s = b[i]
        for j in range(i + 1, n):
            s -= a[i][j] * x[j]
        x[i] = s / a[i][i]
    return {"x": x, "trace": trace}
