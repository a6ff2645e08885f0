"""Interval arithmetic (Sederberg's notes, chapter 12.1): exact and outward-rounded.

Two types with the same interface:

:class:`Interval`       closed interval ``[lo, hi]`` with exact rational endpoints
                        (``gmpy2.mpq``); the operations (12.3) are exact set operations
                        on the endpoints, so ``x in [u], y in [v]  =>  x * y in [u] * [v]``
                        with no rounding at all.
:class:`FloatInterval`  binary64 endpoints, every endpoint rounded *outward* with a
                        directed-rounding context (``gmpy2``, round-down for ``lo``,
                        round-up for ``hi``); never round-to-nearest for an endpoint, so
                        the result contains the exact interval result (notes 13, (13.3)).

The rules (12.3)::

    [a, b] + [c, d] = [a + c, b + d]
    [a, b] - [c, d] = [a - d, b - c]
    [a, b] * [c, d] = [min(ac, ad, bc, bd), max(ac, ad, bc, bd)]
    [a, b] / [c, d] = [a, b] * [1/d, 1/c]         (0 not in [c, d], else DomainError)

Numbers mix with intervals as degenerate intervals (12.4); a float enters with its exact
binary value.  Note ``[u] - [u] != 0`` and multiplication is only sub-distributive
(12.33), e.g. ``([1, 2] + [3, 4]) - [3, 4] == [0, 3]``.

>>> from exactcagd.numeric.interval import Interval
>>> (Interval(1, 2) + Interval(3, 4)) - Interval(3, 4)
Interval(0, 3)
>>> Interval(-1, 2) ** 2
Interval(0, 4)
>>> Interval("1/3").to_float().contains("1/3")
True
"""

from __future__ import annotations

import math

import gmpy2
from gmpy2 import mpfr, mpq

from ..errors import DomainError, InexactInputError, InputError
from ..exact.scalars import Rational, rational_str, to_rational
from .fp_error import round_down, round_up

__all__ = ["Interval", "FloatInterval", "as_interval"]


def _interval_operand(x, where: str):
    """Coerce an operand: intervals stay, numbers become exact rationals."""
    if isinstance(x, (Interval, FloatInterval)):
        return x
    return to_rational(x, where=where, policy="exact")


