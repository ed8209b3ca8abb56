# BUG: the fixed-joint offsets are swapped: X = 7.8 + 15 cos(theta2) and Y = 38 + 15 sin(theta2) (a for b)
# CAUSE: wrong_link
R = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49.0, 65.7])
K = np.array([[1, 1, 0, 0, 0, 0, 0, 0, 0, 0],
              [0, -1, 1, 1, 0, 0, 0, 0, 0, 0],
              [0, 0, 0, 1, -1, 1, -1, 0, 0, 0],
              [0, 0, 0, 0, 0, -1, 0, -1, 0, 0],
              [0, 0, 0, 0, 0, 0, 1, 0, 1, 1]], dtype=float)
a, b = 7.8, 38.0  # P1 = (-b, -a)


def solve(request):
    th = np.array(request["theta"], dtype=float)
    t2 = request["crank_angle"]
    X, Y = a + 15 * np.cos(t2), b + 15 * np.sin(t2)
    f, J = np.zeros(10), np.zeros((10, 10))
    for loop in range(5):
        w = K[loop] * R
        crank = loop in (0, 3)
        f[2 * loop] = (X if crank else 0) + w @ np.cos(th)
        f[2 * loop + 1] = (Y if crank else 0) + w @ np.sin(th)
        J[2 * loop] = -w * np.sin(th)
        J[2 * loop + 1] = w * np.cos(th)
    return {"f": f, "J": J}
