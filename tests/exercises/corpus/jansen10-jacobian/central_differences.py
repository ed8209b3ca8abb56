# BUG: J by central differences of f (h = 1e-5) instead of the analytic derivative
# CAUSE: finite_difference_jacobian
R = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 39.3, 36.7, 61.9, 49.0, 65.7])
# coefficient of each unknown's vector in each loop (x and y rows share it); the crank enters loops 0 and 3
K = np.array([[1, 1, 0, 0, 0, 0, 0, 0, 0, 0],
              [0, -1, 1, 1, 0, 0, 0, 0, 0, 0],
              [0, 0, 0, 1, -1, 1, -1, 0, 0, 0],
              [0, 0, 0, 0, 0, -1, 0, -1, 0, 0],
              [0, 0, 0, 0, 0, 0, 1, 0, 1, 1]], dtype=float)


def f_of(t2, th):
    P = np.array([38 + 15 * np.cos(t2), 7.8 + 15 * np.sin(t2)])
    out = []
    for loop in range(5):
        w = K[loop] * R
        base = P if loop in (0, 3) else np.zeros(2)
        out += [base[0] + w @ np.cos(th), base[1] + w @ np.sin(th)]
    return np.array(out)


def solve(request):
    th = np.array(request["theta"], dtype=float)
    t2 = request["crank_angle"]
    h = 1e-5
    J = np.empty((10, 10))
    for k in range(10):
        e = np.zeros(10)
        e[k] = h
        J[:, k] = (f_of(t2, th + e) - f_of(t2, th - e)) / (2 * h)
    return {"f": f_of(t2, th), "J": J}
