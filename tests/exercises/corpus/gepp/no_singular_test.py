# BUG: no singular test at all: the student relies on numpy to complain, so a zero or rounding-level pivot gives inf, nan or a huge x
# CAUSE: no_singular_test
def solve(request):
    U = np.array(request["A"], dtype=float)
    y = np.array(request["b"], dtype=float)
    n = len(y)
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(U[k:, k])))
        U[[k, p]] = U[[p, k]]
        y[[k, p]] = y[[p, k]]
        trace.append({"column": k, "pivot_row": p, "pivot": U[k, k]})
        for i in range(k + 1, n):
            l = U[i, k] / U[k, k]
            U[i, k:] -= l * U[k, k:]
            y[i] -= l * y[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (y[i] - U[i, i + 1:] @ x[i + 1:]) / U[i, i]
    if not np.all(np.isfinite(x)):
        raise ValueError("elimination failed")
    return {"x": x, "trace": trace}
