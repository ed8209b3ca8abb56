# BUG: power-sum normal equations with the right-hand side sums shifted by one power, t[j] = sum x^(j+1) y
# CAUSE: normal_equations_wrong
def solve(request):
    x = np.asarray(request["x"], dtype=float)
    y = np.asarray(request["y"], dtype=float)
    n = int(request["degree"]) + 1
    if np.unique(x).size < n:
        return {"status": "singular"}
    N = np.zeros((n, n))
    r = np.zeros(n)
    for i in range(n):
        for j in range(n):
            N[i, j] = np.sum(x ** (i + j))
        r[i] = np.sum(x ** (i + 1) * y)
    return {"coefficients": np.linalg.solve(N, r)}
