"""Resource limits (exactcagd.limits), tolerances and the size guards of exact input.

References are independent: Python's Fraction for the parsed values, IEEE 754 facts
(``sys.float_info``) for the float rules, the arithmetic of the estimates by hand.
"""

import math
import sys
import threading
import time
from fractions import Fraction

import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, compose, limits
from exactcagd.errors import ExactCAGDError, InputError, LimitError, WeightError
from exactcagd.exact.scalars import to_count, to_float, to_rational, to_tolerance


# ---------------------------------------------------------------- limits table
def test_check_names_estimate_limit_and_how_to_raise():
    with pytest.raises(LimitError) as info:
        limits.check("max_degree", 1001, "elevate(r=998)")
    message = str(info.value)
    assert "elevate(r=998)" in message and "1001" in message and "1000" in message
    assert "limits.raised(max_degree=" in message
    assert issubclass(LimitError, ExactCAGDError)


def test_raised_is_scoped_and_restores():
    assert limits.get("max_degree") == limits.DEFAULTS["max_degree"]
    with limits.raised(max_degree=5):
        assert limits.get("max_degree") == 5
        with limits.raised(max_degree=None):
            limits.check("max_degree", 10**9, "unlimited")
        with pytest.raises(LimitError):
            limits.check("max_degree", 6, "x")
    assert limits.get("max_degree") == limits.DEFAULTS["max_degree"]


def test_raised_is_per_thread():
    seen = []
    with limits.raised(max_degree=7):
        worker = threading.Thread(target=lambda: seen.append(limits.get("max_degree")))
        worker.start()
        worker.join()
    assert seen == [limits.DEFAULTS["max_degree"]]


def test_set_limits_process_wide():
    try:
        limits.set_limits(max_control_points=3)
        with pytest.raises(LimitError):
            limits.check("max_control_points", 4, "points")
    finally:
        limits.set_limits(max_control_points=limits.DEFAULTS["max_control_points"])


@pytest.mark.parametrize("bad", [{"max_degre": 3}, {"max_degree": -1}, {"max_degree": True}, {"max_degree": 2.5}])
def test_bad_limit_settings_are_refused(bad):
    with pytest.raises(InputError):
        limits.set_limits(**bad)
    with pytest.raises(InputError), limits.raised(**bad):
        pass


# ---------------------------------------------------------------- to_tolerance
@pytest.mark.parametrize(
    "value, expected",
    [(1e-9, 1e-9), ("1e-9", 1e-9), ("1/1024", 2.0**-10), (1, 1.0), (Fraction(1, 3), 1 / 3), (sympy.Rational(1, 8), 0.125)],
)
def test_tolerance_accepted(value, expected):
    assert to_tolerance(value) == expected


@pytest.mark.parametrize(
    "value",
    [True, False, b"1e-9", bytearray(b"1"), None, "abc", "", 0, 0.0, -1e-9, "-1", math.nan, math.inf, -math.inf,
     sympy.pi, sympy.Symbol("x"), sympy.sqrt(2), Fraction(1, 10**400), 10**400, [1e-9], 1j],
)
def test_tolerance_refused_naming_the_argument(value):
    with pytest.raises(InputError, match="^eps must be a positive finite number"):
        to_tolerance(value, name="eps")


def test_tolerance_accepts_floats_under_the_reject_policy():
    from exactcagd.exact.scalars import float_policy

    with float_policy("reject"):
        assert to_tolerance(1e-6) == 1e-6


# ---------------------------------------------------------------- to_rational / to_count / to_float
@pytest.mark.parametrize("value", [b"3", bytearray(b"3"), memoryview(b"3"), True])
def test_to_rational_refuses_bytes_and_bools_naming_the_argument(value):
    with pytest.raises(InputError, match="^weight"):
        to_rational(value, where="weight")


@pytest.mark.parametrize("value", [True, False, b"3", 2.0, -1, "3", None, sympy.Integer(3) / 2])
def test_to_count_refuses(value):
    with pytest.raises(InputError, match="r must be a non-negative integer"):
        to_count(value, where="r")


def test_to_count_message_of_a_huge_integer_stays_short():
    with pytest.raises(InputError) as info:
        to_count(-(10**5000), where="r")
    assert len(str(info.value)) < 200


def test_huge_integers_are_exact_not_overflow():
    big = 10**5000
    assert to_rational(big) == big
    assert to_rational("1" + "0" * 5000) == big  # no 4300-digit cap of int(str)
    assert to_rational("1/1" + "0" * 5000) * big == 1
    assert to_rational("1e5000") == big


