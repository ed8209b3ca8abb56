# BUG: normal_equations is never read: every request is swept on A x = b itself
# CAUSE: plain_when_normal_asked
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    x = np.array(request["x0"], dtype=float)
    n = len(x)
    tol, itmax = request["tolerance"], request["max_iterations"]
    trace, status, first = [], "max_iterations", None
    sweeps = 0
    while sweeps < itmax:
        sweeps += 1
        change = 0.0
        for i in range(n):
            new = (b[i] - sum(A[i, j] * x[j] for j in range(n) if j != i)) / A[i, i]
            change = max(change, abs(new - x[i]))
            x[i] = new
        if first is None:
            first = change
        trace.append({"x": x.tolist(), "update_inf": change})
        if change <= tol * max(1.0, np.abs(x).max()):
            status = "converged"
            break
        if change > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": sweeps, "trace": trace}
