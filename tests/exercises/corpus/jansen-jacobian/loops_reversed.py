# BUG: each loop is written P1 side minus crank side (P1->B - O->A->B), so every f[i] has the opposite sign (and J with it)
# CAUSE: f_sign
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
TERMS = [[(0, 1), (1, -1)], [(0, 1), (2, 1), (3, -1)], [(5, 1), (6, -1)], [(0, 1), (2, 1), (4, 1), (6, -1), (7, -1)]]


def solve(request):
    th = np.array(request["theta"], dtype=float)
    g = request["crank_angle"]
    A = np.array([15 * np.cos(g) + 38, 15 * np.sin(g) + 7.8])  # the crank tip seen from P1
    f, J = np.zeros(8), np.zeros((8, 8))
    for r, terms in enumerate(TERMS):
        p1_side = sum(-s * LEN[k] * np.array([np.cos(th[k]), np.sin(th[k])]) for k, s in terms)
        f[2 * r], f[2 * r + 1] = (p1_side - A)[::-1]
        for k, s in terms:
            J[2 * r, k] = -s * LEN[k] * np.cos(th[k])
            J[2 * r + 1, k] = s * LEN[k] * np.sin(th[k])
    return {"f": f, "J": J}
