# BUG: seed 001's typo: the J entries of theta12 use 67.5 where |r12| = 65.7 (f uses 65.7)
# CAUSE: wrong_link
def solve(request):
    t3, t4, t5, t6, t7, t8, t9, t10, t11, t12 = request["theta"]
    t2 = request["crank_angle"]
    X = 38 + 15 * np.cos(t2)
    Y = 7.8 + 15 * np.sin(t2)
    cos, sin = np.cos, np.sin
    f = [X + 50 * cos(t3) + 41.5 * cos(t4), Y + 50 * sin(t3) + 41.5 * sin(t4),
         -41.5 * cos(t4) + 55.8 * cos(t5) + 40.1 * cos(t6), -41.5 * sin(t4) + 55.8 * sin(t5) + 40.1 * sin(t6),
         40.1 * cos(t6) - 39.4 * cos(t7) + 39.3 * cos(t8) - 36.7 * cos(t9),
         40.1 * sin(t6) - 39.4 * sin(t7) + 39.3 * sin(t8) - 36.7 * sin(t9),
         X - 39.3 * cos(t8) - 61.9 * cos(t10), Y - 39.3 * sin(t8) - 61.9 * sin(t10),
         36.7 * cos(t9) + 49 * cos(t11) + 65.7 * cos(t12), 36.7 * sin(t9) + 49 * sin(t11) + 65.7 * sin(t12)]
    J = np.zeros((10, 10))
    J[0, 0], J[0, 1] = -50 * sin(t3), -41.5 * sin(t4)
    J[1, 0], J[1, 1] = 50 * cos(t3), 41.5 * cos(t4)
    J[2, 1], J[2, 2], J[2, 3] = 41.5 * sin(t4), -55.8 * sin(t5), -40.1 * sin(t6)
    J[3, 1], J[3, 2], J[3, 3] = -41.5 * cos(t4), 55.8 * cos(t5), 40.1 * cos(t6)
    J[4, 3], J[4, 4], J[4, 5], J[4, 6] = -40.1 * sin(t6), 39.4 * sin(t7), -39.3 * sin(t8), 36.7 * sin(t9)
    J[5, 3], J[5, 4], J[5, 5], J[5, 6] = 40.1 * cos(t6), -39.4 * cos(t7), 39.3 * cos(t8), -36.7 * cos(t9)
    J[6, 5], J[6, 7] = 39.3 * sin(t8), 61.9 * sin(t10)
    J[7, 5], J[7, 7] = -39.3 * cos(t8), -61.9 * cos(t10)
    J[8, 6], J[8, 8], J[8, 9] = -36.7 * sin(t9), -49 * sin(t11), -67.5 * sin(t12)
    J[9, 6], J[9, 8], J[9, 9] = 36.7 * cos(t9), 49 * cos(t11), 67.5 * cos(t12)
    return {"f": f, "J": J}
