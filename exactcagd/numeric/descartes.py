"""Exact real-root isolation in Bernstein form: Descartes' rule + exact de Casteljau (VCA).

The number of sign variations ``V`` of the Bernstein coefficients of ``p`` on an
interval bounds the number of roots there (variation diminishing property, notes
9.2: "a root is isolated if there is exactly one sign change"); ``V`` and the root
count have the same parity.  So ``V = 0`` excludes the interval, ``V = 1`` isolates
exactly one root, and otherwise the interval is halved by an *exact* de Casteljau
subdivision at the midpoint (notes 2.3).  On a square-free polynomial this always
terminates (the Vincent-Collins-Akritas / Bernstein-Descartes method).

Square-free preparation: the polynomial is split into its square-free factors
(python-flint ``factor_squarefree`` in the power basis, exact), each factor is
isolated on its own and carries the multiplicity of its roots.  All arithmetic is
on Python integers: a halving step multiplies the pieces by ``2**n`` so no
fraction ever appears.

This is the second exact route of exactcagd (the first is
:func:`exactcagd.exact.algebraic.real_roots`, flint's complex root isolation);
the tests cross-check both.

>>> [str(r) for r in isolate_exact([1, -3, 1])]    # 8t^2 - 8t + 1: two roots
['(0, 1/2) x1', '(1/2, 1) x1']
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import flint
from gmpy2 import mpq

from ..errors import InputError
from ..exact.algebraic import sign_at
from ..exact.bernstein import as_coefficients, from_power, to_power
from ..exact.scalars import rational_str

__all__ = ["IsolatingInterval", "isolate_exact", "sign_variations"]


@dataclass(frozen=True)
class IsolatingInterval:
    """One real root of a polynomial, isolated exactly.

    ``lo == hi`` means the root is this rational number; otherwise the root is the
    only root of ``poly`` (a square-free factor) in the open interval ``(lo, hi)``.
    ``multiplicity`` is the exact multiplicity in the original polynomial.
    """

    lo: mpq
    hi: mpq
    multiplicity: int
    poly: flint.fmpz_poly = field(compare=False, repr=False)

    @property
    def is_rational(self) -> bool:
        return self.lo == self.hi

    def contains(self, x) -> bool:
        """True when the exact number ``x`` (rational or RealAlgebraic) is the isolated root's interval member."""
        if self.is_rational:
            return x == self.lo
        return self.lo < x < self.hi

    def refine(self, width) -> "IsolatingInterval":
        """A narrower interval (width < ``width``) by exact bisection on the square-free factor."""
        lo, hi = self.lo, self.hi
        width = mpq(width)
        if lo == hi:
            return self
        poly = _nonzero_at_ends(self.poly, lo, hi)
        s_lo = sign_at(poly, lo)
        while hi - lo >= width:
            mid = (lo + hi) / 2
            s = sign_at(poly, mid)
            if s == 0:
                return IsolatingInterval(mid, mid, self.multiplicity, self.poly)
            if s == s_lo:
                lo = mid
            else:
                hi = mid
        return IsolatingInterval(lo, hi, self.multiplicity, self.poly)

    def __str__(self) -> str:
        if self.is_rational:
            return f"[{rational_str(self.lo)}] x{self.multiplicity}"
        return f"({rational_str(self.lo)}, {rational_str(self.hi)}) x{self.multiplicity}"


def _nonzero_at_ends(poly: flint.fmpz_poly, lo: mpq, hi: mpq) -> flint.fmpz_poly:
    """Divide out the (simple) rational roots ``lo``/``hi`` of a square-free ``poly``.

    An isolating interval may end at another root of the same factor (a root at 0 or 1,
    or a midpoint root found by VCA); bisection by the sign at ``lo`` needs
    ``poly(lo) != 0``, and the open interval's root is a root of the quotient too.
    """
    for e in (lo, hi):
        if sign_at(poly, e) == 0:
            poly = poly // flint.fmpz_poly([-int(e.numerator), int(e.denominator)])
    return poly


def sign_variations(coeffs) -> int:
    """Number of sign changes in a sequence, zeros skipped (Descartes' count)."""
    count, last = 0, 0
    for c in coeffs:
        s = (c > 0) - (c < 0)
        if s == 0:
            continue
        if last and s != last:
            count += 1
        last = s
    return count


def _integer_bernstein(poly: flint.fmpz_poly) -> list[int]:
    """Bernstein coefficients (degree = deg poly) of an integer polynomial, scaled to integers."""
    import numpy as np

    power = np.array([mpq(int(c)) for c in poly.coeffs()], dtype=object)
    bern = from_power(power)
    den = math.lcm(*(int(b.denominator) for b in bern))
    return _primitive([int(b * den) for b in bern])


