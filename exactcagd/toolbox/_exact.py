"""Small exact helpers shared by the toolbox modules (private).

* exact linear algebra over Q (python-flint ``fmpq_mat``): solve, nullspace, rank;
* polynomials in power form (lists of ``mpq``, lowest degree first): evaluation,
  interval enclosure, arithmetic;
* exact extrema of a polynomial on an interval, with the extreme *value* carried as a
  :class:`~exactcagd.exact.algebraic.RealAlgebraic` (the resultant
  ``Res_x(f(x), D y - D p(x))`` gives its defining polynomial).

>>> from exactcagd.toolbox._exact import solve, poly_max
>>> solve([[1, 2], [3, 4]], [[1], [1]])[:, 0].tolist()
[mpq(-1,1), mpq(1,1)]
>>> value, where = poly_max([0, 1, -1], 0, 1)          # t - t^2 on [0, 1]
>>> value.value, [w.value for w in where]
(mpq(1,4), [mpq(1,2)])
"""

from __future__ import annotations

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import InputError
from ..exact.algebraic import RealAlgebraic, real_roots
from ..exact.scalars import from_fmpq as _from_fmpq
from ..exact.scalars import to_fmpq as _fmpq
from ..exact.scalars import to_rational

_MPQ = type(mpq(0))


# ---------------------------------------------------------------- conversions
def q(x) -> _MPQ:
    """Any exact number -> mpq (through the package's single entry point)."""
    return x if isinstance(x, _MPQ) else to_rational(x)


def matrix(rows) -> flint.fmpq_mat:
    rows = [list(r) for r in rows]
    n, m = len(rows), (len(rows[0]) if rows else 0)
    return flint.fmpq_mat(n, m, [_fmpq(x) for r in rows for x in r])


def to_array(mat: flint.fmpq_mat) -> np.ndarray:
    out = np.empty((mat.nrows(), mat.ncols()), dtype=object)
    for i in range(mat.nrows()):
        for j in range(mat.ncols()):
            out[i, j] = _from_fmpq(mat[i, j])
    return out


# ---------------------------------------------------------------- linear algebra
def solve(a, b, what: str = "linear system") -> np.ndarray:
    """Exact solution ``X`` of ``A X = B`` (``B`` a matrix: one column per right side).

    Raises :class:`InputError` when ``A`` is singular.
    """
    A, B = matrix(a), matrix(b)
    if A.nrows() != A.ncols():
        raise InputError(f"{what}: matrix is {A.nrows()}x{A.ncols()}, not square")
    try:
        return to_array(A.solve(B))
    except ZeroDivisionError:
        raise InputError(f"{what}: the matrix is singular (rank {A.rank()} < {A.nrows()})") from None


def rank(a) -> int:
    return matrix(a).rank()


def nullspace(a) -> list[np.ndarray]:
    """Basis of the right nullspace ``{x : A x = 0}`` (exact, from the reduced row echelon form)."""
    A = matrix(a)
    R, r = A.rref()
    m = A.ncols()
    pivots = []
    row = 0
    for col in range(m):
        if row < r and R[row, col] != 0:
            pivots.append(col)
            row += 1
    free = [c for c in range(m) if c not in pivots]
    basis = []
    for f in free:
        v = np.array([mpq(0)] * m, dtype=object)
        v[f] = mpq(1)
        for i, p in enumerate(pivots):
            v[p] = -_from_fmpq(R[i, f])
        basis.append(v)
    return basis


def solve_general(a, b) -> tuple[np.ndarray, list[np.ndarray]]:
    """Particular solution (free variables 0) and nullspace basis of ``A x = b`` (``b`` a vector).

    Raises :class:`InputError` when the system is inconsistent.
    """
    rows = [list(r) + [bi] for r, bi in zip(a, b)]
    M = matrix(rows)
    R, r = M.rref()
    m = M.ncols() - 1
    pivots = []
    row = 0
    for col in range(m + 1):
        if row < r and R[row, col] != 0:
            if col == m:
                raise InputError("the conditions are inconsistent (no solution)")
            pivots.append(col)
            row += 1
    x = np.array([mpq(0)] * m, dtype=object)
    for i, p in enumerate(pivots):
        x[p] = _from_fmpq(R[i, m])
    return x, nullspace(a)


# ---------------------------------------------------------------- power-form polynomials
def trim(p: list) -> list:
    p = [q(c) for c in p]
    while len(p) > 1 and p[-1] == 0:
        p.pop()
    return p or [mpq(0)]


