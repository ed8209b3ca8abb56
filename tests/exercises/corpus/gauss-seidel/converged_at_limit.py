# BUG: when the sweeps run out the status is still "converged" (the student assumed the loop always converges)
# CAUSE: limit_reported_converged
def solve(request):
    M = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M, c = M.T @ M, M.T @ c
    x = np.array(request["x0"], dtype=float)
    n = len(x)
    tol = request["tolerance"]
    trace, first = [], None
    status = "converged"
    it = 0
    while it < request["max_iterations"]:
        it += 1
        old = x.copy()
        for i in range(n):
            x[i] = (c[i] - M[i, :i] @ x[:i] - M[i, i + 1:] @ x[i + 1:]) / M[i, i]
        d = float(np.max(np.abs(x - old)))
        first = d if first is None else first
        trace.append({"x": x.tolist(), "update_inf": d})
        if d <= tol * max(1.0, float(np.max(np.abs(x)))):
            break
        if d > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": it, "trace": trace}
