"""The certified distance of section VIII (Lasser & Bonneau) is an upper bound, checked exactly.

``distance_bound(F, X, phi)`` claims ``r >= sup_t |F(t) - X(phi(t))|``.  The reference
evaluates both curves from their Bernstein definition in ``fractions.Fraction`` arithmetic
(no exactcagd code) at many rational parameters and compares squared distances exactly:
every sampled ``|F(t) - X(phi(t))|^2`` must be ``<= r^2``, and ``r`` must not be far above
the sampled maximum (the bound is meant to be tight to about ``rel`` plus sampling).
"""

from __future__ import annotations

from fractions import Fraction as Fr
from math import comb

from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.composition.distance_bound import distance_bound

SAMPLES = [Fr(k, 97) for k in range(98)]


def _bernstein(coeffs, t):
    n = len(coeffs) - 1
    return sum(comb(n, i) * t**i * (1 - t) ** (n - i) * c for i, c in enumerate(coeffs))


def _point(points, weights, t):
    w = weights or [Fr(1)] * len(points)
    den = _bernstein(w, t)
    return [_bernstein([wi * p[k] for wi, p in zip(w, points)], t) / den for k in range(len(points[0]))]


def _sup_sampled_sq(F, X, phi):
    best = Fr(0)
    for t in SAMPLES:
        a = _point(*F, t)
        b = _point(X, None, _bernstein(phi, t))
        best = max(best, sum((x - y) ** 2 for x, y in zip(a, b)))
    return best


coord = st.integers(-40, 40).map(lambda k: Fr(k, 20))
weight = st.integers(1, 8).map(lambda k: Fr(k, 4))


@st.composite
def cases(draw):
    dim = draw(st.integers(2, 3))
    n = draw(st.integers(1, 6))
    pts = [[draw(coord) for _ in range(dim)] for _ in range(n + 1)]
    ws = [draw(weight) for _ in range(n + 1)] if draw(st.booleans()) else None
    cubic = [[draw(coord) for _ in range(dim)] for _ in range(4)]
    inner = sorted(draw(st.lists(st.integers(0, 12).map(lambda k: Fr(k, 12)), min_size=0, max_size=2)))
    return (pts, ws), cubic, [Fr(0)] + inner + [Fr(1)]


@settings(max_examples=25, deadline=None)
@given(cases())
def test_bound_is_above_every_exact_sample_and_reasonably_tight(case):
    (pts, ws), cubic, phi = case
    r = distance_bound(BezierCurve(pts, ws), BezierCurve(cubic), phi)
    sampled = _sup_sampled_sq((pts, ws), cubic, phi)
    assert sampled <= Fr(int(r.numerator), int(r.denominator)) ** 2
    # tightness: rel = 0.02 in max E, plus what 98 samples can miss; a loose bound would exceed this
    assert r**2 <= Fr(3, 2) * sampled + Fr(1, 10**6)


def test_exact_zero_for_the_same_cubic_and_positive_otherwise():
    X = BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]])
    assert distance_bound(X, X) == 0
    assert distance_bound(X.elevate(3), X) == 0
    shifted = BezierCurve([[0, Fr(1, 8)], [1, Fr(17, 8)], [3, Fr(17, 8)], [4, Fr(1, 8)]])
    r = distance_bound(shifted, X)
    assert Fr(1, 8) <= Fr(int(r.numerator), int(r.denominator)) <= Fr(1, 8) * Fr(101, 100)


# ---------------------------------------------------------------------------- ball first (issue 18)
def _shifted(points, delta):
    return [[p[0] + delta] + list(p[1:]) for p in points]


def test_planted_violation_just_above_the_bound_is_caught():
    """X = F + (delta, 0): sup |F - X| = delta exactly (reference: the construction).  With
    delta = tol (1 + 2^-50) no certificate <= tol may come out, whichever arithmetic decides;
    with delta = tol = 2^-10 the bound tol itself is proven."""
    from exactcagd.composition import ball

    F = [[Fr(0), Fr(0)], [Fr(1, 3), Fr(2)], [Fr(2, 3), Fr(-1)], [Fr(1), Fr(1, 7)]]
    tol = Fr(1, 2**10)
    planted = tol * (1 + Fr(1, 2**50))
    stats: dict = {}
    bound = distance_bound(BezierCurve(F), BezierCurve(_shifted(F, planted)), target=tol, stats=stats)
    assert bound > tol and bound >= planted
    assert sum(stats.values()) == 1 and set(stats) <= {ball.BALL, ball.EXACT}
    assert distance_bound(BezierCurve(F), BezierCurve(_shifted(F, tol)), target=tol) == tol


def test_ball_and_exact_bisections_agree_to_high_precision():
    """The ball bisection (default) and the exact one bound the same maximum: both >= the
    exactly sampled maximum, and both stop within the factor (1 + rel) of it."""
    import flint

    from exactcagd.composition import ball
    from exactcagd.composition import distance_bound as module

    F = BezierCurve([[0, 0, 1], ["1/3", 2, 0], ["2/3", -1, "1/5"], [1, "1/7", 0]], weights=[1, 2, "1/2", 1])
    X = BezierCurve([[0, 0, 1], ["1/2", "3/2", 0], ["3/4", "-1/2", 0], [1, "1/7", 0]])
    e_scaled, w_scaled, D = module._squared_error(F, X, [Fr(0), Fr(1)])
    with ball.precision():
        quick = ball.ratio_max_bound(e_scaled, w_scaled, D, 0.02, 400)
    e_pow = module.bz.scaled_to_power(e_scaled, D)
    w_pow = module.bz.scaled_to_power(w_scaled, D)
    slow = module._exact_bisection(e_pow, w_pow, D, 0.02, 400, None) ** 2
    sampled = _sup_sampled_sq(([[Fr(x) for x in p] for p in F.control_points], [Fr(w) for w in F.weights]),
                              [[Fr(x) for x in p] for p in X.control_points], [Fr(0), Fr(1)])
    quick, slow = (Fr(int(x.numerator), int(x.denominator)) for x in (quick, slow))
    assert quick >= sampled and slow >= sampled
    assert abs(quick - slow) <= max(quick, slow) * Fr(2, 100)
    assert flint.ctx.prec == 53  # the working precision was restored
