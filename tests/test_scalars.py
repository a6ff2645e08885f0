"""exactcagd.exact.scalars: the one entry point for user numbers (float policy, exact parsing)."""

from fractions import Fraction

import numpy as np
import pytest
import sympy as sp
from gmpy2 import mpfr, mpq, mpz
from hypothesis import given, settings
from hypothesis import strategies as st

import exactcagd
from exactcagd.errors import InexactInputError, InputError
from exactcagd.exact.scalars import (
    float_policy,
    get_float_policy,
    rational_str,
    set_float_policy,
    to_fraction,
    to_rational,
    to_rational_array,
    to_sympy,
)

MPQ = type(mpq(0))


@pytest.mark.parametrize(
    "value, expected",
    [
        (0, Fraction(0)),
        (-7, Fraction(-7)),
        (10**40 + 1, Fraction(10**40 + 1)),
        (Fraction(-3, 14), Fraction(-3, 14)),
        (mpq(5, 9), Fraction(5, 9)),
        (mpz(12), Fraction(12)),
        ("3/7", Fraction(3, 7)),
        (" -3 / 7 ", Fraction(-3, 7)),
        ("-2", Fraction(-2)),
        ("0.125", Fraction(1, 8)),
        ("0.1", Fraction(1, 10)),  # a decimal string means its decimal value
        ("1e-3", Fraction(1, 1000)),
        ("-2.5E2", Fraction(-250)),
        (sp.Rational(-4, 6), Fraction(-2, 3)),
        (sp.Integer(9), Fraction(9)),
        (sp.sqrt(4) / 6, Fraction(1, 3)),  # a sympy number that is rational
        (sp.sqrt(2) * sp.sqrt(8), Fraction(4)),
        (sp.cos(1) ** 2 + sp.sin(1) ** 2, Fraction(1)),  # exactly 1, proved symbolically
        (np.int64(-5), Fraction(-5)),
        (np.uint8(200), Fraction(200)),
    ],
)
def test_exact_inputs(value, expected):
    q = to_rational(value)
    assert isinstance(q, MPQ)
    assert Fraction(int(q.numerator), int(q.denominator)) == expected


@pytest.mark.parametrize(
    "x",
    [0.1, -0.75, 1e-300, 5e-324, 1.7976931348623157e308, 2.0**-60, -0.0],
)
def test_float_is_its_exact_binary_value(x):
    q = to_rational(x)
    assert Fraction(int(q.numerator), int(q.denominator)) == Fraction(x)  # Fraction(float) is exact
    assert float(q) == x


def test_float_0_1_is_not_one_tenth():
    assert to_rational(0.1) == mpq(3602879701896397, 36028797018963968)
    assert to_rational(0.1) != to_rational("1/10")


@pytest.mark.parametrize("x", [np.float64(0.1), np.float32(0.1), np.float16(0.1), np.longdouble(1) / 3])
def test_numpy_floats_exact_binary_value(x):
    q = to_rational(x)
    num, den = x.as_integer_ratio()
    assert q == mpq(int(num), int(den))


def test_sympy_float_keeps_its_own_precision():
    """A 30-digit sympy Float converts to its exact binary value at its own precision
    (regression: it used to be rounded to 53 bits)."""
    x = sp.Float("0.1", 30)
    q = to_rational(x)
    sign, man, exp, _ = x._mpf_
    assert q == mpq(int(man), 2 ** (-exp))
    assert q != to_rational(0.1)
    assert to_rational(sp.Float("-2.5", 30)) == mpq(-5, 2)
    assert to_rational(sp.Float(0.1)) == to_rational(0.1)


def test_mpfr_exact_binary_value():
    assert to_rational(mpfr("0.5")) == mpq(1, 2)
    assert to_rational(mpfr(1) / 3) == mpq(mpfr(1) / 3)


@given(st.floats(allow_nan=False, allow_infinity=False))
@settings(max_examples=60, deadline=None)
def test_random_floats_exact(x):
    q = to_rational(x)
    assert Fraction(int(q.numerator), int(q.denominator)) == Fraction(x)


@given(st.fractions(max_denominator=10**6))
@settings(max_examples=60, deadline=None)
def test_string_round_trip(f):
    q = to_rational(f"{f.numerator}/{f.denominator}")
    assert to_fraction(q) == f
    assert to_rational(rational_str(q)) == q
    assert to_sympy(q) == sp.Rational(f.numerator, f.denominator)


