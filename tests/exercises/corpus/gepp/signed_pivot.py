# BUG: the pivot is the row with the largest signed a_ik (np.argmax without abs), not the largest |a_ik|
# CAUSE: signed_pivot
def solve(request):
    M = np.array(request["A"], dtype=float)
    v = np.array(request["b"], dtype=float)
    n = len(v)
    limit = n * 2.220446049250313e-16 * np.max(np.abs(M))
    pivots = []
    for k in range(n):
        p = k + np.argmax(M[k:, k])
        M[[k, p]] = M[[p, k]]
        v[[k, p]] = v[[p, k]]
        if abs(M[k, k]) <= limit:
            return {"status": "singular"}
        pivots.append({"column": k, "pivot_row": int(p), "pivot": float(M[k, k])})
        for i in range(k + 1, n):
            m = M[i, k] / M[k, k]
            M[i, k:] -= m * M[k, k:]
            v[i] -= m * v[k]
    x = np.zeros(n)
    for i in reversed(range(n)):
        x[i] = (v[i] - M[i, i + 1:] @ x[i + 1:]) / M[i, i]
    return {"x": x, "trace": pivots}
