"""Singular points, double points, genus and discriminants of plane algebraic curves
(notes 19.1, 19.2, 19.4; 7.3.1 for multiplicities).

* :func:`line_section` -- the notes' test (19.2): substitute ``x = x0 + a t``,
  ``y = y0 + b t``; the lowest power of ``t`` is the multiplicity of the point and
  its coefficient (a form in ``a, b``) gives the tangent lines;
* :func:`singular_points` -- all singular points (affine and at infinity) with
  multiplicity, type (crunode / cusp / acnode / ordinary m-fold / other) and
  delta invariant, exactly (orbits of conjugate points over number fields);
* :func:`genus` -- ``g = (n - 1)(n - 2) / 2 - sum delta_P`` (19.1) for curves whose
  singularities are ordinary multiple points or simple cusps;
* :func:`curve_discriminant` -- ``Res_y(f, f_y)`` (19.4): its roots are the ``x`` of
  the vertical tangents and of the singular points.

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> [(p.kind, str(p.point[0]), str(p.point[1])) for p in singular_points(x**3 + 9*x**2 - 12*y**2)]
[('crunode', '0', '0')]
>>> genus(x**3 + 9*x**2 - 12*y**2), genus(x**3 + x*y**2 - y - 1)
(0, 1)
"""

from __future__ import annotations

from dataclasses import dataclass, field

import flint
import sympy

from ..errors import InputError, NotSupportedError
from ..exact.algebraic import RealAlgebraic, real_roots
from ..exact.bernstein import binomial
from ._poly import X_SYM, Y_SYM
from .numberfield import NumberField, algebraic_sign, algebraic_value
from .resultants import resultant
from .solve import _as_dict, solve_bivariate, to_xy_mpoly

__all__ = [
    "SingularPoint",
    "line_section",
    "singular_points",
    "genus",
    "curve_discriminant",
    "is_irreducible",
]


@dataclass
class SingularPoint:
    """A singular point (or ``count`` complex-conjugate ones with the same data).

    Attributes
    ----------
    point : ``(x, y)`` of :class:`RealAlgebraic` for a real affine point;
        ``(x, 1, 0)`` / ``(1, 0, 0)`` (homogeneous) for a real point at infinity;
        ``None`` for non-real points
    count : number of points the record stands for (1 for a real point)
    multiplicity : order of the point (2 = double point)
    kind : ``"crunode"``, ``"acnode"``, ``"cusp"`` (simple cusp), ``"tacnode+"``
        (double point with one tangent, not a simple cusp), ``"ordinary"`` (m >= 3
        distinct tangents), ``"non-ordinary"``, or ``"complex-node"`` /
        ``"complex-cusp"`` / ... for non-real points (classified over C)
    delta : delta invariant (``m (m - 1) / 2`` for ordinary points, 1 for a simple
        cusp), ``None`` when not determined
    at_infinity : bool
    orbit : the exact description (minimal polynomial and coordinates in ``Q(s)``)
    """

    point: tuple | None
    count: int
    multiplicity: int
    kind: str
    delta: int | None
    at_infinity: bool = False
    orbit: object = field(default=None, repr=False)


# ---------------------------------------------------------------------- 19.2 line test
def line_section(f, point=(0, 0)):
    """``f(x0 + a t, y0 + b t)`` as a polynomial in ``t`` (19.2), with the multiplicity.

    Returns ``(poly, multiplicity, cone)``: the sympy polynomial in ``t`` with
    coefficients in ``a, b``, the order of the lowest non-vanishing power of ``t``
    (the multiplicity of the point; 0 if the point is not on the curve) and that
    coefficient (the tangent cone: its linear factors are the tangent directions).
    """
    a, b, t = sympy.symbols("a b t")
    x0, y0 = (sympy.Rational(str(v)) for v in point)
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    sec = sympy.Poly(sympy.expand(fe.subs({X_SYM: x0 + a * t, Y_SYM: y0 + b * t}, simultaneous=True)), t)
    coeffs = sec.all_coeffs()[::-1]
    k = next((i for i, c in enumerate(coeffs) if sympy.expand(c) != 0), None)
    if k is None:
        raise InputError("the polynomial vanishes identically on every line through the point")
    return sec.as_expr(), k, sympy.factor(coeffs[k])