def peval(p, x):
    """Horner evaluation of ``sum p[k] x^k`` (works for any ring element ``x``)."""
    acc = p[-1] * 1
    for c in reversed(p[:-1]):
        acc = acc * x + c
    return acc


def pmul(a, b) -> list:
    out = [mpq(0)] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        if x == 0:
            continue
        for j, y in enumerate(b):
            out[i + j] += x * y
    return out


def padd(a, b) -> list:
    n = max(len(a), len(b))
    return [(a[k] if k < len(a) else 0) + (b[k] if k < len(b) else 0) for k in range(n)]


def pscale(a, s) -> list:
    return [s * c for c in a]


def pderiv(p) -> list:
    return [k * p[k] for k in range(1, len(p))] or [mpq(0)]


def interval_eval(p, lo, hi) -> tuple:
    """Rational enclosure ``[m, M]`` of ``p`` over ``[lo, hi]`` (interval Horner)."""
    lo, hi = q(lo), q(hi)
    a = b = q(p[-1])
    for c in reversed(p[:-1]):
        prods = (a * lo, a * hi, b * lo, b * hi)
        a, b = min(prods) + c, max(prods) + c
    return a, b


def value_at(p, alpha: RealAlgebraic) -> RealAlgebraic:
    """The exact value ``p(alpha)`` of a rational polynomial at a real algebraic number.

    ``p(alpha)`` is a root of ``Res_x(f(x), D y - D p(x))`` (``f`` the defining polynomial
    of ``alpha``, ``D`` a common denominator); the right root is picked by refining the
    interval of ``alpha`` until the interval enclosure of ``p`` separates it.
    """
    p = trim(p)
    if alpha.is_rational:
        return RealAlgebraic.from_rational(peval(p, alpha.value))
    if len(p) == 1:
        return RealAlgebraic.from_rational(p[0])
    den = 1
    for c in p:
        den = den * int(c.denominator) // _gcd(den, int(c.denominator))
    ctx = flint.fmpz_mpoly_ctx.get(("x", "y"), "lex")
    x, y = ctx.gens()
    f = sum((int(c) * x**k for k, c in enumerate(alpha.poly.coeffs())), ctx.from_dict({}))
    g = den * y - sum((int(c * den) * x**k for k, c in enumerate(p)), ctx.from_dict({}))
    res = f.resultant(g, "x")
    coeffs = [0] * (res.degrees()[1] + 1)
    for exps, c in res.to_dict().items():
        coeffs[exps[1]] += int(c)
    candidates = [r for r, _ in real_roots(coeffs)]
    width = alpha.hi - alpha.lo
    while True:
        lo, hi = interval_eval(p, alpha.lo, alpha.hi)
        hits = [r for r in candidates if not (r.hi < lo or r.lo > hi)]
        if len(hits) == 1:
            return hits[0]
        for r in hits:
            if not r.is_rational:
                r.refine((r.hi - r.lo) / 2)
        width = width / 4
        alpha.refine(width)


def _gcd(a: int, b: int) -> int:
    while b:
        a, b = b, a % b
    return a


def critical_points(p, lo, hi) -> list:
    """Endpoints and the roots of ``p'`` in ``(lo, hi)`` as RealAlgebraic numbers, sorted."""
    lo, hi = q(lo), q(hi)
    pts = [RealAlgebraic.from_rational(lo)]
    d = trim(pderiv(trim(p)))
    if len(d) > 1 or d[0] != 0:
        pts += [r for r, _ in real_roots(d, lo, hi) if lo < r < hi]
    pts.append(RealAlgebraic.from_rational(hi))
    return pts


def poly_max(p, lo, hi) -> tuple[RealAlgebraic, list]:
    """Exact maximum of ``p`` on ``[lo, hi]``: ``(value, [arguments where it is attained])``."""
    p = trim(p)
    pts = critical_points(p, lo, hi)
    values = [value_at(p, a) for a in pts]
    best = values[0]
    for v in values[1:]:
        if v > best:
            best = v
    where = [a for a, v in zip(pts, values) if v == best]
    return best, where


def poly_min(p, lo, hi) -> tuple[RealAlgebraic, list]:
    """Exact minimum of ``p`` on ``[lo, hi]``."""
    value, where = poly_max([-c for c in trim(p)], lo, hi)
    return _negate(value), where


