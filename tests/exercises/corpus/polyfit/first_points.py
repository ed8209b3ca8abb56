# BUG: the polynomial through the first degree + 1 points (a square Vandermonde system) instead of the least-squares fit to all of them
# CAUSE: interpolation
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if np.unique(x).size < deg + 1:
        return {"status": "singular"}
    xs, ys = x[:deg + 1], y[:deg + 1]
    V = np.vander(xs, deg + 1, increasing=True)
    scale = np.abs(V).max(axis=0)
    return {"coefficients": np.linalg.solve(V / scale, ys) / scale}
