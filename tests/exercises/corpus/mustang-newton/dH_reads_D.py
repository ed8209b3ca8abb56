# BUG: seed 003's typo: d f[7] / dH is written -cos(D) where -cos(H) belongs
# CAUSE: wrong_jacobian
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = loops(th, v)
    while np.max(np.abs(f)) > request["tolerance"] and k < request["max_iterations"]:
        J[7, 7] = -np.cos(v[3])
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    if np.max(np.abs(f)) <= request["tolerance"]:
        status = "converged"
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
