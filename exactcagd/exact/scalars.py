"""Exact rational scalars: the single entry point for user numbers.

Every number that enters the exact layer passes through :func:`to_rational`,
which returns a ``gmpy2.mpq``.  Floats are handled by an explicit policy:

* ``"exact"`` (default): a float is converted to the rational number equal to its
  binary value, e.g. ``0.1 -> 3602879701896397/36028797018963968``;
* ``"reject"``: a float raises :class:`~exactcagd.errors.InexactInputError`.

NaN and infinities are always rejected.  The policy can be set globally with
:func:`set_float_policy` or locally with the :func:`float_policy` context manager.

>>> from exactcagd.exact.scalars import to_rational
>>> to_rational("3/7")
mpq(3,7)
>>> to_rational(0.5)
mpq(1,2)
"""

from __future__ import annotations

import contextlib
import math
import numbers
import re
import threading
from fractions import Fraction

import flint
import gmpy2
from gmpy2 import mpq, mpz

from .. import limits
from ..errors import InexactInputError, InputError, LimitError

__all__ = [
    "Rational",
    "to_rational",
    "to_rational_array",
    "float_policy",
    "set_float_policy",
    "get_float_policy",
    "to_fraction",
    "to_sympy",
    "to_fmpq",
    "from_fmpq",
    "rational_str",
    "to_float",
    "to_count",
    "to_tolerance",
    "short_repr",
]

#: The exact scalar type used throughout the exact layer.
Rational = type(mpq(0))

_POLICIES = ("exact", "reject")
_state = threading.local()
_default_policy = "exact"


def get_float_policy() -> str:
    """Return the float policy in force in this thread (``"exact"`` or ``"reject"``)."""
    return getattr(_state, "policy", _default_policy)


def set_float_policy(policy: str) -> None:
    """Set the process-wide default float policy (``"exact"`` or ``"reject"``)."""
    global _default_policy
    _check_policy(policy)
    _default_policy = policy


@contextlib.contextmanager
def float_policy(policy: str):
    """Context manager that sets the float policy for the enclosed block.

    >>> from exactcagd.exact.scalars import float_policy, to_rational
    >>> with float_policy("reject"):
    ...     to_rational(1)
    mpq(1,1)
    """
    _check_policy(policy)
    previous = getattr(_state, "policy", None)
    _state.policy = policy
    try:
        yield
    finally:
        if previous is None:
            del _state.policy
        else:
            _state.policy = previous


def _check_policy(policy: str) -> None:
    if policy not in _POLICIES:
        raise InputError(f"unknown float policy {policy!r}; expected one of {_POLICIES}")


def _from_float(x: float, policy: str, where: str) -> Rational:
    if math.isnan(x) or math.isinf(x):
        raise InexactInputError(f"{where}: {x!r} is not a finite number")
    if policy == "reject":
        raise InexactInputError(
            f"{where}: float {x!r} rejected by the 'reject' float policy; "
            "give an int, a Fraction or a string such as '3/7'"
        )
    return mpq(*x.as_integer_ratio())


