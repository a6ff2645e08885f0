"""Exact real quadratic fields Q(sqrt(D)): numbers ``a + b sqrt(D)`` with rational ``a, b``.

The G1 parabola construction of Yang et al. (004), section 5, eq. (16), needs
``alpha_2 = (alpha_1 + alpha_3 + sqrt(Delta)) / 2`` with a rational but usually
non-square ``Delta``; every coefficient built from it (the Möbius parameter ``beta``,
the control points of the reparameterized surface and of its iso-line) lies in
``Q(sqrt(Delta))``.  :class:`QuadraticNumber` carries such numbers exactly:
``+ - * /``, exact sign and comparison, ``float`` and ``sympy`` conversion.

Representation: ``a + b sqrt(D)`` with ``a, b`` ``gmpy2.mpq`` and ``D`` a positive
non-square integer (a rational radicand ``p/q`` is rewritten as ``sqrt(p q) / q``).
Numbers with ``b == 0`` are rationals and mix with every field; two irrational
numbers of different radicands cannot be combined (:class:`InputError`).
Plain ``mpq``/``int`` operands are accepted on either side, so numpy object arrays
and :mod:`exactcagd.exact.bernstein` work on these numbers unchanged.

Measured (``benchmarks/bench_curves_on_surfaces.py``, D = 1000003, 40-bit entries):
products ``a * b + a`` are about 6x faster than with sympy's
``QQ.algebraic_field(sqrt(D))`` elements (ANP); chains of divisions run at about
the same speed (both are dominated by big-integer growth).  The curves-on-surfaces
code avoids field divisions in its hot paths (homogeneous weights), so this class
is used rather than sympy.

>>> from exactcagd.exact.quadratic import sqrt_rational
>>> r = sqrt_rational(2)
>>> x = (1 + r) / (1 - r)
>>> x
QuadraticNumber(-3 - 2*sqrt(2))
>>> x * x.conjugate() == 1
True
>>> float(r) == 2 ** 0.5, r > "7/5", r < "3/2"
(True, True, True)
"""

from __future__ import annotations

import gmpy2
from gmpy2 import mpq, mpz

from ..errors import InputError
from .scalars import Rational, rational_str, to_rational

__all__ = ["QuadraticNumber", "sqrt_rational", "field_of", "as_quadratic"]

_MPQ = type(mpq(0))
_MPZ = type(mpz(0))


def _q(x) -> Rational:
    if isinstance(x, _MPQ):
        return x
    if isinstance(x, (int, _MPZ)) and not isinstance(x, bool):
        return mpq(x)
    return to_rational(x)


def _square_free_part(n: int) -> tuple[int, int]:
    """Write ``n = f^2 * r``, removing square factors of small primes only (cheap).

    The result need not be square-free; it only keeps radicands small.
    """
    f = 1
    for p in (2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37, 41, 43, 47):
        pp = p * p
        while n % pp == 0:
            n //= pp
            f *= p
    return f, n


