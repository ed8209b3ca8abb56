# The correct f and J of seed 003's Mustang roof linkage, shared by the corpus files whose bug is elsewhere
# (a line "# include: mustang_closure.py" in a file stands for this text).
def loops(th, v, chord=2 * 2.5 * np.cos(np.pi / 9), r=np.sqrt(0.5), bend=np.pi / 9):
    A, B, C, D, E, F, G, H = v
    t = 4.0 / 3.0
    f = np.array([-2.5 * np.cos(th) + 2 * np.cos(A) + 2 * np.cos(B),
                  -1 - 2.5 * np.sin(th) + 2 * np.sin(A) + 2 * np.sin(B),
                  -r + chord * np.cos(th + bend) + t * np.cos(C) - 5 * np.cos(D),
                  1 + r + chord * np.sin(th + bend) - t * np.sin(C) - 5 * np.sin(D),
                  t * np.cos(th + bend) + 4 * np.cos(C - bend) - 4.5 * np.cos(E) - t * np.cos(F),
                  t * np.sin(th + bend) - 4 * np.sin(C - bend) + 4.5 * np.sin(E) - t * np.sin(F),
                  np.cos(C + bend) + t * np.cos(F) - t * np.cos(G) + np.cos(H),
                  -np.sin(C + bend) + t * np.sin(F) + t * np.sin(G) - np.sin(H)])
    J = np.zeros((8, 8))
    J[0, 0], J[0, 1], J[1, 0], J[1, 1] = -2 * np.sin(A), -2 * np.sin(B), 2 * np.cos(A), 2 * np.cos(B)
    J[2, 2], J[2, 3], J[3, 2], J[3, 3] = -t * np.sin(C), 5 * np.sin(D), -t * np.cos(C), -5 * np.cos(D)
    J[4, 2], J[4, 4], J[4, 5] = -4 * np.sin(C - bend), 4.5 * np.sin(E), t * np.sin(F)
    J[5, 2], J[5, 4], J[5, 5] = -4 * np.cos(C - bend), 4.5 * np.cos(E), -t * np.cos(F)
    J[6, 2], J[6, 5], J[6, 6], J[6, 7] = -np.sin(C + bend), -t * np.sin(F), t * np.sin(G), -np.sin(H)
    J[7, 2], J[7, 5], J[7, 6], J[7, 7] = -np.cos(C + bend), t * np.cos(F), t * np.cos(G), -np.cos(H)
    return f, J
