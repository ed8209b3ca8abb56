# BUG: the inverse is built right as a numpy array, then sent as inv.T.tolist() (the student thought the reply wanted columns): the transpose of the inverse
# CAUSE: transposed
# SET: heldout
import math


def solve(request):
    A = np.array(request["A"], dtype=float)
    m = np.max(np.abs(A))
    if m == 0.0:
        return {"status": "singular"}
    e = math.frexp(m)[1]
    S = np.ldexp(A, -e)
    a, b, c, d = S[0, 0], S[0, 1], S[1, 0], S[1, 1]
    det = a * d - b * c
    if abs(det) <= np.finfo(float).eps * np.sum(S * S):
        return {"status": "singular"}
    inv = np.array([[d, -b], [-c, a]]) / det
    inv = np.ldexp(inv, -e)
    return {"inverse": inv.T.tolist()}
