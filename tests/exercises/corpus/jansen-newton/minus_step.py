# BUG: dx solves J dx = -f and then x <- x - dx: the step goes away from the root
# CAUSE: step_sign
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    x = np.array(request["theta0"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = f_and_J(crank, x)
    while np.max(np.abs(f)) > request["tolerance"]:
        if k == request["max_iterations"]:
            break
        dx = np.linalg.solve(J, -f)
        x = x - dx
        k += 1
        f, J = f_and_J(crank, x)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dx))})
        if not np.all(np.isfinite(f)):
            status = "diverged"
            break
    else:
        status = "converged"
    return {"theta": x, "status": status, "iterations": k, "trace": trace}
