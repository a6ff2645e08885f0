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
