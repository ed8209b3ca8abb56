# BUG: the new angles go into theta_new, but f and J are evaluated at theta every time: x is never updated
# CAUSE: x_never_updated
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    theta = np.array(request["theta0"], dtype=float)
    tol, itmax = request["tolerance"], request["max_iterations"]
    trace, it, status = [], 0, "max_iterations"
    theta_new = theta.copy()
    while it < itmax:
        f, J = f_and_J(crank, theta)
        if np.max(np.abs(f)) <= tol:
            status = "converged"
            break
        dx = np.linalg.solve(J, -f)
        theta_new = theta + dx
        it += 1
        trace.append({"residual_inf": np.max(np.abs(f_and_J(crank, theta_new)[0])), "step_inf": np.max(np.abs(dx))})
    return {"theta": theta_new, "status": status, "iterations": it, "trace": trace}