def _primitive(b: list[int]) -> list[int]:
    g = math.gcd(*b)
    return [x // g for x in b] if g > 1 else b


def _halve(b: list[int]) -> tuple[list[int], list[int]]:
    """Exact de Casteljau at 1/2 on integers: both halves scaled by ``2**n`` (notes 2.3)."""
    n = len(b) - 1
    left, right = [0] * (n + 1), [0] * (n + 1)
    level = list(b)
    left[0], right[n] = level[0] << n, level[n] << n
    for r in range(1, n + 1):
        level = [level[i] + level[i + 1] for i in range(len(level) - 1)]
        left[r] = level[0] << (n - r)
        right[n - r] = level[-1] << (n - r)
    return _primitive(left), _primitive(right)


def _deflate(b: list[int], side: int) -> list[int]:
    """Divide out a root at the left (side 0) or right (side 1) end (notes 9.1, (9.1)).

    ``p = t q`` with ``q_i = n / (i + 1) p_{i+1}``; mirrored for ``p = (1 - t) q``.
    Integer scaling by ``lcm(1..n)`` keeps everything integral.
    """
    n = len(b) - 1
    scale = math.lcm(*range(1, n + 1)) if n > 0 else 1
    if side == 0:
        out = [b[i + 1] * n * scale // (i + 1) for i in range(n)]
    else:
        out = [b[i] * n * scale // (n - i) for i in range(n)]
    return _primitive(out)


def _vca(b: list[int]) -> list[tuple[mpq, mpq]]:
    """Isolating intervals of the roots in [0, 1] of a square-free integer Bernstein polynomial."""
    out: list[tuple[mpq, mpq]] = []
    if b[0] == 0:
        out.append((mpq(0), mpq(0)))
        b = _deflate(b, 0)
    if b[-1] == 0:
        out.append((mpq(1), mpq(1)))
        b = _deflate(b, 1)
    stack = [(b, mpq(0), mpq(1))]
    while stack:
        b, lo, hi = stack.pop()
        v = sign_variations(b)
        if v == 0:
            continue
        if v == 1:
            out.append((lo, hi))
            continue
        mid = (lo + hi) / 2
        left, right = _halve(b)
        if right[0] == 0:  # the midpoint is a root (simple: square-free)
            out.append((mid, mid))
            left, right = _deflate(left, 1), _deflate(right, 0)
        stack.append((left, lo, mid))
        stack.append((right, mid, hi))
    return out


def isolate_in_unit_interval(poly: flint.fmpz_poly) -> list[tuple[mpq, mpq]]:
    """Isolating intervals of the roots in [0, 1] of a square-free integer polynomial
    (power form), by Descartes' rule on its Bernstein coefficients with exact bisection:
    ``(q, q)`` for a root found exactly at a bisection point or an end, else an open
    interval ``(lo, hi)`` holding exactly one root, with ``poly`` nonzero at both ends.

    >>> import flint
    >>> [tuple(map(str, i)) for i in isolate_in_unit_interval(flint.fmpz_poly([-1, 0, 2]))]   # 2t^2 - 1
    [('0', '1')]
    """
    return _vca(_integer_bernstein(poly))


def isolate_exact(coeffs) -> list[IsolatingInterval]:
    """All real roots in [0, 1] of a Bernstein polynomial, isolated exactly.

    Parameters
    ----------
    coeffs : sequence of exact numbers
        Bernstein coefficients on [0, 1] (converted by ``to_rational``).

    Returns
    -------
    list of IsolatingInterval, sorted, pairwise disjoint; each holds exactly one root
    (with its exact multiplicity).

    Raises
    ------
    InputError
        For the zero polynomial (every number is a root).
    """
    c = as_coefficients(coeffs)
    if c.ndim != 1:
        raise InputError("isolate_exact expects a scalar Bernstein polynomial (1-D coefficients)")
    power = to_power(c)
    poly = flint.fmpq_poly([flint.fmpq(int(q.numerator), int(q.denominator)) for q in power])
    if poly == 0:
        raise InputError("the zero polynomial has every number as a root")
    if poly.degree() == 0:
        return []
    _, factors = poly.numer().factor_squarefree()
    found: list[IsolatingInterval] = []
    for factor, mult in factors:
        factor = flint.fmpz_poly(factor)
        for lo, hi in isolate_in_unit_interval(factor):
            found.append(IsolatingInterval(lo, hi, int(mult), factor))
    return _separate(found)


def _overlap(a: IsolatingInterval, b: IsolatingInterval) -> bool:
    if a.is_rational and b.is_rational:
        return a.lo == b.lo
    if a.is_rational:
        return b.lo < a.lo < b.hi
    if b.is_rational:
        return a.lo < b.lo < a.hi
    return max(a.lo, b.lo) < min(a.hi, b.hi)


def _separate(items: list[IsolatingInterval]) -> list[IsolatingInterval]:
    """Refine intervals of different square-free factors until they are disjoint."""
    items = sorted(items, key=lambda r: (r.lo, r.hi))
    changed = True
    while changed:
        changed = False
        for i in range(len(items)):
            for j in range(i + 1, len(items)):
                a, b = items[i], items[j]
                if not _overlap(a, b):
                    continue
                if a.is_rational and b.is_rational:  # pragma: no cover - distinct factors, distinct roots
                    raise ArithmeticError("two square-free factors share a root")
                if not a.is_rational:
                    items[i] = a.refine((a.hi - a.lo) / 2)
                if not b.is_rational:
                    items[j] = b.refine((b.hi - b.lo) / 2)
                changed = True
        items.sort(key=lambda r: (r.lo, r.hi))
    return items
