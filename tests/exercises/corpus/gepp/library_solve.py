# BUG: x comes from numpy.linalg.solve; the pivot trace is made up by a separate pivot search, so the elimination is never written
# CAUSE: library_call
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    n = len(b)
    work = A.copy()
    trace = []
    for k in range(n):
        p = k + int(np.argmax(np.abs(work[k:, k])))
        work[[k, p]] = work[[p, k]]
        if abs(work[k, k]) <= n * np.finfo(float).eps * np.abs(A).max():
            return {"status": "singular"}
        trace.append({"column": k, "pivot_row": p, "pivot": work[k, k]})
        work[k + 1:, k:] -= np.outer(work[k + 1:, k] / work[k, k], work[k, k:])
    return {"x": np.linalg.solve(A, b), "trace": trace}
