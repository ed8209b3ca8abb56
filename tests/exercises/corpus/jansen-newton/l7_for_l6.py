# BUG: J[4][5] and J[5][5] (the theta6 column of the D rows) use l7 = 39.3 where l6 = 61.9 belongs: Newton converges only linearly
# CAUSE: wrong_jacobian
import math

LENGTHS = [50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7]
PATHS = [((0, 1.0), (1, -1.0)), ((0, 1.0), (2, 1.0), (3, -1.0)), ((5, 1.0), (6, -1.0)),
         ((0, 1.0), (2, 1.0), (4, 1.0), (6, -1.0), (7, -1.0))]


def evaluate(ti, t):
    Y, X = 15 * math.sin(ti) + 7.8, 15 * math.cos(ti) + 38
    f = np.zeros(8)
    J = np.zeros((8, 8))
    for row, path in enumerate(PATHS):
        f[2 * row] = Y + sum(sg * LENGTHS[k] * math.sin(t[k]) for k, sg in path)
        f[2 * row + 1] = X + sum(sg * LENGTHS[k] * math.cos(t[k]) for k, sg in path)
        for k, sg in path:
            L = LENGTHS[6] if k == 5 else LENGTHS[k]
            J[2 * row, k] = sg * L * math.cos(t[k])
            J[2 * row + 1, k] = -sg * L * math.sin(t[k])
    return f, J


def solve(request):
    ti = request["crank_angle"]
    t = np.array(request["theta0"], dtype=float)
    out, it, status = [], 0, "max_iterations"
    f, J = evaluate(ti, t)
    while np.max(np.abs(f)) > request["tolerance"] and it < request["max_iterations"]:
        dt = np.linalg.solve(J, -f)
        t = t + dt
        it += 1
        f, J = evaluate(ti, t)
        out.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dt))})
    if np.max(np.abs(f)) <= request["tolerance"]:
        status = "converged"
    return {"theta": t, "status": status, "iterations": it, "trace": out}
