"""Double points of rational curves (notes 19.2, 18.4.2-18.4.4).

Two ways:

* :func:`double_points` -- parameter pairs ``{s, t}``, ``s != t``, with
  ``P(s) x P(t) = 0``: the three components of ``(P(s) x P(t)) / (s - t)`` are
  symmetric, hence polynomials in ``sigma1 = s + t, sigma2 = s t`` (via
  ``(s^i t^j - s^j t^i)/(s - t) = -sigma2^i h_(j-i-1)``, ``h_k`` the complete
  symmetric polynomials); their common zeros (:func:`solve_bivariate`) are the
  double points, cusps included (``s = t``, ``sigma1^2 = 4 sigma2``).  Real
  ``sigma``: crunode (``sigma1^2 > 4 sigma2``, two real parameters), cusp (``=``),
  acnode (``<``, complex conjugate parameters).  A proper curve of degree ``n``
  with only such points has ``(n - 1)(n - 2) / 2`` of them over C (18.100).
* the moving-line methods of chapter 18: the axis of the pencil of a cubic's
  mu-basis (:func:`double_point_cubic`, 18.4.3) and the axial members of the
  pencil of quadratic moving lines of a quartic (:func:`double_points_quartic`,
  (18.70)-(18.73)).

>>> from exactcagd import BezierCurve
>>> dp = double_points(BezierCurve([[0, 0], [0, 1], [1, 2], [3, 0]]))
>>> [(d.kind, str(d.point[0]), str(d.point[1]), [str(p) for p in d.params]) for d in dp]
[('crunode', '3', '0', ['-1', '1'])]
"""

from __future__ import annotations

from dataclasses import dataclass

import flint
import sympy
from gmpy2 import mpq

from ..errors import DegreeError
from ..exact.algebraic import RealAlgebraic, real_roots
from ._diagnostics import ImproperParametrizationError
from ._poly import XY
from .implicitize import reduced_components
from .numberfield import NumberField, algebraic_sign, algebraic_value, interval_eval
from .solve import solve_bivariate

__all__ = ["DoublePoint", "double_point_polynomials", "double_points", "double_point_cubic", "double_points_quartic"]


@dataclass
class DoublePoint:
    """A double point of a rational curve.

    ``kind``: ``"crunode"``, ``"cusp"``, ``"acnode"`` or ``"complex"`` (non-real
    point; ``count`` conjugates).  ``point``: ``(x, y)`` RealAlgebraic (``None`` for
    a complex point, homogeneous ``(X, Y, 0)`` for a real point at infinity).
    ``params``: the real parameters (two for a crunode, one repeated for a cusp,
    ``None`` for acnodes/complex; ``None`` inside the pair means ``t = infinity``).
    ``sigma``: ``(s + t, s t)`` as RealAlgebraic when real.
    """

    kind: str
    point: tuple | None
    params: tuple | None
    sigma: tuple | None = None
    count: int = 1


def _coeffs(p) -> list[int]:
    return [int(c) for c in p.coeffs()]


def double_point_polynomials(X, Y, W) -> list:
    """The three symmetric polynomials ``(P(s) x P(t)) / (s - t)`` in ``(sigma1, sigma2)``,
    as ``fmpz_mpoly`` in the context ``(x, y) = (sigma1, sigma2)``."""
    s1, s2 = XY.gens()
    n = max(p.degree() for p in (X, Y, W))
    h = [XY.from_dict({(0, 0): 1}), s1]
    for _ in range(2, n + 1):
        h.append(s1 * h[-1] - s2 * h[-2])
    s2pow = [XY.from_dict({(0, 0): 1})]
    for _ in range(n):
        s2pow.append(s2pow[-1] * s2)
    comps = [_coeffs(p) + [0] * (n + 1 - p.degree() - 1) for p in (X, Y, W)]
    out = []
    for a, b in ((1, 2), (2, 0), (0, 1)):  # components of the cross product (18.3)
        A, B = comps[a], comps[b]
        acc = XY.from_dict({})
        for i in range(n + 1):
            for j in range(i + 1, n + 1):
                c = A[i] * B[j] - A[j] * B[i]
                if c:
                    acc -= c * s2pow[i] * h[j - i - 1]
        out.append(acc)
    return out


def _reduce_mod_quadratic(coeffs, K, s1, s2):
    """``p(z) mod (z^2 - s1 z + s2)`` over K: returns ``(A, B)`` with ``p = A + B z``."""
    a, b = K(1), K(0)
    A, B = K(0), K(0)
    for c in coeffs:
        A = A + a * c
        B = B + b * c
        a, b = K.mul(-s2, b), K(a + K.mul(s1, b))
    return K(A), K(B)


