# BUG: dx = -solve(J, f) instead of solve(J, -f): the same numbers to the last bit (LU is odd in its right-hand side)
# CAUSE: no_effect
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    x = np.array(request["theta0"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = f_and_J(crank, x)
    while True:
        if np.max(np.abs(f)) <= request["tolerance"]:
            status = "converged"
            break
        if k >= request["max_iterations"]:
            break
        try:
            dx = -np.linalg.solve(J, f)
        except np.linalg.LinAlgError:
            status = "singular"
            break
        x = x + dx
        k += 1
        f, J = f_and_J(crank, x)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dx))})
        if not np.all(np.isfinite(f)):
            status = "diverged"
            break
    return {"theta": x, "status": status, "iterations": k, "trace": trace}
