# BUG: plain Gaussian elimination: no row search and no swap at all, the diagonal entry is always the pivot
# CAUSE: no_pivoting
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    thresh = n * np.finfo(float).eps * abs(A).max()
    tr = []
    for k in range(n):
        if abs(A[k, k]) <= thresh:
            return {"status": "singular"}
        tr.append({"column": k, "pivot_row": k, "pivot": A[k, k]})
        for i in range(k + 1, n):
            f = A[i, k] / A[k, k]
            A[i] -= f * A[k]
            b[i] -= f * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - A[i, i + 1:].dot(x[i + 1:])) / A[i, i]
    return {"x": x, "trace": tr}
