"""exactcagd.toolbox.knot_intervals against Cox-de Boor evaluation on the equivalent knot vector.

The reference builds the knot vector from the intervals by the rule of notes 6.13
independently (cumulative sums), evaluates with the Fraction Cox-de Boor recursion of
``_sympy_ref``, and differentiates with sympy.
"""

from fractions import Fraction

import numpy as np
import pytest
from _sympy_ref import R, T, small_rationals, spline_point
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd.errors import DegreeError, DomainError, InputError, KnotError, NotSupportedError
from exactcagd.toolbox import knot_intervals as ki

FAST = settings(max_examples=12, deadline=None)


def ref_unrolled(points, d, p):
    """Reference unrolled spline of a periodic curve: knots with k_{j+1} - k_j = d_{(j-c) mod N}, k_c = 0."""
    n = len(points)
    c = (p + 1) // 2
    knots = [Fraction(0)]
    for j in range(n + 2 * p):
        knots.append(knots[-1] + Fraction(d[(j - c) % n]))
    shift = knots[c]
    return list(points) + list(points[:p]), [k - shift for k in knots]


def ref_samples(points, d, p, k=9):
    """Parameters covering one period inside the reference's domain [k_p, k_p + period)."""
    _, knots = ref_unrolled(points, d, p)
    lo = knots[p]
    return [lo + Fraction(sum(d)) * Fraction(i, k) for i in range(k)]


def ref_periodic(points, d, p, t):
    pts, knots = ref_unrolled(points, d, p)
    return spline_point(pts, knots, p, t)


def cases(max_degree=4):
    return st.integers(1, max_degree).flatmap(
        lambda p: st.integers(p + 1, p + 3).flatmap(
            lambda n: st.tuples(
                st.just(p),
                st.lists(st.lists(small_rationals, min_size=2, max_size=2), min_size=n, max_size=n),
                st.lists(st.integers(1, 4), min_size=n, max_size=n),
            )
        )
    )


def frac(p):
    return tuple(Fraction(int(x.numerator), int(x.denominator)) for x in p)


@given(cases())
@FAST
def test_evaluation_matches_reference(case):
    p, pts, d = case
    c = ki.KnotIntervalCurve(pts, d, p)
    for t in ref_samples(pts, d, p):
        assert frac(c.evaluate(t)) == ref_periodic(pts, d, p, t)
    assert c.evaluate(sum(d) + Fraction(1, 3)) == c.evaluate(Fraction(1, 3))  # periodic


@given(cases(), st.data())
@FAST
def test_split_halve_elevate_keep_the_curve(case, data):
    p, pts, d = case
    c = ki.KnotIntervalCurve(pts, d, p)
    i = data.draw(st.integers(0, len(d) - 1))
    # a zero interval (left = 0 or d_i) is a double knot: allowed from degree 2 on
    left = Fraction(d[i]) * Fraction(data.draw(st.integers(0 if p > 1 else 1, 4 if p > 1 else 3)), 4)
    variants = [c.split_interval(i, left), c.halve(), c.elevate()]
    for v in variants:
        for t in ref_samples(pts, d, p, 7):
            assert frac(v.evaluate(t)) == ref_periodic(pts, d, p, t)
    assert len(variants[0].control_points) == len(pts) + 1
    assert list(variants[2].intervals) == [x for v in d for x in (v, 0)]


@given(cases(max_degree=5))
@settings(max_examples=6, deadline=None)
def test_hodograph_is_the_derivative(case):
    p, pts, d = case
    if p < 2:
        return
    c = ki.KnotIntervalCurve(pts, d, p)
    h = c.hodograph()
    assert h.degree == p - 1
    spline = c.to_spline()
    for (a, b), piece in spline.to_sympy_pieces(T):
        for t in (a + (b - a) / 3, b - (b - a) / 5):
            assert [R(x) for x in h.evaluate(t)] == list(piece.diff(T).subs(T, R(t)))


@given(cases(max_degree=3))
@FAST
def test_explicit_formulas_equal_polar_resampling(case):
    p, pts, d = case
    if p == 2:
        c = ki.KnotIntervalCurve(pts, d, 2)
        assert np.all(np.roll(c.halve().points_array(), -1, axis=0) == ki.halving_quadratic(pts, d))
        assert np.all(np.roll(c.elevate().points_array(), -1, axis=0) == ki.elevate_quadratic(pts, d))
    if p == 3:
        c = ki.KnotIntervalCurve(pts, d, 3)
        assert np.all(c.halve().points_array() == ki.halving_cubic(pts, d))
        assert np.all(np.roll(c.elevate().points_array(), 1, axis=0) == ki.elevate_cubic(pts, d))
        for i in range(len(d) - 1):
            assert np.all(ki.split_cubic_construction(pts, d, i, Fraction(d[i], 3)) == c.split_interval(i, Fraction(d[i], 3)).points_array())


def test_labels_and_zero_intervals():
    c = ki.KnotIntervalCurve([[0, 0], [4, 0], [4, 4], [0, 4]], [1, 2, 3, 4], 3)
    labels = c.polar_labels()
    assert labels[0] == (-4, 0, 1)  # P_0 = f(k_1, k_2, k_3), origin k_2 = 0
    assert labels[1] == (0, 1, 3)
    double = c.split_interval(1, 0)
    assert double.intervals == (1, 0, 2, 3, 4)
    assert double.same_curve(c)


def test_open_curve():
    pts = [[0, 0], [1, 2], [3, 3], [5, 1], [6, 0]]
    d = [1, 1, 2, 3, 1, 2]  # N + p - 2 = 6 for a cubic, one end interval on each side
    c = ki.KnotIntervalCurve(pts, d, 3, periodic=False)
    knots = c.to_spline().knots
    assert [knots[j + 1] - knots[j] for j in range(1, len(knots) - 2)] == d
    s = c.split_interval(2, 1)
    assert s.same_curve(c) and len(s.control_points) == 6
    with pytest.raises(NotSupportedError):
        c.halve()


def test_bad_input():
    with pytest.raises(KnotError):
        ki.KnotIntervalCurve([[0, 0], [1, 0], [1, 1]], [1, 1], 2)
    with pytest.raises(KnotError):
        ki.KnotIntervalCurve([[0, 0], [1, 0], [1, 1]], [1, -1, 1], 2)
    with pytest.raises(DegreeError):
        ki.KnotIntervalCurve([[0, 0], [1, 0], [1, 1]], [1, 1, 1], 0)
    c = ki.KnotIntervalCurve([[0, 0], [1, 0], [1, 1]], [1, 0, 1], 2)
    with pytest.raises(DomainError):
        c.split_interval(1, 0)
    with pytest.raises(DomainError):
        c.split_interval(0, 2)
    with pytest.raises(InputError):
        c.split_interval(5, 0)
    with pytest.raises(DegreeError):
        ki.KnotIntervalCurve([[0, 0], [1, 0], [1, 1]], [1, 1, 1], 1).hodograph()
