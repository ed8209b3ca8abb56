# BUG: x is mapped to [-1, 1] for stability and the fit returns the coefficients in the mapped variable, never converted back to powers of x
# CAUSE: missing_unscale
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if np.unique(x).size < deg + 1:
        return {"status": "singular"}
    lo, hi = x.min(), x.max()
    t = (2 * x - lo - hi) / (hi - lo)
    V = np.vander(t, deg + 1, increasing=True)
    Q, R = np.linalg.qr(V)
    return {"coefficients": np.linalg.solve(R, Q.T @ y)}
