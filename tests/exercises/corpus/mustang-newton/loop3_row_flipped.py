# BUG: seed 003's loop-3 Jacobian: the second row (d f[5]) has every sign flipped
# CAUSE: wrong_jacobian
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = loops(th, v)
    while np.max(np.abs(f)) > request["tolerance"] and k < request["max_iterations"]:
        J[5] = -J[5]
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    if np.max(np.abs(f)) <= request["tolerance"]:
        status = "converged"
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
