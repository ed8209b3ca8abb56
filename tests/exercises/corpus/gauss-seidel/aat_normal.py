# BUG: the normal matrix is built as A A^T instead of A^T A (the right-hand side A^T b is right)
# CAUSE: a_at_instead_of_at_a
def solve(request):
    A = np.array(request["A"], dtype=float)
    rhs = np.array(request["b"], dtype=float)
    if request["normal_equations"]:
        M = A @ A.T
        rhs = A.T @ rhs
    else:
        M = A
    x = np.array(request["x0"], dtype=float)
    tol, maxit = request["tolerance"], request["max_iterations"]
    history, u1, status, it = [], 0.0, "max_iterations", 0
    for it in range(1, maxit + 1):
        prev = x.copy()
        for i in range(len(x)):
            x[i] = (rhs[i] - M[i, :i] @ x[:i] - M[i, i + 1:] @ x[i + 1:]) / M[i, i]
        u = float(np.max(np.abs(x - prev)))
        if it == 1:
            u1 = u
        history.append({"x": x.tolist(), "update_inf": u})
        if u <= tol * max(1.0, float(np.max(np.abs(x)))):
            status = "converged"
            break
        if u > 1e8 * max(u1, tol):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": it, "trace": history}
