# BUG: none: QR of the column-scaled Vandermonde matrix, coefficients unscaled, lowest power first (a check against false failures)
# CAUSE: none
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if np.unique(x).size < deg + 1:
        return {"status": "singular"}
    V = np.vander(x, deg + 1, increasing=True)
    norms = np.linalg.norm(V, axis=0)
    Q, R = np.linalg.qr(V / norms)
    return {"coefficients": np.linalg.solve(R, Q.T @ y) / norms}