def _negate(a: RealAlgebraic) -> RealAlgebraic:
    if a.is_rational:
        return RealAlgebraic.from_rational(-a.value)
    coeffs = [int(c) * (-1) ** k for k, c in enumerate(a.poly.coeffs())]
    poly = flint.fmpz_poly(coeffs)
    if int(poly.coeffs()[-1]) < 0:
        poly = -poly
    return RealAlgebraic(poly, -a.hi, -a.lo)


def negate(a: RealAlgebraic) -> RealAlgebraic:
    """``-a`` for a RealAlgebraic ``a``."""
    return _negate(a)


def sign_on_interval(num, den, lo, hi) -> set:
    """Set of signs taken by ``num/den`` on ``[lo, hi]`` (exact; ``den`` must not vanish there).

    Samples one rational point in every open piece between consecutive roots of
    ``num * den`` plus the roots themselves (where ``num/den`` is 0 or undefined).
    """
    lo, hi = q(lo), q(hi)
    num, den = trim(num), trim(den)
    if any(True for _ in _roots_in(den, lo, hi)):
        raise InputError("the denominator vanishes on the interval")
    if len(num) == 1 and num[0] == 0:
        return {0}
    cuts = sorted({lo, hi} | set(_rational_cuts(num, lo, hi)))
    signs = set()
    for a, b in zip(cuts[:-1], cuts[1:]):
        mid = (a + b) / 2
        v = peval(num, mid) / peval(den, mid)
        signs.add((v > 0) - (v < 0))
    for r, _ in real_roots(num, lo, hi):
        signs.add(0)
    for x in (lo, hi):
        v = peval(num, x) / peval(den, x)
        signs.add((v > 0) - (v < 0))
    return signs


def _roots_in(p, lo, hi):
    if len(p) == 1:
        return []
    return [r for r, _ in real_roots(p, lo, hi)]


def _rational_cuts(p, lo, hi) -> list:
    """Rational points separating the real roots of ``p`` in ``[lo, hi]`` (root intervals' ends)."""
    out = []
    roots = sorted(_roots_in(p, lo, hi))
    # roots of different irreducible factors may have overlapping intervals: separate them
    changed = True
    while changed:
        changed = False
        for a, b in zip(roots[:-1], roots[1:]):
            if a.hi >= b.lo:
                for r in (a, b):
                    if not r.is_rational:
                        r.refine((r.hi - r.lo) / 2)
                changed = True
    for r in roots:
        if r.is_rational:
            out.append(r.value)
        else:
            # isolating intervals of distinct roots are disjoint: both ends separate
            out += [max(r.lo, lo), min(r.hi, hi)]
    return [x for x in out if lo <= x <= hi]


# ---------------------------------------------------------------- exact LP feasibility
def feasible_nonnegative(a, b):
    """A solution ``x >= 0`` of ``A x = b`` or ``None`` (exact phase-1 simplex, Bland's rule).

    Rows with negative right side are negated; artificial variables start as the basis and
    the sum of artificials is minimized; the system is feasible iff that minimum is 0.
    """
    A = [[q(x) for x in row] for row in a]
    rhs = [q(x) for x in b]
    m = len(A)
    n = len(A[0]) if m else 0
    for i in range(m):
        if rhs[i] < 0:
            A[i] = [-x for x in A[i]]
            rhs[i] = -rhs[i]
    # tableau columns: n originals, m artificials
    T = [A[i] + [mpq(1) if j == i else mpq(0) for j in range(m)] + [rhs[i]] for i in range(m)]
    basis = [n + i for i in range(m)]
    cost = [mpq(0)] * n + [mpq(1)] * m
    while True:
        # reduced costs r_j = c_j - c_B B^-1 A_j  (tableau rows are B^-1 A)
        reduced = [cost[j] - sum((cost[basis[i]] * T[i][j] for i in range(m)), mpq(0)) for j in range(n + m)]
        entering = next((j for j in range(n + m) if reduced[j] < 0), None)
        if entering is None:
            break
        ratios = [(T[i][-1] / T[i][entering], basis[i], i) for i in range(m) if T[i][entering] > 0]
        if not ratios:  # pragma: no cover - phase 1 is bounded below by 0
            break
        _, _, row = min(ratios)
        piv = T[row][entering]
        T[row] = [x / piv for x in T[row]]
        for i in range(m):
            if i != row and T[i][entering] != 0:
                f = T[i][entering]
                T[i] = [x - f * y for x, y in zip(T[i], T[row])]
        basis[row] = entering
    x = [mpq(0)] * (n + m)
    for i in range(m):
        x[basis[i]] = T[i][-1]
    if any(x[n + i] != 0 for i in range(m)):
        return None
    return x[:n]
