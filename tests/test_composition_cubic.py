"""Section VIII (Lasser & Bonneau): G1 cubic approximation with a certified distance.

The certified bound is checked against an independent dense-sampling estimate of the
Hausdorff distance (float64, both directions, with the sampling slack subtracted).
"""

from __future__ import annotations

from fractions import Fraction as Fr

import numpy as np
import pytest
from gmpy2 import mpq

from exactcagd import BezierCurve, BSplineSurface, compose
from exactcagd.composition import approximate_cubic
from exactcagd.composition.cubic_approx import approximate_cubic_curve, fit_cubic
from exactcagd.composition.distance_bound import distance_bound, sqrt_upper
from exactcagd.composition.paper_examples import figure5, figure8
from exactcagd.errors import InputError


def _sample(curve: BezierCurve, t: np.ndarray) -> np.ndarray:
    hom = curve.homogeneous()
    n = curve.degree
    from math import comb

    basis = np.array([[comb(n, i) * x**i * (1 - x) ** (n - i) for i in range(n + 1)] for x in t])
    h = basis @ np.vectorize(float, otypes=[float])(hom)
    return h[:, :-1] / h[:, -1:]


def _hausdorff_estimate(exact: BezierCurve, segments, a=0.0, b=1.0, k=1500):
    """Lower estimate of the Hausdorff distance (dense sampling minus discretization slack)."""
    ts = np.linspace(0, 1, k)
    F = _sample(exact, ts)
    X = np.vstack([_sample(s.curve, ts) for s in segments])
    d = np.sqrt(((F[:, None, :] - X[None, :, :]) ** 2).sum(-1))
    step = max(np.max(np.linalg.norm(np.diff(F, axis=0), axis=1)), np.max(np.linalg.norm(np.diff(X, axis=0), axis=1)))
    return max(d.min(axis=1).max(), d.min(axis=0).max()) - step


def _cross_zero(u, v) -> bool:
    u, v = list(u), list(v)
    if len(u) == 2:
        return u[0] * v[1] - u[1] * v[0] == 0
    return all(x == 0 for x in (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]))


@pytest.mark.parametrize("tol", [Fr(1, 50), Fr(1, 400)])
def test_bicubic_cubic_certified(tol):
    fig = figure5()
    surface, curve = fig["surface"], fig["curves"][0]
    exact = compose(surface, curve)
    result = approximate_cubic(surface, curve, tol)
    assert result.tolerance_met and result.distance_bound <= tol
    assert result.distance_bound >= _hausdorff_estimate(exact, result.segments)
    assert result.distance_bound <= 3 * max(result.sampled_error, 1e-12)
    assert all(result.g1_joints())
    # (20): exact end points; b1 - b0 parallel to B1 - B0 of the exact (sub)curve
    first, last = result.segments[0].curve.points_array(), result.segments[-1].curve.points_array()
    B = exact.points_array()
    assert np.all(first[0] == B[0]) and np.all(last[3] == B[-1])
    assert _cross_zero(first[1] - first[0], B[1] - B[0])
    assert _cross_zero(last[2] - last[3], B[-2] - B[-1])
    # segments tile the parameter interval with exact rational ends
    assert result.segments[0].interval[0] == 0 and result.segments[-1].interval[1] == 1
    for s, t in zip(result.segments, result.segments[1:]):
        assert s.interval[1] == t.interval[0]
        assert all(isinstance(x, type(mpq(0))) for p in s.curve.points_array() for x in p)


def test_rational_case_figure8():
    fig = figure8()
    surface, curve = fig["surface"], fig["curves"][4]  # beta_1 = 4
    exact = compose(surface, curve)
    result = approximate_cubic(surface, curve, Fr(1, 100))
    assert result.tolerance_met
    assert result.distance_bound >= _hausdorff_estimate(exact, result.segments)


def test_bound_is_sharp_for_a_known_offset():
    """F = X + 2t(1 - t) c with |c| = 1/2: sup |F - X| = 1/4 exactly (identity reparametrization)."""
    X = BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    bump = BezierCurve([[0, 0], [Fr(3, 10), Fr(4, 10)], [0, 0]]).elevate(1)  # 2t(1-t) (3/10, 4/10)
    F = BezierCurve._trusted(X.points_array() + bump.points_array(), None)
    bound = distance_bound(F, X)
    true = Fr(1, 4)  # |c| = 1/2 times max 2t(1-t) = 1/2
    assert bound >= true
    assert bound <= true * Fr(102, 100)


def test_sqrt_upper_is_upper():
    for q in (mpq(2), mpq(1, 3), mpq(10**30 + 7, 11), mpq(1, 10**40)):
        r = sqrt_upper(q)
        assert r * r >= q and (r * r - q) / q < mpq(1, 2**50)


def test_fit_cubic_reproduces_a_cubic():
    X = BezierCurve([[0, 0, 0], [1, 2, 1], [3, 2, -1], [4, 0, 2]])
    F = X.elevate(5)
    cubic, lams, *_ = fit_cubic(F)
    assert cubic == X
    assert distance_bound(F, cubic) == 0
    result = approximate_cubic_curve(F, Fr(1, 10**9))
    assert len(result.segments) == 1 and result.distance_bound == 0


def test_spline_surface_with_rational_crossings():
    net = [[[Fr(i, 3), Fr(j, 3), Fr((i * j) % 3, 4)] for j in range(4)] for i in range(4)]
    surface = BSplineSurface(net, [0, 0, 0, Fr(1, 2), 1, 1, 1], [0, 0, 0, Fr(1, 2), 1, 1, 1])
    line = BezierCurve([[Fr(1, 8), Fr(1, 4)], [Fr(7, 8), Fr(5, 8)]])
    result = approximate_cubic(surface, line, Fr(1, 200))
    assert result.tolerance_met
    assert [str(s.interval[0]) for s in result.segments][:1] == ["0"] and result.segments[-1].interval[1] == 1


def test_segment_cap_reports_failure():
    fig = figure5()
    result = approximate_cubic(fig["surface"], fig["curves"][0], Fr(1, 10**8), max_segments=2)
    assert len(result.segments) == 2 and not result.tolerance_met
    assert result.distance_bound > Fr(1, 10**8)


def test_bad_input():
    fig = figure5()
    with pytest.raises(InputError):
        approximate_cubic(fig["surface"], fig["curves"][0], 0)
    with pytest.raises(InputError):
        approximate_cubic_curve("curve", Fr(1, 10))
    with pytest.raises(InputError):
        distance_bound(BezierCurve([[0, 0], [1, 1]]), BezierCurve([[0, 0], [1, 1]]), phi=[0, 2, 1])
    with pytest.raises(InputError):
        distance_bound(BezierCurve([[0, 0], [1, 1]]), BezierCurve([[0, 0, 0], [1, 1, 1]]))


def test_result_serializes_exactly():
    fig = figure5()
    data = approximate_cubic(fig["surface"], fig["curves"][1], Fr(1, 20)).to_dict()
    assert data["tolerance"] == "1/20" and data["tolerance_met"] is True
    assert "/" in data["distance_bound"] or data["distance_bound"].isdigit()
