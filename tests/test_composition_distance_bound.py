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
    """The ball bisection (default, coefficients rounded outward to ``ball.PREC`` bits) and the
    exact one bound the same maximum: both >= the exactly sampled maximum, and both stop
    within the factor (1 + rel) of it."""
    import flint

    from exactcagd.composition import ball
    from exactcagd.composition import distance_bound as module

    F = BezierCurve([[0, 0, 1], ["1/3", 2, 0], ["2/3", -1, "1/5"], [1, "1/7", 0]], weights=[1, 2, "1/2", 1])
    X = BezierCurve([[0, 0, 1], ["1/2", "3/2", 0], ["3/4", "-1/2", 0], [1, "1/7", 0]])
    e_scaled, w_scaled, D = module._squared_error(F.homogeneous(), X.homogeneous())
    quick = module.ratio_max_bound(e_scaled, w_scaled, D, 0.02, 400, bits=ball.PREC)
    slow = module.ratio_max_bound(e_scaled, w_scaled, D, 0.02, 400)
    sampled = _sup_sampled_sq(([[Fr(x) for x in p] for p in F.control_points], [Fr(w) for w in F.weights]),
                              [[Fr(x) for x in p] for p in X.control_points], [Fr(0), Fr(1)])
    quick, slow = (Fr(int(x.numerator), int(x.denominator)) for x in (quick, slow))
    assert quick >= sampled and slow >= sampled
    assert abs(quick - slow) <= max(quick, slow) * Fr(2, 100)
    assert flint.ctx.prec == 53  # the working precision is untouched


def test_scaled_halves_are_de_casteljau_at_one_half():
    """``2^-n`` times the halves of the scaled form ``s_i = C(n, i) b_i``, divided by ``C(n, i)``,
    are both halves' Bernstein coefficients; reference: the de Casteljau triangle at t = 1/2
    in Fractions (its two edges, notes 2.3)."""
    import flint

    from exactcagd.composition.fast import scaled_halves

    for n in (0, 1, 2, 5, 9, 36):
        b = [Fr((7 * i * i - 3 * i + 2) % 11 - 5, 3) for i in range(n + 1)]
        b[0] = b[-1] = Fr(0)  # zero ends: the mirror image loses its trailing coefficients
        rows, left, right = [b], [b[0]], [b[-1]]
        while len(rows[-1]) > 1:
            prev = rows[-1]
            rows.append([(x + y) / 2 for x, y in zip(prev[:-1], prev[1:])])
            left.append(rows[-1][0])
            right.append(rows[-1][-1])
        scaled = [flint.fmpz(int(3 * x * comb(n, i))) for i, x in enumerate(b)]  # 3 b_i is integral
        got_left, got_right = scaled_halves(scaled, n)
        assert len(got_left) == len(got_right) == n + 1
        assert [Fr(int(v), 3 * 2**n * comb(n, i)) for i, v in enumerate(got_left)] == left
        assert [Fr(int(v), 3 * 2**n * comb(n, i)) for i, v in enumerate(got_right)] == right[::-1]


def _bump_case(rational: bool, delta: Fr):
    """``F = C + delta (4 t (1 - t), 0, 0)``: ``max |F - C| = delta`` exactly, at t = 1/2 (the
    reference is the construction); Bernstein coefficients from the power form by the
    textbook formula (sympy), ``F = H / W`` with ``W = 1 + t`` in the rational case."""
    import numpy as np
    import sympy as sp
    from gmpy2 import mpq

    t = sp.Symbol("t")
    c = [sp.Rational(1, 3) + t - 2 * t**2, 2 * t + sp.Rational(1, 5) * t**2, 1 - 3 * t**2]
    f = [c[0] + sp.Rational(delta.numerator, delta.denominator) * 4 * t * (1 - t)] + c[1:]
    w = 1 + t if rational else sp.Integer(1)
    num = [sp.expand(w * x) for x in f] + [w]
    deg = max(sp.Poly(x, t).degree() for x in num)

    def bern(expr, n):
        a = sp.Poly(expr, t).all_coeffs()[::-1] + [0] * (n + 1)
        return [sum(sp.binomial(i, k) / sp.binomial(n, k) * a[k] for k in range(i + 1)) for i in range(n + 1)]

    cols = [bern(x, deg) for x in num]
    hom_f = np.array([[mpq(str(col[i])) for col in cols] for i in range(deg + 1)], dtype=object)
    ccols = [bern(x, 2) for x in c] + [[1, 1, 1]]
    hom_c = np.array([[mpq(str(col[i])) for col in ccols] for i in range(3)], dtype=object)
    return hom_f, hom_c


