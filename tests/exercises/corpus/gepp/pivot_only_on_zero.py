# BUG: rows are swapped only when the diagonal entry is exactly 0 (then with the first row below whose entry is not 0): the textbook's "pivot if you must", not partial pivoting
# CAUSE: no_pivoting
# SET: heldout
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    tol = n * np.finfo(float).eps * np.max(np.abs(A))
    trace = []
    for k in range(n):
        p = k
        if A[k, k] == 0.0:
            for i in range(k + 1, n):
                if A[i, k] != 0.0:
                    p = i
                    break
        if p != k:
            A[[k, p]] = A[[p, k]]
            b[[k, p]] = b[[p, k]]
        if abs(A[k, k]) <= tol:
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": A[k, k]})
        mult = A[k + 1:, k] / A[k, k]
        A[k + 1:, k:] -= np.outer(mult, A[k, k:])
        b[k + 1:] -= mult * b[k]
    x = np.zeros(n)
    for i in reversed(range(n)):
        x[i] = (b[i] - np.dot(A[i, i + 1:], x[i + 1:])) / A[i, i]
    return {"x": x, "trace": trace}
