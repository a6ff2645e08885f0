"""Exact solution of zero-dimensional bivariate polynomial systems (notes 19.3).

The notes intersect two implicit curves by resultants and pair the coordinates
with Euclid's algorithm (19.3).  :func:`solve_bivariate` does exactly that,
robustly:

1. a shear ``x' = x + c y`` (``c = 0, 1, -1, 2, ...``) puts the solutions in
   general position (distinct ``x'``);
2. ``R(x') = gcd_k Res_y(p_1, p_k)`` holds every ``x'`` coordinate;
3. for each irreducible factor ``m`` of ``R`` the gcd of the ``p_k(alpha, y)`` over
   ``Q(alpha) = Q[s]/(m)`` is computed (Euclid); degree 0: no solution over this
   factor; degree 1: ``y`` is an element of ``Q(alpha)`` (one solution per conjugate
   of ``alpha``); degree > 1: the shear was not generic, the next ``c`` is tried.

Each result is an :class:`Orbit` -- a Galois orbit of ``deg m`` conjugate solutions
with coordinates as elements of the number field -- from which the real
solutions follow exactly (:meth:`Orbit.real_points`).

>>> import sympy
>>> x, y = sympy.symbols("x y")
>>> pts = common_points([x**2 - y**2 - 1, 6*x**2 + 6*y**2 - 2*x - 15*y - 4])
>>> [(str(a), str(b)) for a, b in pts]
[('-5/4', '3/4'), ('-13/12', '5/12'), ('1', '0'), ('5/3', '4/3')]
"""

from __future__ import annotations

from dataclasses import dataclass

import flint

from .. import limits
from ..errors import InputError, NotSupportedError
from ..exact.algebraic import real_roots
from ..exact.scalars import short_repr
from ._poly import X_SYM, XY, Y_SYM, polynomial_input, symbol_input, sympy_to_mpoly, zctx
from .numberfield import NumberField, algebraic_value

__all__ = ["Orbit", "solve_bivariate", "common_points", "to_xy_mpoly"]


@dataclass
class Orbit:
    """``deg m`` conjugate solutions: ``x = x_num(s)/x_den(s), y = y_num(s)/y_den(s)``
    for the roots ``s`` of the irreducible ``m`` (``fmpz_poly``)."""

    m: flint.fmpz_poly
    x: tuple  # (num, den) fmpq_poly, reduced mod m
    y: tuple

    @property
    def size(self) -> int:
        return self.m.degree()

    @property
    def field(self) -> NumberField:
        return NumberField(self.m)

    def x_element(self):
        K = self.field
        return K.mul(K(self.x[0]), K.inv(self.x[1]))

    def y_element(self):
        K = self.field
        return K.mul(K(self.y[0]), K.inv(self.y[1]))

    def real_points(self) -> list[tuple]:
        """The real solutions of the orbit as ``(RealAlgebraic, RealAlgebraic)``."""
        out = []
        for alpha, _ in real_roots([int(c) for c in self.m.coeffs()]):
            out.append((algebraic_value(alpha, *self.x), algebraic_value(alpha, *self.y)))
        return out


def to_xy_mpoly(p, gens=None):
    """A sympy expression/Poly (or fmpz_mpoly) as an ``fmpz_mpoly`` in the context ``(x, y)``."""
    if isinstance(p, flint.fmpz_mpoly):
        return XY.from_dict({tuple(m): int(c) for m, c in p.to_dict().items()})
    gens = (X_SYM, Y_SYM) if gens is None else gens
    q, _ = sympy_to_mpoly(polynomial_input(p, "f"), gens, XY)
    return q


def _shear(p, c: int):
    """``p(x' - c y, y)`` as fmpz_mpoly in (x', y)."""
    if c == 0:
        return p
    x, y = XY.gens()
    return p.compose(x - c * y, y)


def _as_dict(p) -> dict:
    return {tuple(int(e) for e in m): int(c) for m, c in p.to_dict().items()}


