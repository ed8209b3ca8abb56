# BUG: the crank angle is converted with np.deg2rad before use (the student read "theta" in the figure's degrees), though the request gives it in radians
# CAUSE: degrees_for_radians
# SET: heldout
# include: mustang_closure.py


def solve(request):
    th = np.deg2rad(request["crank_angle"])
    v = np.asarray(request["guess"], dtype=float).copy()
    tol = request["tolerance"]
    iters, trace = 0, []
    f, J = loops(th, v)
    while np.abs(f).max() > tol:
        if iters == request["max_iterations"]:
            return {"angles": v, "status": "max_iterations", "iterations": iters, "trace": trace}
        step = np.linalg.solve(J, -f)
        v += step
        iters += 1
        f, J = loops(th, v)
        trace.append({"residual_inf": np.abs(f).max(), "step_inf": np.abs(step).max()})
    return {"angles": v, "status": "converged", "iterations": iters, "trace": trace}