class Interval:
    """A closed interval ``[lo, hi]`` of real numbers with exact rational endpoints.

    Parameters
    ----------
    lo : number
        Lower endpoint (any number :func:`exactcagd.to_rational` accepts; a float is
        taken as its exact binary value).
    hi : number, optional
        Upper endpoint; defaults to ``lo`` (a degenerate interval, notes (12.4)).

    Examples
    --------
    >>> Interval(1, 2) * Interval(-3, "1/2")
    Interval(-6, 1)
    >>> Interval(0, 1).midpoint(), Interval(0, 1).width()
    (mpq(1,2), mpq(1,1))
    """

    __slots__ = ("_lo", "_hi")

    def __init__(self, lo, hi=None):
        lo = to_rational(lo, where="interval lower endpoint", policy="exact")
        hi = lo if hi is None else to_rational(hi, where="interval upper endpoint", policy="exact")
        if lo > hi:
            raise InputError(f"interval endpoints out of order: [{lo}, {hi}]")
        self._lo, self._hi = lo, hi

    @classmethod
    def _make(cls, lo: Rational, hi: Rational) -> "Interval":
        out = object.__new__(cls)
        out._lo, out._hi = lo, hi
        return out

    @classmethod
    def centered(cls, center, error) -> "Interval":
        """The interval ``center + error [-1, 1]`` (centered form, notes (12.21))."""
        c = to_rational(center, where="center", policy="exact")
        e = to_rational(error, where="error", policy="exact")
        if e < 0:
            raise InputError(f"centered form needs a non-negative error, got {e}")
        return cls._make(c - e, c + e)

    # ------------------------------------------------------------------ accessors
    @property
    def lo(self) -> Rational:
        return self._lo

    @property
    def hi(self) -> Rational:
        return self._hi

    def width(self) -> Rational:
        """``hi - lo``."""
        return self._hi - self._lo

    def midpoint(self) -> Rational:
        """The center ``(lo + hi) / 2`` (notes (12.21))."""
        return (self._lo + self._hi) / 2

    def radius(self) -> Rational:
        """The error ``(hi - lo) / 2`` of the centered form (notes (12.21))."""
        return (self._hi - self._lo) / 2

    def magnitude(self) -> Rational:
        """``max |x|`` over the interval."""
        return max(abs(self._lo), abs(self._hi))

    def is_degenerate(self) -> bool:
        return self._lo == self._hi

    def contains(self, x) -> bool:
        """True if the number (or every point of the interval) ``x`` lies in this interval."""
        if isinstance(x, (Interval, FloatInterval)):
            return self._lo <= x.lo and x.hi <= self._hi
        q = to_rational(x, where="point", policy="exact")
        return self._lo <= q <= self._hi

    __contains__ = contains

    def hull(self, other) -> "Interval":
        """The smallest interval containing both."""
        other = as_interval(other)
        return Interval._make(min(self._lo, other._lo), max(self._hi, other._hi))

    def intersection(self, other) -> "Interval | None":
        """The common part, or ``None`` when the intervals are disjoint."""
        other = as_interval(other)
        lo, hi = max(self._lo, other._lo), min(self._hi, other._hi)
        return Interval._make(lo, hi) if lo <= hi else None

    def to_float(self) -> "FloatInterval":
        """The tightest float interval containing this one (outward rounding)."""
        return FloatInterval._make(round_down(self._lo), round_up(self._hi))

    # ------------------------------------------------------------------ arithmetic (12.3)
    def _coerce(self, other):
        try:
            other = _interval_operand(other, "interval operand")
        except InputError:
            return None  # not a number: Python tries the other operand (or raises TypeError)
        if isinstance(other, FloatInterval):
            return None  # let FloatInterval handle the mixed operation
        if isinstance(other, Interval):
            return other
        return Interval._make(other, other)

    def __neg__(self) -> "Interval":
        return Interval._make(-self._hi, -self._lo)

    def __pos__(self) -> "Interval":
        return self

    def __add__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return Interval._make(self._lo + o._lo, self._hi + o._hi)

    __radd__ = __add__

    def __sub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return Interval._make(self._lo - o._hi, self._hi - o._lo)

    def __rsub__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o - self

    def __mul__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if o._lo == o._hi:  # scalar times interval (12.5): exact, order by sign
            a, b = self._lo * o._lo, self._hi * o._lo
            return Interval._make(min(a, b), max(a, b))
        p = (self._lo * o._lo, self._lo * o._hi, self._hi * o._lo, self._hi * o._hi)
        return Interval._make(min(p), max(p))

    __rmul__ = __mul__

    def __truediv__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        if o._lo <= 0 <= o._hi:
            raise DomainError(f"division by the interval {o!r}, which contains 0")
        return self * Interval._make(1 / o._hi, 1 / o._lo)

    def __rtruediv__(self, other):
        o = self._coerce(other)
        if o is None:
            return NotImplemented
        return o / self

    def __pow__(self, k):
        """Integer power; the exact range of ``x**k`` (even powers of a 0-straddling interval start at 0)."""
        if not isinstance(k, int) or isinstance(k, bool):
            raise InputError(f"interval powers need an integer exponent, got {k!r}")
        if k < 0:
            return Interval._make(mpq(1), mpq(1)) / (self**-k)
        if k == 0:
            return Interval._make(mpq(1), mpq(1))
        a, b = self._lo**k, self._hi**k
        if k % 2 == 1 or self._lo >= 0:
            return Interval._make(a, b) if k % 2 == 1 or a <= b else Interval._make(b, a)
        if self._hi <= 0:
            return Interval._make(b, a)
        return Interval._make(mpq(0), max(a, b))

    # ------------------------------------------------------------------ comparison & display
    def __eq__(self, other) -> bool:
        if isinstance(other, Interval):
            return self._lo == other._lo and self._hi == other._hi
        return NotImplemented

    def __hash__(self):
        return hash((self._lo, self._hi))

    def __repr__(self) -> str:
        return f"Interval({rational_str(self._lo)}, {rational_str(self._hi)})"

    def to_dict(self) -> dict:
        return {"lo": rational_str(self._lo), "hi": rational_str(self._hi)}


def _check_float(x, where: str) -> float:
    if isinstance(x, bool):
        raise InputError(f"{where}: booleans are not numbers")
    if isinstance(x, float):
        if math.isnan(x):
            raise InexactInputError(f"{where}: NaN is not an interval endpoint")
        return x
    return None


_UP = gmpy2.ieee(64)
_UP.round = gmpy2.RoundUp
_DOWN = gmpy2.ieee(64)
_DOWN.round = gmpy2.RoundDown


