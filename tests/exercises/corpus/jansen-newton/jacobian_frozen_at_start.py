# BUG: J is computed once at the start and reused for every step (the student "saved work" with a chord method): the steps are not Newton's and converge only linearly
# CAUSE: wrong_jacobian
# SET: heldout
L1, L2, L3, L4, L5, L6, L7, L8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7


def residual(ti, t):
    s, c = np.sin(t), np.cos(t)
    Y, X = 15.0 * np.sin(ti) + 7.8, 15.0 * np.cos(ti) + 38.0
    return np.array([Y + L1 * s[0] - L2 * s[1],
                     X + L1 * c[0] - L2 * c[1],
                     Y + L1 * s[0] + L3 * s[2] - L4 * s[3],
                     X + L1 * c[0] + L3 * c[2] - L4 * c[3],
                     Y + L6 * s[5] - L7 * s[6],
                     X + L6 * c[5] - L7 * c[6],
                     Y + L1 * s[0] + L3 * s[2] + L5 * s[4] - L7 * s[6] - L8 * s[7],
                     X + L1 * c[0] + L3 * c[2] + L5 * c[4] - L7 * c[6] - L8 * c[7]])


def jacobian(t):
    s, c = np.sin(t), np.cos(t)
    J = np.zeros((8, 8))
    J[0, :2] = [L1 * c[0], -L2 * c[1]]
    J[1, :2] = [-L1 * s[0], L2 * s[1]]
    J[2, [0, 2, 3]] = [L1 * c[0], L3 * c[2], -L4 * c[3]]
    J[3, [0, 2, 3]] = [-L1 * s[0], -L3 * s[2], L4 * s[3]]
    J[4, [5, 6]] = [L6 * c[5], -L7 * c[6]]
    J[5, [5, 6]] = [-L6 * s[5], L7 * s[6]]
    J[6, [0, 2, 4, 6, 7]] = [L1 * c[0], L3 * c[2], L5 * c[4], -L7 * c[6], -L8 * c[7]]
    J[7, [0, 2, 4, 6, 7]] = [-L1 * s[0], -L3 * s[2], -L5 * s[4], L7 * s[6], L8 * s[7]]
    return J


def solve(request):
    ti = request["crank_angle"]
    t = np.array(request["theta0"], dtype=float)
    tol, nmax = request["tolerance"], request["max_iterations"]
    J0 = jacobian(t)
    f = residual(ti, t)
    trace = []
    it = 0
    while np.max(np.abs(f)) > tol and it < nmax:
        dx = np.linalg.solve(J0, -f)
        t = t + dx
        it += 1
        f = residual(ti, t)
        trace.append({"residual_inf": np.max(np.abs(f)), "step_inf": np.max(np.abs(dx))})
    status = "converged" if np.max(np.abs(f)) <= tol else "max_iterations"
    return {"theta": t, "status": status, "iterations": it, "trace": trace}
