# BUG: the stop test uses < where the rule says <= (an update exactly equal to the bound never occurs here)
# CAUSE: no_effect
def solve(request):
    M = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M, c = M.T @ M, M.T @ c
    x = np.array(request["x0"], dtype=float)
    n = len(x)
    tol = request["tolerance"]
    trace, first, status, k = [], None, "max_iterations", 0
    while k < request["max_iterations"]:
        k += 1
        old = x.copy()
        for i in range(n):
            x[i] = (c[i] - M[i, :i] @ x[:i] - M[i, i + 1:] @ x[i + 1:]) / M[i, i]
        u = float(np.max(np.abs(x - old)))
        first = u if first is None else first
        trace.append({"x": x.tolist(), "update_inf": u})
        if u < tol * max(1.0, float(np.max(np.abs(x)))):
            status = "converged"
            break
        if u > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": trace}
