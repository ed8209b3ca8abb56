# BUG: the angles are taken to be degrees: theta and the crank angle go through np.radians before sin and cos
# CAUSE: degrees_for_radians
L = {"1": 50.0, "2": 41.5, "3": 55.8, "4": 40.1, "5": 39.4, "6": 61.9, "7": 39.3, "8": 36.7}
CRANK, A_OFF, B_OFF = 15.0, 7.8, 38.0


def solve(request):
    th = np.radians(np.array(request["theta"], dtype=float))
    phi = np.radians(float(request["crank_angle"]))
    S, C = np.sin(th), np.cos(th)
    Y = CRANK * np.sin(phi) + A_OFF
    X = CRANK * np.cos(phi) + B_OFF
    # each loop: (angle number, sign) along O->A->...->joint minus P1->...->joint
    loops = [[(1, 1), (2, -1)], [(1, 1), (3, 1), (4, -1)], [(6, 1), (7, -1)], [(1, 1), (3, 1), (5, 1), (7, -1), (8, -1)]]
    f = np.zeros(8)
    J = np.zeros((8, 8))
    for n, loop in enumerate(loops):
        f[2 * n] = Y + sum(sg * L[str(k)] * S[k - 1] for k, sg in loop)
        f[2 * n + 1] = X + sum(sg * L[str(k)] * C[k - 1] for k, sg in loop)
        for k, sg in loop:
            J[2 * n][k - 1] = sg * L[str(k)] * C[k - 1]
            J[2 * n + 1][k - 1] = -sg * L[str(k)] * S[k - 1]
    return {"f": f, "J": J}
