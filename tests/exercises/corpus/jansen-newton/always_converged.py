# BUG: the status is "converged" whenever the loop ends, also when it ran out of iterations
# CAUSE: converged_when_stopped
import math

LENGTHS = [50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7]
PATHS = [((0, 1.0), (1, -1.0)), ((0, 1.0), (2, 1.0), (3, -1.0)), ((5, 1.0), (6, -1.0)),
         ((0, 1.0), (2, 1.0), (4, 1.0), (6, -1.0), (7, -1.0))]


def evaluate(ti, t):
    Y, X = 15 * math.sin(ti) + 7.8, 15 * math.cos(ti) + 38
    f = np.zeros(8)
    J = np.zeros((8, 8))
    for row, path in enumerate(PATHS):
        for k, sg in path:
            f[2 * row] += sg * LENGTHS[k] * math.sin(t[k])
            f[2 * row + 1] += sg * LENGTHS[k] * math.cos(t[k])
            J[2 * row, k] = sg * LENGTHS[k] * math.cos(t[k])
            J[2 * row + 1, k] = -sg * LENGTHS[k] * math.sin(t[k])
        f[2 * row] += Y
        f[2 * row + 1] += X
    return f, J


def solve(request):
    ti = request["crank_angle"]
    t = np.array(request["theta0"], dtype=float)
    trace, it = [], 0
    f, J = evaluate(ti, t)
    while np.max(np.abs(f)) > request["tolerance"] and it < request["max_iterations"]:
        dt = np.linalg.solve(J, -f)
        t = t + dt
        it += 1
        f, J = evaluate(ti, t)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dt))})
    return {"theta": t, "status": "converged", "iterations": it, "trace": trace}
