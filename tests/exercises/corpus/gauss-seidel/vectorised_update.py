# BUG: the sweep is written with whole vectors, x = (c - (M - diag(M)) x) / diag(M): every x_i uses the previous sweep's x, which is a Jacobi sweep
# CAUSE: jacobi_sweep
# SET: heldout
def solve(request):
    A = np.array(request["A"], dtype=float)
    b = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M, c = A.T @ A, A.T @ b
    else:
        M, c = A, b
    d = np.diag(M)
    off = M - np.diag(d)
    x = np.array(request["x0"], dtype=float)
    tol, limit = request["tolerance"], request["max_iterations"]
    trace, status, k, u1 = [], "max_iterations", 0, None
    while k < limit:
        new = (c - off @ x) / d
        u = np.max(np.abs(new - x))
        x = new
        k += 1
        if u1 is None:
            u1 = u
        trace.append({"x": x, "update_inf": u})
        if u <= tol * max(1.0, np.max(np.abs(x))):
            status = "converged"
            break
        if u > 1e8 * max(u1, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": k, "trace": trace}
