"""Moving lines: implicitization with two moving lines (notes chapter 18).

A moving line ``L[t] = (a[t], b[t], c[t])`` *follows* a curve ``P[t] = (X, Y, W)``
when ``L[t] . P[t] == 0`` (18.14).  Every rational curve of degree ``n`` without
base points is the intersection of two moving lines of degrees ``mu`` and
``n - mu`` (a *mu-basis*); the implicit equation is their resultant, a
determinant of size ``n - mu`` (about ``n / 2``) instead of ``n`` (18.4.6).

Contents
--------
* :func:`cross`, :func:`dot` -- (18.3), (18.4); :func:`line_through` (18.6),
  :func:`intersection_point` (18.7);
* :func:`moving_line_following` (18.44), :func:`moving_point_of_lines` (18.49),
  :func:`axial_moving_line` (18.53);
* :func:`moving_line_matrix` -- the ``n x n`` matrix of control lines ``L_ij`` of
  (18.78) with (18.79) *as corrected* (sum over ``l <= min(i, j)``; ledger);
* :func:`zeroing_process` -- the elimination (18.80)-(18.84);
* :func:`mu_basis` -- the two moving lines (zeroing process, checked; exact
  null-space construction as fallback for special curves, e.g. triple points);
* :func:`implicit_from_moving_lines` -- the resultant of the two moving lines (18.85).

Moving lines are :class:`MovingLine` objects holding power-basis coefficients.

>>> from exactcagd import BezierCurve
>>> c = BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]])     # notes figure 18.11
>>> p, q = mu_basis(c)
>>> p.degree, q.degree
(1, 2)
>>> p.axis()                                               # the double point (18.66)
(mpq(3,1), mpq(0,1))
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DegreeError, InputError
from ..exact import bernstein as bz
from ._poly import XY, common_factor, curve_power, fmpq_poly_of

__all__ = [
    "cross",
    "dot",
    "line_through",
    "intersection_point",
    "MovingLine",
    "moving_line_following",
    "moving_point_of_lines",
    "axial_moving_line",
    "moving_line_matrix",
    "zeroing_process",
    "ZeroingResult",
    "mu_basis",
    "mu_basis_nullspace",
    "implicit_from_moving_lines",
    "homogeneous_control_points",
]


def cross(a, b) -> tuple:
    """``(a, b, c) x (d, e, f) = (bf - ec, dc - af, ae - db)`` (18.3)."""
    return (a[1] * b[2] - b[1] * a[2], b[0] * a[2] - a[0] * b[2], a[0] * b[1] - b[0] * a[1])


def dot(a, b):
    """``(a, b, c) . (d, e, f) = ad + be + cf`` (18.4)."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def line_through(p1, p2) -> tuple:
    """The line containing two homogeneous points: ``L = P1 x P2`` (18.6)."""
    return cross(p1, p2)


def intersection_point(l1, l2) -> tuple:
    """The homogeneous point common to two lines: ``P = L1 x L2`` (18.7)."""
    return cross(l1, l2)


def homogeneous_control_points(curve) -> list[tuple]:
    """Homogeneous control points ``P_i = (w_i x_i, w_i y_i, w_i)`` of a planar curve (18.11)."""
    if curve.dimension != 2:
        from ..errors import DimensionError

        raise DimensionError(f"moving lines need a planar curve, got dimension {curve.dimension}")
    return [tuple(row) for row in curve.homogeneous()]


# ------------------------------------------------------------------------ polynomials of triples
def _triples_mul(a: list, b: list) -> list:
    """Product of a power-basis polynomial ``a`` (scalars) and triples ``b``."""
    out = [(mpq(0), mpq(0), mpq(0))] * (len(a) + len(b) - 1)
    for i, s in enumerate(a):
        if s == 0:
            continue
        for j, v in enumerate(b):
            o = out[i + j]
            out[i + j] = (o[0] + s * v[0], o[1] + s * v[1], o[2] + s * v[2])
    return out


def _trim_triples(c: list) -> list:
    c = list(c)
    while len(c) > 1 and all(x == 0 for x in c[-1]):
        c.pop()
    return c


def _power_of_scaled_bernstein(entries: list) -> list:
    """``sum_j e_j (1 - t)^(d - j) t^j`` (no binomials) in power form; ``d = len - 1``."""
    d = len(entries) - 1
    out = [(mpq(0), mpq(0), mpq(0))] * (d + 1)
    for j, e in enumerate(entries):
        for i in range(d - j + 1):
            coef = bz.binomial(d - j, i) * (-1) ** i
            o = out[j + i]
            out[j + i] = (o[0] + coef * e[0], o[1] + coef * e[1], o[2] + coef * e[2])
    return out


