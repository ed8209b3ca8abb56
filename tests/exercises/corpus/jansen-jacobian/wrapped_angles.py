# BUG: the angles are wrapped into [0, 2 pi) with np.mod before sin and cos, which changes nothing but the last bits
# CAUSE: no_effect
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
TERMS = [[(0, 1), (1, -1)], [(0, 1), (2, 1), (3, -1)], [(5, 1), (6, -1)], [(0, 1), (2, 1), (4, 1), (6, -1), (7, -1)]]


def solve(request):
    th = np.mod(np.array(request["theta"], dtype=float), 2 * np.pi)
    g = np.mod(float(request["crank_angle"]), 2 * np.pi)
    Y, X = 15 * np.sin(g) + 7.8, 15 * np.cos(g) + 38
    f, J = np.zeros(8), np.zeros((8, 8))
    for r, terms in enumerate(TERMS):
        f[2 * r] = Y + sum(s * LEN[k] * np.sin(th[k]) for k, s in terms)
        f[2 * r + 1] = X + sum(s * LEN[k] * np.cos(th[k]) for k, s in terms)
        for k, s in terms:
            J[2 * r, k] = s * LEN[k] * np.cos(th[k])
            J[2 * r + 1, k] = -s * LEN[k] * np.sin(th[k])
    return {"f": f, "J": J}
