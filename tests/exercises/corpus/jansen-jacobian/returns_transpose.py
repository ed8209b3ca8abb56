# BUG: J is filled as J[k][i] = d f[i] / d theta_k (columns as rows): the whole Jacobian is transposed
# CAUSE: transposed_jacobian
l1, l2, l3, l4, l5, l6, l7, l8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7
li, a, b = 15.0, 7.8, 38.0


def solve(request):
    t = np.array(request["theta"], dtype=float)
    ti = request["crank_angle"]
    s, c = np.sin(t), np.cos(t)
    Y = li * np.sin(ti) + a
    X = li * np.cos(ti) + b
    f = [Y + l1 * s[0] - l2 * s[1],
         X + l1 * c[0] - l2 * c[1],
         Y + l1 * s[0] + l3 * s[2] - l4 * s[3],
         X + l1 * c[0] + l3 * c[2] - l4 * c[3],
         Y + l6 * s[5] - l7 * s[6],
         X + l6 * c[5] - l7 * c[6],
         Y + l1 * s[0] + l3 * s[2] + l5 * s[4] - l7 * s[6] - l8 * s[7],
         X + l1 * c[0] + l3 * c[2] + l5 * c[4] - l7 * c[6] - l8 * c[7]]
    J = np.zeros((8, 8))
    J[0][0], J[1][0] = l1 * c[0], -l2 * c[1]
    J[0][1], J[1][1] = -l1 * s[0], l2 * s[1]
    J[0][2], J[2][2], J[3][2] = l1 * c[0], l3 * c[2], -l4 * c[3]
    J[0][3], J[2][3], J[3][3] = -l1 * s[0], -l3 * s[2], l4 * s[3]
    J[5][4], J[6][4] = l6 * c[5], -l7 * c[6]
    J[5][5], J[6][5] = -l6 * s[5], l7 * s[6]
    J[0][6], J[2][6], J[4][6], J[6][6], J[7][6] = l1 * c[0], l3 * c[2], l5 * c[4], -l7 * c[6], -l8 * c[7]
    J[0][7], J[2][7], J[4][7], J[6][7], J[7][7] = -l1 * s[0], -l3 * s[2], -l5 * s[4], l7 * s[6], l8 * s[7]
    return {"f": f, "J": J}