def _univariate_x(p) -> flint.fmpz_poly:
    d = _as_dict(p)
    top = max((m[0] for m in d), default=0)
    return flint.fmpz_poly([d.get((k, 0), 0) for k in range(top + 1)])


def solve_bivariate(polys, gens=None, max_shear: int = 40) -> list[Orbit]:
    """All complex solutions of ``p_1 = ... = p_k = 0`` (k >= 2, finitely many) as orbits.

    Raises
    ------
    InputError
        when the polynomials have a common factor (infinitely many solutions).
    """
    if not isinstance(polys, (list, tuple)):
        raise InputError(f"polys: expected a list of polynomials, got {type(polys).__name__}")
    if gens is not None and (not isinstance(gens, (list, tuple)) or len(gens) != 2):
        raise InputError(f"gens: expected two sympy Symbols, got {short_repr(gens, 40)}")
    gens = None if gens is None else tuple(symbol_input(g, "gens") for g in gens)
    P = [to_xy_mpoly(p, gens) for p in polys]
    for k, p in enumerate(P):  # Bezout: up to deg(p) deg(q) solutions, each an algebraic number of that degree
        limits.check("max_implicit_degree", p.total_degree(), f"polys[{k}]: total degree")
    P = [p for p in P if p != 0]
    if len(P) < 2:
        raise InputError("need at least two non-zero polynomials for a finite solution set")
    g = P[0]
    for p in P[1:]:
        g = g.gcd(p)
    if g.total_degree() > 0:
        raise InputError(f"the polynomials share the factor {g}: infinitely many solutions")
    if any(p.total_degree() == 0 for p in P):
        return []
    for c in _shears(max_shear):
        Q = [_shear(p, c) for p in P]
        big = zctx(("x", "y"), "lex")
        lifted = [big.from_dict(_as_dict(q)) for q in Q]
        with_y = [q for q in lifted if q.degrees()[1] > 0]
        R = None
        for q in lifted:  # polynomials free of y constrain x directly
            if q.degrees()[1] == 0:
                r = _univariate_x(q)
                R = r if R is None else R.gcd(r)
        for q in with_y[1:]:
            r = _univariate_x(with_y[0].resultant(q, "y"))
            R = r if R is None else R.gcd(r)
        if R is None or R == 0:
            continue  # pragma: no cover - excluded by the gcd test
        if R.degree() < 1:
            return []
        _, factors = R.factor()
        orbits = []
        generic = True
        for m, _ in factors:
            if m.coeffs()[-1] < 0:
                m = -m
            K = NumberField(m)
            G = None
            for q in Q:
                poly_y = K.eval_bivariate(_as_dict(q), 0)
                G = poly_y if G is None else K.poly_gcd(G, poly_y)
            G = K.trim(G)
            if len(G) <= 1:
                continue
            if len(G) > 2:  # square-free part (a multiple solution is one point)
                dG = [K(G[k] * k) for k in range(1, len(G))]
                G = K.poly_divmod(G, K.poly_gcd(G, dG))[0]
            if len(G) > 2:
                generic = False
                break
            # y = -G0 / G1 ; x = x' - c y = (s G1 + c G0) / G1
            s = flint.fmpq_poly([0, 1])
            y_num, y_den = K(-G[0]), K(G[1])
            x_num = K(s * G[1] + c * G[0])
            orbits.append(Orbit(m, (x_num, K(G[1])), (y_num, y_den)))
        if generic:
            return orbits
    raise NotSupportedError("could not find a shear putting the solutions in general position")


def _shears(limit: int):
    yield 0
    for k in range(1, limit + 1):
        yield k
        yield -k


def common_points(polys, gens=None) -> list[tuple]:
    """Real common points of plane curves (19.3), exact, sorted by ``(x, y)``.

    Returns ``[(x, y)]`` with :class:`RealAlgebraic` coordinates.
    """
    pts = []
    for orbit in solve_bivariate(polys, gens):
        pts.extend(orbit.real_points())
    pts.sort(key=lambda p: (p[0], p[1]))
    return pts
