# BUG: the length table has l5 = 39.3 (l7's value typed twice) where l5 = 39.4 belongs, so f and J both use the wrong C->E length
# CAUSE: wrong_link
# SET: heldout
LINKS = {"li": 15.0, "l1": 50.0, "l2": 41.5, "l3": 55.8, "l4": 40.1,
         "l5": 39.3, "l6": 61.9, "l7": 39.3, "l8": 36.7, "a": 7.8, "b": 38.0}
# each loop: (crank side links, P1 side links), as (angle index, length name)
LOOPS = [([(0, "l1")], [(1, "l2")]),
         ([(0, "l1"), (2, "l3")], [(3, "l4")]),
         ([(5, "l6")], [(6, "l7")]),
         ([(0, "l1"), (2, "l3"), (4, "l5")], [(6, "l7"), (7, "l8")])]


def solve(request):
    th = np.asarray(request["theta"], dtype=float)
    crank = request["crank_angle"]
    L = LINKS
    base_y = L["li"] * np.sin(crank) + L["a"]
    base_x = L["li"] * np.cos(crank) + L["b"]
    f = np.zeros(8)
    J = np.zeros((8, 8))
    for r, (plus, minus) in enumerate(LOOPS):
        f[2 * r], f[2 * r + 1] = base_y, base_x
        for sign, side in ((1.0, plus), (-1.0, minus)):
            for k, name in side:
                length = sign * L[name]
                f[2 * r] += length * np.sin(th[k])
                f[2 * r + 1] += length * np.cos(th[k])
                J[2 * r, k] += length * np.cos(th[k])
                J[2 * r + 1, k] -= length * np.sin(th[k])
    return {"f": f, "J": J}
