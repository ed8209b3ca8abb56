# BUG: the step is taken before the test, so one more Newton step is done (and counted) after the residual is already below the tolerance
# CAUSE: one_iteration_too_many
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    x = np.array(request["theta0"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    while k < request["max_iterations"]:
        f, J = f_and_J(crank, x)
        dx = np.linalg.solve(J, -f)
        x = x + dx
        k += 1
        fn = f_and_J(crank, x)[0]
        trace.append({"residual_inf": np.max(np.abs(fn)), "step_inf": np.max(np.abs(dx))})
        if np.max(np.abs(f)) <= request["tolerance"]:
            status = "converged"
            break
    return {"theta": x, "status": status, "iterations": k, "trace": trace}
