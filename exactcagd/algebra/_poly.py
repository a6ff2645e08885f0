"""Polynomial plumbing shared by the algebra modules (no mathematics of its own).

* integer polynomial rings of python-flint (``fmpz_mpoly``) in named variables;
* conversion between sympy expressions / ``Poly`` and flint polynomials;
* the homogeneous power-basis components ``(X(t), Y(t), W(t))`` of a planar curve;
* the sign/scale convention of implicit equations.

Convention for implicit equations (used by every route of :func:`implicitize`):
integer coefficients, content 1 (primitive), and the leading coefficient in
graded reverse lexicographic order with ``x > y`` is positive.

>>> from exactcagd import BezierCurve
>>> X, Y, W = curve_power(BezierCurve([[0, 0], [1, 2], [2, 0]]))
>>> X, Y, W
(2*x, (-4)*x^2 + 4*x, 1)
"""

from __future__ import annotations

from fractions import Fraction
from functools import lru_cache

import flint
import numpy as np
import sympy
from gmpy2 import mpq
from sympy.polys.domains import QQ, ZZ
from sympy.polys.polyclasses import DMP

from .. import limits
from ..errors import DegreeError, DimensionError, InputError, WeightError
from ..exact import bernstein as bz
from ..exact.scalars import from_fmpq, short_repr, to_fmpq

__all__ = [
    "X_SYM",
    "Y_SYM",
    "T_SYM",
    "zctx",
    "XY",
    "curve_power",
    "curve_from_polynomials",
    "primitive_fmpz_polys",
    "common_factor",
    "mpoly_to_sympy",
    "grevlex_full_poly",
    "grevlex_triangle_poly",
    "sympy_to_mpoly",
    "normalize_implicit",
    "fmpq_poly_of",
    "mpq_of",
]

X_SYM, Y_SYM = sympy.symbols("x y")
T_SYM = sympy.Symbol("t")


def polynomial_input(value, name: str):
    """A user polynomial for the implicit algebra: a sympy ``Poly`` or a polynomial sympy
    expression (an ``int``/``Fraction``/``mpq`` constant becomes a sympy ``Rational``).

    Strings are refused (``sympify`` would evaluate them: ``"1e100000000"`` runs for
    minutes), as are bools, bytes, ``oo``/``nan`` and non-polynomial expressions
    (``1/x``, ``sin(x)``), with :class:`InputError` naming ``name``; the total degree is
    bounded by the limit ``max_degree``.

    >>> x = sympy.Symbol("x")
    >>> polynomial_input(x**2 - 1, "f")
    x**2 - 1
    """
    if isinstance(value, sympy.Poly):
        limits.check("max_degree", value.total_degree(), f"{name}: total degree")
        return value
    if isinstance(value, (bool, str, bytes, bytearray)) or not isinstance(value, (sympy.Basic, int, Fraction, type(mpq(0)))):
        raise InputError(f"{name}: expected a sympy expression or Poly, got {type(value).__name__} {short_repr(value, 40)}")
    if not isinstance(value, sympy.Basic):
        value = sympy.Rational(int(value.numerator), int(value.denominator))
    if not isinstance(value, sympy.Expr) or value.has(sympy.oo, -sympy.oo, sympy.zoo, sympy.nan) or not value.is_polynomial():
        raise InputError(f"{name}: {short_repr(value, 60)} is not a polynomial")
    for power in value.atoms(sympy.Pow):  # x**(10**6) is checked before any expansion
        if power.exp.is_Integer:
            limits.check("max_degree", int(power.exp), f"{name}: exponent of {str(power.base)[:30]}")
    return value


def symbol_input(value, name: str) -> sympy.Symbol:
    """A sympy ``Symbol`` (a variable to eliminate or a generator), else :class:`InputError`."""
    if not isinstance(value, sympy.Symbol):
        raise InputError(f"{name}: expected a sympy Symbol, got {type(value).__name__} {short_repr(value, 40)}")
    return value


def zctx(names, order: str = "degrevlex") -> flint.fmpz_mpoly_ctx:
    """The (cached) flint context of integer polynomials in ``names``."""
    return flint.fmpz_mpoly_ctx.get(tuple(str(n) for n in names), order)


XY = zctx(("x", "y"))


mpq_of = from_fmpq  # a flint ``fmpq``/``fmpz`` (or int) as gmpy2 ``mpq``


def fmpq_poly_of(coeffs) -> flint.fmpq_poly:
    """A flint rational polynomial from exact coefficients (lowest degree first)."""
    return flint.fmpq_poly([to_fmpq(c) for c in coeffs])


