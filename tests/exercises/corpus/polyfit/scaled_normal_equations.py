# BUG: the columns of V are scaled to unit length (as the task asks), but then the normal equations (Vs^T Vs) z = Vs^T y are solved instead of a QR or SVD of Vs: kappa squared on Wampler's sets
# CAUSE: normal_equations_wrong
# SET: heldout
def solve(request):
    x = np.asarray(request["x"], dtype=float)
    y = np.asarray(request["y"], dtype=float)
    p = int(request["degree"]) + 1
    if len(set(x.tolist())) < p:
        return {"status": "singular"}
    V = np.column_stack([x ** k for k in range(p)])
    s = np.sqrt(np.sum(V * V, axis=0))
    Vs = V / s
    z = np.linalg.solve(Vs.T @ Vs, Vs.T @ y)
    return {"coefficients": z / s}
