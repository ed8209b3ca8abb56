# BUG: each loop's y component is put first and its x component second (rows 2p and 2p + 1 swapped in f and J)
# CAUSE: mislabelled_entries
R = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49.0, 65.7])
K = np.array([[1, 1, 0, 0, 0, 0, 0, 0, 0, 0],
              [0, -1, 1, 1, 0, 0, 0, 0, 0, 0],
              [0, 0, 0, 1, -1, 1, -1, 0, 0, 0],
              [0, 0, 0, 0, 0, -1, 0, -1, 0, 0],
              [0, 0, 0, 0, 0, 0, 1, 0, 1, 1]], dtype=float)


def solve(request):
    th = np.array(request["theta"], dtype=float)
    t2 = request["crank_angle"]
    X, Y = 38 + 15 * np.cos(t2), 7.8 + 15 * np.sin(t2)
    f, J = np.zeros(10), np.zeros((10, 10))
    for loop in range(5):
        w = K[loop] * R
        crank = loop in (0, 3)
        f[2 * loop] = (Y if crank else 0) + w @ np.sin(th)
        f[2 * loop + 1] = (X if crank else 0) + w @ np.cos(th)
        J[2 * loop] = w * np.cos(th)
        J[2 * loop + 1] = -w * np.sin(th)
    return {"f": f, "J": J}