# ---------------------------------------------------------------------- local analysis
def _taylor(fd: dict, K: NumberField, x0, y0, upto: int) -> dict:
    """Coefficients ``T_pq`` (p + q <= upto) of ``f(x0 + X, y0 + Y)`` in K."""
    maxi = max((m[0] for m in fd), default=0)
    maxj = max((m[1] for m in fd), default=0)
    xp = [K(1)]
    for _ in range(maxi):
        xp.append(K.mul(xp[-1], x0))
    yp = [K(1)]
    for _ in range(maxj):
        yp.append(K.mul(yp[-1], y0))
    T = {}
    for (i, j), c in fd.items():
        for p in range(0, min(i, upto) + 1):
            for q in range(0, min(j, upto - p) + 1):
                coef = c * binomial(i, p) * binomial(j, q)
                term = K.mul(xp[i - p], yp[j - q]) * coef
                T[(p, q)] = T.get((p, q), flint.fmpq_poly([])) + term
    return {k: K(v) for k, v in T.items()}


def _analyse(fd: dict, K: NumberField, x0, y0):
    """(multiplicity, cone coefficients [T_(m,0) .. T_(0,m)], cubic-next form, squarefree, A2)."""
    deg = max(sum(m) for m in fd)
    T = _taylor(fd, K, x0, y0, deg)
    m = next(k for k in range(deg + 1) if any(not K.is_zero(T.get((p, k - p), 0)) for p in range(k + 1)))
    cone = [T.get((p, m - p), flint.fmpq_poly([])) for p in range(m + 1)]  # coefficient of a^p b^(m-p)
    U = K.trim(cone)  # U(a) = sum cone[p] a^p  (b = 1)
    deg_u = len(U) - 1
    inf_mult = m - deg_u
    squarefree = inf_mult <= 1
    if squarefree and deg_u >= 1:
        dU = [K(U[p] * p) for p in range(1, len(U))]
        g = K.poly_gcd(U, dU)
        squarefree = len(g) <= 1
    a2 = False
    if m == 2 and not squarefree:
        # direction v of the double tangent line; simple cusp iff cubic(v) != 0
        if deg_u == 2:
            r = K.mul(-U[1], K.inv(K(U[2] * 2)))
            v = (r, K(1))
        else:
            v = (K(1), K(0))
        cubic = K(0)
        for p in range(4):
            term = K.mul(T.get((p, 3 - p), flint.fmpq_poly([])), _kpow(K, v[0], p))
            cubic = cubic + K.mul(term, _kpow(K, v[1], 3 - p))
        a2 = not K.is_zero(cubic)
    return m, cone, squarefree, a2


def _kpow(K, a, k):
    out = K(1)
    for _ in range(k):
        out = K.mul(out, a)
    return out


def _classify(m, squarefree, a2):
    if m == 2:
        if squarefree:
            return "node", 1
        return ("cusp", 1) if a2 else ("tacnode+", None)
    if squarefree:
        return "ordinary", m * (m - 1) // 2
    return "non-ordinary", None


def _records(orbit_m, x_el, y_el, fd, at_infinity, embed) -> list[SingularPoint]:
    """Analyse one orbit; ``embed(alpha)`` gives the point record for a real root."""
    K = NumberField(orbit_m)
    m, cone, squarefree, a2 = _analyse(fd, K, x_el, y_el)
    if m < 2:
        return []
    kind, delta = _classify(m, squarefree, a2)
    out = []
    reals = real_roots([int(c) for c in orbit_m.coeffs()])
    for alpha, _ in reals:
        k = kind
        if kind == "node":
            disc = K(cone[1] * cone[1] - 4 * cone[0] * cone[2])
            k = "crunode" if algebraic_sign(alpha, disc) > 0 else "acnode"
        out.append(SingularPoint(embed(alpha), 1, m, k, delta, at_infinity, (orbit_m, x_el, y_el)))
    rest = orbit_m.degree() - len(reals)
    if rest:
        out.append(SingularPoint(None, rest, m, "complex-" + kind, delta, at_infinity, (orbit_m, x_el, y_el)))
    return out


