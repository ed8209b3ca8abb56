# BUG: the loops are written in the order B, C, E, D (the student followed the figure from the top): rows 4-5 hold the E loop and rows 6-7 the D loop, in f and in J
# CAUSE: mislabelled_entries
# SET: heldout
def solve(request):
    q = np.array(request["theta"], dtype=float)
    phi = float(request["crank_angle"])
    lengths = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
    loops = [{0: 1, 1: -1},
             {0: 1, 2: 1, 3: -1},
             {0: 1, 2: 1, 4: 1, 6: -1, 7: -1},
             {5: 1, 6: -1}]
    ya = 15.0 * np.sin(phi) + 7.8
    xa = 15.0 * np.cos(phi) + 38.0
    f = []
    J = []
    for loop in loops:
        fy, fx = ya, xa
        jy, jx = [0.0] * 8, [0.0] * 8
        for k, sgn in loop.items():
            fy += sgn * lengths[k] * np.sin(q[k])
            fx += sgn * lengths[k] * np.cos(q[k])
            jy[k] = sgn * lengths[k] * np.cos(q[k])
            jx[k] = -sgn * lengths[k] * np.sin(q[k])
        f += [fy, fx]
        J += [jy, jx]
    return {"f": f, "J": J}
