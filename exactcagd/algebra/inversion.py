"""Inversion: the parameter ``t`` of a point ``(x, y)`` on a rational curve (17.5-17.7).

An inversion formula is a rational function ``t = f(x, y) / g(x, y)`` that holds
identically on the curve.  Routes:

* :func:`inversion` / :func:`inversion_linear_algebra` -- 17.7: solve the linear
  system ``t g(X, Y, W) - f(X, Y, W) == 0`` for forms of degree ``d``; ``d = 1`` for
  ``n <= 3`` and ``d = n - 2`` suffices for every proper curve of degree ``n >= 3``
  (the system has ``(d+1)(d+2)`` unknowns and ``n d + 2`` equations);
* :func:`inversion_cramer` -- 17.5: Cramer's rule on the first ``n - 1`` rows of
  the Bezout matrix of ``W x - X`` and ``W y - Y`` (degree ``n - 1`` formula);
* :func:`inversion_bezier` -- 17.6.1: (17.11) for ``n = 2`` and the linear formula
  (17.14) for cubics;
* :func:`inversion_moving_line` -- the pencil of a mu-basis with ``mu = 1``.

At a double point every inversion formula gives ``0/0`` (17.6.1).

>>> from exactcagd import BezierCurve
>>> c = BezierCurve([[1, 0], [5, 0], [5, 2], [4, 3]])      # notes 17.6.1 example
>>> inversion(c)
2*y/(x + y - 1)
"""

from __future__ import annotations

import flint
import sympy

from ..errors import DegreeError
from ._diagnostics import ImproperParametrizationError
from ._poly import X_SYM, Y_SYM, mpoly_to_sympy
from .implicitize import l_matrix, reduced_components, _xy_coeff_lists
from .resultants import bezout_matrix, det_bareiss

__all__ = [
    "inversion",
    "inversion_linear_algebra",
    "inversion_cramer",
    "inversion_bezier",
    "inversion_moving_line",
    "InversionFormula",
]


class InversionFormula:
    """``t = num(x, y) / den(x, y)`` with integer polynomial numerator and denominator.

    ``num`` and ``den`` are sympy expressions; ``homogeneous`` holds the forms in
    ``(x, y, w)`` (sympy) when the formula came from 17.7.
    """

    def __init__(self, num, den, homogeneous=None):
        self.num = sympy.expand(num)
        self.den = sympy.expand(den)
        self.homogeneous = homogeneous

    def expr(self):
        return self.num / self.den

    def __call__(self, x, y):
        """Exact value at a rational point; ``None`` for ``0/0`` (double point)."""
        subs = {X_SYM: sympy.Rational(str(x)), Y_SYM: sympy.Rational(str(y))}
        n, d = self.num.subs(subs), self.den.subs(subs)
        if d == 0:
            return None
        return n / d

    def __repr__(self):
        return f"InversionFormula(t = ({self.num}) / ({self.den}))"


def _monomials(d: int) -> list[tuple[int, int, int]]:
    return [(i, j, d - i - j) for i in range(d, -1, -1) for j in range(d - i, -1, -1)]


def _nullspace_int(rows: list[list[int]]) -> list[list[int]]:
    if not rows:
        return []
    mat = flint.fmpz_mat(len(rows), len(rows[0]), [v for r in rows for v in r])
    basis, nullity = mat.nullspace()
    return [[int(basis[i, j]) for i in range(len(rows[0]))] for j in range(int(nullity))]


def inversion_linear_algebra(curve, degree: int | None = None) -> InversionFormula:
    """Inversion formula of lowest degree by the linear algebra of 17.7 (17.16)-(17.20).

    ``degree`` forces the degree ``d`` of the forms; by default ``d`` runs from 1
    upward.  Among the solutions one with ``g(P(t)) != 0`` is chosen (with the fewest
    terms in ``g``, then in ``f``).

    Raises
    ------
    ImproperParametrizationError
        when no formula exists (the parametrization is not one-to-one).
    """
    X, Y, W, _ = reduced_components(curve)
    n = max(p.degree() for p in (X, Y, W))
    comps = (X, Y, W)
    degrees = [degree] if degree is not None else range(1, max(n - 1, 1) + 1)
    for d in degrees:
        monos = _monomials(d)
        polys = []
        for (i, j, k) in monos:
            polys.append(X**i * Y**j * W**k)
        top = n * d + 1
        rows = [[0] * (2 * len(monos)) for _ in range(top + 1)]
        for c, p in enumerate(polys):
            for e, v in enumerate(p.coeffs()):
                rows[e + 1][c] += int(v)  # t * g(P)
                rows[e][len(monos) + c] -= int(v)  # - f(P)
        candidates = []
        # prefer a polynomial formula (g = c w^d), then any formula
        w_only = [c for c, m in enumerate(monos) if m == (0, 0, d)][0]
        restricted = [[r[w_only]] + r[len(monos) :] for r in rows]
        vectors = [[0] * w_only + [v[0]] + [0] * (len(monos) - w_only - 1) + v[1:] for v in _nullspace_int(restricted)]
        for vec in vectors + _nullspace_int(rows):
            g_vec, f_vec = vec[: len(monos)], vec[len(monos) :]
            gP = sum((c * p for c, p in zip(g_vec, polys) if c), flint.fmpz_poly([]))
            if gP == 0:
                continue
            candidates.append((sum(1 for c in g_vec if c), sum(1 for c in f_vec if c), g_vec, f_vec))
        if candidates:
            if not vectors or candidates[0][2][w_only] == 0:
                candidates.sort(key=lambda c: (c[0], c[1]))
            _, _, g_vec, f_vec = candidates[0]
            w = sympy.Symbol("w")
            g_h = sum(c * X_SYM**i * Y_SYM**j * w**k for c, (i, j, k) in zip(g_vec, monos))
            f_h = sum(c * X_SYM**i * Y_SYM**j * w**k for c, (i, j, k) in zip(f_vec, monos))
            num, den = sympy.fraction(sympy.cancel(f_h.subs(w, 1) / g_h.subs(w, 1)))
            return InversionFormula(num, den, (f_h, g_h))
    raise ImproperParametrizationError(
        "no inversion formula exists: the parametrization is not one-to-one (improper)"
    )


