# BUG: the stop test takes the largest signed change, max(x_new - x_old), without abs: a sweep that only decreases x stops at once (seed 001)
# CAUSE: stop_test
def solve(request):
    M = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        c = M.T @ c
        M = M.T @ M
    x = np.array(request["x0"], dtype=float)
    tol, limit = request["tolerance"], request["max_iterations"]
    n = len(x)
    out, status, k, first = [], "max_iterations", 0, None
    while k < limit:
        k += 1
        old = x.copy()
        for i in range(n):
            x[i] = (c[i] - np.dot(M[i, :i], x[:i]) - np.dot(M[i, i + 1:], x[i + 1:])) / M[i, i]
        change = np.max(x - old)
        size = np.max(np.abs(x - old))
        first = size if first is None else first
        out.append({"x": x.tolist(), "update_inf": size})
        if change <= tol * max(1.0, np.max(np.abs(x))):
            status = "converged"
            break
        if size > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": out}
