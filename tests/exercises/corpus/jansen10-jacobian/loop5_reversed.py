# BUG: loop 5 is walked the other way round (E->F->D->E), so f[8] = -(36.7 c9 + 49 c11 + 65.7 c12) and f[9] likewise: the last pair of f has the opposite sign (J with it)
# CAUSE: f_sign
# SET: heldout
R = {3: 50.0, 4: 41.5, 5: 55.8, 6: 40.1, 7: 39.4, 8: 39.3, 9: 36.7, 10: 61.9, 11: 49.0, 12: 65.7}
# (vector, sign) of each loop, x row first
LOOPS = [[(3, 1), (4, 1)],
         [(4, -1), (5, 1), (6, 1)],
         [(6, 1), (7, -1), (8, 1), (9, -1)],
         [(8, -1), (10, -1)],
         [(9, -1), (11, -1), (12, -1)]]


def solve(request):
    t2 = request["crank_angle"]
    th = dict(zip(range(3, 13), request["theta"]))
    X = 38.0 + 15.0 * np.cos(t2)
    Y = 7.8 + 15.0 * np.sin(t2)
    starts = [(X, Y), (0.0, 0.0), (0.0, 0.0), (X, Y), (0.0, 0.0)]
    f = np.zeros(10)
    J = np.zeros((10, 10))
    for p, loop in enumerate(LOOPS):
        f[2 * p], f[2 * p + 1] = starts[p]
        for v, s in loop:
            f[2 * p] += s * R[v] * np.cos(th[v])
            f[2 * p + 1] += s * R[v] * np.sin(th[v])
            J[2 * p, v - 3] = -s * R[v] * np.sin(th[v])
            J[2 * p + 1, v - 3] = s * R[v] * np.cos(th[v])
    return {"f": f, "J": J}
