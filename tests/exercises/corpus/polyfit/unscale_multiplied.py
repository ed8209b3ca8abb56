# BUG: the unscaling goes the wrong way: the solution of the column-scaled problem is multiplied by the column norms instead of divided by them
# CAUSE: missing_unscale
# SET: heldout
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    D = request["degree"]
    if len(np.unique(x)) <= D:
        return {"status": "singular"}
    V = np.vander(x, D + 1, increasing=True)
    w = np.linalg.norm(V, axis=0)
    U, sv, Wt = np.linalg.svd(V / w, full_matrices=False)
    z = Wt.T @ ((U.T @ y) / sv)
    return {"coefficients": z * w}
