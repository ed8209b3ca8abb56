# BUG: one entry typed with its indices the wrong way round: d f4 / d theta6 = l6 cos(theta6) is written into J[5][4] instead of J[4][5] (J[4][5] stays 0)
# CAUSE: transposed_pair
# SET: heldout
def solve(request):
    ti = request["crank_angle"]
    t1, t2, t3, t4, t5, t6, t7, t8 = request["theta"]
    li, a, b = 15.0, 7.8, 38.0
    l1, l2, l3, l4, l5, l6, l7, l8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7
    s1, s2, s3, s4, s5, s6, s7, s8 = np.sin([t1, t2, t3, t4, t5, t6, t7, t8])
    c1, c2, c3, c4, c5, c6, c7, c8 = np.cos([t1, t2, t3, t4, t5, t6, t7, t8])
    Y = li * np.sin(ti) + a
    X = li * np.cos(ti) + b
    f = [Y + l1 * s1 - l2 * s2,
         X + l1 * c1 - l2 * c2,
         Y + l1 * s1 + l3 * s3 - l4 * s4,
         X + l1 * c1 + l3 * c3 - l4 * c4,
         Y + l6 * s6 - l7 * s7,
         X + l6 * c6 - l7 * c7,
         Y + l1 * s1 + l3 * s3 + l5 * s5 - l7 * s7 - l8 * s8,
         X + l1 * c1 + l3 * c3 + l5 * c5 - l7 * c7 - l8 * c8]
    J = np.zeros((8, 8))
    J[0][0], J[0][1] = l1 * c1, -l2 * c2
    J[1][0], J[1][1] = -l1 * s1, l2 * s2
    J[2][0], J[2][2], J[2][3] = l1 * c1, l3 * c3, -l4 * c4
    J[3][0], J[3][2], J[3][3] = -l1 * s1, -l3 * s3, l4 * s4
    J[5][4], J[4][6] = l6 * c6, -l7 * c7
    J[5][5], J[5][6] = -l6 * s6, l7 * s7
    J[6][0], J[6][2], J[6][4], J[6][6], J[6][7] = l1 * c1, l3 * c3, l5 * c5, -l7 * c7, -l8 * c8
    J[7][0], J[7][2], J[7][4], J[7][6], J[7][7] = -l1 * s1, -l3 * s3, -l5 * s5, l7 * s7, l8 * s8
    return {"f": f, "J": J}