def to_rational(x, *, policy: str | None = None, where: str = "value") -> Rational:
    """Convert one user number to an exact rational (``gmpy2.mpq``).

    Parameters
    ----------
    x : int, Fraction, gmpy2.mpz/mpq, str, sympy Rational/Integer, float, numpy scalar
        The number.  Strings are parsed exactly (``"3/7"``, ``"-2"``, ``"0.125"``,
        ``"1e-3"``); decimal strings mean their decimal value, not a float.
    policy : {"exact", "reject"}, optional
        Float policy; defaults to the one in force (:func:`get_float_policy`).
    where : str
        Name of the value, used in error messages.

    Returns
    -------
    gmpy2.mpq

    Raises
    ------
    InexactInputError
        For NaN/inf, for floats under ``"reject"``, for irrational sympy numbers.
    InputError
        For anything that is not a number.

    Examples
    --------
    >>> to_rational("0.125")
    mpq(1,8)
    >>> to_rational(0.1) == to_rational("1/10")
    False
    """
    if policy is None:
        policy = get_float_policy()
    else:
        _check_policy(policy)
    if isinstance(x, Rational):
        return x
    if isinstance(x, bool):
        raise InputError(f"{where}: booleans are not numbers here ({x!r})")
    if isinstance(x, (bytes, bytearray, memoryview)):
        raise InputError(f"{where}: bytes are not numbers here ({short_repr(x)}); give an int, a Fraction or a str")
    if isinstance(x, (int, type(mpz(0)))):
        _check_bits(x, 1, where)
        return mpq(x)
    if isinstance(x, Fraction):
        _check_bits(x.numerator, x.denominator, where)
        return mpq(x.numerator, x.denominator)
    if isinstance(x, float):
        return _from_float(x, policy, where)
    if isinstance(x, str):
        return _from_string(x, where)
    # numpy scalars
    try:
        import numpy as np

        if isinstance(x, np.integer):
            return mpq(int(x))
        if isinstance(x, np.floating):  # exact binary value of any width (float16 ... longdouble)
            if not np.isfinite(x):
                raise InexactInputError(f"{where}: {x!r} is not a finite number")
            if policy == "reject":
                return _from_float(float(x), policy, where)
            return mpq(*(int(v) for v in x.as_integer_ratio()))
    except ImportError:  # pragma: no cover
        pass
    if type(x).__module__.startswith("gmpy2"):  # mpfr: exact binary value, like float
        if not gmpy2.is_finite(x):
            raise InexactInputError(f"{where}: {x!r} is not a finite number")
        if policy == "reject":
            raise InexactInputError(f"{where}: mpfr {x!r} rejected by the 'reject' float policy")
        return mpq(x)
    if type(x).__module__.startswith("sympy"):
        return _from_sympy(x, policy, where)
    if type(x).__module__.startswith("flint"):
        return _from_flint(x, where)
    if isinstance(x, numbers.Rational):
        return mpq(int(x.numerator), int(x.denominator))
    raise InputError(f"{where}: cannot convert {short_repr(x)} of type {type(x).__name__} to an exact rational")


_INTEGER = re.compile(r"\s*([+-]?)([0-9](?:_?[0-9])*)\s*")
_DECIMAL = re.compile(
    r"\s*([+-]?)(?=[0-9]|\.[0-9])([0-9](?:_?[0-9])*)?(?:\.([0-9](?:_?[0-9])*)?)?(?:[eE]([+-]?[0-9](?:_?[0-9])*))?\s*"
)


def _from_string(s: str, where: str) -> Rational:
    """``"p/q"`` or an exact decimal (``"-1.25e-3"``), digits read by gmpy2 (no 4300-digit
    cap as with ``int(str)``), the size bounded first (:func:`_check_number_string`)."""
    text = s.strip()
    if text.lower().lstrip("+-") in {"nan", "inf", "infinity"}:
        raise InexactInputError(f"{where}: {s!r} is not a finite number")
    _check_number_string(text, where)
    num_text, slash, den_text = text.partition("/")
    if slash:
        num, den = _INTEGER.fullmatch(num_text), _INTEGER.fullmatch(den_text)
        if num is None or den is None:
            raise InputError(f"{where}: cannot parse {short_repr(s)} as an exact rational")
        denominator = _digits(den)
        if denominator == 0:
            raise InputError(f"{where}: {short_repr(s)} has a zero denominator")
        return mpq(_digits(num), denominator)
    match = _DECIMAL.fullmatch(text)
    if match is None:
        raise InputError(f"{where}: cannot parse {short_repr(s)} as an exact rational")
    sign, whole, fraction, exponent = match.groups()
    fraction = (fraction or "").replace("_", "")
    mantissa = mpz((whole or "0").replace("_", "") + fraction)
    exp = (int(exponent.replace("_", "")) if exponent else 0) - len(fraction)
    value = mpq(mantissa * mpz(10) ** exp) if exp >= 0 else mpq(mantissa, mpz(10) ** -exp)
    return -value if sign == "-" else value


def _digits(match) -> mpz:
    value = mpz(match.group(2).replace("_", ""))
    return -value if match.group(1) == "-" else value


_LOG2_10 = 3.3219280948873626


def _check_number_string(text: str, where: str) -> None:
    """Bound the size of the number a string spells before it is built: ``"1e100000000"``
    is 11 characters but a 332-million-bit integer (limit ``max_input_bits``)."""
    mantissa, _, exponent = text.lower().partition("e")
    digits = sum(ch.isdigit() for ch in mantissa)
    try:
        exp = abs(int(exponent)) if exponent and len(exponent) <= 40 else (0 if not exponent else None)
    except ValueError:
        return  # not a number: Fraction's own parser reports it
    if exp is None:
        raise InputError(f"{where}: exponent of {text[:40]!r}... is absurdly long")
    limits.check("max_input_bits", int((digits + exp) * _LOG2_10), f"{where} = {text[:40]!r}")


