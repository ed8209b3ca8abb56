# BUG: least squares on the raw Vandermonde matrix (numpy.linalg.lstsq on V, columns not scaled): Wampler's sets lose the digits the task allows
# CAUSE: unscaled_vandermonde
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if len(set(request["x"])) < deg + 1:
        return {"status": "singular"}
    V = np.vander(x, deg + 1, increasing=True)
    coeffs, *_ = np.linalg.lstsq(V, y, rcond=None)
    return {"coefficients": coeffs}
