# BUG: the determinant is computed as b c - a d, so every entry of the inverse has the wrong sign
# CAUSE: determinant_sign
def solve(request):
    A = np.array(request["A"], dtype=float)
    s = 2.0 ** np.round(np.log2(np.max(np.abs(A)))) if np.any(A) else 1.0
    B = A / s
    det = B[0, 1] * B[1, 0] - B[0, 0] * B[1, 1]
    if abs(det) <= np.finfo(float).eps * np.sum(B * B):
        return {"status": "singular"}
    inv = np.array([[B[1, 1], -B[0, 1]], [-B[1, 0], B[0, 0]]]) / det
    return {"inverse": inv / s}
