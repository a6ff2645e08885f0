"""Rational parametrization of unicursal curves and undetermined coefficients
(notes 19.5, 19.6).

A curve of degree ``n`` with a point ``O`` of multiplicity ``n - 1`` (every conic
through any of its points, a cubic through its double point, ...) is
parametrized by the pencil of lines through ``O``: after translating ``O`` to the
origin ``f = f_n + f_(n-1)`` (homogeneous parts), and ``y = t x`` gives
``x^(n-1) (x f_n(1, t) + f_(n-1)(1, t)) = 0``, so
``x = -f_(n-1)(1, t) / f_n(1, t)``, ``y = t x`` (19.5).

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> parametrize_unicursal(x**2 - 2*x + y**2, (0, 0))
(2/(t**2 + 1), 2*t/(t**2 + 1))
"""

from __future__ import annotations

import sympy

from ..errors import InputError, NotSupportedError
from ..exact.scalars import short_repr, to_rational, to_sympy
from ._poly import T_SYM, X_SYM, Y_SYM

__all__ = [
    "parametrize_unicursal",
    "parametrize_conic",
    "parametrize_rational_cubic",
    "undetermined_coefficients",
    "conic_through_points",
    "circle_through_points",
    "translate",
]


def translate(f, point):
    """``f(x + x0, y + y0)``: moves ``point`` to the origin (19.5)."""
    x0, y0 = (sympy.Rational(str(v)) for v in point)
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    return sympy.expand(fe.subs({X_SYM: X_SYM + x0, Y_SYM: Y_SYM + y0}, simultaneous=True))


def parametrize_unicursal(f, point, t=None):
    """Rational parametrization through a point of multiplicity ``n - 1`` (19.5).

    Parameters
    ----------
    f : sympy expression / Poly in ``x, y`` of total degree ``n``
    point : rational ``(x0, y0)`` of multiplicity exactly ``n - 1`` on the curve

    Returns
    -------
    ``(x(t), y(t))`` sympy rational functions; ``t`` is the slope of the line
    through ``point``.

    Raises
    ------
    InputError
        when ``point`` does not have multiplicity ``n - 1``.
    """
    t = T_SYM if t is None else t
    g = sympy.Poly(translate(f, point), X_SYM, Y_SYM)
    n = g.total_degree()
    if n < 1:
        raise InputError("a constant does not define a curve")
    low = [m for m in g.monoms() if sum(m) < n - 1]
    if low:
        raise InputError(f"the point is not of multiplicity {n - 1} on this degree-{n} curve")
    fn = sum(c * X_SYM**i * Y_SYM**j for (i, j), c in g.terms() if i + j == n)
    fm = sum(c * X_SYM**i * Y_SYM**j for (i, j), c in g.terms() if i + j == n - 1)
    fn_t = sympy.expand(fn.subs({X_SYM: 1, Y_SYM: t}))
    fm_t = sympy.expand(fm.subs({X_SYM: 1, Y_SYM: t}))
    if fn_t == 0:
        raise InputError("the curve contains every line through the point")
    xt = sympy.cancel(-fm_t / fn_t)
    x0, y0 = (sympy.Rational(str(v)) for v in point)
    return sympy.cancel(xt + x0), sympy.cancel(t * xt + y0)


def _rational_point_on_conic(f, search: int = 12):
    """A rational point of a conic found on the lines ``x = k`` and ``y = k``, ``|k| <= search``."""
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    for k in range(0, search + 1):
        for kk in ((k, -k) if k else (0,)):
            for var, other in ((X_SYM, Y_SYM), (Y_SYM, X_SYM)):
                g = sympy.Poly(sympy.expand(fe.subs(var, kk)), other)
                if g.degree() < 1:
                    continue
                for r in sympy.roots(g, filter="Q"):
                    return (kk, r) if var == X_SYM else (r, kk)
    return None