def _quadratic_roots(alpha, K, s1, s2, expected: int) -> list[RealAlgebraic]:
    """Real roots of ``z^2 - s1(alpha) z + s2(alpha)`` (exact: count-based selection)."""
    ctx = flint.fmpz_mpoly_ctx.get(("s", "z"), "lex")
    sv, z = ctx.gens()
    den = int(s1.denom()) * int(s2.denom())
    lift = lambda p: sum((int(c * den) * sv**k for k, c in enumerate(p.coeffs())), ctx.from_dict({}))  # noqa: E731
    m = sum((int(c) * sv**k for k, c in enumerate(alpha.poly.coeffs())), ctx.from_dict({}))
    q = den * z**2 - lift(s1) * z + lift(s2)
    N = m.resultant(q, "s")
    d = N.to_dict()
    top = max(e[1] for e in d)
    norm = [int(d.get((0, k), 0)) for k in range(top + 1)]
    cands = [r for r, _ in real_roots(norm)]
    while len(cands) > expected:
        keep = []
        s1i = interval_eval(s1, alpha.lo, alpha.hi)
        s2i = interval_eval(s2, alpha.lo, alpha.hi)
        for r in cands:
            zl, zh = r.lo, r.hi
            zz = sorted((zl * zl, zh * zh, zl * zh))
            z2 = (mpq(0) if zl <= 0 <= zh else zz[0], zz[-1])
            prods = [s1i[0] * zl, s1i[0] * zh, s1i[1] * zl, s1i[1] * zh]
            lo = z2[0] - max(prods) + s2i[0]
            hi = z2[1] - min(prods) + s2i[1]
            if lo <= 0 <= hi:
                keep.append(r)
        cands = keep
        if len(cands) > expected:
            alpha.refine((alpha.hi - alpha.lo) / 4)
            for r in cands:
                if not r.is_rational:
                    r.refine((r.hi - r.lo) / 4)
    return sorted(cands)


def double_points(curve) -> list[DoublePoint]:
    """All double points (crunodes, cusps, acnodes, complex) of a rational planar curve.

    Raises
    ------
    ImproperParametrizationError
        when the parametrization is not one-to-one (every point is "double").
    """
    X, Y, W, _ = reduced_components(curve)
    n = max(p.degree() for p in (X, Y, W))
    if n <= 2:
        return []
    D = [d for d in double_point_polynomials(X, Y, W) if d != 0]
    g = D[0]
    for d in D[1:]:
        g = g.gcd(d)
    if g.total_degree() > 0:
        raise ImproperParametrizationError("the parametrization is not proper: infinitely many parameter pairs")
    out = []
    comps = [[flint.fmpq(c) for c in _coeffs(p)] for p in (X, Y, W)]
    for orbit in solve_bivariate(D):
        K = orbit.field
        s1, s2 = orbit.x_element(), orbit.y_element()
        disc = K(K.mul(s1, s1) - 4 * s2)
        cusp = K.is_zero(disc)
        if cusp:
            zc = K(s1 / 2)
            vals = []
            for c in comps:
                acc = K(0)
                for coef in reversed(c):
                    acc = K(K.mul(acc, zc) + coef)
                vals.append(acc)
            coords = ((vals[0], vals[2]), (vals[1], vals[2])) if not K.is_zero(vals[2]) else None
        else:
            AB = [_reduce_mod_quadratic(c, K, s1, s2) for c in comps]
            if not K.is_zero(AB[2][1]):
                coords = ((AB[0][1], AB[2][1]), (AB[1][1], AB[2][1]))
            elif not K.is_zero(AB[2][0]):
                coords = ((AB[0][0], AB[2][0]), (AB[1][0], AB[2][0]))
            else:
                coords = None  # the double point is at infinity
        reals = real_roots(_coeffs(orbit.m))
        for alpha, _ in reals:
            sig = (algebraic_value(alpha, s1), algebraic_value(alpha, s2))
            pt = None
            if coords is not None:
                pt = (algebraic_value(alpha, *coords[0]), algebraic_value(alpha, *coords[1]))
            if cusp:
                t0 = algebraic_value(alpha, K(s1 / 2))
                out.append(DoublePoint("cusp", pt, (t0, t0), sig))
            elif algebraic_sign(alpha, disc) > 0:
                params = tuple(_quadratic_roots(alpha, K, s1, s2, 2))
                out.append(DoublePoint("crunode", pt, params, sig))
            else:
                out.append(DoublePoint("acnode", pt, None, sig))
        rest = orbit.m.degree() - len(reals)
        if rest:
            out.append(DoublePoint("complex", None, None, None, rest))
    out.extend(_at_parameter_infinity(X, Y, W, n))
    return out