class QuadraticNumber:
    """``a + b sqrt(D)``, exact (``D`` a positive non-square integer).

    Build with :func:`sqrt_rational` or ``QuadraticNumber(a, b, D)``; arithmetic with
    ``int``/``mpq``/other numbers of the same field gives numbers of the field.

    Examples
    --------
    >>> x = QuadraticNumber(1, 1, 5)        # the golden ratio times 2
    >>> x * x == 2 * x + 4
    True
    >>> (x / 2).sign(), (1 - x).sign()
    (1, -1)
    """

    __slots__ = ("a", "b", "D")

    def __init__(self, a, b=0, D=None):
        self.a = _q(a)
        self.b = _q(b)
        if D is None:
            if self.b != 0:
                raise InputError("QuadraticNumber with b != 0 needs a radicand D")
            self.D = None
            return
        D = mpz(D)
        if D <= 0 or gmpy2.is_square(D):
            raise InputError(f"radicand D = {D} must be a positive non-square integer")
        self.D = D

    @classmethod
    def _make(cls, a, b, D) -> "QuadraticNumber":
        x = object.__new__(cls)
        x.a, x.b, x.D = a, b, D
        return x

    # ------------------------------------------------------------------ field bookkeeping
    @property
    def is_rational(self) -> bool:
        return self.b == 0

    @property
    def rational(self) -> Rational:
        """The value as ``mpq`` (only for rational numbers)."""
        if self.b != 0:
            raise InputError(f"{self} is irrational")
        return self.a

    def _coerce(self, other):
        """Return ``(a, b, D)`` of ``other`` in this number's field, or ``None``."""
        if isinstance(other, QuadraticNumber):
            if other.b == 0:
                return other.a, other.b, self.D
            if self.b == 0 or self.D is None:
                return other.a, other.b, other.D
            if other.D != self.D:
                raise InputError(f"cannot combine numbers of Q(sqrt({self.D})) and Q(sqrt({other.D}))")
            return other.a, other.b, self.D
        if isinstance(other, _MPQ):
            return other, mpq(0), self.D
        if isinstance(other, (int, _MPZ)) and not isinstance(other, bool):
            return mpq(other), mpq(0), self.D
        return None

    def _field(self, D_other):
        return self.D if self.D is not None else D_other

    # ------------------------------------------------------------------ arithmetic
    def __add__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        return QuadraticNumber._make(self.a + a, self.b + b, self._field(D))

    __radd__ = __add__

    def __sub__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        return QuadraticNumber._make(self.a - a, self.b - b, self._field(D))

    def __rsub__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        return QuadraticNumber._make(a - self.a, b - self.b, self._field(D))

    def __neg__(self):
        return QuadraticNumber._make(-self.a, -self.b, self.D)

    def __pos__(self):
        return self

    def __mul__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        if b == 0:
            return QuadraticNumber._make(self.a * a, self.b * a, self._field(D))
        if self.b == 0:
            return QuadraticNumber._make(self.a * a, self.a * b, D)
        return QuadraticNumber._make(self.a * a + self.b * b * D, self.a * b + self.b * a, D)

    __rmul__ = __mul__

    def inverse(self) -> "QuadraticNumber":
        """``1 / x = (a - b sqrt D) / (a^2 - b^2 D)`` (the norm is non-zero for x != 0)."""
        if self.b == 0:
            if self.a == 0:
                raise ZeroDivisionError("division by zero in Q(sqrt(D))")
            return QuadraticNumber._make(1 / self.a, mpq(0), self.D)
        n = self.norm()
        return QuadraticNumber._make(self.a / n, -self.b / n, self.D)

    def __truediv__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        if b == 0:
            if a == 0:
                raise ZeroDivisionError("division by zero in Q(sqrt(D))")
            return QuadraticNumber._make(self.a / a, self.b / a, self._field(D))
        return self * QuadraticNumber._make(a, b, D).inverse()

    def __rtruediv__(self, other):
        c = self._coerce(other)
        if c is None:
            return NotImplemented
        a, b, D = c
        return QuadraticNumber._make(a, b, self._field(D)) * self.inverse()

    def __pow__(self, k: int):
        if not isinstance(k, int):
            return NotImplemented
        if k < 0:
            return self.inverse() ** (-k)
        result = QuadraticNumber._make(mpq(1), mpq(0), self.D)
        base = self
        while k:
            if k & 1:
                result = result * base
            base = base * base
            k >>= 1
        return result

    # ------------------------------------------------------------------ exact order
    def conjugate(self) -> "QuadraticNumber":
        """``a - b sqrt(D)``."""
        return QuadraticNumber._make(self.a, -self.b, self.D)

    def norm(self) -> Rational:
        """``(a + b sqrt D)(a - b sqrt D) = a^2 - b^2 D`` (rational)."""
        return self.a * self.a - self.b * self.b * (self.D or 0)

    def sign(self) -> int:
        """Exact sign in {-1, 0, 1}: compare ``a^2`` with ``b^2 D`` when the signs differ."""
        sa = (self.a > 0) - (self.a < 0)
        sb = (self.b > 0) - (self.b < 0)
        if sb == 0:
            return sa
        if sa == 0 or sa == sb:
            return sb
        n = self.norm()  # a^2 - b^2 D; non-zero since D is not a square
        return sa if n > 0 else sb

    def _cmp(self, other) -> int:
        c = self._coerce(other)
        if c is None:
            c = (to_rational(other), mpq(0), self.D)
        a, b, D = c
        return QuadraticNumber._make(self.a - a, self.b - b, self._field(D)).sign()

    def __eq__(self, other):
        try:
            return self._cmp(other) == 0
        except (InputError, TypeError):
            return NotImplemented

    def __ne__(self, other):
        result = self.__eq__(other)
        return result if result is NotImplemented else not result

    def __lt__(self, other):
        return self._cmp(other) < 0

    def __le__(self, other):
        return self._cmp(other) <= 0

    def __gt__(self, other):
        return self._cmp(other) > 0

    def __ge__(self, other):
        return self._cmp(other) >= 0

    def __abs__(self):
        return -self if self.sign() < 0 else self

    def __bool__(self):
        return self.sign() != 0

    def __hash__(self):
        return hash(self.a) if self.b == 0 else hash((self.a, self.b, int(self.D)))

    # ------------------------------------------------------------------ conversion
    def __float__(self) -> float:
        if self.b == 0:
            return float(self.a)
        with gmpy2.context(gmpy2.get_context(), precision=200):
            root = gmpy2.sqrt(gmpy2.mpfr(self.D))
            a, bt = gmpy2.mpfr(self.a), gmpy2.mpfr(self.b) * root
            if (a > 0) != (bt > 0) and a != 0:  # cancellation: use the conjugate form
                value = gmpy2.mpfr(self.norm()) / (a - bt)
            else:
                value = a + bt
            return float(value)

    def bounds(self, bits: int = 64) -> tuple[Rational, Rational]:
        """Rational ``lo <= x <= hi`` with ``hi - lo <= |b| 2^-bits`` (exact integer sqrt)."""
        if self.b == 0:
            return self.a, self.a
        scale = mpz(2) ** bits
        r = gmpy2.isqrt(self.D * scale * scale)  # r <= sqrt(D) 2^bits < r + 1
        lo_root, hi_root = mpq(r, scale), mpq(r + 1, scale)
        if self.b > 0:
            return self.a + self.b * lo_root, self.a + self.b * hi_root
        return self.a + self.b * hi_root, self.a + self.b * lo_root

    def to_sympy(self):
        import sympy

        from .scalars import to_sympy

        if self.b == 0:
            return to_sympy(self.a)
        return to_sympy(self.a) + to_sympy(self.b) * sympy.sqrt(sympy.Integer(int(self.D)))

    def __str__(self) -> str:
        if self.b == 0:
            return rational_str(self.a)
        b = "" if self.b == 1 else ("-" if self.b == -1 else f"{rational_str(self.b)}*")
        root = f"{b}sqrt({int(self.D)})"
        if self.a == 0:
            return root
        sign = " - " if root.startswith("-") else " + "
        return f"{rational_str(self.a)}{sign}{root.lstrip('-')}"

    def __repr__(self) -> str:
        return f"QuadraticNumber({self})"