def _check_bits(num: int, den: int, where: str) -> None:
    bits = max(num.bit_length(), den.bit_length())
    if bits > 4096:  # the common case costs two bit_length calls
        limits.check("max_input_bits", bits, where)


def _from_sympy(x, policy: str, where: str) -> Rational:
    import sympy

    if isinstance(x, sympy.Rational):
        return mpq(int(x.p), int(x.q))
    if isinstance(x, sympy.Float):
        return _from_float(float(x), policy, where) if x._prec <= 53 else _exact_mpf(x, policy, where)
    if isinstance(x, sympy.Basic) and x.is_number:
        # symbolic simplification only: nsimplify would *guess* a nearby rational
        # from a 15-digit evaluation (1 + exp(-40) -> 1), a silent rounding
        simplified = sympy.simplify(x)
        if simplified.is_Rational:
            return mpq(int(simplified.p), int(simplified.q))
        raise InexactInputError(f"{where}: {short_repr(x)} is not rational; exact rationals only")
    raise InputError(f"{where}: sympy object {short_repr(x)} is not a number")


def _exact_mpf(x, policy: str, where: str) -> Rational:
    if policy == "reject":
        raise InexactInputError(f"{where}: sympy Float {x} rejected by the 'reject' float policy")
    # the raw (sign, mantissa, exponent, bits) tuple: exact at the Float's own precision
    # (mpmath.mpf(...) would round it to the working precision, 53 bits by default)
    sign, man, exp, _ = x._mpf_
    value = mpq(int(man)) * (mpq(2) ** int(exp))
    return -value if sign else value


def _from_flint(x, where: str) -> Rational:
    import flint

    if isinstance(x, flint.fmpz):
        return mpq(int(x))
    if isinstance(x, flint.fmpq):
        return mpq(int(x.p), int(x.q))
    raise InputError(f"{where}: cannot convert flint object {short_repr(x)} to an exact rational")


def to_rational_array(values, *, policy: str | None = None, where: str = "array"):
    """Convert a (possibly nested) sequence to a numpy object array of ``mpq``.

    The array is rectangular; a ragged input raises :class:`InputError` naming it.

    >>> to_rational_array([[1, "1/2"], [0, 3]]).shape
    (2, 2)
    """
    import numpy as np

    def convert(item, path):
        if isinstance(item, (list, tuple)) or (isinstance(item, np.ndarray) and item.ndim > 0):
            return [convert(sub, f"{path}[{i}]") for i, sub in enumerate(item)]
        return to_rational(item, policy=policy, where=f"{where}{path}")

    nested = convert(values, "")
    shape = _rectangular_shape(nested, where)
    out = np.empty(shape, dtype=object)
    _fill(out, nested, ())
    return out


def _rectangular_shape(nested, where):
    shape = []
    level = [nested]
    while level and isinstance(level[0], list):
        lengths = {len(x) if isinstance(x, list) else -1 for x in level}
        if len(lengths) != 1 or -1 in lengths:
            raise InputError(f"{where}: ragged nested sequence (lengths {sorted(lengths)} at depth {len(shape)})")
        shape.append(lengths.pop())
        level = [y for x in level for y in x]
    if any(isinstance(x, list) for x in level):  # pragma: no cover - caught above
        raise InputError(f"{where}: ragged nested sequence")
    return tuple(shape)


def _fill(out, nested, index):
    if isinstance(nested, list):
        for i, sub in enumerate(nested):
            _fill(out, sub, index + (i,))
    else:
        out[index] = nested


def to_count(x, *, where: str = "count", error: type = InputError) -> int:
    """A non-negative integer (degree, elevation amount, multiplicity) as a Python ``int``.

    ``bool`` and integral floats such as ``2.0`` are rejected like any non-integer: a count
    given as ``True`` or ``2.0`` is almost always a mistake in the call.

    >>> to_count(3, where="r")
    3
    """
    if isinstance(x, bool) or not isinstance(x, numbers.Integral) or x < 0:
        raise error(f"{where} must be a non-negative integer, got {short_repr(x)}")
    value = int(x)  # numpy, gmpy2 and sympy integers alike
    if value.bit_length() > 62:  # no degree, amount or count of 2^62 can be honoured, whatever the limits
        raise LimitError(f"{where} = {short_repr(value)} exceeds every resource limit (counts must stay below 2^62)")
    return value


