# BUG: the sweep runs i = n-1 down to 0 (a backward Gauss-Seidel sweep), not 0 up to n-1
# CAUSE: reverse_order
def solve(request):
    M = np.array(request["A"], dtype=float)
    c = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M, c = M.T @ M, M.T @ c
    x = np.array(request["x0"], dtype=float)
    n = len(x)
    trace, u1, status, k = [], 0.0, "max_iterations", 0
    while k < request["max_iterations"]:
        k += 1
        old = x.copy()
        for i in range(n - 1, -1, -1):
            x[i] = (c[i] - M[i] @ x + M[i, i] * x[i]) / M[i, i]
        u = float(np.max(np.abs(x - old)))
        if k == 1:
            u1 = u
        trace.append({"x": x.tolist(), "update_inf": u})
        if u <= request["tolerance"] * max(1.0, float(np.max(np.abs(x)))):
            status = "converged"
            break
        if u > 1e8 * max(u1, request["tolerance"]):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": trace}
