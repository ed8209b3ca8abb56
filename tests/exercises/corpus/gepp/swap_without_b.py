# BUG: rows k and p of A are swapped but b is left as it was
# CAUSE: swap_without_b
def solve(request):
    a = [list(map(float, row)) for row in request["A"]]
    b = [float(v) for v in request["b"]]
    n = len(b)
    eps = 2.220446049250313e-16
    biggest = max(abs(v) for row in a for v in row)
    trace = []
    for k in range(n):
        p = max(range(k, n), key=lambda i: abs(a[i][k]))
        a[k], a[p] = a[p], a[k]
        if abs(a[k][k]) <= n * eps * biggest:
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
