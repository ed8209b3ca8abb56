# BUG: the inverse comes from numpy.linalg.inv (a forbidden library call) with a condition-number test in front of it
# CAUSE: library_call
def solve(request):
    A = np.array(request["A"], dtype=float)
    if not np.any(A) or np.linalg.cond(A) >= 1 / np.finfo(float).eps:
        return {"status": "singular"}
    return {"inverse": np.linalg.inv(A)}
