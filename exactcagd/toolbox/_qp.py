"""Exact convex quadratic programming via Lemke's algorithm (private).

``min 1/2 x^T H x + g^T x  subject to  A x <= b`` with ``H`` symmetric positive
semi-definite and exact rational data.  With ``x = u - v`` (``u, v >= 0``) the KKT
conditions are the linear complementarity problem

    w = M z + q,  w, z >= 0,  w^T z = 0,
    M = [[H', A'^T], [-A', 0]],  q = [g'; b],  H' = [[H, -H], [-H, H]],  A' = [A, -A],

with a positive semi-definite ``M``; Lemke's complementary pivoting (covering vector of
ones, lexicographic ratio test against cycling) solves it in exact rational arithmetic
whenever the QP is feasible and bounded below, and ends on a secondary ray otherwise.
The result is checked again exactly (feasibility, stationarity, ``lambda >= 0``,
complementarity): for a convex problem these KKT conditions certify the optimum.
"""

from __future__ import annotations

from gmpy2 import mpq

from ..errors import DomainError
from . import _exact as ex


def lemke(M: list, q: list, max_pivots: int = 10000) -> list:
    """A solution ``z`` of the LCP ``w = M z + q >= 0, z >= 0, w.z = 0`` (exact).

    Raises :class:`DomainError` on ray termination (no solution found: for a convex QP,
    infeasible constraints or an objective unbounded below).
    """
    n = len(q)
    if all(v >= 0 for v in q):
        return [mpq(0)] * n
    # tableau columns: w_0..w_{n-1}, z_0..z_{n-1}, z_art ; rows: I w - M z - e z_art = q
    cols = 2 * n + 1
    T = []
    for i in range(n):
        row = [mpq(0)] * cols
        row[i] = mpq(1)
        for j in range(n):
            row[n + j] = -M[i][j]
        row[2 * n] = mpq(-1)
        T.append(row)
    rhs = list(q)
    basis = list(range(n))  # w variables

    def pivot(r, c):
        piv = T[r][c]
        T[r] = [v / piv for v in T[r]]
        rhs[r] = rhs[r] / piv
        for i in range(n):
            if i != r and T[i][c] != 0:
                f = T[i][c]
                T[i] = [a - f * b for a, b in zip(T[i], T[r])]
                rhs[i] = rhs[i] - f * rhs[r]
        basis[r] = c

    def lex_key(i, c):
        # lexicographic ratio: (rhs_i, row of the basis inverse (w columns)) / T[i][c]
        return [rhs[i] / T[i][c]] + [T[i][k] / T[i][c] for k in range(n)]

    # first pivot: z_art enters, the row with the most negative q leaves
    r = min(range(n), key=lambda i: [rhs[i]] + [-T[i][k] for k in range(n)])
    pivot(r, 2 * n)
    leaving = r  # index of the w variable that left
    entering = n + leaving  # its complement z_leaving
    for _ in range(max_pivots):
        rows = [i for i in range(n) if T[i][entering] > 0]
        if not rows:
            raise DomainError("Lemke's algorithm ended on a ray: the QP is infeasible or unbounded below")
        # prefer the artificial variable on ties (terminates immediately)
        r = min(rows, key=lambda i: (lex_key(i, entering), basis[i] != 2 * n))
        left_var = basis[r]
        pivot(r, entering)
        if left_var == 2 * n:
            z = [mpq(0)] * n
            for i, b in enumerate(basis):
                if n <= b < 2 * n:
                    z[b - n] = rhs[i]
            return z
        entering = left_var + n if left_var < n else left_var - n
    raise DomainError("Lemke's algorithm did not terminate")  # pragma: no cover


def solve_qp(H, g, A, b) -> dict:
    """Certified exact minimizer; returns ``{"x", "multipliers", "active"}``."""
    H = [[ex.q(x) for x in row] for row in H]
    g = [ex.q(x) for x in g]
    A = [[ex.q(x) for x in row] for row in A]
    b = [ex.q(x) for x in b]
    n, m = len(g), len(A)
    N = 2 * n + m
    M = [[mpq(0)] * N for _ in range(N)]
    for i in range(n):
        for j in range(n):
            M[i][j] = H[i][j]
            M[i][n + j] = -H[i][j]
            M[n + i][j] = -H[i][j]
            M[n + i][n + j] = H[i][j]
        for k in range(m):
            M[i][2 * n + k] = A[k][i]
            M[n + i][2 * n + k] = -A[k][i]
    for k in range(m):
        for j in range(n):
            M[2 * n + k][j] = -A[k][j]
            M[2 * n + k][n + j] = A[k][j]
    q = list(g) + [-v for v in g] + list(b)
    z = lemke(M, q)
    x = [z[i] - z[n + i] for i in range(n)]
    lam = z[2 * n:]
    # exact certificate
    Ax = [sum((A[k][j] * x[j] for j in range(n)), mpq(0)) for k in range(m)]
    grad = [sum((H[i][j] * x[j] for j in range(n)), mpq(0)) + g[i] + sum((A[k][i] * lam[k] for k in range(m)), mpq(0)) for i in range(n)]
    if any(Ax[k] > b[k] for k in range(m)) or any(v != 0 for v in grad) or any(v < 0 for v in lam) \
            or any(lam[k] != 0 and Ax[k] != b[k] for k in range(m)):  # pragma: no cover - Lemke's output is exact
        raise AssertionError("KKT certificate failed")
    return {"x": x, "multipliers": lam, "active": [k for k in range(m) if Ax[k] == b[k]]}
