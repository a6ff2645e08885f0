"""Exact arithmetic with algebraic numbers beyond what :class:`RealAlgebraic` stores.

An intersection parameter, a double point or a singular point is generally
irrational; the quantities derived from it (the other curve's parameter, the
coordinates) live in the number field ``K = Q(alpha) = Q[s] / (m(s))`` of its
minimal polynomial ``m``.  This module supplies

* :class:`NumberField` -- arithmetic in ``K`` and Euclid's algorithm in ``K[y]``
  (notes 17.4 / 19.3: the gcd finds the common roots);
* :func:`algebraic_value` -- the real number ``num(alpha) / den(alpha)`` as a
  :class:`RealAlgebraic` (minimal polynomial = minimal polynomial of the
  multiplication matrix, root chosen by exact interval evaluation);
* :func:`algebraic_sign` -- the exact sign of ``p(alpha)``.

No float is used anywhere; every interval is rational.

>>> import flint
>>> from exactcagd.exact.algebraic import real_roots
>>> alpha = real_roots([-2, 0, 1], 0, 2)[0][0]           # sqrt(2)
>>> str(algebraic_value(alpha, flint.fmpq_poly([1, 1])))  # 1 + sqrt(2)
'root of t^2 - 2*t - 1 in (2, 3)'
"""

from __future__ import annotations

import flint
from gmpy2 import mpq

from ..errors import DomainError
from ..exact.algebraic import RealAlgebraic, integer_poly, real_roots
from ._poly import mpq_of

__all__ = ["NumberField", "algebraic_value", "algebraic_sign", "interval_eval", "as_fmpq_poly"]


def as_fmpq_poly(p) -> flint.fmpq_poly:
    if isinstance(p, flint.fmpq_poly):
        return p
    if isinstance(p, flint.fmpz_poly):
        return flint.fmpq_poly([flint.fmpq(int(c)) for c in p.coeffs()])
    if isinstance(p, (list, tuple)):
        return flint.fmpq_poly([flint.fmpq(int(mpq(c).numerator), int(mpq(c).denominator)) for c in p])
    return flint.fmpq_poly([flint.fmpq(int(mpq(p).numerator), int(mpq(p).denominator))])


class NumberField:
    """``Q[s] / (m(s))`` for an irreducible ``m``; elements are ``fmpq_poly`` of degree < deg m.

    Polynomials over the field (in another variable) are lists of elements, lowest
    degree first.
    """

    def __init__(self, modulus):
        self.m = as_fmpq_poly(modulus)
        if self.m.degree() < 1:
            raise DomainError("a number field needs a modulus of degree >= 1")

    @property
    def degree(self) -> int:
        return self.m.degree()

    def __call__(self, p) -> flint.fmpq_poly:
        return as_fmpq_poly(p) % self.m

    def is_zero(self, a) -> bool:
        return (as_fmpq_poly(a) % self.m) == 0

    def inv(self, a) -> flint.fmpq_poly:
        a = self(a)
        if a == 0:
            raise ZeroDivisionError("division by zero in the number field")
        g, u, _ = a.xgcd(self.m)
        if g.degree() != 0:  # pragma: no cover - m irreducible
            raise ArithmeticError("modulus is not irreducible")
        return (u / g[0]) % self.m

    def mul(self, a, b) -> flint.fmpq_poly:
        return (a * b) % self.m

    # ------------------------------------------------------------ polynomials over K
    def trim(self, P: list) -> list:
        P = [self(c) for c in P]
        while P and P[-1] == 0:
            P.pop()
        return P

    def poly_divmod(self, A: list, B: list) -> tuple[list, list]:
        A, B = self.trim(A), self.trim(B)
        if not B:
            raise ZeroDivisionError("polynomial division by zero")
        inv_lead = self.inv(B[-1])
        Q = [flint.fmpq_poly([])] * max(len(A) - len(B) + 1, 0)
        R = list(A)
        while len(R) >= len(B):
            c = self.mul(R[-1], inv_lead)
            shift = len(R) - len(B)
            Q[shift] = c
            for i, b in enumerate(B):
                R[shift + i] = (R[shift + i] - c * b) % self.m
            R = self.trim(R)
        return Q, R

    def poly_gcd(self, A: list, B: list) -> list:
        """Monic gcd in ``K[y]`` by Euclid's algorithm (notes 17.4)."""
        A, B = self.trim(A), self.trim(B)
        while B:
            _, R = self.poly_divmod(A, B)
            A, B = B, R
        if not A:
            return []
        inv_lead = self.inv(A[-1])
        return [self.mul(c, inv_lead) for c in A]

    def eval_bivariate(self, coeffs: dict, var_index: int = 0) -> list:
        """Substitute ``alpha`` for one variable of ``sum c_ij x^i y^j`` -> polynomial over K.

        ``coeffs`` maps exponent pairs ``(i, j)`` to rationals; ``var_index`` = 0
        substitutes for ``x`` (result in ``y``), 1 for ``y`` (result in ``x``).
        """
        out: dict[int, flint.fmpq_poly] = {}
        s_pow = {}
        for mono, c in coeffs.items():
            e_sub, e_keep = (mono[0], mono[1]) if var_index == 0 else (mono[1], mono[0])
            if e_sub not in s_pow:
                s_pow[e_sub] = flint.fmpq_poly([0] * e_sub + [1]) % self.m
            out[e_keep] = out.get(e_keep, flint.fmpq_poly([])) + as_fmpq_poly(c) * s_pow[e_sub]
        if not out:
            return []
        return self.trim([out.get(k, flint.fmpq_poly([])) for k in range(max(out) + 1)])