def sqrt_rational(x) -> Rational | QuadraticNumber:
    """Exact ``sqrt(x)`` of a non-negative rational: ``mpq`` if ``x`` is a square, else a
    :class:`QuadraticNumber` ``b sqrt(D)`` with an integer radicand ``D``.

    >>> sqrt_rational("9/4"), sqrt_rational("1/2")
    (mpq(3,2), QuadraticNumber(1/2*sqrt(2)))
    """
    q = to_rational(x, where="radicand")
    if q < 0:
        raise InputError(f"sqrt of a negative number {q} is not real")
    p, d = int(q.numerator), int(q.denominator)
    if gmpy2.is_square(p) and gmpy2.is_square(d):
        return mpq(int(gmpy2.isqrt(p)), int(gmpy2.isqrt(d)))
    f, n = _square_free_part(p * d)  # sqrt(p/d) = sqrt(p d) / d = f sqrt(n) / d
    if gmpy2.is_square(n):  # pragma: no cover - excluded by the test above
        return mpq(f * int(gmpy2.isqrt(n)), d)
    return QuadraticNumber._make(mpq(0), mpq(f, d), mpz(n))


def field_of(values) -> int | None:
    """The common radicand ``D`` of an iterable of numbers (``None``: all rational)."""
    D = None
    for x in values:
        if isinstance(x, QuadraticNumber) and x.b != 0:
            if D is None:
                D = x.D
            elif D != x.D:
                raise InputError(f"numbers of two fields Q(sqrt({D})) and Q(sqrt({x.D}))")
    return None if D is None else int(D)


def as_quadratic(x) -> QuadraticNumber:
    """Any exact number as a :class:`QuadraticNumber` (rationals get ``b = 0``)."""
    if isinstance(x, QuadraticNumber):
        return x
    return QuadraticNumber._make(_q(x), mpq(0), None)


def is_exact_zero(x) -> bool:
    """``x == 0`` for mpq or QuadraticNumber (exact)."""
    if isinstance(x, QuadraticNumber):
        return x.sign() == 0
    return x == 0
