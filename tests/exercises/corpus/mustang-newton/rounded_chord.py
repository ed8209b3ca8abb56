# BUG: the seed's rounded constants: the chord |2 6| typed as 4.698 and sqrt 0.5 as 0.707
# CAUSE: rounded_constants
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    f, J = loops(th, v, chord=4.698, r=0.707)
    while True:
        if np.max(np.abs(f)) <= request["tolerance"]:
            status = "converged"
            break
        if k >= request["max_iterations"]:
            break
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v, chord=4.698, r=0.707)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
