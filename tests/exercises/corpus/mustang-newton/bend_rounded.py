# BUG: the bend is typed as 0.349 rad (20 degrees rounded to 3 decimals) and the chord computed from it, 5 cos(0.349), instead of pi/9 exactly
# CAUSE: rounded_constants
# SET: heldout
BEND = 0.349
CHORD = 5 * np.cos(BEND)
ROOT_HALF = np.sqrt(0.5)
THIRD4 = 4 / 3


def residual_and_jacobian(theta, angles):
    A, B, C, D, E, F, G, H = angles
    cs, sn = np.cos, np.sin
    f = np.array([
        2 * cs(A) + 2 * cs(B) - 2.5 * cs(theta),
        2 * sn(A) + 2 * sn(B) - 2.5 * sn(theta) - 1,
        CHORD * cs(theta + BEND) + THIRD4 * cs(C) - 5 * cs(D) - ROOT_HALF,
        CHORD * sn(theta + BEND) - THIRD4 * sn(C) - 5 * sn(D) + 1 + ROOT_HALF,
        THIRD4 * cs(theta + BEND) + 4 * cs(C - BEND) - 4.5 * cs(E) - THIRD4 * cs(F),
        THIRD4 * sn(theta + BEND) - 4 * sn(C - BEND) + 4.5 * sn(E) - THIRD4 * sn(F),
        cs(C + BEND) + THIRD4 * cs(F) - THIRD4 * cs(G) + cs(H),
        -sn(C + BEND) + THIRD4 * sn(F) + THIRD4 * sn(G) - sn(H)])
    rows = [{0: -2 * sn(A), 1: -2 * sn(B)},
            {0: 2 * cs(A), 1: 2 * cs(B)},
            {2: -THIRD4 * sn(C), 3: 5 * sn(D)},
            {2: -THIRD4 * cs(C), 3: -5 * cs(D)},
            {2: -4 * sn(C - BEND), 4: 4.5 * sn(E), 5: THIRD4 * sn(F)},
            {2: -4 * cs(C - BEND), 4: 4.5 * cs(E), 5: -THIRD4 * cs(F)},
            {2: -sn(C + BEND), 5: -THIRD4 * sn(F), 6: THIRD4 * sn(G), 7: -sn(H)},
            {2: -cs(C + BEND), 5: THIRD4 * cs(F), 6: THIRD4 * cs(G), 7: -cs(H)}]
    J = np.zeros((8, 8))
    for i, row in enumerate(rows):
        for k, value in row.items():
            J[i, k] = value
    return f, J


def solve(request):
    theta = request["crank_angle"]
    x = np.array(request["guess"], dtype=float)
    trace = []
    k = 0
    f, J = residual_and_jacobian(theta, x)
    while np.max(np.abs(f)) > request["tolerance"] and k < request["max_iterations"]:
        dx = np.linalg.solve(J, -f)
        x = x + dx
        k += 1
        f, J = residual_and_jacobian(theta, x)
        trace.append({"residual_inf": float(np.max(np.abs(f))), "step_inf": float(np.max(np.abs(dx)))})
    status = "converged" if np.max(np.abs(f)) <= request["tolerance"] else "max_iterations"
    return {"angles": x, "status": status, "iterations": k, "trace": trace}