def test_interior_maximum_planted_violation_is_caught_by_the_bisection():
    """The hull bound on [0, 1] is (16/6) delta^2 here, so only the bisection can prove a
    bound near delta: delta = tol (1 + 2^-50) must never certify <= tol (either arithmetic),
    delta = tol 49/50 must (the bisection stops within 1 + rel = 1.02 of max E = delta^2)."""
    from exactcagd.composition import ball
    from exactcagd.composition.distance_bound import homogeneous_distance_bound

    tol = Fr(1, 2**12)
    for rational in (False, True):
        for delta, ok in ((tol * (1 + Fr(1, 2**50)), False), (tol * Fr(49, 50), True)):
            hom_f, hom_c = _bump_case(rational, delta)
            stats: dict = {}
            bound = homogeneous_distance_bound(hom_f, hom_c, target=tol, stats=stats)
            assert Fr(int(bound.numerator), int(bound.denominator)) >= delta
            assert (bound <= tol) == ok
            assert sum(stats.values()) == 1
            if ok:
                assert stats == {ball.BALL: 1}


def test_a_tie_the_rounded_coefficients_cannot_prove_is_decided_exactly():
    """F = C + (delta, 0) written as H / W with W = 1 + t / 3^90 (long coefficients), C
    polynomial: E = delta^2 W^2 / W^2 = delta^2 exactly (the construction is the reference;
    H = W (C + delta e_x) by the Bernstein product formula, notes 9.3, in Fractions).  Rounded
    outward to ball.PREC bits the coefficients of delta^2 W^2 and W^2 no longer prove
    target = delta; the exact ones prove exactly delta; delta (1 + 2^-50) is refused."""
    import numpy as np
    from gmpy2 import mpq

    from exactcagd.composition import ball
    from exactcagd.composition.distance_bound import homogeneous_distance_bound

    tol = Fr(1, 1000)
    C = [[Fr(0), Fr(0)], [Fr(1, 3), Fr(2)], [Fr(1), Fr(-1)]]
    W = [Fr(1), 1 + Fr(1, 3**90)]

    def hom_of(delta):
        G = [[p[0] + delta, p[1]] for p in C]
        rows = []
        for k in range(4):  # degree 1 x degree 2 -> degree 3
            terms = [(i, k - i) for i in range(2) if 0 <= k - i <= 2]
            coef = {(i, j): Fr(comb(1, i) * comb(2, j), comb(3, k)) for i, j in terms}
            h = [sum(coef[i, j] * W[i] * G[j][c] for i, j in terms) for c in range(2)]
            rows.append(h + [sum(coef[i, j] * W[i] for i, j in terms)])
        return np.array([[mpq(x.numerator, x.denominator) for x in r] for r in rows], dtype=object)

    hom_c = np.array([[mpq(p[0].numerator, p[0].denominator), mpq(p[1].numerator, p[1].denominator), mpq(1)] for p in C],
                     dtype=object)
    stats: dict = {}
    assert homogeneous_distance_bound(hom_of(tol), hom_c, target=tol, stats=stats) == tol
    assert stats == {ball.EXACT: 1}
    assert homogeneous_distance_bound(hom_of(tol * (1 + Fr(1, 2**50))), hom_c, target=tol) > tol


