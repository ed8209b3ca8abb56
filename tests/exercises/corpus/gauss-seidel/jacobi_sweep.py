# BUG: each sweep computes every x_i from the previous sweep's x (a copy), which is a Jacobi sweep, not Gauss-Seidel
# CAUSE: jacobi_sweep
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        A, b = A.T @ A, A.T @ b
    x = np.array(request["x0"], dtype=float)
    tol, kmax = request["tolerance"], request["max_iterations"]
    n = len(x)
    trace, first, status, k = [], None, "max_iterations", 0
    while k < kmax:
        k += 1
        old = x.copy()
        for i in range(n):
            s = 0.0
            for j in range(n):
                if j != i:
                    s += A[i, j] * old[j]
            x[i] = (b[i] - s) / A[i, i]
        du = np.max(np.abs(x - old))
        first = du if first is None else first
        trace.append({"x": x.copy(), "update_inf": du})
        if du <= tol * max(1.0, np.max(np.abs(x))):
            status = "converged"
            break
        if du > 1e8 * max(first, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": trace}
