# BUG: the row multiplier is written a_kk / a_ik (upside down) instead of a_ik / a_kk
# CAUSE: inverted_multiplier
def solve(request):
    A = np.array(request["A"], dtype=float)
    rhs = np.array(request["b"], dtype=float)
    n = A.shape[0]
    tiny = n * np.finfo(float).eps * np.abs(A).max()
    trace = []
    for col in range(n):
        best = col
        for r in range(col + 1, n):
            if abs(A[r, col]) > abs(A[best, col]):
                best = r
        if best != col:
            A[[col, best]] = A[[best, col]]
            rhs[[col, best]] = rhs[[best, col]]
        if abs(A[col, col]) <= tiny:
            return {"status": "singular"}
        trace.append({"column": col, "pivot_row": best, "pivot": A[col, col]})
        for r in range(col + 1, n):
            if A[r, col] == 0:
                continue
            factor = A[col, col] / A[r, col]
            A[r, :] = A[r, :] - factor * A[col, :]
            rhs[r] = rhs[r] - factor * rhs[col]
    x = np.zeros(n)
    for r in range(n - 1, -1, -1):
        x[r] = (rhs[r] - np.dot(A[r, r + 1:], x[r + 1:])) / A[r, r]
    return {"x": x, "trace": trace}
