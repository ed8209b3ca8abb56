# BUG: the swap moves only columns k ... n-1 of rows k and p (the columns left of k are already eliminated, so nothing changes)
# CAUSE: no_effect
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    tol = n * np.finfo(float).eps * np.max(np.abs(A))
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(A[k:, k])))
        tmp = A[k, k:].copy()
        A[k, k:] = A[p, k:]
        A[p, k:] = tmp
        b[k], b[p] = b[p], b[k]
        if abs(A[k, k]) <= tol:
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": A[k, k]})
        for i in range(k + 1, n):
            l = A[i, k] / A[k, k]
            A[i, k:] -= l * A[k, k:]
            b[i] -= l * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - A[i, i + 1:] @ x[i + 1:]) / A[i, i]
    return {"x": x, "trace": trace}