def _rd(op: str, a: float, b: float) -> float:
    return float(getattr(_DOWN, op)(mpfr(a), mpfr(b)))


def _ru(op: str, a: float, b: float) -> float:
    return float(getattr(_UP, op)(mpfr(a), mpfr(b)))


# Directed rounding without a rounding-mode switch: the round-to-nearest result ``r`` and
# its exact error ``e`` (error-free transformations: Knuth's TwoSum, Dekker's TwoProduct --
# Ogita, Rump & Oishi, SIAM J. Sci. Comput. 26 (2005), Algorithms 3.1-3.3) decide the
# directed roundings: ``exact = r + e``, so round-down is ``r`` if ``e >= 0`` else the float
# below ``r``, and symmetrically upward.  These identities hold while no operand or result
# overflows and no product underflows; outside that range the gmpy2 contexts decide.
_SPLIT = 134217729.0  # 2^27 + 1 (Veltkamp's splitting constant for binary64)
_SAFE_HI = 2.0**960  # |operands| and |results| below: no overflow in splitting or products
_SAFE_LO = 2.0**-960  # |products| and |quotients| above: their errors are representable


def _directed(r: float, e: float) -> tuple[float, float]:
    if e > 0:
        return r, math.nextafter(r, math.inf)
    if e < 0:
        return math.nextafter(r, -math.inf), r
    return r, r


def _two_product_error(a: float, b: float, p: float) -> float:
    """``a b - p`` exactly (Dekker), for ``p = fl(a b)`` inside the safe range."""
    c = _SPLIT * a
    ah = c - (c - a)
    al = a - ah
    c = _SPLIT * b
    bh = c - (c - b)
    bl = b - bh
    return ((ah * bh - p) + ah * bl + al * bh) + al * bl


def _add_directed(a: float, b: float, upward: bool) -> float:
    """``round_up(a + b)`` if ``upward`` else ``round_down(a + b)``."""
    s = a + b
    if -_SAFE_HI < s < _SAFE_HI and -_SAFE_HI < a < _SAFE_HI and -_SAFE_HI < b < _SAFE_HI:
        if s == 0.0:
            if a == 0.0 and b == 0.0 and math.copysign(1.0, a) == math.copysign(1.0, b):
                return a  # the sum of two zeros of one sign is that zero
            return 0.0 if upward else -0.0  # any other exact zero sum: +0 up, -0 down (IEEE 754 6.3)
        bb = s - a
        error = (a - (s - bb)) + (b - bb)  # a + b = s + error exactly (TwoSum)
        if upward:
            return s if error <= 0 else math.nextafter(s, math.inf)
        return s if error >= 0 else math.nextafter(s, -math.inf)
    return _ru("add", a, b) if upward else _rd("add", a, b)


def _mul_directed(a: float, b: float, upward: bool) -> float:
    """``round_up(a b)`` if ``upward`` else ``round_down(a b)`` (NaN for ``0 * inf``)."""
    p = a * b
    if a == 0.0 or b == 0.0:
        if math.isfinite(a) and math.isfinite(b):
            return p  # an exact zero
    elif _SAFE_LO < abs(p) < _SAFE_HI and abs(a) < _SAFE_HI and abs(b) < _SAFE_HI:
        error = _two_product_error(a, b, p)  # a b = p + error exactly
        if upward:
            return p if error <= 0 else math.nextafter(p, math.inf)
        return p if error >= 0 else math.nextafter(p, -math.inf)
    return _ru("mul", a, b) if upward else _rd("mul", a, b)


def _mul_down(a: float, b: float) -> float:
    return _mul_directed(a, b, False)


def _mul_up(a: float, b: float) -> float:
    return _mul_directed(a, b, True)


def _interval_product(al: float, ah: float, bl: float, bh: float) -> tuple[float, float]:
    """Endpoints of ``[al, ah] [bl, bh]`` by the signs of the endpoints (Moore, *Interval
    Analysis* (1966), the nine cases): two directed products except when both factors
    contain 0; the same bits as the minimum and maximum of the four directed corner products."""
    if al >= 0:
        if bl >= 0:
            return _mul_down(al, bl), _mul_up(ah, bh)
        if bh <= 0:
            return _mul_down(ah, bl), _mul_up(al, bh)
        return _mul_down(ah, bl), _mul_up(ah, bh)
    if ah <= 0:
        if bl >= 0:
            return _mul_down(al, bh), _mul_up(ah, bl)
        if bh <= 0:
            return _mul_down(ah, bh), _mul_up(al, bl)
        return _mul_down(al, bh), _mul_up(al, bl)
    if bl >= 0:
        return _mul_down(al, bh), _mul_up(ah, bh)
    if bh <= 0:
        return _mul_down(ah, bl), _mul_up(al, bl)
    return min(_mul_down(al, bh), _mul_down(ah, bl)), max(_mul_up(al, bl), _mul_up(ah, bh))