@dataclass
class MovingLine:
    """A moving line ``L[t] = sum_k L_k t^k`` (power basis, triples of ``mpq``) (18.12)."""

    coeffs: list = field(default_factory=list)

    def __post_init__(self):
        self.coeffs = _trim_triples([tuple(mpq(x) for x in c) for c in self.coeffs])

    @property
    def degree(self) -> int:
        return len(self.coeffs) - 1

    @classmethod
    def from_bernstein(cls, control_lines) -> "MovingLine":
        """From control lines ``L_i`` of ``sum L_i B_i^n(t)`` (18.38)."""
        arr = np.array([[mpq(x) for x in line] for line in control_lines], dtype=object)
        power = bz.to_power(arr)
        return cls([tuple(row) for row in power])

    def bernstein(self, degree: int | None = None) -> list[tuple]:
        """Control lines in Bernstein form (of ``degree`` >= the degree, elevated)."""
        d = self.degree if degree is None else degree
        arr = np.array([list(c) for c in self.coeffs], dtype=object)
        return [tuple(row) for row in bz.from_power(arr, d)]

    def at(self, t) -> tuple:
        """The line ``L[t]`` (Horner)."""
        t = mpq(t)
        acc = (mpq(0), mpq(0), mpq(0))
        for c in reversed(self.coeffs):
            acc = (acc[0] * t + c[0], acc[1] * t + c[1], acc[2] * t + c[2])
        return acc

    def follows(self, X, Y, W) -> bool:
        """``L[t] . P[t] == 0`` identically (18.14); X, Y, W power-basis polynomials."""
        comps = [fmpq_poly_of([c[k] for c in self.coeffs]) for k in range(3)]
        return comps[0] * X + comps[1] * Y + comps[2] * W == 0

    def component_polys(self) -> tuple:
        return tuple(fmpq_poly_of([c[k] for c in self.coeffs]) for k in range(3))

    def remove_base_points(self) -> tuple["MovingLine", object]:
        """Divide out the gcd of the components (base points, 18.3.4): ``(line, gcd)``."""
        a, b, c = self.component_polys()
        g = a.gcd(b).gcd(c)
        if g.degree() <= 0:
            return self, flint.fmpq_poly([1])
        parts = [p // g for p in (a, b, c)]
        d = max(p.degree() for p in parts)
        coeffs = [tuple(mpq(int(p[k].p), int(p[k].q)) if k <= p.degree() else mpq(0) for p in parts) for k in range(d + 1)]
        return MovingLine(coeffs), g

    def axis(self):
        """The common point of all lines (an *axial* moving line, 18.3.5), or ``None``.

        Returns Cartesian ``(x, y)`` (``mpq``), or the homogeneous triple when the
        axis is at infinity.
        """
        rank_rows = [c for c in self.coeffs if any(x != 0 for x in c)]
        if len(rank_rows) < 2:
            return None
        ax = None
        for i in range(len(rank_rows)):
            for j in range(i + 1, len(rank_rows)):
                ax = cross(rank_rows[i], rank_rows[j])
                if any(x != 0 for x in ax):
                    break
            if ax is not None and any(x != 0 for x in ax):
                break
        if ax is None or all(x == 0 for x in ax):
            return None
        if any(dot(ax, c) != 0 for c in rank_rows):
            return None
        if ax[2] == 0:
            return ax
        return (ax[0] / ax[2], ax[1] / ax[2])

    def xy_coefficients(self) -> list:
        """Coefficients of ``L[t] . (x, y, 1)`` in ``t`` as integer polynomials in x, y.

        Scaled by one positive rational so that everything is integral.
        """
        den = 1
        for c in self.coeffs:
            for v in c:
                den = den * int(v.denominator) // math.gcd(den, int(v.denominator))
        x, y = XY.gens()
        return [int(c[0] * den) * x + int(c[1] * den) * y + int(c[2] * den) for c in self.coeffs]

    def scaled(self) -> "MovingLine":
        """The same moving line with coprime integer coefficients."""
        import math

        den = 1
        for c in self.coeffs:
            for v in c:
                den = den * int(v.denominator) // math.gcd(den, int(v.denominator))
        ints = [[int(v * den) for v in c] for c in self.coeffs]
        g = 0
        for c in ints:
            for v in c:
                g = math.gcd(g, v)
        g = g or 1
        return MovingLine([tuple(mpq(v, g) for v in c) for c in ints])


# ------------------------------------------------------------------------ constructions
def moving_line_following(P: list, Q: list) -> list[tuple]:
    """Control lines of ``L[t] = P[t] x Q[t]`` for Bézier moving points (18.43)-(18.44).

    ``L_k = sum_{i+j=k} C(m,i) C(n,j) P_i x Q_j / C(m+n, k)``.
    """
    m, n = len(P) - 1, len(Q) - 1
    out = []
    for k in range(m + n + 1):
        acc = (mpq(0), mpq(0), mpq(0))
        for i in range(max(0, k - n), min(m, k) + 1):
            c = cross(P[i], Q[k - i])
            w = bz.binomial(m, i) * bz.binomial(n, k - i)
            acc = (acc[0] + w * c[0], acc[1] + w * c[1], acc[2] + w * c[2])
        s = mpq(1, bz.binomial(m + n, k))
        out.append((acc[0] * s, acc[1] * s, acc[2] * s))
    return out


def moving_point_of_lines(L0: list, L1: list) -> list[tuple]:
    """Control points of ``P[t] = L0[t] x L1[t]`` (18.48)-(18.49), the dual of (18.44)."""
    return moving_line_following(L0, L1)


def axial_moving_line(axis, P: list) -> list[tuple]:
    """``L_i = P_A x P_i``: the axial moving line through ``axis`` following ``P`` (18.53)."""
    A = tuple(mpq(v) for v in axis) if len(axis) == 3 else (mpq(axis[0]), mpq(axis[1]), mpq(1))
    return [cross(A, p) for p in P]


def moving_line_matrix(P: list) -> list[list[tuple]]:
    """The ``n x n`` matrix of control lines of (18.57)/(18.78).

    ``L_ij = sum_{l + m = i + j + 1, l <= min(i, j)} C(n, l) C(n, m) P_l x P_m`` --
    the printed (18.58)/(18.79) omit ``l <= min(i, j)`` (without it the terms cancel
    in pairs); see the ledger.  Row ``i`` is a degree ``n - 1`` moving line in the
    basis ``(1 - t)^(n-1-j) t^j`` that follows the curve.
    """
    n = len(P) - 1
    if n < 1:
        raise DegreeError("moving lines need a curve of degree >= 1")
    M = [[None] * n for _ in range(n)]
    for i in range(n):
        for j in range(n):
            acc = (mpq(0), mpq(0), mpq(0))
            for lo in range(min(i, j) + 1):
                hi = i + j + 1 - lo
                if hi > n or hi <= lo:
                    continue
                c = cross(P[lo], P[hi])
                w = bz.binomial(n, lo) * bz.binomial(n, hi)
                acc = (acc[0] + w * c[0], acc[1] + w * c[1], acc[2] + w * c[2])
            M[i][j] = acc
    return M


@dataclass
class ZeroingResult:
    """Outcome of the zeroing process (18.80)-(18.84).

    ``steps``: the matrices after each elimination (lists of rows of triples, rows
    zeroed on the left); ``lines``: the final two moving lines (higher degree first),
    as :class:`MovingLine`; ``degrees``: their degrees; ``ops``: the row operations
    ``(step, row, pivot_rows, coefficients)``: ``row -= sum c_p * row_p`` (traces).
    """

    steps: list
    lines: tuple
    degrees: tuple
    ops: list = field(default_factory=list)


def _combine(rows: list, col: int, pivots: list, target: int) -> list | None:
    """Coefficients ``c`` with ``row_target[col] = sum c_p row_p[col]`` (None if impossible)."""
    vecs = [rows[p][col] for p in pivots]
    goal = rows[target][col]
    # solve in the least-squares-free exact way: try 1 or 2 pivots
    if len(vecs) == 1:
        v = vecs[0]
        k = next((i for i in range(3) if v[i] != 0), None)
        if k is None:
            return None
        c = goal[k] / v[k]
        if all(goal[i] == c * v[i] for i in range(3)):
            return [c]
        return None
    v, w = vecs
    for i in range(3):
        for j in range(i + 1, 3):
            det = v[i] * w[j] - v[j] * w[i]
            if det != 0:
                c1 = (goal[i] * w[j] - goal[j] * w[i]) / det
                c2 = (v[i] * goal[j] - v[j] * goal[i]) / det
                if all(goal[k] == c1 * v[k] + c2 * w[k] for k in range(3)):
                    return [c1, c2]
                return None
    return None


def zeroing_process(P: list) -> ZeroingResult:
    """The notes' zeroing process on the matrix (18.78) (generic case).

    At step ``s`` the rows ``2s-2, 2s-1`` are pivots and the entries of column
    ``s - 1`` of all later rows are eliminated (they are lines through ``P_0``,
    (18.82)).  For ``n = 2m`` the last two rows are two degree-``m`` moving lines
    (18.83); for ``n = 2m + 1`` the last step eliminates one entry and rows
    ``n - 2, n - 1`` are moving lines of degrees ``m + 1`` and ``m`` (18.84).

    Raises
    ------
    DegreeError
        when a pivot pair is dependent (special curves, e.g. a quartic with a triple
        point, 18.4.4); :func:`mu_basis` then falls back to the null-space method.
    """
    n = len(P) - 1
    M = [list(r) for r in moving_line_matrix(P)]
    steps = [[list(r) for r in M]]
    if n == 1:
        line = MovingLine(_power_of_scaled_bernstein(M[0]))
        return ZeroingResult(steps, (line,), (0,))
    s = 0
    ops = []
    while 2 * s + 2 <= n - 1:
        # rows 2s, 2s+1 are pivots for column s; zero column s in rows >= 2s+2
        piv = [2 * s, 2 * s + 1]
        for r in range(2 * s + 2, n):
            coef = _combine(M, s, piv, r)
            if coef is None:
                raise DegreeError("zeroing process: pivot lines are dependent (special curve)")
            ops.append((s, r, tuple(piv[: len(coef)]), tuple(coef)))
            for col in range(s, n):
                e = M[r][col]
                for c, p in zip(coef, piv):
                    q = M[p][col]
                    e = (e[0] - c * q[0], e[1] - c * q[1], e[2] - c * q[2])
                M[r][col] = e
        s += 1
        steps.append([list(r) for r in M])
    if n % 2 == 0:
        m = n // 2
        rows = (n - 2, n - 1)
        lines = tuple(MovingLine(_power_of_scaled_bernstein(M[r][m - 1 :])) for r in rows)
    else:
        m = (n - 1) // 2
        hi = MovingLine(_power_of_scaled_bernstein(M[n - 2][m - 1 :]))
        lo = MovingLine(_power_of_scaled_bernstein(M[n - 1][m:]))
        lines = (hi, lo)
    return ZeroingResult(steps, lines, tuple(l.degree for l in lines), ops)


# ------------------------------------------------------------------------ mu-basis
def _lines_of_degree(X, Y, W, d: int) -> list[MovingLine]:
    """A basis of the moving lines of degree <= d following ``(X, Y, W)`` (exact null space)."""
    comps = [X, Y, W]
    n = max(p.degree() for p in comps)
    rows = n + d + 1
    cols = 3 * (d + 1)
    entries = [[0] * cols for _ in range(rows)]
    for k, poly in enumerate(comps):
        coeffs = [int(c) for c in poly.coeffs()]
        for i in range(d + 1):
            for e, c in enumerate(coeffs):
                entries[i + e][k * (d + 1) + i] += c
    mat = flint.fmpz_mat(rows, cols, [v for row in entries for v in row])
    basis, nullity = mat.nullspace()
    out = []
    for j in range(int(nullity)):
        vec = [int(basis[i, j]) for i in range(cols)]
        coeffs = [tuple(mpq(vec[k * (d + 1) + i]) for k in range(3)) for i in range(d + 1)]
        out.append(MovingLine(coeffs).scaled())
    return out


def _independent_of_shifts(p: MovingLine, v: MovingLine, d: int) -> bool:
    """Is ``v`` outside the span of ``t^i p`` (i = 0 .. d - deg p)?"""
    shifts = [[(mpq(0),) * 3] * i + p.coeffs for i in range(d - p.degree + 1)]
    vecs = []
    for s in shifts + [v.coeffs]:
        s = list(s) + [(mpq(0),) * 3] * (d + 1 - len(s))
        vecs.append([x for c in s for x in c])
    rank = _rank(vecs)
    return rank == len(vecs)


def _rank(vectors) -> int:
    dens = []
    for v in vectors:
        den = 1
        for x in v:
            den = den * int(mpq(x).denominator) // math.gcd(den, int(mpq(x).denominator))
        dens.append([int(mpq(x) * den) for x in v])
    return int(flint.fmpz_mat(dens).rank()) if dens else 0


def mu_basis_nullspace(X, Y, W) -> tuple[MovingLine, MovingLine]:
    """A mu-basis ``(p, q)``, ``deg p + deg q = n``, by exact linear algebra.

    The moving lines of degree ``d`` following the curve form a space of dimension
    ``max(0, d - mu + 1) + max(0, d - (n - mu) + 1)``; the first ``d`` with a
    non-zero solution is ``mu``.
    """
    n = max(p.degree() for p in (X, Y, W))
    for d in range(0, n + 1):
        sols = _lines_of_degree(X, Y, W, d)
        if sols:
            break
    else:  # pragma: no cover - d = n always has solutions
        raise ArithmeticError("no moving line found")
    mu = d
    if len(sols) >= 2 and 2 * mu == n:
        p, q = sols[0], sols[1]
    else:
        p = sols[0]
        cand = _lines_of_degree(X, Y, W, n - mu)
        q = next(v for v in cand if _independent_of_shifts(p, v, n - mu))
    return p, q


def _is_basis(p: MovingLine, q: MovingLine, X, Y, W) -> bool:
    """``p x q == c P`` with a non-zero constant ``c`` (then (p, q) is a mu-basis)."""
    pa, pb, pc = p.component_polys()
    qa, qb, qc = q.component_polys()
    cr = (pb * qc - qb * pc, qa * pc - pa * qc, pa * qb - qa * pb)
    comps = [flint.fmpq_poly(list(c.coeffs())) for c in (X, Y, W)]
    # find the ratio from a non-zero component
    for a, b in zip(cr, comps):
        if b != 0:
            if a == 0 or a.degree() != b.degree():
                return False
            ratio = a.coeffs()[-1] / b.coeffs()[-1]
            break
    else:  # pragma: no cover
        return False
    return all(a == ratio * b for a, b in zip(cr, comps))


def mu_basis(curve, method: str = "auto") -> tuple[MovingLine, MovingLine]:
    """Two moving lines whose intersection is the curve (18.4), lower degree first.

    ``method="zeroing"`` runs the notes' zeroing process (18.80)-(18.84) on the
    curve's Bézier form, ``"nullspace"`` the exact linear-algebra construction,
    ``"auto"`` the zeroing process checked by ``p x q = const * P`` with the
    null-space method as fallback.  The curve must be free of base points (common
    factors of X, Y, W), which are removed first.

    Raises
    ------
    DegreeError
        for a constant curve.
    """
    X, Y, W = curve_power(curve)
    g, (X, Y, W) = common_factor(X, Y, W)
    from ._poly import check_not_constant

    check_not_constant(X, Y, W)
    if method not in ("auto", "zeroing", "nullspace"):
        raise InputError(f"unknown mu-basis method {method!r}")
    if method in ("auto", "zeroing"):
        P = _bernstein_hom(X, Y, W)
        try:
            res = zeroing_process(P)
            if len(res.lines) == 2:
                hi, lo = res.lines
                if _is_basis(hi, lo, X, Y, W):
                    return (lo, hi) if lo.degree <= hi.degree else (hi, lo)
            if method == "zeroing":
                raise DegreeError("zeroing process did not produce a basis (special curve)")
        except DegreeError:
            if method == "zeroing":
                raise
    return mu_basis_nullspace(X, Y, W)


def _bernstein_hom(X, Y, W) -> list[tuple]:
    """Homogeneous Bernstein control points of the power-form components (true degree)."""
    n = max(p.degree() for p in (X, Y, W))
    arr = np.empty((n + 1, 3), dtype=object)
    for j, p in enumerate((X, Y, W)):
        coeffs = [int(c) for c in p.coeffs()]
        for k in range(n + 1):
            arr[k, j] = mpq(coeffs[k]) if k < len(coeffs) else mpq(0)
    hom = bz.from_power(arr, n)
    return [tuple(row) for row in hom]


def implicit_from_moving_lines(p: MovingLine, q: MovingLine, via: str = "bezout"):
    """The resultant of ``p[t] . (x, y, 1)`` and ``q[t] . (x, y, 1)`` (18.85), in ``Z[x, y]``.

    ``via="bezout"``: the notes' (hybrid) Bezout determinant of size
    ``max(deg p, deg q)`` (about ``n / 2``), by fraction-free elimination;
    ``via="flint"``: python-flint's subresultant resultant of the same pair.  The
    value is the Sylvester resultant (sign and scale are normalized by the caller).
    """
    from .resultants import resultant_coeffs

    a = p.scaled().xy_coefficients()
    b = q.scaled().xy_coefficients()
    if len(a) < len(b):
        a, b = b, a
    return resultant_coeffs(a, b, via)
