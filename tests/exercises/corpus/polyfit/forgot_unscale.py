# BUG: the columns of V are scaled to unit length but the solution is not divided by the scales afterwards
# CAUSE: missing_unscale
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if np.unique(x).size < deg + 1:
        return {"status": "singular"}
    V = np.vander(x, deg + 1, increasing=True)
    colnorm = np.linalg.norm(V, axis=0)
    Vs = V / colnorm
    Q, R = np.linalg.qr(Vs)
    beta = np.linalg.solve(R, Q.T @ y)
    return {"coefficients": beta}
