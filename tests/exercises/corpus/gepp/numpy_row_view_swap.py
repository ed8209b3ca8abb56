# BUG: the row swap `A[k], A[p] = A[p], A[k]` on numpy rows (views) copies row p over row k and keeps row p: row k's old entries are lost
# CAUSE: partial_row_swap
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    small = n * np.finfo(float).eps * np.max(np.abs(A))
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(A[k:, k])))
        A[k], A[p] = A[p], A[k]
        b[k], b[p] = b[p], b[k]
        if abs(A[k, k]) <= small:
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": A[k, k]})
        for i in range(k + 1, n):
            ratio = A[i, k] / A[k, k]
            A[i, k:] -= ratio * A[k, k:]
            b[i] -= ratio * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        x[i] = (b[i] - A[i, i + 1:] @ x[i + 1:]) / A[i, i]
    return {"x": x, "trace": trace}
