# BUG: back substitution sums j over i+1 ... n-2 (range(i + 1, n - 1)): the last unknown is left out of every row
# CAUSE: back_substitution
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    tol = n * np.finfo(float).eps * np.abs(A).max()
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(A[k:, k])))
        A[[k, p], :] = A[[p, k], :]
        b[[k, p]] = b[[p, k]]
        if abs(A[k, k]) <= tol:
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": A[k, k]})
        for i in range(k + 1, n):
            l = A[i, k] / A[k, k]
            A[i, k:] -= l * A[k, k:]
            b[i] -= l * b[k]
    x = np.zeros(n)
    for i in range(n - 1, -1, -1):
        total = 0.0
        for j in range(i + 1, n - 1):
            total += A[i, j] * x[j]
        x[i] = (b[i] - total) / A[i, i]
    return {"x": x, "trace": trace}
