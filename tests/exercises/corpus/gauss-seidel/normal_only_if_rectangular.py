# BUG: the normal equations are formed only when A is not square (the student read normal_equations as "A has more rows"): a square A with normal_equations true is swept as A x = b
# CAUSE: plain_when_normal_asked
# SET: heldout
def solve(request):
    A = np.asarray(request["A"], dtype=float)
    b = np.asarray(request["b"], dtype=float)
    rows, cols = A.shape
    if rows != cols:
        b = A.T @ b
        A = A.T @ A
    x = np.asarray(request["x0"], dtype=float).copy()
    n = len(x)
    history = []
    first = None
    status = "max_iterations"
    sweeps = 0
    for sweeps in range(1, request["max_iterations"] + 1):
        change = 0.0
        for i in range(n):
            s = b[i]
            for j in range(n):
                if j != i:
                    s -= A[i, j] * x[j]
            value = s / A[i, i]
            change = max(change, abs(value - x[i]))
            x[i] = value
        history.append({"x": x.copy(), "update_inf": change})
        if first is None:
            first = change
        if change <= request["tolerance"] * max(1.0, np.max(np.abs(x))):
            status = "converged"
            break
        if change > 1e8 * max(first, request["tolerance"]):
            status = "diverged"
            break
    return {"x": x, "status": status, "iterations": sweeps, "trace": history}
