"""Exact real algebraic numbers: a root of an irreducible integer polynomial with an
isolating interval with rational endpoints.

Crossing parameters, intersection parameters and roots in general are irrational
in most cases; exactcagd never rounds them.  A :class:`RealAlgebraic` is either a
rational number (``is_rational``) or the unique root of its irreducible defining
polynomial in an open interval ``(lo, hi)``; the interval can be refined to any
width by exact bisection, and comparisons are exact.

Isolation: the polynomial is factored over the integers (python-flint), every
irreducible factor's real roots are isolated by flint's certified complex root
finder (real roots come back with exactly zero imaginary part), the balls are
turned into rational intervals and the sign change at the endpoints is checked
exactly.

>>> from exactcagd.exact.algebraic import real_roots
>>> [(str(r), m) for r, m in real_roots([-1, 0, 2], 0, 1)]      # 2 t^2 - 1 on [0, 1]
[('root of 2*t^2 - 1 in (0, 1)', 1)]
"""

from __future__ import annotations

import math

from functools import total_ordering

import flint
from gmpy2 import mpq

from ..errors import InputError
from .scalars import rational_str, to_fmpq, to_rational

__all__ = ["RealAlgebraic", "real_roots", "real_roots_bernstein", "integer_poly", "bernstein_integer_poly", "exact_dyadic", "sign_at"]


_MPQ = type(mpq(0))


def exact_dyadic(x) -> mpq:
    """The exact value ``man * 2^exp`` of a flint ``arb`` with zero radius (e.g. a ball's
    ``mid()`` or ``rad()``), as an ``mpq``.

    >>> import flint
    >>> str(exact_dyadic(flint.arb(3) / 8))
    '3/8'
    """
    man, exp = x.man_exp()
    man, exp = int(man), int(exp)
    return mpq(man << exp) if exp >= 0 else mpq(man, 1 << -exp)