def _scaled_value(p, degree, t):
    """A scaled Bernstein form ``sum c_i x^i`` of degree ``degree`` (flint ``fmpq_poly``, or an
    ``fmpq`` constant ``c``: the polynomial ``c``) at ``t``: ``sum c_i t^i (1 - t)^(degree - i)``."""
    if not hasattr(p, "coeffs"):
        return Fr(int(p.p), int(p.q))
    return sum(Fr(int(c.p), int(c.q)) * t**i * (1 - t) ** (degree - i) for i, c in enumerate(p.coeffs()))


@st.composite
def weighted_pairs(draw):
    """Two curves of one dimension, each with unit, constant (!= 1) or varying weights."""
    dim = draw(st.integers(1, 3))

    def curve():
        n = draw(st.integers(0, 5))
        pts = [[draw(coord) for _ in range(dim)] for _ in range(n + 1)]
        kind = draw(st.sampled_from(["unit", "constant", "varying"]))
        c = draw(weight)
        ws = [Fr(1)] * (n + 1) if kind == "unit" else [c] * (n + 1) if kind == "constant" else [draw(weight) for _ in range(n + 1)]
        return pts, ws

    return curve(), curve()


@settings(max_examples=60, deadline=None)
@given(weighted_pairs())
def test_squared_error_is_the_squared_distance_in_both_input_forms(pair):
    """``e / w2`` of ``_squared_error`` at rational t is ``|F(t) - X(t)|^2`` (Fraction reference),
    for object arrays and for their integer form (ScaledBernstein): same canonical polynomials."""
    import numpy as np
    from gmpy2 import mpq

    from exactcagd.composition import distance_bound as module
    from exactcagd.composition.fast import ScaledBernstein

    (pf, wf), (px, wx) = pair

    def hom(pts, ws):
        return np.array([[mpq(w * x) for x in p] + [mpq(w)] for p, w in zip(pts, ws)], dtype=object)

    hf, hx = hom(pf, wf), hom(px, wx)
    e, w2, D = module._squared_error(hf, hx)
    e2, w22, D2 = module._squared_error(ScaledBernstein.from_homogeneous(hf), ScaledBernstein.from_homogeneous(hx))
    assert (e, w2, D) == (e2, w22, D2) and e.denom() == e2.denom()
    for t in (Fr(0), Fr(1, 3), Fr(5, 7), Fr(1)):
        a, b = _point(pf, wf, t), _point(px, wx, t)
        assert _scaled_value(e, D, t) / _scaled_value(w2, D, t) == sum((x - y) ** 2 for x, y in zip(a, b))


@settings(max_examples=80, deadline=None)
@given(st.lists(st.integers(-(2**400), 2**400), min_size=1, max_size=40), st.integers(1, 2**90), st.booleans())
def test_integer_column_rounds_outward_within_its_precision(numer, den, up):
    """``_integer_column`` at ``bits`` precision: every ``c_i s`` lies on the requested side of the
    exact Bernstein coefficient ``b_i = p_i / C(n, i)`` (Fractions), by less than ``2^(1 - bits)``
    times the largest ``|b_i|``; exact (``bits=None``) it is ``b_i`` itself."""
    import flint

    from exactcagd.composition import distance_bound as module

    n, bits = len(numer) - 1, 64
    p = flint.fmpq_poly(numer, den)
    exact = [Fr(int(c.p), int(c.q)) / comb(n, i) for i, c in enumerate(p.coeffs() + [flint.fmpq(0)] * (n + 1 - len(p.coeffs())))]
    column, scale = module._integer_column(p, n, bits, up)
    s = Fr(int(scale.p), int(scale.q))
    got = [int(c) * s for c in column]
    largest = max(abs(b) for b in exact)
    for g, b in zip(got, exact):
        assert (g >= b) if up else (g <= b)
        assert abs(g - b) <= largest * Fr(2, 2**bits)
    column, scale = module._integer_column(p, n, None, up)
    assert [int(c) * Fr(int(scale.p), int(scale.q)) for c in column] == exact
