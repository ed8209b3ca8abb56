# BUG: none: Newton with f as the gap between each joint reached from the crank tip and from P1, the residual tested before each step, numpy's solve for J dx = -f (a check against false failures)
# CAUSE: none
# SET: heldout
L = {1: 50.0, 2: 41.5, 3: 55.8, 4: 40.1, 5: 39.4, 6: 61.9, 7: 39.3, 8: 36.7}
P1 = np.array([-38.0, -7.8])
# each joint reached two ways: the links from the crank tip A, the links from P1
JOINTS = [([1], [2]), ([1, 3], [4]), ([6], [7]), ([1, 3, 5], [7, 8])]


def f_and_jacobian(crank, theta):
    A = 15.0 * np.array([np.cos(crank), np.sin(crank)])
    f, J = [], np.zeros((8, 8))
    for r, (from_a, from_p1) in enumerate(JOINTS):
        gap = A - P1
        for sign, links in ((1.0, from_a), (-1.0, from_p1)):
            for k in links:
                t = theta[k - 1]
                gap = gap + sign * L[k] * np.array([np.cos(t), np.sin(t)])
                J[2 * r, k - 1] = sign * L[k] * np.cos(t)
                J[2 * r + 1, k - 1] = -sign * L[k] * np.sin(t)
        f += [gap[1], gap[0]]
    return np.array(f), J


def solve(request):
    crank = request["crank_angle"]
    theta = np.array(request["theta0"], dtype=float)
    tol = request["tolerance"]
    trace = []
    iterations = 0
    status = "max_iterations"
    while True:
        f, J = f_and_jacobian(crank, theta)
        if np.max(np.abs(f)) <= tol:
            status = "converged"
            break
        if iterations >= request["max_iterations"]:
            break
        try:
            dx = np.linalg.solve(J, -f)
        except np.linalg.LinAlgError:
            status = "singular"
            break
        theta = theta + dx
        iterations += 1
        trace.append({"residual_inf": np.max(np.abs(f_and_jacobian(crank, theta)[0])),
                      "step_inf": np.max(np.abs(dx))})
    return {"theta": theta, "status": status, "iterations": iterations, "trace": trace}
