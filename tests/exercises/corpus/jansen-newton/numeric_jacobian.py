# BUG: Newton's J comes from forward differences with a large step h = 1e-3, not the analytic derivative
# CAUSE: finite_difference_jacobian
import math

LENGTHS = [50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7]


def residual(ti, t):
    p = [L * math.sin(a) for L, a in zip(LENGTHS, t)]
    q = [L * math.cos(a) for L, a in zip(LENGTHS, t)]
    Y, X = 15 * math.sin(ti) + 7.8, 15 * math.cos(ti) + 38
    return np.array([Y + p[0] - p[1], X + q[0] - q[1], Y + p[0] + p[2] - p[3], X + q[0] + q[2] - q[3],
                     Y + p[5] - p[6], X + q[5] - q[6], Y + p[0] + p[2] + p[4] - p[6] - p[7],
                     X + q[0] + q[2] + q[4] - q[6] - q[7]])


def jacobian(ti, t, h=1e-3):
    base = residual(ti, t)
    cols = []
    for k in range(len(t)):
        moved = list(t)
        moved[k] += h
        cols.append((residual(ti, moved) - base) / h)
    return np.array(cols).T


def solve(request):
    ti = request["crank_angle"]
    t = np.array(request["theta0"], dtype=float)
    trace, count, status = [], 0, "max_iterations"
    while True:
        r = residual(ti, t)
        if np.max(np.abs(r)) <= request["tolerance"]:
            status = "converged"
            break
        if count >= request["max_iterations"]:
            break
        d = np.linalg.solve(jacobian(ti, t), -r)
        t = t + d
        count += 1
        trace.append({"residual_inf": np.max(np.abs(residual(ti, t))), "step_inf": np.max(np.abs(d))})
    return {"theta": t, "status": status, "iterations": count, "trace": trace}