def test_to_float_rule_beyond_the_float_range():
    # IEEE 754 round-to-nearest: beyond the largest finite float by half an ulp -> inf
    top = Fraction(sys.float_info.max)
    assert to_float(mpq(10**5000)) == math.inf
    assert to_float(mpq(-(10**5000), 3)) == -math.inf
    assert to_float(mpq(1, 10**5000)) == 0.0
    assert to_float(mpq(top.numerator)) == sys.float_info.max


@given(st.integers(-(10**30), 10**30), st.integers(1, 10**30), st.integers(-40, 40))
def test_decimal_strings_parse_like_fraction(p, q, e):
    # independent reference: Python's Fraction parser
    text = f"{p}.{q}e{e}"
    ref = Fraction(text)
    assert to_rational(text) == mpq(ref.numerator, ref.denominator)
    assert to_rational(f"{p}/{q}") == mpq(p, q)


@pytest.mark.parametrize("text", ["1e100000000", "1e-100000000", "9" * 400_000, "1/" + "7" * 400_000])
def test_number_strings_are_bounded_before_they_are_built(text):
    with pytest.raises(LimitError, match="max_input_bits"):
        to_rational(text, where="x")


def test_input_bits_limit_on_integers_and_raising_it():
    big = 1 << 1_000_001
    with pytest.raises(LimitError, match="max_input_bits"):
        to_rational(big)
    with limits.raised(max_input_bits=2_000_000):
        assert to_rational(big) == big


@pytest.mark.parametrize("text", ["abc", "1e", "0x10", "1.2/3", "1/0", "_1", "1__0", ".", "e5", "1e" + "9" * 60])
def test_malformed_number_strings(text):
    with pytest.raises(InputError):
        to_rational(text)


# ---------------------------------------------------------------- the cases, through the public API


def _refused_quickly(call, limit_name, estimate):
    start = time.perf_counter()
    with pytest.raises(LimitError) as info:
        call()
    assert time.perf_counter() - start < 5, "the limit must be checked before the work"
    assert limit_name in str(info.value) and str(estimate) in str(info.value)


def test_elevate_by_a_million_is_refused_with_its_estimate():
    curve = BezierCurve([[0, 0], [1, 2], [2, 0]])
    _refused_quickly(lambda: curve.elevate(10**6), "max_degree", 10**6 + 2)
    with limits.raised(max_degree=12):
        assert curve.elevate(10).degree == 12


def test_a_100k_point_curve_is_refused_before_conversion():
    points = [[i, 0] for i in range(100_000)]
    _refused_quickly(lambda: BezierCurve(points), "max_degree", 99_999)


def test_long_bsplines_knot_checks_are_linear_and_the_point_limit_holds():
    n = 20_000
    start = time.perf_counter()
    curve = BSplineCurve([[i, 0] for i in range(n)], knots=[0] * 4 + list(range(1, n - 3)) + [n - 3] * 4)
    assert time.perf_counter() - start < 20
    assert curve.evaluate(n - 3)[0] == n - 1  # a clamped spline ends at its last control point
    with pytest.raises(LimitError, match="max_control_points"):
        BSplineCurve([[0, 0]] * 100_001, knots=[0] * 4 + list(range(1, 99_998)) + [99_998] * 4)


def test_composition_degree_is_estimated_before_work():
    surface = BezierSurface([[[i, j, 0] for j in range(41)] for i in range(41)])
    curve = BezierCurve([["1/2", k * mpq(1, 41) + mpq(1, 100)] for k in range(41)])
    _refused_quickly(lambda: compose(surface, curve), "max_degree", 40 * (40 + 40))


def test_degree_40_implicitization_is_refused_and_degree_3_is_not():
    from exactcagd.algebra import implicitize

    curve = BezierCurve([[k, (k * k) % 7] for k in range(41)])
    _refused_quickly(lambda: implicitize(curve), "max_implicit_degree", 40)
    cubic = implicitize(BezierCurve([[0, 0], [1, 0], [1, 1], [0, 1]]))
    # independent reference: substitute the parametrization into the equation
    x, y = cubic.gens
    t = sympy.Symbol("t")
    px = 3 * t * (1 - t) ** 2 + 3 * t**2 * (1 - t)
    py = 3 * t**2 * (1 - t) + t**3
    assert sympy.expand(cubic.as_expr().subs({x: px, y: py})) == 0


def test_approximate_refuses_nonsense_snap_bits():
    from exactcagd.curves_on_surfaces import approximate

    surface = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    domain = BezierCurve([["1/4", "1/4"], ["3/4", "3/4"]])
    for bad in (-5, 0, 24, True, 2.5, "64"):
        with pytest.raises(InputError, match="snap_bits"):
            approximate(surface, domain, "1/100", snap_bits=bad)
    with pytest.raises(LimitError, match="max_input_bits"):
        approximate(surface, domain, "1/100", snap_bits=10**7)


