# BUG: the crank angle is converted with math.radians as if it were given in degrees
# CAUSE: degrees_for_radians
import math

l1, l2, l3, l4, l5, l6, l7, l8 = 50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7


def equations(ti, t):
    s, c = np.sin(t), np.cos(t)
    Y, X = 15.0 * math.sin(ti) + 7.8, 15.0 * math.cos(ti) + 38.0
    f = np.array([Y + l1 * s[0] - l2 * s[1], X + l1 * c[0] - l2 * c[1],
                  Y + l1 * s[0] + l3 * s[2] - l4 * s[3], X + l1 * c[0] + l3 * c[2] - l4 * c[3],
                  Y + l6 * s[5] - l7 * s[6], X + l6 * c[5] - l7 * c[6],
                  Y + l1 * s[0] + l3 * s[2] + l5 * s[4] - l7 * s[6] - l8 * s[7],
                  X + l1 * c[0] + l3 * c[2] + l5 * c[4] - l7 * c[6] - l8 * c[7]])
    J = np.zeros((8, 8))
    J[0, :2] = l1 * c[0], -l2 * c[1]
    J[1, :2] = -l1 * s[0], l2 * s[1]
    J[2, [0, 2, 3]] = l1 * c[0], l3 * c[2], -l4 * c[3]
    J[3, [0, 2, 3]] = -l1 * s[0], -l3 * s[2], l4 * s[3]
    J[4, [5, 6]] = l6 * c[5], -l7 * c[6]
    J[5, [5, 6]] = -l6 * s[5], l7 * s[6]
    J[6, [0, 2, 4, 6, 7]] = l1 * c[0], l3 * c[2], l5 * c[4], -l7 * c[6], -l8 * c[7]
    J[7, [0, 2, 4, 6, 7]] = -l1 * s[0], -l3 * s[2], -l5 * s[4], l7 * s[6], l8 * s[7]
    return f, J


def solve(request):
    ti = math.radians(request["crank_angle"])
    t = np.array(request["theta0"], dtype=float)
    hist, n, status = [], 0, "max_iterations"
    f, J = equations(ti, t)
    while np.abs(f).max() > request["tolerance"]:
        if n == request["max_iterations"]:
            break
        step = np.linalg.solve(J, -f)
        t = t + step
        n += 1
        f, J = equations(ti, t)
        hist.append({"residual_inf": np.abs(f).max(), "step_inf": np.abs(step).max()})
    else:
        status = "converged"
    return {"theta": t, "status": status, "iterations": n, "trace": hist}
