# BUG: d(l cos t)/dt is written +l sin t (the minus sign dropped) in every x row
# CAUSE: derivative_sign
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
SIGNS = np.array([[1, -1, 0, 0, 0, 0, 0, 0],
                  [1, 0, 1, -1, 0, 0, 0, 0],
                  [0, 0, 0, 0, 0, 1, -1, 0],
                  [1, 0, 1, 0, 1, 0, -1, -1]], dtype=float)


def solve(request):
    th = np.array(request["theta"], dtype=float)
    g = request["crank_angle"]
    Y, X = 15 * np.sin(g) + 7.8, 15 * np.cos(g) + 38
    f, J = np.zeros(8), np.zeros((8, 8))
    for r in range(4):
        w = SIGNS[r] * LEN
        f[2 * r] = Y + w @ np.sin(th)
        f[2 * r + 1] = X + w @ np.cos(th)
        J[2 * r] = w * np.cos(th)
        J[2 * r + 1] = w * np.sin(th)
    return {"f": f, "J": J}
