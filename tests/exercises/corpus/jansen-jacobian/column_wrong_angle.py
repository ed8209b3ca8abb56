# BUG: the theta3 column of the C and E rows uses theta4's sine and cosine (s4/c4 where s3/c3 belong)
# CAUSE: wrong_angle_column
l1, l2, l3, l4, l5, l6, l7, l8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7


def solve(request):
    t1, t2, t3, t4, t5, t6, t7, t8 = request["theta"]
    ti = request["crank_angle"]
    Y = 15.0 * np.sin(ti) + 7.8
    X = 15.0 * np.cos(ti) + 38.0
    s1, s2, s3, s4, s5, s6, s7, s8 = np.sin([t1, t2, t3, t4, t5, t6, t7, t8])
    c1, c2, c3, c4, c5, c6, c7, c8 = np.cos([t1, t2, t3, t4, t5, t6, t7, t8])
    f = [Y + l1 * s1 - l2 * s2, X + l1 * c1 - l2 * c2,
         Y + l1 * s1 + l3 * s3 - l4 * s4, X + l1 * c1 + l3 * c3 - l4 * c4,
         Y + l6 * s6 - l7 * s7, X + l6 * c6 - l7 * c7,
         Y + l1 * s1 + l3 * s3 + l5 * s5 - l7 * s7 - l8 * s8,
         X + l1 * c1 + l3 * c3 + l5 * c5 - l7 * c7 - l8 * c8]
    J = [[l1 * c1, -l2 * c2, 0, 0, 0, 0, 0, 0],
         [-l1 * s1, l2 * s2, 0, 0, 0, 0, 0, 0],
         [l1 * c1, 0, l3 * c4, -l4 * c4, 0, 0, 0, 0],
         [-l1 * s1, 0, -l3 * s4, l4 * s4, 0, 0, 0, 0],
         [0, 0, 0, 0, 0, l6 * c6, -l7 * c7, 0],
         [0, 0, 0, 0, 0, -l6 * s6, l7 * s7, 0],
         [l1 * c1, 0, l3 * c4, 0, l5 * c5, 0, -l7 * c7, -l8 * c8],
         [-l1 * s1, 0, -l3 * s4, 0, -l5 * s5, 0, l7 * s7, l8 * s8]]
    return {"f": f, "J": J}
