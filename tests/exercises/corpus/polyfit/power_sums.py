# BUG: seed 001's method: the normal equations from power sums, S[j][k] = sum x^(j+k), t[j] = sum x^j y, solved as they stand (kappa squared, no scaling)
# CAUSE: normal_equations_wrong
def solve(request):
    xs = np.array(request["x"], dtype=float)
    ys = np.array(request["y"], dtype=float)
    D = int(request["degree"])
    if len(set(xs.tolist())) < D + 1:
        return {"status": "singular"}
    sums = [np.sum(xs ** p) for p in range(2 * D + 1)]
    S = np.array([[sums[j + k] for k in range(D + 1)] for j in range(D + 1)])
    t = np.array([np.sum(xs ** j * ys) for j in range(D + 1)])
    return {"coefficients": np.linalg.solve(S, t)}