# ------------------------------------------------------------------ interval evaluation
def interval_eval(p: flint.fmpq_poly, lo: mpq, hi: mpq) -> tuple[mpq, mpq]:
    """Rational enclosure of ``p([lo, hi])`` (Horner form in interval arithmetic)."""
    coeffs = [mpq_of(c) for c in p.coeffs()]
    if not coeffs:
        return mpq(0), mpq(0)
    a = b = coeffs[-1]
    for c in reversed(coeffs[:-1]):
        products = (a * lo, a * hi, b * lo, b * hi)
        a, b = min(products) + c, max(products) + c
    return a, b


def _interval_div(n: tuple, d: tuple) -> tuple | None:
    if d[0] <= 0 <= d[1]:
        return None
    q = (n[0] / d[0], n[0] / d[1], n[1] / d[0], n[1] / d[1])
    return min(q), max(q)


def algebraic_sign(alpha: RealAlgebraic, p) -> int:
    """Exact sign of ``p(alpha)`` for a rational polynomial ``p``."""
    p = as_fmpq_poly(p)
    if alpha.is_rational:
        v = p(flint.fmpq(int(alpha.lo.numerator), int(alpha.lo.denominator)))
        return (v > 0) - (v < 0)
    if p % as_fmpq_poly(alpha.poly) == 0:
        return 0
    while True:
        lo, hi = interval_eval(p, alpha.lo, alpha.hi)
        if lo > 0:
            return 1
        if hi < 0:
            return -1
        alpha.refine((alpha.hi - alpha.lo) / 4)


def algebraic_value(alpha: RealAlgebraic, num, den=None) -> RealAlgebraic:
    """The real algebraic number ``num(alpha) / den(alpha)``, exactly.

    Parameters
    ----------
    alpha : RealAlgebraic
    num, den : rational polynomials (fmpq_poly / fmpz_poly / coefficient lists)

    Raises
    ------
    ZeroDivisionError
        when ``den(alpha) == 0``.
    """
    num = as_fmpq_poly(num)
    den = as_fmpq_poly(1 if den is None else den)
    if alpha.is_rational:
        x = flint.fmpq(int(alpha.lo.numerator), int(alpha.lo.denominator))
        d = den(x)
        if d == 0:
            raise ZeroDivisionError("denominator vanishes at the algebraic number")
        return RealAlgebraic.from_rational(mpq_of(num(x) / d))
    field = NumberField(alpha.poly)
    c = field.mul(field(num), field.inv(den))  # raises ZeroDivisionError when den(alpha) = 0
    k = field.degree
    if c.degree() <= 0:
        return RealAlgebraic.from_rational(mpq_of(c[0]) if c.degree() == 0 else 0)
    # multiplication-by-c matrix in the basis 1, s, ..., s^(k-1); its minimal polynomial
    cols = []
    s_j = flint.fmpq_poly([1])
    for _ in range(k):
        col = (c * s_j) % field.m
        cols.append([col[i] for i in range(k)])
        s_j = (s_j * flint.fmpq_poly([0, 1])) % field.m
    mat = flint.fmpq_mat(k, k, [cols[j][i] for i in range(k) for j in range(k)])
    minpoly = mat.minpoly()
    poly = integer_poly([mpq_of(q) for q in minpoly.coeffs()])
    roots = [r for r, _ in real_roots([int(q) for q in poly.coeffs()])]
    if len(roots) == 1:
        return roots[0]
    while True:
        j_lo, j_hi = interval_eval(c, alpha.lo, alpha.hi)
        hits = [r for r in roots if not (r.hi < j_lo or r.lo > j_hi)]
        if len(hits) == 1:
            r = hits[0]
            if r.is_rational:
                return r
            out = RealAlgebraic(r.poly, max(r.lo, j_lo), min(r.hi, j_hi))
            if out.hi - out.lo > 1:  # readable isolating interval
                out.refine(1)
            return out
        alpha.refine((alpha.hi - alpha.lo) / 4)
        for r in hits:
            if not r.is_rational:
                r.refine((r.hi - r.lo) / 2)
