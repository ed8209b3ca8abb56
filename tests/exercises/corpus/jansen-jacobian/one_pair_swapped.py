# BUG: one entry typed with its indices the wrong way round: J[2][0] (d f2/d theta1) is written into J[0][2], so J[0][2] and J[2][0] trade places
# CAUSE: transposed_pair
l1, l2, l3, l4, l5, l6, l7, l8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7


def solve(request):
    th = np.array(request["theta"], dtype=float)
    ti = request["crank_angle"]
    s, c = np.sin(th), np.cos(th)
    Y = 15.0 * np.sin(ti) + 7.8
    X = 15.0 * np.cos(ti) + 38.0
    f = np.array([Y + l1 * s[0] - l2 * s[1], X + l1 * c[0] - l2 * c[1],
                  Y + l1 * s[0] + l3 * s[2] - l4 * s[3], X + l1 * c[0] + l3 * c[2] - l4 * c[3],
                  Y + l6 * s[5] - l7 * s[6], X + l6 * c[5] - l7 * c[6],
                  Y + l1 * s[0] + l3 * s[2] + l5 * s[4] - l7 * s[6] - l8 * s[7],
                  X + l1 * c[0] + l3 * c[2] + l5 * c[4] - l7 * c[6] - l8 * c[7]])
    J = np.zeros((8, 8))
    J[0, 0], J[0, 1] = l1 * c[0], -l2 * c[1]
    J[1, 0], J[1, 1] = -l1 * s[0], l2 * s[1]
    J[0, 2], J[2, 2], J[2, 3] = l1 * c[0], l3 * c[2], -l4 * c[3]
    J[3, 0], J[3, 2], J[3, 3] = -l1 * s[0], -l3 * s[2], l4 * s[3]
    J[4, 5], J[4, 6] = l6 * c[5], -l7 * c[6]
    J[5, 5], J[5, 6] = -l6 * s[5], l7 * s[6]
    J[6, 0], J[6, 2], J[6, 4], J[6, 6], J[6, 7] = l1 * c[0], l3 * c[2], l5 * c[4], -l7 * c[6], -l8 * c[7]
    J[7, 0], J[7, 2], J[7, 4], J[7, 6], J[7, 7] = -l1 * s[0], -l3 * s[2], -l5 * s[4], l7 * s[6], l8 * s[7]
    return {"f": f, "J": J}