def short_repr(x, limit: int = 80) -> str:
    """``repr(x)`` cut to ``limit`` characters, for error messages about user values.

    A 10^5000 argument must neither flood the message nor break it: ``repr`` of an int
    above 4300 digits raises ``ValueError`` in Python >= 3.11 (such ints are described by
    their size instead).

    >>> short_repr(10**5000)
    '<int of 16610 bits>'
    """
    if isinstance(x, int) and not isinstance(x, bool) and x.bit_length() > 4000:
        return f"<int of {x.bit_length()} bits>"
    try:
        text = repr(x)
    except Exception:  # noqa: BLE001 - a broken __repr__ must not hide the real error
        return f"<{type(x).__name__}>"
    return text if len(text) <= limit else f"{text[:limit - 20]}...({len(text)} chars)"


def to_tolerance(value, name: str = "tol") -> float:
    """A tolerance (a positive, finite width) as the ``float`` the float methods compare with.

    Accepted: ``int``, ``float``, ``Fraction``, ``gmpy2``/``flint``/numpy/sympy rationals and
    number strings (``"1e-9"``, ``"1/1024"``); a non-float is converted exactly and then
    rounded to the nearest float (:func:`to_float`).  A tolerance is a float parameter by
    nature, so floats are accepted under either float policy.

    Refused with :class:`~exactcagd.errors.InputError` naming ``name``: booleans, bytes,
    ``None``, strings that are not numbers, zero, negative values, NaN and infinities,
    symbols and irrational numbers (``sympy.pi``: convert explicitly with ``float(pi)`` if
    that is what you mean), and values whose nearest float is 0 or infinite (``10**-400``,
    ``10**400``), which no float comparison can honour.

    Parameters
    ----------
    value : number
        The tolerance.
    name : str
        Name of the argument, used in error messages.

    Returns
    -------
    float
        ``0 < tol < inf``.

    Examples
    --------
    >>> to_tolerance("1/1024")
    0.0009765625
    >>> to_tolerance(True)
    Traceback (most recent call last):
    ...
    exactcagd.errors.InputError: tol must be a positive finite number, got True (a bool)
    """
    if isinstance(value, bool):
        raise InputError(f"{name} must be a positive finite number, got {value!r} (a bool)")
    if isinstance(value, float):
        tol = value
    else:
        try:
            tol = to_float(to_rational(value, policy="exact", where=name))
        except InputError as exc:
            raise InputError(f"{name} must be a positive finite number, got {short_repr(value)} ({exc})") from None
    if not (tol > 0 and math.isfinite(tol)):
        raise InputError(
            f"{name} must be a positive finite number, got {short_repr(value)}"
            + (" (its nearest float is 0.0)" if tol == 0 and not isinstance(value, float) and value != 0 else "")
        )
    return tol


def to_fraction(x: Rational) -> Fraction:
    """Return the exact rational ``x`` as a :class:`fractions.Fraction`."""
    return Fraction(int(x.numerator), int(x.denominator))


def to_sympy(x: Rational):
    """Return the exact rational ``x`` as a ``sympy.Rational``."""
    import sympy

    return sympy.Rational(int(x.numerator), int(x.denominator))


def rational_str(x: Rational) -> str:
    """Return ``"p/q"`` (or ``"p"`` for integers): the exchange format of exact data."""
    return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"


def to_fmpq(x) -> flint.fmpq:
    """An exact number as python-flint's ``fmpq`` (through :func:`to_rational`).

    >>> to_fmpq("3/7")
    3/7
    """
    x = x if isinstance(x, Rational) else to_rational(x)
    return flint.fmpq(int(x.numerator), int(x.denominator))


def from_fmpq(x) -> Rational:
    """python-flint's ``fmpq`` or ``fmpz`` (or an int) as ``gmpy2.mpq``.

    >>> from_fmpq(to_fmpq("-5/4"))
    mpq(-5,4)
    """
    if isinstance(x, flint.fmpq):
        return mpq(int(x.p), int(x.q))
    return mpq(int(x))


def to_float(x: Rational) -> float:
    """The float64 nearest to the exact rational ``x`` (correctly rounded, ties to even).

    Python's ``int / int`` true division is correctly rounded, which makes this the
    reference for the float companions of exact outputs.  Rule for values beyond the
    float range: they round to ``inf`` / ``-inf``, as IEEE 754 round-to-nearest does
    (where Python's division raises ``OverflowError``); tiny values round to ``0.0``.

    >>> to_float(mpq(1, 3)), to_float(mpq(-10**400))
    (0.3333333333333333, -inf)
    """
    num, den = int(x.numerator), int(x.denominator)
    try:
        return num / den
    except OverflowError:
        return math.inf if num > 0 else -math.inf
