# BUG: a pivot counts as zero when |a_kk| < machine epsilon (np.finfo(float).eps, an absolute 2.2e-16), not n * eps * max|a_ij|
# CAUSE: absolute_singular_threshold
# SET: heldout
def solve(request):
    M = [list(map(float, row)) for row in request["A"]]
    rhs = [float(v) for v in request["b"]]
    n = len(rhs)
    steps = []
    for col in range(n):
        best = max(range(col, n), key=lambda r: abs(M[r][col]))
        M[col], M[best] = M[best], M[col]
        rhs[col], rhs[best] = rhs[best], rhs[col]
        piv = M[col][col]
        if abs(piv) < np.finfo(float).eps:
            return {"status": "singular"}
        steps.append({"column": col, "pivot_row": best, "pivot": piv})
        for r in range(col + 1, n):
            factor = M[r][col] / piv
            for c in range(col, n):
                M[r][c] -= factor * M[col][c]
            rhs[r] -= factor * rhs[col]
    x = [0.0] * n
    for i in reversed(range(n)):
        acc = rhs[i]
        for j in range(i + 1, n):
            acc -= M[i][j] * x[j]
        x[i] = acc / M[i][i]
    return {"x": x, "trace": steps}
