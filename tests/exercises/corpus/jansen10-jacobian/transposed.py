# BUG: J is built row by row as d f / d theta_k for each unknown k, then sent as it is: the rows are the unknowns, so the whole J is transposed
# CAUSE: transposed_jacobian
r = {3: 50.0, 4: 41.5, 5: 55.8, 6: 40.1, 7: 39.4, 8: 39.3, 9: 36.7, 10: 61.9, 11: 49.0, 12: 65.7}
# loop -> (starts at the crank?, [(unknown, sign)])
LOOPS = [(True, [(3, 1), (4, 1)]), (False, [(4, -1), (5, 1), (6, 1)]), (False, [(6, 1), (7, -1), (8, 1), (9, -1)]),
         (True, [(8, -1), (10, -1)]), (False, [(9, 1), (11, 1), (12, 1)])]


def solve(request):
    th = dict(zip(range(3, 13), request["theta"]))
    t2 = request["crank_angle"]
    X, Y = 38.0 + 15.0 * np.cos(t2), 7.8 + 15.0 * np.sin(t2)
    f = []
    for crank, terms in LOOPS:
        f.append((X if crank else 0.0) + sum(s * r[k] * np.cos(th[k]) for k, s in terms))
        f.append((Y if crank else 0.0) + sum(s * r[k] * np.sin(th[k]) for k, s in terms))
    rows = []
    for k in range(3, 13):
        grad = []
        for crank, terms in LOOPS:
            s = dict(terms).get(k, 0)
            grad += [-s * r[k] * np.sin(th[k]), s * r[k] * np.cos(th[k])]
        rows.append(grad)
    return {"f": f, "J": rows}