# ---------------------------------------------------------------- float policy
def test_reject_policy_context_manager():
    assert get_float_policy() == "exact"
    with float_policy("reject"):
        assert get_float_policy() == "reject"
        with pytest.raises(InexactInputError):
            to_rational(0.5)
        with pytest.raises(InexactInputError):
            to_rational(np.float32(0.5))
        with pytest.raises(InexactInputError):
            to_rational(mpfr("0.5"))
        with pytest.raises(InexactInputError):
            to_rational(sp.Float("0.5", 40))
        with pytest.raises(InexactInputError):
            exactcagd.BezierCurve([[0, 0], [0.5, 1]])
        # exact inputs still pass
        assert to_rational("1/2") == mpq(1, 2) == to_rational(Fraction(1, 2)) == to_rational(1) / 2
        with float_policy("exact"):  # nesting restores the outer policy
            assert to_rational(0.5) == mpq(1, 2)
        with pytest.raises(InexactInputError):
            to_rational(0.5)
    assert to_rational(0.5) == mpq(1, 2)


def test_reject_policy_argument_and_global_setter():
    with pytest.raises(InexactInputError):
        to_rational(0.25, policy="reject")
    set_float_policy("reject")
    try:
        assert get_float_policy() == "reject"
        with pytest.raises(InexactInputError):
            to_rational(0.25)
        assert to_rational(0.25, policy="exact") == mpq(1, 4)
        with pytest.raises(InexactInputError):
            to_rational_array([[1, 2.5]])
    finally:
        set_float_policy("exact")
    assert to_rational(0.25) == mpq(1, 4)


def test_unknown_policy():
    with pytest.raises(InputError):
        set_float_policy("round")
    with pytest.raises(InputError):
        with float_policy("approximate"):
            pass
    with pytest.raises(InputError):
        to_rational(1, policy="lenient")


# ---------------------------------------------------------------- rejected inputs
@pytest.mark.parametrize(
    "x",
    [
        float("nan"),
        float("inf"),
        -float("inf"),
        np.float64("nan"),
        np.float32("inf"),
        np.longdouble("-inf"),
        mpfr("nan"),
        mpfr("inf"),
        "nan",
        "inf",
        "-Infinity",
        sp.nan,
        sp.oo,
        sp.zoo,
    ],
)
@pytest.mark.parametrize("policy", ["exact", "reject"])
def test_nan_inf_always_rejected(x, policy):
    with pytest.raises(InexactInputError):
        to_rational(x, policy=policy)


@pytest.mark.parametrize(
    "x",
    [
        sp.sqrt(2),
        sp.pi,
        sp.pi - sp.Rational(355, 113),
        sp.exp(-40),
        sp.I,
        # irrational but within 1e-15 of a rational: must not be "recognized" as that rational
        # (regression: sympy.nsimplify used to turn 1 + exp(-40) into 1)
        1 + sp.exp(-40),
        sp.Rational(1, 3) + sp.exp(-100),
        sp.sqrt(2) - sp.Rational(14142135623730951, 10**16),
    ],
)
def test_irrational_sympy_numbers_rejected(x):
    with pytest.raises(InexactInputError):
        to_rational(x)


@pytest.mark.parametrize(
    "x",
    [True, False, np.bool_(True), None, "abc", "1/0", "1/2/3", "", "0x10", [1], (1, 2), {}, 1j, object(), sp.Symbol("t")],
)
def test_garbage_rejected(x):
    with pytest.raises(InputError):
        to_rational(x)


def test_error_names_the_value():
    with pytest.raises(InputError, match=r"knots\[3\]"):
        to_rational("x", where="knots[3]")


# ---------------------------------------------------------------- arrays
def test_rational_array_shapes_and_types():
    a = to_rational_array([[1, "1/2", 0.5], [Fraction(1, 3), np.int32(2), sp.Rational(3, 4)]])
    assert a.shape == (2, 3) and a.dtype == object
    assert all(isinstance(x, MPQ) for x in a.reshape(-1))
    assert a[0, 1] == a[0, 2] == mpq(1, 2)
    b = to_rational_array(np.array([[0.25, 1.0], [2.0, -3.5]]))
    assert b.shape == (2, 2) and b[1, 1] == mpq(-7, 2)
    c = to_rational_array([[[1, 2], [3, 4]], [[5, 6], [7, 8]]])
    assert c.shape == (2, 2, 2)
    assert to_rational_array(7).shape == ()


@pytest.mark.parametrize(
    "ragged",
    [
        [[1, 2], [3]],
        [[1, 2], 3],
        [1, [2, 3]],
        [[[0, 0], [1, 1]], [[0, 0]]],
        [[[0, 0], [1, 1]], [[0, 0], [1, 1, 1]]],
    ],
)
def test_ragged_arrays_rejected(ragged):
    with pytest.raises(InputError, match="ragged"):
        to_rational_array(ragged)


def test_array_elements_checked():
    with pytest.raises(InexactInputError, match=r"pts\[1\]\[0\]"):
        to_rational_array([[0, 0], [float("nan"), 1]], where="pts")
    with pytest.raises(InputError):
        to_rational_array([[0, 0], ["x", 1]])
