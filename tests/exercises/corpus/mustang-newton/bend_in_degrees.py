# BUG: the bend is typed as 20 (degrees) and used in np.cos and np.sin as if it were radians
# CAUSE: degrees_for_radians
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = loops(th, v, bend=20)
    while True:
        if np.max(np.abs(f)) <= request["tolerance"]:
            status = "converged"
            break
        if k >= request["max_iterations"]:
            break
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v, bend=20)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