def parametrize_conic(f, point=None, t=None):
    """Rational parametrization of a conic through a rational point (19.5).

    Without ``point`` a rational point is searched on small axis-parallel lines;
    :class:`NotSupportedError` if none is found (a conic may have no rational point).
    """
    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    if sympy.Poly(fe, X_SYM, Y_SYM).total_degree() != 2:
        raise InputError("parametrize_conic needs a polynomial of degree 2")
    if point is None:
        point = _rational_point_on_conic(fe)
        if point is None:
            raise NotSupportedError("no rational point found on the conic; pass one explicitly")
    if sympy.expand(fe.subs({X_SYM: sympy.Rational(str(point[0])), Y_SYM: sympy.Rational(str(point[1]))})) != 0:
        raise InputError("the point does not lie on the conic")
    return parametrize_unicursal(fe, point, t)


def parametrize_rational_cubic(f, t=None):
    """Parametrize a cubic with a rational double point (19.5): the double point is
    found from ``f = f_x = f_y = 0`` (via resultants, 19.3) and used as the pencil
    center."""
    from .singularities import singular_points

    fe = f.as_expr() if isinstance(f, sympy.Poly) else sympy.sympify(f)
    if sympy.Poly(fe, X_SYM, Y_SYM).total_degree() != 3:
        raise InputError("parametrize_rational_cubic needs a cubic")
    for sp in singular_points(fe, include_infinity=False):
        if sp.point is not None and sp.multiplicity == 2 and all(v.is_rational for v in sp.point):
            point = tuple(v.value for v in sp.point)
            return parametrize_unicursal(fe, point, t), point
    raise InputError("the cubic has no (rational affine) double point: genus 1, not rational")


def _point(p, name: str) -> tuple:
    """A user point ``(x, y)`` as two sympy Rationals (exactly, through :func:`to_rational`)."""
    if isinstance(p, (str, bytes, bytearray)) or not hasattr(p, "__len__") or len(p) != 2:
        raise InputError(f"{name}: expected a point (x, y), got {short_repr(p, 40)}")
    return tuple(to_sympy(to_rational(v, where=name)) for v in p)


def undetermined_coefficients(points, monomials):
    """Coefficients ``c`` with ``sum c_k m_k(x_i, y_i) = 0`` for every point (19.6).

    Returns a basis of the solution space (lists of sympy Rationals): the matrix of
    19.6 has one row per point and one column per monomial.
    """
    if isinstance(points, (str, bytes, bytearray)) or not hasattr(points, "__iter__"):
        raise InputError(f"points: expected a sequence of points (x, y), got {short_repr(points, 40)}")
    rows = []
    for k, p in enumerate(points):
        px, py = _point(p, f"points[{k}]")
        rows.append([sympy.sympify(m).subs({X_SYM: px, Y_SYM: py}) for m in monomials])
    return [list(v) for v in sympy.Matrix(rows).nullspace()]


def conic_through_points(points):
    """The conic ``c20 x^2 + c11 xy + c02 y^2 + c10 x + c01 y + c00`` through five points (19.6)."""
    if not isinstance(points, (list, tuple)) or len(points) != 5:
        raise InputError("a conic is fixed by five points")
    monos = [X_SYM**2, X_SYM * Y_SYM, Y_SYM**2, X_SYM, Y_SYM, 1]
    sols = undetermined_coefficients(points, monos)
    if len(sols) != 1:
        raise InputError("the five points do not determine a unique conic (four collinear?)")
    expr = sum(c * m for c, m in zip(sols[0], monos))
    den = sympy.ilcm(*[sympy.Rational(c).q for c in sols[0]])
    P = sympy.Poly(sympy.expand(expr * den), X_SYM, Y_SYM)
    P = P.primitive()[1]
    if P.LC(order="grevlex") < 0:
        P = -P
    return P


def circle_through_points(p1, p2, p3):
    """Centre ``(a, b)`` and squared radius of the circle through three points (19.6).

    Solves ``A x + B y + C = x^2 + y^2``; ``a = A/2``, ``b = B/2``, ``r^2 = C + a^2 + b^2``.
    """
    rows, rhs = [], []
    for k, p in enumerate((p1, p2, p3)):
        px, py = _point(p, f"p{k + 1}")
        rows.append([px, py, 1])
        rhs.append(px**2 + py**2)
    M = sympy.Matrix(rows)
    if M.det() == 0:
        raise InputError("the three points are collinear")
    A, B, C = M.LUsolve(sympy.Matrix(rhs))
    a, b = A / 2, B / 2
    return (a, b), C + a**2 + b**2