def inversion(curve):
    """``t`` as a sympy expression in ``x, y`` (lowest-degree formula of 17.7).

    Valid at every point of the curve except its singular points (0/0 there).

    Raises
    ------
    ImproperParametrizationError
        for a parametrization that covers its curve more than once.
    DegreeError
        for a constant curve.
    """
    return inversion_linear_algebra(curve).expr()


def inversion_cramer(curve) -> InversionFormula:
    """Cramer's rule on the Bezout matrix of ``W x - X``, ``W y - Y`` (17.5).

    The first ``n - 1`` equations ``B (t^(n-1), ..., t, 1)^T = 0`` determine the
    vector up to scale: ``v_j = (-1)^j det(B without column j)``; ``t = v_(n-2) / v_(n-1)``.
    """
    X, Y, W, _ = reduced_components(curve)
    a, b = _xy_coeff_lists(X, Y, W)
    if len(a) < len(b):
        a, b = b, a
    n = len(a) - 1
    if n < 1:
        raise DegreeError("inversion needs a curve of degree >= 1")
    if n == 1:
        # a1 t + a0 = 0
        num, den = -a[0], a[1]
        if den == 0:
            num, den = -b[0], b[1]
        return InversionFormula(mpoly_to_sympy(num, (X_SYM, Y_SYM)).as_expr(), mpoly_to_sympy(den, (X_SYM, Y_SYM)).as_expr())
    B = bezout_matrix(a, b)
    rows = B[: n - 1]

    def minor(skip):
        return det_bareiss([[r[c] for c in range(n) if c != skip] for r in rows])

    v_num = minor(n - 2) * (-1) ** (n - 2)
    v_den = minor(n - 1) * (-1) ** (n - 1)
    conv = lambda p: mpoly_to_sympy(p, (X_SYM, Y_SYM)).as_expr() if not isinstance(p, int) else sympy.Integer(p)  # noqa: E731
    return InversionFormula(conv(v_num), conv(v_den))


def inversion_bezier(curve) -> InversionFormula:
    """Inversion in Bézier form (17.6.1): (17.11) for quadratics, (17.14) for cubics.

    ``n = 2``: ``t = l_20 / (l_20 - l_21)``.  ``n = 3``: with
    ``c_1 = w_0 |P_0 P_1 P_3| / (3 w_2 |P_1 P_2 P_3|)``,
    ``c_2 = -w_0 |P_0 P_2 P_3| / (3 w_1 |P_1 P_2 P_3|)``,
    ``l_a = c_1 l_31 + c_2 (l_30 + l_21) + l_20``, ``l_b = c_1 l_30 + c_2 l_20 + l_10``:
    ``t = l_b / (l_b - l_a)``.  Needs ``P_1, P_2, P_3`` not collinear for cubics.
    """
    n = curve.degree
    L = l_matrix(curve)
    if n == 2:
        return InversionFormula(L[(2, 0)], L[(2, 0)] - L[(2, 1)])
    if n != 3:
        raise DegreeError("inversion_bezier implements the notes' formulas for degrees 2 and 3")
    pts = curve.control_points
    w = curve.weights_array()
    D = lambda i, j, k: sympy.Matrix(  # noqa: E731
        [[sympy.Rational(str(pts[a][0])), sympy.Rational(str(pts[a][1])), 1] for a in (i, j, k)]
    ).det()
    d123 = D(1, 2, 3)
    if d123 == 0:
        raise DegreeError("formula (17.14) needs P1, P2, P3 not collinear")
    wq = [sympy.Rational(str(v)) for v in w]
    c1 = wq[0] * D(0, 1, 3) / (3 * wq[2] * d123)
    c2 = -wq[0] * D(0, 2, 3) / (3 * wq[1] * d123)
    la = sympy.expand(c1 * L[(3, 1)] + c2 * (L[(3, 0)] + L[(2, 1)]) + L[(2, 0)])
    lb = sympy.expand(c1 * L[(3, 0)] + c2 * L[(2, 0)] + L[(1, 0)])
    num, den = sympy.fraction(sympy.cancel(lb / (lb - la)))
    return InversionFormula(num, den)


def inversion_moving_line(curve) -> InversionFormula:
    """From a degree-one moving line ``p0 + t p1`` following the curve (a pencil, 18.4.3):
    ``t = -(p0 . X) / (p1 . X)`` with ``X = (x, y, 1)``.  Needs ``mu = 1``.
    """
    from .moving_lines import mu_basis

    p, _ = mu_basis(curve)
    if p.degree != 1:
        raise DegreeError(f"the curve's mu-basis starts with degree {p.degree}, not a pencil")
    c = p.xy_coefficients()
    return InversionFormula(-mpoly_to_sympy(c[0], (X_SYM, Y_SYM)).as_expr(), mpoly_to_sympy(c[1], (X_SYM, Y_SYM)).as_expr())