def _div_both(a: float, b: float) -> tuple[float, float]:
    """``(round_down(a / b), round_up(a / b))`` for ``b != 0``."""
    q = a / b
    if _SAFE_LO < abs(q) < _SAFE_HI and _SAFE_LO < abs(b) < _SAFE_HI and _SAFE_LO < abs(a) < _SAFE_HI:
        p = q * b
        residual = (a - p) - _two_product_error(q, b, p)  # a - q b: a - p is exact (Sterbenz)
        return _directed(q, residual if b > 0 else -residual)  # a/b - q = residual / b
    if a == 0.0 and math.isfinite(b):
        return q, q
    return _rd("div", a, b), _ru("div", a, b)


class FloatInterval:
    """A closed interval with binary64 endpoints and outward-rounded arithmetic.

    Parameters
    ----------
    lo, hi : float or number
        A float is taken as it is; any other number (``"1/10"``, ``Fraction``, ``mpq``,
        ``int``) is enclosed outward (``lo`` rounded down, ``hi`` rounded up).  Infinite
        endpoints are allowed (they arise from overflow), NaN is not.

    Examples
    --------
    >>> x = FloatInterval("1/10")
    >>> x.lo < x.hi and x.contains("1/10")
    True
    >>> (FloatInterval(1.0) / 3.0).contains("1/3")
    True
    """

    __slots__ = ("_lo", "_hi")

    def __init__(self, lo, hi=None):
        hi = lo if hi is None else hi
        flo = _check_float(lo, "lower endpoint")
        fhi = _check_float(hi, "upper endpoint")
        flo = round_down(to_rational(lo, where="lower endpoint", policy="exact")) if flo is None else flo
        fhi = round_up(to_rational(hi, where="upper endpoint", policy="exact")) if fhi is None else fhi
        if not flo <= fhi:
            raise InputError(f"interval endpoints out of order: [{flo!r}, {fhi!r}]")
        self._lo, self._hi = flo, fhi

    @classmethod
    def _make(cls, lo: float, hi: float) -> "FloatInterval":
        out = object.__new__(cls)
        out._lo, out._hi = lo, hi
        return out

    @property
    def lo(self) -> float:
        return self._lo

    @property
    def hi(self) -> float:
        return self._hi

    def width(self) -> float:
        """An upper bound of ``hi - lo`` (rounded up)."""
        return _ru("sub", self._hi, self._lo)

    def midpoint(self) -> float:
        """A float inside the interval near its center (exact for finite endpoints unless overflow)."""
        if math.isinf(self._lo) or math.isinf(self._hi):
            return 0.0 if self._lo < 0 < self._hi else (self._lo if math.isinf(self._hi) else self._hi)
        m = self._lo / 2 + self._hi / 2
        return min(max(m, self._lo), self._hi)

    def radius(self) -> float:
        """An upper bound of the largest distance from :meth:`midpoint` to an endpoint."""
        m = self.midpoint()
        return max(_ru("sub", self._hi, m), _ru("sub", m, self._lo))

    def magnitude(self) -> float:
        return max(abs(self._lo), abs(self._hi))

    def is_degenerate(self) -> bool:
        return self._lo == self._hi

    def contains(self, x) -> bool:
        """Exact containment test of a number (compared by exact value) or an interval."""
        if isinstance(x, (Interval, FloatInterval)):
            return _exact_le(self._lo, x.lo) and _exact_le(x.hi, self._hi, upper=True)
        q = to_rational(x, where="point", policy="exact")
        return _exact_le(self._lo, q) and _exact_le(q, self._hi, upper=True)

    __contains__ = contains

    def to_exact(self) -> Interval:
        """The same set as an exact :class:`Interval` (finite endpoints only)."""
        if math.isinf(self._lo) or math.isinf(self._hi):
            raise DomainError("an interval with an infinite endpoint has no exact rational form")
        return Interval._make(mpq(self._lo), mpq(self._hi))

    def hull(self, other) -> "FloatInterval":
        o = _as_float_interval(other)
        return FloatInterval._make(min(self._lo, o._lo), max(self._hi, o._hi))

    # ------------------------------------------------------------------ arithmetic
    def __neg__(self) -> "FloatInterval":
        return FloatInterval._make(-self._hi, -self._lo)

    def __add__(self, other):
        o = _float_operand(other)
        if o is None:
            return NotImplemented
        return FloatInterval._make(_add_directed(self._lo, o._lo, False), _add_directed(self._hi, o._hi, True))

    __radd__ = __add__

    def __sub__(self, other):
        o = _float_operand(other)
        if o is None:
            return NotImplemented
        return FloatInterval._make(_add_directed(self._lo, -o._hi, False), _add_directed(self._hi, -o._lo, True))

    def __rsub__(self, other):
        o = _float_operand(other)
        return NotImplemented if o is None else o - self

    def __mul__(self, other):
        o = _float_operand(other)
        if o is None:
            return NotImplemented
        lo, hi = _interval_product(self._lo, self._hi, o._lo, o._hi)
        if lo != lo or hi != hi:  # NaN from 0 * inf: the set product is unbounded
            return FloatInterval._make(-math.inf, math.inf)
        return FloatInterval._make(lo, hi)

    __rmul__ = __mul__

    def __truediv__(self, other):
        o = _float_operand(other)
        if o is None:
            return NotImplemented
        if o._lo <= 0 <= o._hi:
            raise DomainError(f"division by the interval {o!r}, which contains 0")
        both = [_div_both(a, b) for a in {self._lo, self._hi} for b in {o._lo, o._hi}]
        lows, highs = [x for x, _ in both], [y for _, y in both]
        if any(math.isnan(x) for x in lows + highs):  # inf / inf
            return FloatInterval._make(-math.inf, math.inf)
        return FloatInterval._make(min(lows), max(highs))

    def __rtruediv__(self, other):
        o = _float_operand(other)
        return NotImplemented if o is None else o / self

    def __pow__(self, k):
        if not isinstance(k, int) or isinstance(k, bool):
            raise InputError(f"interval powers need an integer exponent, got {k!r}")
        if k < 0:
            return FloatInterval._make(1.0, 1.0) / (self**-k)
        if k == 0:
            return FloatInterval._make(1.0, 1.0)
        lo, hi = self._lo, self._hi

        def pw(ctx, x):
            return float(ctx.pow(mpfr(x), k))

        if k % 2 == 1 or lo >= 0:
            return FloatInterval._make(pw(_DOWN, lo), pw(_UP, hi))
        if hi <= 0:
            return FloatInterval._make(pw(_DOWN, hi), pw(_UP, lo))
        return FloatInterval._make(0.0, max(pw(_UP, lo), pw(_UP, hi)))

    def __eq__(self, other) -> bool:
        if isinstance(other, FloatInterval):
            return self._lo == other._lo and self._hi == other._hi
        return NotImplemented

    def __hash__(self):
        return hash(("float", self._lo, self._hi))

    def __repr__(self) -> str:
        return f"FloatInterval({self._lo!r}, {self._hi!r})"


