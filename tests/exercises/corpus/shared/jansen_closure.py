# The correct f and J of seed 000's Jansen leg, shared by the corpus files whose bug is elsewhere
# (a line "# include: jansen_closure.py" in a file stands for this text).
LEN = np.array([50.0, 41.5, 55.8, 40.1, 39.4, 61.9, 39.3, 36.7])
TERMS = [[(0, 1), (1, -1)], [(0, 1), (2, 1), (3, -1)], [(5, 1), (6, -1)], [(0, 1), (2, 1), (4, 1), (6, -1), (7, -1)]]


def f_and_J(crank, th):
    Y, X = 15 * np.sin(crank) + 7.8, 15 * np.cos(crank) + 38
    f, J = np.zeros(8), np.zeros((8, 8))
    for r, terms in enumerate(TERMS):
        f[2 * r] = Y + sum(s * LEN[k] * np.sin(th[k]) for k, s in terms)
        f[2 * r + 1] = X + sum(s * LEN[k] * np.cos(th[k]) for k, s in terms)
        for k, s in terms:
            J[2 * r, k] = s * LEN[k] * np.cos(th[k])
            J[2 * r + 1, k] = -s * LEN[k] * np.sin(th[k])
    return f, J
