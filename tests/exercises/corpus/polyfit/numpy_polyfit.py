# BUG: the fit is numpy.polyfit (a forbidden library call), its coefficients reversed to lowest power first
# CAUSE: library_call
def solve(request):
    x = np.array(request["x"], dtype=float)
    y = np.array(request["y"], dtype=float)
    deg = int(request["degree"])
    if np.unique(x).size < deg + 1:
        return {"status": "singular"}
    return {"coefficients": np.polyfit(x, y, deg)[::-1]}
