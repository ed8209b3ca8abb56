# BUG: J by forward differences of f with step h = 1e-6 instead of the analytic derivative
# CAUSE: finite_difference_jacobian
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])


def residual(crank, th):
    Y = 15.0 * np.sin(crank) + 7.8
    X = 15.0 * np.cos(crank) + 38.0
    ls = LEN * np.sin(th)
    lc = LEN * np.cos(th)
    return np.array([Y + ls[0] - ls[1], X + lc[0] - lc[1],
                     Y + ls[0] + ls[2] - ls[3], X + lc[0] + lc[2] - lc[3],
                     Y + ls[5] - ls[6], X + lc[5] - lc[6],
                     Y + ls[0] + ls[2] + ls[4] - ls[6] - ls[7], X + lc[0] + lc[2] + lc[4] - lc[6] - lc[7]])


def solve(request):
    crank = request["crank_angle"]
    th = np.array(request["theta"], dtype=float)
    f0 = residual(crank, th)
    h = 1e-6
    J = np.zeros((8, 8))
    for k in range(8):
        tp = th.copy()
        tp[k] += h
        J[:, k] = (residual(crank, tp) - f0) / h
    return {"f": f0, "J": J}
