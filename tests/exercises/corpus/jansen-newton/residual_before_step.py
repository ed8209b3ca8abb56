# BUG: the trace's residual_inf is max|f| before the step (the residual the step started from), not after it
# CAUSE: trace_before_step
# include: jansen_closure.py


def solve(request):
    crank = request["crank_angle"]
    x = np.array(request["theta0"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    while True:
        f, J = f_and_J(crank, x)
        res = float(np.max(np.abs(f)))
        if res <= request["tolerance"]:
            status = "converged"
            break
        if k >= request["max_iterations"]:
            break
        dx = np.linalg.solve(J, -f)
        x = x + dx
        k += 1
        trace.append({"residual_inf": res, "step_inf": float(np.max(np.abs(dx)))})
    return {"theta": x, "status": status, "iterations": k, "trace": trace}