def _at_parameter_infinity(X, Y, W, n) -> list[DoublePoint]:
    """Double points involving the parameter ``t = infinity``."""
    lead = [int(p.coeffs()[n]) if p.degree() == n else 0 for p in (X, Y, W)]
    Xq, Yq, Wq = X, Y, W
    cr = (Yq * lead[2] - Wq * lead[1], Wq * lead[0] - Xq * lead[2], Xq * lead[1] - Yq * lead[0])
    g = flint.fmpz_poly([])
    for c in cr:
        g = c if g == 0 else (g.gcd(c) if c != 0 else g)
    out = []
    pt = None
    if lead[2] != 0:
        pt = (RealAlgebraic.from_rational(mpq(lead[0], lead[2])), RealAlgebraic.from_rational(mpq(lead[1], lead[2])))
    if g != 0 and g.degree() >= 1:
        for t0, _ in real_roots(_coeffs(g)):
            out.append(DoublePoint("crunode", pt, (t0, None)))
        nreal = len(real_roots(_coeffs(g)))
        if g.degree() - nreal:
            out.append(DoublePoint("complex", None, None, None, g.degree() - nreal))
    # cusp at infinity: leading vector parallel to the next one
    nxt = [int(p.coeffs()[n - 1]) if p.degree() >= n - 1 else 0 for p in (X, Y, W)]
    cross = (lead[1] * nxt[2] - nxt[1] * lead[2], nxt[0] * lead[2] - lead[0] * nxt[2], lead[0] * nxt[1] - nxt[0] * lead[1])
    if all(c == 0 for c in cross):
        out.append(DoublePoint("cusp", pt, (None, None)))
    return out


def double_point_cubic(curve):
    """The double point of a rational cubic: the axis of its pencil (18.4.3, (18.66)).

    Returns Cartesian ``(x, y)`` (``mpq``) or the homogeneous triple if at infinity.
    """
    from .moving_lines import mu_basis

    X, Y, W, _ = reduced_components(curve)
    if max(p.degree() for p in (X, Y, W)) != 3:
        raise DegreeError("double_point_cubic needs a curve of true degree 3")
    p, _ = mu_basis(curve)
    if p.degree != 1:  # pragma: no cover - proper cubics have mu = 1
        raise DegreeError("no pencil follows this cubic")
    return p.axis()


def double_points_quartic(curve) -> tuple[list, int]:
    """Double points of a rational quartic from its two quadratic moving lines (18.4.4).

    The combination ``L_Q = (1 - tau) L_1 + tau L_2`` is axial iff its three control
    lines are concurrent, ``det = 0`` (18.72), a cubic in ``tau``; the axes are the
    double points (18.73).  With a triple point the mu-basis contains a pencil whose
    axis is the triple point (18.76)-(18.77).

    Returns ``(points, n_complex)``: real points as ``(RealAlgebraic, RealAlgebraic)``
    and the number of non-real ones.
    """
    from .moving_lines import cross, mu_basis

    X, Y, W, _ = reduced_components(curve)
    if max(p.degree() for p in (X, Y, W)) != 4:
        raise DegreeError("double_points_quartic needs a curve of true degree 4")
    p, q = mu_basis(curve)
    if p.degree == 1:
        ax = p.axis()
        return [tuple(RealAlgebraic.from_rational(v) for v in ax)] if len(ax) == 2 else [], 0
    tau = sympy.Symbol("tau")
    L1 = [tuple(sympy.Rational(int(v.numerator), int(v.denominator)) for v in c) for c in p.bernstein()]
    L2 = [tuple(sympy.Rational(int(v.numerator), int(v.denominator)) for v in c) for c in q.bernstein()]
    LQ = [tuple((1 - tau) * a + tau * b for a, b in zip(l1, l2)) for l1, l2 in zip(L1, L2)]
    cubic = sympy.Poly(sympy.expand(sympy.Matrix(LQ).det()), tau)
    points, n_complex = [], 0
    if cubic.degree() < 3:  # tau = infinity: L2 itself is axial
        ax = q.axis()
        if ax is not None and len(ax) == 2:
            points.append(tuple(RealAlgebraic.from_rational(v) for v in ax))
    for fac, _ in sympy.factor_list(cubic)[1]:
        fp = sympy.Poly(fac, tau)
        m = flint.fmpz_poly([int(c) for c in reversed(fp.all_coeffs())])
        K = NumberField(m)
        lines = [[K(flint.fmpq_poly([flint.fmpq(int(sympy.Rational(c).p), int(sympy.Rational(c).q)) for c in reversed(sympy.Poly(comp, tau).all_coeffs())])) for comp in line] for line in LQ]
        axis = None
        for i in range(3):
            for j in range(i + 1, 3):
                a, b = lines[i], lines[j]
                c = [K(K.mul(a[1], b[2]) - K.mul(b[1], a[2])), K(K.mul(b[0], a[2]) - K.mul(a[0], b[2])), K(K.mul(a[0], b[1]) - K.mul(b[0], a[1]))]
                if not all(K.is_zero(v) for v in c):
                    axis = c
                    break
            if axis is not None:
                break
        reals = real_roots([int(c) for c in m.coeffs()])
        for alpha, _ in reals:
            if axis is None or K.is_zero(axis[2]):
                continue
            points.append((algebraic_value(alpha, axis[0], axis[2]), algebraic_value(alpha, axis[1], axis[2])))
        n_complex += m.degree() - len(reals)
    points.sort()
    return points, n_complex
