"""``from_dict`` reads back what ``to_dict`` writes, for every geometry class.

References: the original exact control data (compared exactly, mpq == mpq) after a JSON
round trip, and for Bezier curves the point sympy gets from the Bernstein sum written
out from the dict's strings (notes 2.1 / 2.9), not from the class.
"""

from __future__ import annotations

import json

import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface
from exactcagd.errors import DegreeError, ExactCAGDError, InputError

rationals = st.fractions(min_value=-4, max_value=4, max_denominator=50).map(lambda f: mpq(f.numerator, f.denominator))
weights = st.fractions(min_value="1/8", max_value=8, max_denominator=50).map(lambda f: mpq(f.numerator, f.denominator))


def _json_trip(obj):
    return json.loads(json.dumps(obj.to_dict()))


def _sympy_bezier_point(data: dict, t):
    """Evaluate the curve dict by the Bernstein sum (notes 2.1 / 2.9), sympy rationals."""
    pts = [[sympy.Rational(x) for x in p] for p in data["control_points"]]
    n = len(pts) - 1
    w = [sympy.Rational(x) for x in data.get("weights", ["1"] * (n + 1))]
    basis = [sympy.binomial(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)]
    den = sum(w[i] * basis[i] for i in range(n + 1))
    return tuple(sum(w[i] * pts[i][k] * basis[i] for i in range(n + 1)) / den for k in range(len(pts[0])))


@settings(max_examples=40, deadline=None)
@given(st.integers(0, 6), st.integers(1, 3), st.booleans(), st.data())
def test_bezier_curve_round_trip(n, d, rational, data):
    pts = data.draw(st.lists(st.lists(rationals, min_size=d, max_size=d), min_size=n + 1, max_size=n + 1))
    w = data.draw(st.lists(weights, min_size=n + 1, max_size=n + 1)) if rational else None
    curve = BezierCurve(pts, w)
    back = BezierCurve.from_dict(_json_trip(curve))
    assert back == curve and back.is_rational == rational
    t = sympy.Rational(1, 3)
    expected = _sympy_bezier_point(curve.to_dict(), t)
    assert tuple(sympy.Rational(str(x)) for x in back.evaluate("1/3")) == expected


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 3), st.integers(0, 3), st.booleans(), st.data())
def test_bezier_surface_round_trip(l, m, rational, data):
    net = data.draw(st.lists(st.lists(st.lists(rationals, min_size=3, max_size=3), min_size=m + 1, max_size=m + 1),
                             min_size=l + 1, max_size=l + 1))
    w = data.draw(st.lists(st.lists(weights, min_size=m + 1, max_size=m + 1), min_size=l + 1, max_size=l + 1)) if rational else None
    surface = BezierSurface(net, w)
    back = BezierSurface.from_dict(_json_trip(surface))
    assert back.control_net == tuple(tuple(tuple(mpq(x) for x in p) for p in row) for row in net)
    assert back.weights == (None if w is None else tuple(tuple(row) for row in w))
    assert back.degree == (l, m)


def _clamped(p: int, inner: list) -> list:
    return [0] * (p + 1) + inner + [1] * (p + 1)


@settings(max_examples=30, deadline=None)
@given(st.integers(1, 4), st.lists(st.fractions(min_value="1/16", max_value="15/16", max_denominator=16), max_size=4, unique=True),
       st.booleans(), st.data())
def test_bspline_curve_round_trip(p, inner, rational, data):
    knots = _clamped(p, sorted(mpq(f.numerator, f.denominator) for f in inner))
    n = len(knots) - p - 1
    pts = data.draw(st.lists(st.lists(rationals, min_size=2, max_size=2), min_size=n, max_size=n))
    w = data.draw(st.lists(weights, min_size=n, max_size=n)) if rational else None
    curve = BSplineCurve(pts, knots, w)
    back = BSplineCurve.from_dict(_json_trip(curve))
    assert back.knots == tuple(mpq(k) for k in knots)
    assert back.control_points == curve.control_points and back.weights == curve.weights and back.degree == p
    # at a knot of the clamped end the curve interpolates the first point (independent of de Boor)
    assert back.evaluate(0) == tuple(mpq(x) for x in pts[0])


def test_bspline_surface_round_trip_rational():
    net = [[[i, j, (i * j) % 3] for j in range(4)] for i in range(3)]
    w = [[1, 2, "1/2", 1], [3, 1, 1, "5/4"], [1, 1, 2, 1]]
    s = BSplineSurface(net, [0, 0, "1/2", 1, 1], [0, 0, 0, "1/3", 1, 1, 1], w)
    back = BSplineSurface.from_dict(_json_trip(s))
    assert back.knots_u == s.knots_u and back.knots_v == s.knots_v
    assert back.control_net == s.control_net and back.weights == s.weights and back.degree == (1, 2)
    assert back.evaluate(0, 1) == (0, 3, 0)


@pytest.mark.parametrize(
    "cls, data, error, words",
    [
        (BezierCurve, [[0, 0]], InputError, "expected a dict"),
        (BezierCurve, {"points": [[0, 0]]}, InputError, "missing key 'control_points'"),
        (BezierCurve, {"control_points": [[0, 0], [1, 1]], "wieghts": [1, 2]}, InputError, "unknown key 'wieghts'"),
        (BezierCurve, {"control_points": [[0, 0], [1, 1]], "degree": 2}, DegreeError, "'degree' is 2"),
        (BezierSurface, {"control_net": [[[0, 0, 0]]], "degree": [1, 0]}, DegreeError, "'degree' is [1, 0]"),
        (BSplineCurve, {"control_points": [[0], [1]], "knots": [0, 0, 1, 1], "degree": 2}, ExactCAGDError, "degree 2"),
        (BSplineSurface, {"control_net": [[[0, 0, 0]]], "knots_u": [0, 1]}, InputError, "missing key 'knots_v'"),
        (BezierCurve, {"control_points": [["1/0", 0]]}, InputError, "control_points"),
    ],
)
def test_from_dict_bad_input(cls, data, error, words):
    with pytest.raises(error) as info:
        cls.from_dict(data)
    assert words in str(info.value)
