# BUG: np.vander's default column order (highest power first), so the coefficients come out highest power first
# CAUSE: powers_reversed
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = request["degree"]
    if len(np.unique(x)) <= deg:
        return {"status": "singular"}
    V = np.vander(x, deg + 1)
    norms = np.sqrt((V ** 2).sum(axis=0))
    Q, R = np.linalg.qr(V / norms)
    coef = np.linalg.solve(R, Q.T @ y) / norms
    return {"coefficients": coef}
