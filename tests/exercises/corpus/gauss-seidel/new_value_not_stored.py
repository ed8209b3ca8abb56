# BUG: the new x_i is computed into a local variable and never stored back into x, so x stays x0 and the first sweep "converges"
# CAUSE: x_never_updated
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
        x_new = x.copy()
        for i in range(n):
            xi = (c[i] - M[i, :i] @ x_new[:i] - M[i, i + 1:] @ x_new[i + 1:]) / M[i, i]
        du = float(np.max(np.abs(x_new - x)))
        x = x_new
        first = du if first is None else first
        trace.append({"x": x.tolist(), "update_inf": du})
        if du <= tol * max(1.0, float(np.max(np.abs(x)))):
            status = "converged"
            break
        if du > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": trace}
