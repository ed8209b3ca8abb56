# BUG: "converged" is returned whenever the loop stops, also when max_iterations ran out (beyond the assembly limits there is no root)
# CAUSE: converged_when_stopped
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k = [], 0
    f, J = loops(th, v)
    while np.max(np.abs(f)) > request["tolerance"] and k < request["max_iterations"]:
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    return {"angles": v, "status": "converged", "iterations": k, "trace": trace}