def singular_points(f, include_infinity: bool = True) -> list[SingularPoint]:
    """All singular points of the curve ``f(x, y) = 0``, exactly (19.2, 19.5).

    Affine points solve ``f = f_x = f_y = 0`` (:func:`solve_bivariate`); points at
    infinity are found in the charts ``y = 1`` and ``x = 1`` of the projective
    closure.  ``f`` must be square-free.
    """
    P = to_xy_mpoly(f)
    if P.total_degree() < 1:
        raise InputError("a constant polynomial does not define a curve")
    _, sqf = P.factor_squarefree()
    if any(int(e) > 1 for _, e in sqf):
        raise InputError("the polynomial has a repeated factor; pass its square-free part")
    fd = _as_dict(P)
    out = []
    fx, fy = P.derivative(0), P.derivative(1)
    polys = [p for p in (P, fx, fy) if p != 0]
    for orbit in solve_bivariate(polys):
        K = orbit.field
        xe, ye = orbit.x_element(), orbit.y_element()

        def embed(alpha, orbit=orbit):
            return (algebraic_value(alpha, *orbit.x), algebraic_value(alpha, *orbit.y))

        out.extend(_records(orbit.m, xe, ye, fd, False, embed))
    if include_infinity:
        out.extend(_infinite_singular_points(fd))
    return out


def _infinite_singular_points(fd: dict) -> list[SingularPoint]:
    n = max(sum(m) for m in fd)
    hom = {(i, j, n - i - j): c for (i, j), c in fd.items()}
    out = []
    # chart y = 1: g(x, w) = F(x, 1, w); singular points with w = 0
    g = {}
    for (i, j, k), c in hom.items():
        g[(i, k)] = g.get((i, k), 0) + c
    g = {k: v for k, v in g.items() if v}
    gx = {(i - 1, k): c * i for (i, k), c in g.items() if i > 0}
    gw = {(i, k - 1): c * k for (i, k), c in g.items() if k > 0}

    def at_w0(d):
        top = max((i for (i, k) in d if k == 0), default=-1)
        return flint.fmpz_poly([d.get((i, 0), 0) for i in range(top + 1)]) if top >= 0 else flint.fmpz_poly([])

    G = at_w0(g)
    for h in (gx, gw):
        G = G.gcd(at_w0(h)) if G != 0 else at_w0(h)
    if G.degree() >= 1:
        _, factors = G.factor()
        for m, _ in factors:
            if m.coeffs()[-1] < 0:
                m = -m
            K = NumberField(m)
            x_el = K(flint.fmpq_poly([0, 1]))

            def embed(alpha):
                return (alpha, RealAlgebraic.from_rational(1), RealAlgebraic.from_rational(0))

            out.extend(_records(m, x_el, K(0), g, True, embed))
    # chart x = 1: the point (1 : 0 : 0)
    h = {}
    for (i, j, k), c in hom.items():
        h[(j, k)] = h.get((j, k), 0) + c
    h = {k: v for k, v in h.items() if v}
    if all(h.get(key, 0) == 0 for key in ((0, 0), (1, 0), (0, 1))):
        m = flint.fmpz_poly([0, 1])
        K = NumberField(m)

        def embed(alpha):
            return (RealAlgebraic.from_rational(1), RealAlgebraic.from_rational(0), RealAlgebraic.from_rational(0))

        out.extend(_records(m, K(0), K(0), h, True, embed))
    return out


def is_irreducible(f) -> bool:
    """Irreducible over Q (python-flint factorization)."""
    P = to_xy_mpoly(f)
    _, factors = P.factor()
    return len(factors) == 1 and int(factors[0][1]) == 1


def genus(f) -> int:
    """Genus ``(n - 1)(n - 2)/2 - sum delta_P`` of an irreducible plane curve (19.1).

    Exact when every singular point (affine or at infinity, real or complex) is an
    ordinary multiple point or a simple cusp; otherwise :class:`NotSupportedError`.
    A curve irreducible over Q but not over C (e.g. ``x^2 + y^2``) comes out negative
    and raises :class:`InputError`.
    """
    P = to_xy_mpoly(f)
    if not is_irreducible(P):
        raise InputError("the genus is defined here for irreducible curves; this polynomial factors")
    n = P.total_degree()
    delta = 0
    for sp in singular_points(P):
        if sp.delta is None:
            raise NotSupportedError(f"singular point of type {sp.kind!r}: its delta invariant is not computed")
        delta += sp.delta * sp.count
    g = (n - 1) * (n - 2) // 2 - delta
    if g < 0:
        raise InputError("negative genus: the curve is not absolutely irreducible")
    return g


def curve_discriminant(f, var=None):
    """``Res_var(f, df/dvar)`` (19.4), default ``var = y``: a polynomial in the other variable.

    Its roots are the coordinates of the points with a tangent parallel to the
    ``var`` axis and of the singular points ("the silhouette").
    """
    var = Y_SYM if var is None else var
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    return resultant(fe, sympy.diff(fe, var), var)
