# BUG: the loop stops when the step is small, max|dx| <= tolerance, and then says "converged": the residual is never tested (one step more than the rule, and "converged" not backed by f)
# CAUSE: stop_test
# SET: heldout
LENGTHS = [50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7]
SIGNS = [[1, -1, 0, 0, 0, 0, 0, 0],
         [1, 0, 1, -1, 0, 0, 0, 0],
         [0, 0, 0, 0, 0, 1, -1, 0],
         [1, 0, 1, 0, 1, 0, -1, -1]]


def closure(crank, theta):
    w = np.array(SIGNS, dtype=float) * np.array(LENGTHS)
    ys = 15 * np.sin(crank) + 7.8 + w @ np.sin(theta)
    xs = 15 * np.cos(crank) + 38 + w @ np.cos(theta)
    f = np.empty(8)
    f[0::2], f[1::2] = ys, xs
    J = np.empty((8, 8))
    J[0::2] = w * np.cos(theta)
    J[1::2] = -w * np.sin(theta)
    return f, J


def solve(request):
    theta = np.array(request["theta0"], dtype=float)
    crank = request["crank_angle"]
    trace = []
    status = "max_iterations"
    n = 0
    for n in range(1, request["max_iterations"] + 1):
        f, J = closure(crank, theta)
        dx = np.linalg.solve(J, -f)
        theta += dx
        step = np.max(np.abs(dx))
        trace.append({"residual_inf": np.max(np.abs(closure(crank, theta)[0])), "step_inf": step})
        if step <= request["tolerance"]:
            status = "converged"
            break
    return {"theta": theta, "status": status, "iterations": n, "trace": trace}
