# BUG: the stop test is max(f) <= tolerance, without abs: a residual whose entries are all negative counts as converged
# CAUSE: stop_test
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    x = np.array(request["theta0"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = f_and_J(crank, x)
    while k < request["max_iterations"]:
        if np.max(f) <= request["tolerance"]:
            status = "converged"
            break
        dx = np.linalg.solve(J, -f)
        x += dx
        k += 1
        f, J = f_and_J(crank, x)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dx))})
    if status != "converged" and np.max(f) <= request["tolerance"]:
        status = "converged"
    return {"theta": x, "status": status, "iterations": k, "trace": trace}
