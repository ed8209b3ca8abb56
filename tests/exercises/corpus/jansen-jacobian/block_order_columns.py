# BUG: J's columns follow the block order (theta1, theta2, theta3, theta4, theta6, theta7, theta5, theta8), not theta1 ... theta8
# CAUSE: mislabelled_entries
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
ORDER = [0, 1, 2, 3, 5, 6, 4, 7]  # the unknowns as the blocks solve them


def solve(request):
    th = np.array(request["theta"], dtype=float)
    g = request["crank_angle"]
    Y, X = 15 * np.sin(g) + 7.8, 15 * np.cos(g) + 38
    ls, lc = LEN * np.sin(th), LEN * np.cos(th)
    f = np.array([Y + ls[0] - ls[1], X + lc[0] - lc[1],
                  Y + ls[0] + ls[2] - ls[3], X + lc[0] + lc[2] - lc[3],
                  Y + ls[5] - ls[6], X + lc[5] - lc[6],
                  Y + ls[0] + ls[2] + ls[4] - ls[6] - ls[7], X + lc[0] + lc[2] + lc[4] - lc[6] - lc[7]])
    full = np.zeros((8, 8))
    for row, terms in enumerate([[(0, 1), (1, -1)], [(0, 1), (2, 1), (3, -1)], [(5, 1), (6, -1)],
                                 [(0, 1), (2, 1), (4, 1), (6, -1), (7, -1)]]):
        for k, sign in terms:
            full[2 * row, k] = sign * lc[k]
            full[2 * row + 1, k] = -sign * ls[k]
    return {"f": f, "J": full[:, ORDER]}
