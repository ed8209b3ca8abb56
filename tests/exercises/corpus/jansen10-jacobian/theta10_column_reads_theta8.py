# BUG: the theta10 column (J[6][7] and J[7][7], the D->A link 61.9) is evaluated with sin and cos of theta8 (the other link of that loop) where theta10 belongs
# CAUSE: wrong_angle_column
# SET: heldout
def solve(request):
    th2 = request["crank_angle"]
    t = np.asarray(request["theta"], dtype=float)
    c = {k + 3: np.cos(t[k]) for k in range(10)}
    s = {k + 3: np.sin(t[k]) for k in range(10)}
    X = 38 + 15 * np.cos(th2)
    Y = 7.8 + 15 * np.sin(th2)
    f = [X + 50 * c[3] + 41.5 * c[4],
         Y + 50 * s[3] + 41.5 * s[4],
         -41.5 * c[4] + 55.8 * c[5] + 40.1 * c[6],
         -41.5 * s[4] + 55.8 * s[5] + 40.1 * s[6],
         40.1 * c[6] - 39.4 * c[7] + 39.3 * c[8] - 36.7 * c[9],
         40.1 * s[6] - 39.4 * s[7] + 39.3 * s[8] - 36.7 * s[9],
         X - 39.3 * c[8] - 61.9 * c[10],
         Y - 39.3 * s[8] - 61.9 * s[10],
         36.7 * c[9] + 49 * c[11] + 65.7 * c[12],
         36.7 * s[9] + 49 * s[11] + 65.7 * s[12]]
    J = np.zeros((10, 10))
    J[0, 0], J[0, 1] = -50 * s[3], -41.5 * s[4]
    J[1, 0], J[1, 1] = 50 * c[3], 41.5 * c[4]
    J[2, 1], J[2, 2], J[2, 3] = 41.5 * s[4], -55.8 * s[5], -40.1 * s[6]
    J[3, 1], J[3, 2], J[3, 3] = -41.5 * c[4], 55.8 * c[5], 40.1 * c[6]
    J[4, 3], J[4, 4], J[4, 5], J[4, 6] = -40.1 * s[6], 39.4 * s[7], -39.3 * s[8], 36.7 * s[9]
    J[5, 3], J[5, 4], J[5, 5], J[5, 6] = 40.1 * c[6], -39.4 * c[7], 39.3 * c[8], -36.7 * c[9]
    J[6, 5], J[6, 7] = 39.3 * s[8], 61.9 * s[8]
    J[7, 5], J[7, 7] = -39.3 * c[8], -61.9 * c[8]
    J[8, 6], J[8, 8], J[8, 9] = -36.7 * s[9], -49 * s[11], -65.7 * s[12]
    J[9, 6], J[9, 8], J[9, 9] = 36.7 * c[9], 49 * c[11], 65.7 * c[12]
    return {"f": f, "J": J}
