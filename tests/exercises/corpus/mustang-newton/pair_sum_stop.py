# BUG: seed 003's stop test, |f_x + f_y| < tolerance for each loop: the two components of a loop can cancel
# CAUSE: stop_test
BEND, R, T = np.pi / 9, np.sqrt(0.5), 4 / 3
CHORD = 5 * np.cos(BEND)


def residual(th, A, B, C, D, E, F, G, H):
    return np.array([-2.5 * np.cos(th) + 2 * np.cos(A) + 2 * np.cos(B),
                     -1 - 2.5 * np.sin(th) + 2 * np.sin(A) + 2 * np.sin(B),
                     -R + CHORD * np.cos(th + BEND) + T * np.cos(C) - 5 * np.cos(D),
                     1 + R + CHORD * np.sin(th + BEND) - T * np.sin(C) - 5 * np.sin(D),
                     T * np.cos(th + BEND) + 4 * np.cos(C - BEND) - 4.5 * np.cos(E) - T * np.cos(F),
                     T * np.sin(th + BEND) - 4 * np.sin(C - BEND) + 4.5 * np.sin(E) - T * np.sin(F),
                     np.cos(C + BEND) + T * np.cos(F) - T * np.cos(G) + np.cos(H),
                     -np.sin(C + BEND) + T * np.sin(F) + T * np.sin(G) - np.sin(H)])


def jac(A, B, C, D, E, F, G, H):
    s, c = np.sin, np.cos
    return np.array([
        [-2 * s(A), -2 * s(B), 0, 0, 0, 0, 0, 0],
        [2 * c(A), 2 * c(B), 0, 0, 0, 0, 0, 0],
        [0, 0, -T * s(C), 5 * s(D), 0, 0, 0, 0],
        [0, 0, -T * c(C), -5 * c(D), 0, 0, 0, 0],
        [0, 0, -4 * s(C - BEND), 0, 4.5 * s(E), T * s(F), 0, 0],
        [0, 0, -4 * c(C - BEND), 0, 4.5 * c(E), -T * c(F), 0, 0],
        [0, 0, -s(C + BEND), 0, 0, -T * s(F), T * s(G), -s(H)],
        [0, 0, -c(C + BEND), 0, 0, T * c(F), T * c(G), -c(H)]])


def solve(request):
    th = request["crank_angle"]
    v = np.array(request["guess"], dtype=float)
    trace, k, status = [], 0, "max_iterations"
    while k < request["max_iterations"]:
        f = residual(th, *v)
        if all(abs(f[2 * i] + f[2 * i + 1]) < request["tolerance"] for i in range(4)):
            status = "converged"
            break
        dv = np.linalg.solve(jac(*v), -f)
        v = v + dv
        k += 1
        trace.append({"residual_inf": np.max(np.abs(residual(th, *v))), "step_inf": np.max(np.abs(dv))})
    else:
        if all(abs(residual(th, *v)[2 * i] + residual(th, *v)[2 * i + 1]) < request["tolerance"] for i in range(4)):
            status = "converged"
    return {"angles": v, "status": status, "iterations": k, "trace": trace}
