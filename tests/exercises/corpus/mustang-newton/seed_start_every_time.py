# BUG: the guess is ignored: every request starts from the seed's [pi/18, pi/2] pattern, so Newton may land on another branch or not converge
# CAUSE: restart_from_seed_guess
# include: mustang_closure.py


def solve(request):
    th = request["crank_angle"]
    v = np.array([np.pi / 18, np.pi / 2] * 4)
    trace, k, status = [], 0, "max_iterations"
    f, J = loops(th, v)
    while True:
        if np.max(np.abs(f)) <= request["tolerance"]:
            status = "converged"
            break
        if k >= request["max_iterations"]:
            break
        dv = np.linalg.solve(J, -f)
        v = v + dv
        k += 1
        f, J = loops(th, v)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dv))})
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