def primitive_fmpz_polys(polys) -> list[flint.fmpz_poly]:
    """Scale rational polynomials by ONE common factor to coprime integer polynomials.

    The common factor is positive, so signs (and ratios) are kept.
    """
    polys = [p if isinstance(p, flint.fmpq_poly) else flint.fmpq_poly(p) for p in polys]
    den = 1
    for p in polys:
        den = den * int(p.denom()) // _gcd(den, int(p.denom()))
    ints = [flint.fmpz_poly([int(c * den) for c in p.coeffs()]) for p in polys]
    g = 0
    for p in ints:
        for c in p.coeffs():
            g = _gcd(g, int(c))
    if g > 1:
        ints = [flint.fmpz_poly([int(c) // g for c in p.coeffs()]) for p in ints]
    return ints


def _gcd(a: int, b: int) -> int:
    import math

    return math.gcd(a, b)


def curve_power(curve) -> tuple[flint.fmpz_poly, flint.fmpz_poly, flint.fmpz_poly]:
    """Homogeneous power-basis components ``(X(t), Y(t), W(t))`` of a planar curve.

    ``x = X/W, y = Y/W``; integer coefficients, jointly primitive, positive common
    scale (so the sign of ``W`` on [0, 1] is that of the weights).  No common factor
    is removed here (see :func:`common_factor`).

    The homogeneous Bernstein coefficients ``(w_i x_i, w_i y_i, w_i)`` over one common
    denominator go to the power basis in one flint matrix product (notes 3.3:
    ``t^k`` coefficient ``= sum_i C(n,i) C(n-i,k-i) (-1)^(k-i) c_i``).

    >>> from exactcagd import BezierCurve
    >>> curve_power(BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, 2, 1]))   # W = 1 + 2t - 2t^2
    ((-2)*x^2 + 4*x, (-8)*x^2 + 8*x, (-2)*x^2 + 2*x + 1)
    """
    if not isinstance(curve, _bezier_curve_class()):
        raise InputError(f"expected a BezierCurve, got {type(curve).__name__}")
    if curve.dimension != 2:
        raise DimensionError(f"implicit algebra needs a planar curve, got dimension {curve.dimension}")
    n = curve.degree
    if (limit := limits.get("max_implicit_degree")) is not None and n > limit:
        limits.check("max_implicit_degree", n, f"implicit algebra of a degree-{n} curve (implicit degree up to {n})")
    points, weights = curve.points_array().tolist(), curve.weights
    # the three homogeneous columns, one after the other (rows of the transposed product)
    if weights is None:
        flat = [p[0] for p in points] + [p[1] for p in points] + [1] * (n + 1)
    else:
        flat = [p[0] * w for p, w in zip(points, weights)] + [p[1] * w for p, w in zip(points, weights)] + list(weights)
    den = 1
    for v in flat:
        d = v.denominator
        if d != 1:
            den = den * d // _gcd(den, d)
    ints = [int(v) for v in flat] if den == 1 else [int(v * den) for v in flat]
    m = n + 1
    comps = [flint.fmpz_poly(row) for row in (flint.fmpz_mat(3, m, ints) * _power_from_bernstein_z(n)).tolist()]
    g = _gcd(_gcd(int(comps[0].content()), int(comps[1].content())), int(comps[2].content()))
    if g > 1:
        comps = [p // g for p in comps]
    return tuple(comps)


@lru_cache(maxsize=1)
def _bezier_curve_class():
    """:class:`BezierCurve`, imported on first use (the geometry layer imports nothing from here)."""
    from ..geometry.bezier_curve import BezierCurve

    return BezierCurve


@lru_cache(maxsize=64)
def _bernstein_to_power_z(n: int) -> flint.fmpz_mat:
    """The integer matrix taking Bernstein coefficients of degree ``n`` to power coefficients."""
    return flint.fmpz_mat([[bz.binomial(n, i) * bz.binomial(n - i, k - i) * (-1) ** (k - i) if k >= i else 0 for i in range(n + 1)]
                           for k in range(n + 1)])


@lru_cache(maxsize=64)
def _power_from_bernstein_z(n: int) -> flint.fmpz_mat:
    """The transpose of :func:`_bernstein_to_power_z` (coefficient rows times it: power rows)."""
    return _bernstein_to_power_z(n).transpose()


def common_factor(X, Y, W) -> tuple[flint.fmpz_poly, tuple]:
    """``(g, (X/g, Y/g, W/g))``: the gcd of the three components (notes 18.3.4 base points)."""
    g = X.gcd(Y).gcd(W)
    if g.degree() <= 0:
        return flint.fmpz_poly([1]), (X, Y, W)
    if g.coeffs()[-1] < 0:
        g = -g
    return g, tuple(p // g for p in (X, Y, W))


def curve_from_polynomials(x, y, w=1, t=None):
    """A :class:`BezierCurve` from power-basis polynomials ``x(t)/w(t), y(t)/w(t)``.

    The notes (chapter 17) give their examples in power form; this builds the exact
    Bézier form of the same parametrization (degree = the largest degree).  A
    homogeneous Bernstein coefficient of ``w`` equal to zero (a control point at
    infinity) cannot be represented and raises :class:`WeightError`.

    >>> c = curve_from_polynomials("t**2 + 1", "t**2 + 2*t - 2")
    >>> c.control_points
    ((mpq(1,1), mpq(-2,1)), (mpq(1,1), mpq(-1,1)), (mpq(2,1), mpq(1,1)))
    """
    from ..geometry.bezier_curve import BezierCurve

    t = T_SYM if t is None else t
    exprs = [sympy.sympify(e) for e in (x, y, w)]
    free = set().union(*(e.free_symbols for e in exprs)) - {t}
    if free:
        raise InputError(f"curve polynomials may only depend on {t}, found {sorted(map(str, free))}")
    polys = [sympy.Poly(e, t, domain="QQ") for e in exprs]
    n = max(p.degree() for p in polys)
    if n < 0 or polys[2].is_zero:
        raise InputError("the weight polynomial w(t) must not be zero")
    power = np.empty((n + 1, 3), dtype=object)
    for j, p in enumerate(polys):
        coeffs = p.all_coeffs()[::-1]
        for k in range(n + 1):
            c = coeffs[k] if k < len(coeffs) else 0
            power[k, j] = mpq(int(sympy.Rational(c).p), int(sympy.Rational(c).q))
    hom = bz.from_power(power, n)
    if any(hom[i, 2] == 0 for i in range(n + 1)):
        raise WeightError("w(t) has a zero Bernstein coefficient (control point at infinity); not representable")
    if polys[2].degree() == 0:
        return BezierCurve._trusted(hom[:, :2] / hom[0, 2], None)
    return BezierCurve.from_homogeneous(hom)


# ---------------------------------------------------------------------- flint <-> sympy
def mpoly_to_sympy(p, gens) -> sympy.Poly:
    """A flint (integer or rational) multivariate polynomial as a sympy ``Poly`` in ``gens``.

    Built from sympy's dense representation with domain elements directly (no
    sympification of each coefficient: about 3x faster, and the result of every
    implicitization passes through here).
    """
    if isinstance(p, flint.fmpz_mpoly) and len(gens) == 2 and not p.is_zero():
        # bivariate integer (every implicit equation): sympy's dense rows filled directly
        # (half the time of DMP.from_dict: no int exponents, no recursive dict walk)
        if p.context() is XY and (full := grevlex_full_poly(p, gens)) is not None:
            return full
        coeffs = p.coeffs() if ZZ.dtype is flint.fmpz else [ZZ(int(c)) for c in p.coeffs()]
        return sympy.Poly.new(DMP(_dense_bivariate([(int(i), int(j)) for i, j in p.monoms()], coeffs, ZZ.zero), ZZ, 1), *gens)
    monoms = [tuple(int(e) for e in m) for m in p.monoms()]
    coeffs = p.coeffs()
    if isinstance(p, flint.fmpz_mpoly):
        # sympy's ZZ is flint's fmpz under the flint ground type: the coefficients as they are
        rep, domain = dict(zip(monoms, coeffs if ZZ.dtype is flint.fmpz else [ZZ(int(c)) for c in coeffs])), ZZ
    elif all(c.q == 1 for c in coeffs):
        rep, domain = {m: ZZ(int(c.p)) for m, c in zip(monoms, coeffs)}, ZZ
    else:
        rep, domain = {m: QQ(int(c.p), int(c.q)) for m, c in zip(monoms, coeffs)}, QQ
    return sympy.Poly.new(DMP.from_dict(rep, len(gens) - 1, domain), *gens)


def grevlex_full_poly(p, gens) -> sympy.Poly | None:
    """The sympy ``Poly`` in the two ``gens`` of an integer ``fmpz_mpoly`` ``p`` whose first
    two variables are ``x > y`` in grevlex order and whose other variables do not occur
    (``XY``, or a resultant in ``(x, y, t)`` grevlex with ``t`` eliminated), when ``p`` has
    every monomial of total degree ``<= d`` (a generic implicit equation); else ``None``.

    The term order then fixes where each coefficient goes: no monomial is read (reading
    them costs more than the rest of the conversion).

    >>> grevlex_full_poly(XY.from_dict({(1, 0): 2, (0, 1): -3, (0, 0): 5}), (X_SYM, Y_SYM)).as_expr()
    2*x - 3*y + 5
    >>> grevlex_full_poly(XY.from_dict({(1, 0): 2, (0, 0): 5}), (X_SYM, Y_SYM)) is None   # no y term
    True
    """
    coeffs = p.coeffs()
    d = int(p.total_degree())
    if len(coeffs) != _triangle(d):
        return None
    return grevlex_triangle_poly(coeffs, d, gens)


def grevlex_triangle_poly(coeffs, d: int, gens) -> sympy.Poly:
    """The sympy ``Poly`` in the two ``gens`` whose coefficients, all non-zero integers, are
    ``coeffs`` (all ``int`` or all flint ``fmpz``) in grevlex order (``x > y``) over the
    monomials of total degree ``<= d`` (``x^d, x^(d-1) y, ..., y^d, x^(d-1), ..., 1``).

    >>> grevlex_triangle_poly([1, 2, 3], 1, (X_SYM, Y_SYM)).as_expr()
    x + 2*y + 3
    """
    if ZZ.dtype is not flint.fmpz or type(coeffs[0]) is not flint.fmpz:
        coeffs = [ZZ(int(c)) for c in coeffs]
    return sympy.Poly.new(DMP([[coeffs[k] for k in row] for row in _dense_rows_grevlex(d)], ZZ, 1), *gens)


def _triangle(d: int) -> int:
    """The number of monomials ``x^i y^j`` with ``i + j <= d``."""
    return (d + 1) * (d + 2) // 2


@lru_cache(maxsize=64)
def _dense_rows_grevlex(d: int) -> tuple:
    """Positions, in the grevlex (``x > y``) term list of a bivariate polynomial with all
    monomials of total degree ``<= d``, of sympy's dense rows (falling x-degree, each by
    falling y-degree).  The term list runs over total degree ``k = d, ..., 0`` and within
    it ``x^k, x^(k-1) y, ..., y^k``, so ``x^i y^j`` is term ``T(d) - T(i + j) + j``."""
    return tuple(tuple(_triangle(d) - _triangle(i + j) + j for j in range(d - i, -1, -1)) for i in range(d, -1, -1))


def _dense_bivariate(monoms, coeffs, zero) -> list:
    """sympy's dense list of a bivariate polynomial: rows by falling x-degree, each by
    falling y-degree with its leading zeros stripped (``[]`` for a missing x-degree)."""
    top = {}
    for i, j in monoms:
        if top.get(i, -1) < j:
            top[i] = j
    dx = max(top)
    rows = [[zero] * (top[i] + 1) if i in top else [] for i in range(dx, -1, -1)]
    for (i, j), c in zip(monoms, coeffs):
        rows[dx - i][top[i] - j] = c
    return rows


def sympy_to_mpoly(expr, gens, ctx=None):
    """A sympy expression/Poly with rational coefficients -> ``(fmpz_mpoly, denominator)``.

    ``expr == mpoly / denominator`` with a positive integer denominator.
    """
    ctx = zctx(tuple(str(g) for g in gens)) if ctx is None else ctx
    poly = expr if isinstance(expr, sympy.Poly) and tuple(expr.gens) == tuple(gens) else sympy.Poly(sympy.sympify(expr), *gens)
    if not poly.domain.is_Exact or not (poly.domain.is_ZZ or poly.domain.is_QQ):
        try:
            poly = poly.set_domain("QQ")  # raises for non-rational coefficients
        except sympy.polys.polyerrors.BasePolynomialError:
            raise InputError(f"{short_repr(expr, 60)}: coefficients must be rational numbers in {tuple(gens)}, got domain {poly.domain}") from None
    items = [(m, sympy.Rational(c)) for m, c in poly.terms()]
    den = 1
    for _, c in items:
        den = den * int(c.q) // _gcd(den, int(c.q))
    data = {m: int(c * den) for m, c in items}
    return ctx.from_dict(data) if data else ctx.from_dict({}), den


def normalize_implicit(p):
    """Primitive integer polynomial with positive leading coefficient (grevlex, x > y).

    Applied to every implicit equation so that all routes return the same polynomial.
    """
    if p == 0:
        return p
    content = p.content()
    if content != 1:
        p = p / content
    if p.context() is not XY:
        p = XY.from_dict({tuple(m): int(c) for m, c in p.to_dict().items()})
    if p.leading_coefficient() < 0:
        p = -p
    return p


def check_not_constant(X, Y, W) -> None:
    """Raise :class:`DegreeError` when the curve is a single point."""
    # constant iff X W' - X' W == 0 and Y W' - Y' W == 0
    if (X * W.derivative() - X.derivative() * W) == 0 and (Y * W.derivative() - Y.derivative() * W) == 0:
        raise DegreeError("the curve is constant (its image is a single point): no implicit equation")