@pytest.mark.parametrize("weights", [[0, 1, 1], [1, -1, 1], [1, 1, "-1/2"], [True, 1, 1], [1, math.nan, 1], [1, 1]])
def test_non_positive_or_malformed_weights_are_refused(weights):
    with pytest.raises(InputError):
        BezierCurve([[0, 0], [1, 1], [2, 0]], weights=weights)


def test_zero_weight_is_a_weight_error():
    with pytest.raises(WeightError):
        BezierCurve([[0, 0], [1, 1], [2, 0]], weights=[1, 0, 1])


def test_huge_integers_evaluate_exactly_and_their_float_companions_are_inf():
    from exactcagd.numeric import evaluate

    big = 10**5000
    curve = BezierCurve([[big, 0], [0, 1]])
    assert curve.evaluate("1/2") == (mpq(big, 2), mpq(1, 2))  # exact: (P0 + P1) / 2
    values, _ = evaluate(curve, [0.5])
    assert values[0][0] == math.inf and values[0][1] == 0.5


def test_limits_are_reachable_from_the_package():
    import exactcagd

    assert exactcagd.limits.get("max_degree") == limits.DEFAULTS["max_degree"]


def test_float_companions_of_huge_control_points_follow_the_inf_rule():
    big = 10**5000
    points, weights = BezierCurve([[big, 0], [1, "1/3"]], weights=[1, big]).to_float()
    assert points[0][0] == math.inf and points[1][1] == 1 / 3 and weights[1] == math.inf
    net, _ = BezierSurface([[[-big, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]).to_float()
    assert net[0][0][0] == -math.inf and net[1][1][2] == 1.0


@pytest.mark.parametrize("value", [2**62, 10**30, 10**5000], ids=["2^62", "10^30", "10^5000"])
def test_counts_beyond_2_62_are_a_limit_error_with_a_short_message(value):
    with pytest.raises(LimitError, match="r = ") as info:
        to_count(value, where="r")
    assert len(str(info.value)) < 200


# ---------------------------------------------------------------- no silent acceptance of a bad tolerance
def _tol_calls():
    from exactcagd.composition import approximate_cubic
    from exactcagd.curves_on_surfaces import approximate
    from exactcagd.numeric import bernstein_roots, intersect

    surface = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    domain = BezierCurve([["1/4", "1/4"], ["3/4", "3/4"]])
    a, b = BezierCurve([[0, 0], [1, 1]]), BezierCurve([[0, 1], [1, 0]])
    return {
        "approximate": lambda tol: approximate(surface, domain, tol),
        "approximate_cubic": lambda tol: approximate_cubic(surface, domain, tol),
        "numeric.intersect": lambda tol: intersect(a, b, tol=tol),
        "bernstein_roots": lambda tol: bernstein_roots([-1, 0, 1], tol=tol),
    }


_BAD_TOLERANCES = [True, False, b"1e-6", None, "abc", sympy.pi, sympy.Symbol("e"), math.nan, math.inf, -1, 0]


@pytest.mark.parametrize("name", ["approximate", "approximate_cubic", "numeric.intersect", "bernstein_roots"])
def test_bad_tolerances_are_refused_everywhere(name):
    call = _tol_calls()[name]
    for tol in _BAD_TOLERANCES:
        with pytest.raises(ExactCAGDError):
            call(tol)


def test_every_documented_limit_is_checked_by_some_entry_point():
    """A limit in the table that nothing checks would be a promise not kept (issue 14)."""
    from exactcagd.algebra import SurfaceParametrization, implicitize

    cubic_patch = BezierSurface([[[i, j, (i * j) % 2] for j in range(4)] for i in range(4)])
    trips = {
        "max_degree": lambda: BezierCurve([[0, 0], [1, 1]]).elevate(1000),
        "max_control_points": lambda: BSplineCurve([[0, 0]] * 100_001, knots=[0] * 2 + list(range(1, 100_000)) + [100_000] * 2),
        "max_implicit_degree": lambda: implicitize(BezierCurve([[k, k * k % 5] for k in range(26)])),
        "max_surface_implicit": lambda: SurfaceParametrization.from_bezier_surface(cubic_patch),
        "max_input_bits": lambda: to_rational("1e400000"),
    }
    assert set(trips) == set(limits.DEFAULTS)
    for name, call in trips.items():
        with pytest.raises(LimitError, match=name):
            call()


def test_a_huge_tolerance_is_met_exactly_not_overflowed():
    from exactcagd.curves_on_surfaces import approximate

    surface = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    domain = BezierCurve([["1/10", "1/10"], ["1/2", "9/10"], ["9/10", "1/5"]])
    for method in ("parabola", "fit"):
        result = approximate(surface, domain, 10**5000, method)
        assert result.distance_bound <= 10**5000
