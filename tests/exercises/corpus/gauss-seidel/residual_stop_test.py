# BUG: the stop test is on the residual, max|c - M x| <= tolerance, not on the update of the sweep
# CAUSE: stop_test
def solve(request):
    M = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M, c = M.T @ M, M.T @ c
    x = np.array(request["x0"], dtype=float)
    n = len(x)
    tol = request["tolerance"]
    trace, status, first = [], "max_iterations", None
    count = 0
    for count in range(1, request["max_iterations"] + 1):
        before = x.copy()
        for i in range(n):
            x[i] = (c[i] - M[i, :i] @ x[:i] - M[i, i + 1:] @ x[i + 1:]) / M[i, i]
        upd = float(np.max(np.abs(x - before)))
        first = upd if first is None else first
        trace.append({"x": x.tolist(), "update_inf": upd})
        if np.max(np.abs(c - M @ x)) <= tol:
            status = "converged"
            break
        if upd > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": count, "trace": trace}
