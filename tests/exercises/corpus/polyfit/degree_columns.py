# BUG: the Vandermonde matrix gets `degree` columns (x^0 ... x^(D-1)), one too few
# CAUSE: degree_off_by_one
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    d = int(request["degree"])
    if len(np.unique(x)) < d + 1:
        return {"status": "singular"}
    V = np.column_stack([x ** k for k in range(d)])
    s = np.linalg.norm(V, axis=0)
    Q, R = np.linalg.qr(V / s)
    return {"coefficients": np.linalg.solve(R, Q.T @ y) / s}
