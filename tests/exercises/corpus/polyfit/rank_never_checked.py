# BUG: no test for fewer distinct x than coefficients: an undetermined fit gets lstsq's minimum-norm answer instead of status singular
# CAUSE: no_rank_check
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    V = np.vander(x, deg + 1, increasing=True)
    s = np.linalg.norm(V, axis=0)
    b = np.linalg.lstsq(V / s, y, rcond=None)[0]
    return {"coefficients": b / s}
