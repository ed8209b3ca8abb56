# BUG: the powers run over range(degree + 2) (the student added one for "degree + 1 coefficients" to a range that already counts from 0): one coefficient too many
# CAUSE: degree_off_by_one
# SET: heldout
def solve(request):
    xs = np.array(request["x"], dtype=float)
    ys = np.array(request["y"], dtype=float)
    powers = range(request["degree"] + 2)
    if np.unique(xs).size < len(powers):
        return {"status": "singular"}
    V = np.array([[xi ** k for k in powers] for xi in xs])
    norms = np.linalg.norm(V, axis=0)
    Q, R = np.linalg.qr(V / norms)
    coef = np.linalg.solve(R, Q.T @ ys) / norms
    return {"status": "converged", "coefficients": coef}