def integer_poly(coeffs) -> flint.fmpz_poly:
    """Primitive integer polynomial with the roots of ``sum coeffs[k] t^k`` (rational coeffs)."""
    qs = [to_rational(c, where=f"coefficient {k}") for k, c in enumerate(coeffs)]
    poly = flint.fmpq_poly([to_fmpq(q) for q in qs])
    if poly == 0:
        raise InputError("the zero polynomial has every number as a root")
    num = poly.numer()
    content = num.content()
    num = flint.fmpz_poly([c // content for c in num.coeffs()])
    if num.coeffs()[-1] < 0:
        num = -num
    return num


def sign_at(poly: flint.fmpz_poly, x) -> int:
    """The exact sign (-1, 0, 1) of an integer polynomial at a rational ``x`` (``mpq``)."""
    value = poly(flint.fmpq(int(x.numerator), int(x.denominator)) if type(x) is _MPQ else to_fmpq(x))
    return (value > 0) - (value < 0)


def _sign_of(value) -> int:
    return (value > 0) - (value < 0)


def _normal_factor(poly: flint.fmpz_poly, lo: mpq, hi: mpq) -> flint.fmpz_poly:
    """The irreducible, primitive factor with positive leading coefficient of ``poly``
    whose root the interval ``[lo, hi]`` isolates (a sign change for degree >= 2)."""
    if not isinstance(poly, flint.fmpz_poly):
        poly = flint.fmpz_poly([int(c) for c in poly])
    if poly.degree() < 1:
        raise InputError(f"a constant polynomial ({poly}) defines no algebraic number")
    if lo > hi:
        raise InputError(f"empty isolating interval ({lo}, {hi})")
    _, factors = poly.factor()
    candidates = []
    for factor, _ in factors:
        if factor.coeffs()[-1] < 0:
            factor = -factor
        if factor.degree() == 1:
            c0, c1 = (int(c) for c in factor.coeffs())
            if lo <= mpq(-c0, c1) <= hi:
                candidates.append(factor)
        elif sign_at(factor, lo) * sign_at(factor, hi) < 0:
            candidates.append(factor)
    if len(candidates) != 1:
        raise InputError(f"the interval ({lo}, {hi}) does not isolate one root of {poly}")
    return candidates[0]


@total_ordering
class RealAlgebraic:
    """A real algebraic number, carried exactly.

    Attributes
    ----------
    poly : flint.fmpz_poly
        Irreducible, primitive, positive leading coefficient (degree 1 for rationals).
    lo, hi : mpq
        Isolating interval: ``lo < x < hi`` (``lo == hi == x`` when rational).
    """

    __slots__ = ("poly", "lo", "hi")

    def __init__(self, poly: flint.fmpz_poly, lo, hi, *, _checked: bool = False):
        self.lo, self.hi = mpq(lo), mpq(hi)
        if not _checked:
            # exact comparison relies on the normal form (irreducible, primitive, positive
            # leading coefficient): a non-normalized polynomial made == loop forever
            poly = _normal_factor(poly, self.lo, self.hi)
        self.poly = poly
        if poly.degree() == 1:
            c0, c1 = (int(c) for c in poly.coeffs())
            self.lo = self.hi = mpq(-c0, c1)

    def __reduce__(self):
        """Pickle support (flint polynomials do not pickle): integer coefficients + interval."""
        return (_restore, ([int(c) for c in self.poly.coeffs()], self.lo, self.hi))

    @classmethod
    def from_rational(cls, value) -> "RealAlgebraic":
        q = to_rational(value)
        return cls(flint.fmpz_poly([-int(q.numerator), int(q.denominator)]), q, q, _checked=True)

    @property
    def is_rational(self) -> bool:
        return self.poly.degree() == 1

    @property
    def value(self) -> mpq:
        """The exact rational value (only for rational numbers)."""
        if not self.is_rational:
            raise InputError(f"{self} is irrational; use .refine() or float()")
        return self.lo

    def refine(self, width) -> "RealAlgebraic":
        """Shrink the isolating interval below ``width`` by exact bisection (in place)."""
        width = to_rational(width, where="width")
        if width <= 0:
            raise InputError("refinement width must be positive")
        if self.is_rational:
            return self
        if self.hi - self.lo < width:
            return self
        # more than 8 bisections ahead (not a single halving step), and a width a float can bracket
        if width * 256 < self.hi - self.lo and width > max(abs(self.lo), abs(self.hi)) * mpq(1, 2**48):
            self._bracket_float_root(width)
            if self.hi - self.lo < width:
                return self
            # Newton started in a wide interval may leave it: 8 bisections, then once more
            self._bisect((self.hi - self.lo) / 256)
            self._bracket_float_root(width)
        return self._bisect(width)

    def _bisect(self, width: mpq) -> "RealAlgebraic":
        """Exact bisection until the interval is narrower than ``width``."""
        if self.hi - self.lo < width:
            return self
        # bisection in flint's fmpq (one conversion in, one out; ~3x faster per step than mpq)
        poly, half = self.poly, flint.fmpq(1, 2)
        lo, hi, w = (flint.fmpq(int(v.numerator), int(v.denominator)) for v in (self.lo, self.hi, width))
        s_lo = _sign_of(poly(lo))
        while hi - lo >= w:
            mid = (lo + hi) * half
            s_mid = _sign_of(poly(mid))
            if s_mid == 0:  # cannot happen for an irreducible poly of degree >= 2
                self.poly = flint.fmpz_poly([-int(mid.p), int(mid.q)])
                self.lo = self.hi = mpq(int(mid.p), int(mid.q))
                return self
            if s_mid == s_lo:
                lo = mid
            else:
                hi = mid
        self.lo, self.hi = mpq(int(lo.p), int(lo.q)), mpq(int(hi.p), int(hi.q))
        return self

    def _newton_float(self):
        """A float Newton estimate of the root inside the isolating interval, or ``None``
        (left the interval, flat derivative, overflow).  Only a guess: every use checks it
        with exact signs."""
        try:
            coeffs = [float(c) for c in self.poly.coeffs()]
            deriv = [k * c for k, c in enumerate(coeffs)][1:]
            lo_f, hi_f = float(self.lo), float(self.hi)
            x = (lo_f + hi_f) / 2
            previous = float("inf")
            for _ in range(60):
                f = fd = 0.0
                for c in reversed(coeffs):
                    f = f * x + c
                for c in reversed(deriv):
                    fd = fd * x + c
                if fd == 0.0:
                    return None
                step = f / fd
                x -= step
                if not lo_f <= x <= hi_f:
                    return None
                if abs(step) <= 1e-16 * max(abs(x), 1e-300) or abs(step) >= previous:
                    break  # converged, or stagnating at the float resolution
                previous = abs(step)
        except (OverflowError, ZeroDivisionError):
            return None
        return x

    def _bracket_float_root(self, width: mpq) -> None:
        """Try to jump to an interval of width ``width / 2`` around a float Newton estimate.

        Accepted only when the exact signs at both new ends differ (the old interval
        isolates the root, so the new one holds it); otherwise nothing changes and
        bisection does the work.  Saves the ~40 exact bisections to width 1e-12.
        """
        x = self._newton_float()
        if x is None:
            return
        quarter = width / 4
        a, b = mpq(x) - quarter, mpq(x) + quarter
        if a < self.lo or b > self.hi:
            return
        if sign_at(self.poly, a) * sign_at(self.poly, b) < 0:
            self.lo, self.hi = a, b

    def _rounded_by_newton(self):
        """The root correctly rounded to a float, when a float Newton estimate ``x`` is
        confirmed exactly: the root lies strictly between the midpoints of ``x`` and its
        float neighbours (then it rounds to ``x``); the interval shrinks to those midpoints.
        ``None`` when the check fails."""
        x = self._newton_float()
        if x is None or x == 0.0 or math.isinf(x):
            return None
        exact = mpq(x)
        a = (exact + mpq(math.nextafter(x, -math.inf))) / 2
        b = (exact + mpq(math.nextafter(x, math.inf))) / 2
        if a < self.lo or b > self.hi or sign_at(self.poly, a) * sign_at(self.poly, b) >= 0:
            return None
        self.lo, self.hi = a, b
        return x

    def interval(self, width=None) -> tuple[mpq, mpq]:
        """The isolating interval, refined below ``width`` if given."""
        if width is not None:
            self.refine(width)
        return self.lo, self.hi

    def __float__(self) -> float:
        if self.is_rational:
            return float(self.lo)
        x = self._rounded_by_newton()  # correctly rounded, checked exactly
        if x is not None:
            return x
        # else: relative width 2^-60 of the *refined* interval (a wide isolating interval
        # such as (0, 2^62) says nothing about the size of the root itself)
        while self.hi - self.lo > (bound := max(abs(self.lo), abs(self.hi), mpq(1, 2**1000)) * mpq(1, 2**60)):
            self.refine(bound)  # one bisection run to the bound (was one run per halving)
        return float((self.lo + self.hi) / 2)

    def _cmp_rational(self, q: mpq) -> int:
        if self.is_rational:
            return (self.lo > q) - (self.lo < q)
        while self.lo <= q <= self.hi:
            if q == self.lo:
                return 1
            if q == self.hi:
                return -1
            self.refine((self.hi - self.lo) / 2)
        return 1 if self.lo > q else -1

    def _cmp(self, other) -> int:
        if isinstance(other, RealAlgebraic):
            if other.is_rational:
                return self._cmp_rational(other.lo)
            if self.is_rational:
                return -other._cmp_rational(self.lo)
            if self.poly == other.poly and not (self.hi <= other.lo or other.hi <= self.lo):
                # Each interval holds exactly one (simple) root; they hold the same one
                # iff the overlap shows a sign change.
                lo, hi = max(self.lo, other.lo), min(self.hi, other.hi)
                if lo < hi and sign_at(self.poly, lo) * sign_at(self.poly, hi) < 0:
                    return 0
            while not (self.hi <= other.lo or other.hi <= self.lo):
                self.refine((self.hi - self.lo) / 2)
                other.refine((other.hi - other.lo) / 2)
            return -1 if self.hi <= other.lo else 1
        return self._cmp_rational(to_rational(other))

    def __eq__(self, other) -> bool:
        try:
            return self._cmp(other) == 0
        except InputError:
            return NotImplemented

    def __lt__(self, other) -> bool:
        return self._cmp(other) < 0

    def __hash__(self):
        return hash((tuple(int(c) for c in self.poly.coeffs()),) if not self.is_rational else self.lo)

    def to_dict(self) -> dict:
        """Exchange form: defining polynomial (integer coefficients, low to high) and interval."""
        if self.is_rational:
            return {"rational": rational_str(self.lo)}
        return {
            "polynomial": [str(int(c)) for c in self.poly.coeffs()],
            "interval": [rational_str(self.lo), rational_str(self.hi)],
        }

    def to_sympy(self):
        """A sympy ``CRootOf`` (or ``Rational``) equal to this number."""
        import sympy

        if self.is_rational:
            return sympy.Rational(int(self.lo.numerator), int(self.lo.denominator))
        t = sympy.Symbol("t")
        expr = sum(int(c) * t**k for k, c in enumerate(self.poly.coeffs()))
        for root in sympy.Poly(expr, t).real_roots():
            if sympy.Rational(str(self.lo)) < root < sympy.Rational(str(self.hi)):
                return root
        raise AssertionError("isolating interval lost its root")  # pragma: no cover

    def __str__(self) -> str:
        if self.is_rational:
            return rational_str(self.lo)
        terms = []
        for k, c in reversed(list(enumerate(self.poly.coeffs()))):
            c = int(c)
            if c == 0:
                continue
            mono = "" if k == 0 else ("t" if k == 1 else f"t^{k}")
            coef = str(c) if (abs(c) != 1 or k == 0) else ("-" if c < 0 else "")
            terms.append(f"{coef}*{mono}" if mono and coef not in ("", "-") else f"{coef}{mono}")
        text = " + ".join(terms).replace("+ -", "- ")
        return f"root of {text} in ({rational_str(self.lo)}, {rational_str(self.hi)})"

    def __repr__(self) -> str:
        return f"RealAlgebraic({self})"


def _restore(coeffs: list, lo, hi) -> "RealAlgebraic":
    return RealAlgebraic(flint.fmpz_poly(coeffs), lo, hi, _checked=True)


def _dyadic_hull(lo: mpq, hi: mpq, k: int) -> tuple[mpq, mpq]:
    scale = mpq(2) ** k
    return mpq(int((lo * scale).__floor__()), 1) / scale, mpq(int((hi * scale).__ceil__()), 1) / scale


def _coarsest_level(lo: mpq, hi: mpq, others: list, first: int = -64, last: int = 4095) -> int:
    """The smallest ``k`` in ``[first, last]`` whose dyadic hull of ``[lo, hi]`` avoids every
    interval in ``others`` (``last`` if none does).  The hulls are nested (a larger ``k``
    gives a subset), so a search started at the level of the gap finds the same ``k`` as a
    scan from ``first``, in a few steps instead of up to ~70."""

    def separated(k: int) -> bool:
        a, b = _dyadic_hull(lo, hi, k)
        return all(b < o_lo or a > o_hi for o_lo, o_hi in others)

    gaps = [o_lo - hi if o_lo > hi else lo - o_hi for o_lo, o_hi in others]
    if any(g <= 0 for g in gaps):  # pragma: no cover - flint's balls are disjoint
        k = last
    else:
        g = min(gaps, default=None)  # 2^-k about the gap: -log2(g) from bit lengths (no float underflow)
        k = first if g is None else min(last, max(first, 1 + int(g.denominator).bit_length() - int(g.numerator).bit_length()))
    if separated(k):
        if k > first and separated(k - 1):  # a dyadic point between the roots: bisect down
            low, high = first, k - 1
            while low < high:
                mid = (low + high) // 2
                if separated(mid):
                    high = mid
                else:
                    low = mid + 1
            k = low
    else:
        while k < last and not separated(k):
            k += 1
    return k


def _isolate_factor(factor: flint.fmpz_poly, window=(None, None)) -> list[RealAlgebraic]:
    """Isolating intervals of the real roots of an irreducible factor.

    flint's balls are tight but have huge denominators; each is widened to the
    coarsest dyadic interval that still avoids every other root's ball, so the
    printed data stay small.  Roots whose ball lies wholly outside ``window = (lo, hi)``
    (``None`` = unbounded) are left out (they are not widened).
    """
    if factor.degree() == 1:
        return [RealAlgebraic(factor, 0, 0, _checked=True)]
    balls = []
    for root, _ in factor.complex_roots():
        if root.imag.is_zero():
            mid, rad = exact_dyadic(root.real.mid()), exact_dyadic(root.real.rad())
            balls.append((mid - rad, mid + rad))
    out = []
    w_lo, w_hi = window
    for i, (lo, hi) in enumerate(balls):
        if (w_lo is not None and hi < w_lo) or (w_hi is not None and lo > w_hi):
            continue
        others = balls[:i] + balls[i + 1 :]
        a, b = _dyadic_hull(lo, hi, _coarsest_level(lo, hi, others))
        if sign_at(factor, a) * sign_at(factor, b) >= 0:  # pragma: no cover - flint guarantees
            raise ArithmeticError("root isolation failed a sign check")
        out.append(RealAlgebraic(factor, a, b, _checked=True))
    return out


def real_roots(coeffs, lo=None, hi=None) -> list[tuple[RealAlgebraic, int]]:
    """All real roots of ``sum coeffs[k] t^k`` in the closed interval ``[lo, hi]``.

    Parameters
    ----------
    coeffs : sequence of exact numbers, power basis, lowest degree first; or a nonzero
        ``flint.fmpz_poly`` (taken as it is)
    lo, hi : optional bounds (``None`` = unbounded)

    Returns
    -------
    list of (RealAlgebraic, multiplicity), sorted increasingly.
    """
    if isinstance(coeffs, flint.fmpz_poly):
        if coeffs == 0:
            raise InputError("the zero polynomial has every number as a root")
        return _real_roots_of(coeffs, lo, hi)
    return _real_roots_of(integer_poly(coeffs), lo, hi)


def _real_roots_of(poly: flint.fmpz_poly, lo=None, hi=None) -> list[tuple[RealAlgebraic, int]]:
    """:func:`real_roots` of a nonzero integer polynomial."""
    lo = None if lo is None else to_rational(lo)
    hi = None if hi is None else to_rational(hi)
    if poly.degree() <= 0:
        return []
    _, factors = poly.factor()
    roots = []
    for factor, mult in factors:
        if factor.coeffs()[-1] < 0:
            factor = -factor
        for r in _isolate_factor(factor, (lo, hi)):
            roots.append((r, int(mult)))
    out = []
    for r, m in roots:
        if lo is not None and r < lo:
            continue
        if hi is not None and r > hi:
            continue
        if not r.is_rational:  # shrink the interval inside [lo, hi]
            if lo is not None and r.lo < lo:
                r.lo = lo
            if hi is not None and r.hi > hi:
                r.hi = hi
        out.append((r, m))
    out.sort(key=lambda pair: pair[0])
    return out


def bernstein_integer_poly(coeffs) -> flint.fmpz_poly:
    """Primitive integer power form, positive leading coefficient, of ``sum c_i B_i^n(t)``.

    The same roots as the Bernstein polynomial with rational coefficients ``c`` on [0, 1]
    (the same polynomial as :func:`integer_poly` of its power coefficients): with ``L`` the
    lcm of the denominators, the scaled coefficients ``b_i = L C(n, i) c_i`` are integers and
    ``(1 - t)^n b(t / (1 - t))`` is the power form times ``L`` (Sederberg's notes 003, 3.3;
    :func:`exactcagd.exact.bernstein.scaled_to_power`, one Taylor shift in ``fmpz_poly``).

    Parameters
    ----------
    coeffs : sequence of rationals (gmpy2 ``mpq``/``mpz``, ``int``), not all zero

    Examples
    --------
    >>> bernstein_integer_poly([mpq(1), mpq(-3), mpq(1)])      # 8 t^2 - 8 t + 1
    8*x^2 + (-8)*x + 1
    """
    from .bernstein import scaled_to_power

    n = len(coeffs) - 1
    qs = [x if type(x) is _MPQ else to_rational(x, where=f"coefficient {i}") for i, x in enumerate(coeffs)]
    dens = [int(q.denominator) for q in qs]
    lcm = math.lcm(*dens)
    scaled = [int(q.numerator) * (lcm // d) * math.comb(n, i) for i, (q, d) in enumerate(zip(qs, dens))]
    power = scaled_to_power(flint.fmpz_poly(scaled), n)
    if power.is_zero():
        raise InputError("the zero polynomial has every number as a root")
    content = power.content()
    if content != 1:
        power = power // content
    return -power if power.leading_coefficient() < 0 else power


def real_roots_bernstein(coeffs, lo=0, hi=1) -> list[tuple[RealAlgebraic, int]]:
    """Real roots in ``[lo, hi]`` of a polynomial given by Bernstein coefficients on [0, 1]."""
    import numpy as np

    from .bernstein import as_coefficients, to_power

    c = coeffs if isinstance(coeffs, np.ndarray) else as_coefficients(coeffs)
    if c.dtype == object and c.ndim == 1 and all(type(x) is _MPQ for x in c):
        # Bernstein -> power form in flint (scaled form, one Taylor shift: notes 3.3), no mpq arrays
        return _real_roots_of(bernstein_integer_poly(c), lo, hi)
    return real_roots(list(to_power(c)), lo, hi)
