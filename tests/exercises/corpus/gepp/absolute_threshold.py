# BUG: a pivot counts as zero when |a_kk| < 1e-12, an absolute threshold, not n * eps * max|a_ij|
# CAUSE: absolute_singular_threshold
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(A[k:, k])))
        A[[k, p]] = A[[p, k]]
        b[[k, p]] = b[[p, k]]
        if abs(A[k, k]) < 1e-12:
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