def _exact_le(a, b, upper: bool = False) -> bool:
    """Exact ``a <= b`` for floats (possibly infinite) and rationals."""
    if isinstance(a, float) and math.isinf(a):
        return a < 0 or (isinstance(b, float) and b == math.inf)
    if isinstance(b, float) and math.isinf(b):
        return b > 0
    qa = a if isinstance(a, Rational) else mpq(a)
    qb = b if isinstance(b, Rational) else mpq(b)
    return qa <= qb


def _float_operand(x) -> "FloatInterval | None":
    if type(x) is FloatInterval:  # the common case first: no call, no try
        return x
    try:
        return _as_float_interval(x)
    except InputError:
        return None


def _as_float_interval(x) -> FloatInterval:
    if isinstance(x, FloatInterval):
        return x
    if isinstance(x, Interval):
        return x.to_float()
    if isinstance(x, float):
        return FloatInterval(x)
    q = to_rational(x, where="interval operand", policy="exact")
    return FloatInterval._make(round_down(q), round_up(q))


def as_interval(x) -> Interval:
    """Coerce a number, an ``(lo, hi)`` pair or an :class:`Interval` to an exact :class:`Interval`."""
    if isinstance(x, Interval):
        return x
    if isinstance(x, FloatInterval):
        return x.to_exact()
    if isinstance(x, (tuple, list)):
        if len(x) != 2:
            raise InputError(f"an interval is given as (lo, hi); got {len(x)} numbers")
        return Interval(x[0], x[1])
    return Interval(x)
