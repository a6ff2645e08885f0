"""``approximate(..., method="fit")``: fit then certify, each check against an independent reference.

* the certified bound is compared with the exact distance ``|S(D(t)) - C(s)|`` at ~200
  rational parameters, where ``S(D(t))`` is evaluated point by point with the foundation's
  exact ``BezierSurface.evaluate`` / ``BSplineSurface.evaluate`` and ``D.evaluate`` (no
  composition involved) and ``C(s)`` with ``BezierCurve.evaluate``;
* joints: exact equality of neighbouring end points, and of the chain's ends with ``S(D(0))``,
  ``S(D(1))``;
* a bound from samples alone is caught by a curve whose error vanishes at every sampled
  parameter but not in between.
"""
from fractions import Fraction as Fr
import random

import flint
import numpy as np
import pytest
from gmpy2 import mpq

from exactcagd import BezierCurve, BezierSurface, BSplineSurface
from exactcagd.curves_on_surfaces import approximate, fit
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve, open_domain_curve
from exactcagd.errors import InputError
from exactcagd.exact import bernstein as bz

DOMAIN = BezierCurve([["1/10", "1/5"], ["2/5", "1"], ["7/10", "0"], ["9/10", "4/5"]])


def _bicubic(rational: bool, weight_scale=1) -> BezierSurface:
    rng = random.Random(5)  # the surface of benchmarks/bench_peers_curve_on_surface.py
    net = [[[Fr(i, 3), Fr(j, 3), Fr(rng.randint(-500, 500), 1000)] for j in range(4)] for i in range(4)]
    weights = [[Fr(rng.randint(2, 8), 4) * weight_scale for _ in range(4)] for _ in range(4)] if rational else None
    return BezierSurface(net, weights)


def _nurbs() -> BSplineSurface:
    net = [[[i, j, (i * j) % 3] for j in range(4)] for i in range(5)]
    w = [[1 + (i + j) % 2 for j in range(4)] for i in range(5)]
    return BSplineSurface(net, [0, 0, 0, "1/3", "2/3", 1, 1, 1], [0, 0, 0, "1/2", 1, 1, 1], w)


CASES = {
    "bicubic polynomial": lambda: (_bicubic(False), DOMAIN),
    "bicubic rational": lambda: (_bicubic(True), DOMAIN),
    # same surface, all weights / 64: the bound must not depend on the weights' scale
    "bicubic rational, small weights": lambda: (_bicubic(True, Fr(1, 64)), DOMAIN),
    "B-spline surface, spline curve": lambda: (analytic_surface(7, 7, "face"), open_domain_curve(5)),
    "NURBS surface, closed spline curve": lambda: (_nurbs(), closed_domain_curve(8)),
}


def _dist_sq(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b))


def _max_true_error_sq(r, surface, domain, count=200) -> mpq:
    """Largest exact ``|S(D(t)) - C_i(s)|^2`` over ``count`` rational parameters spread over the chain."""
    per = max(8, count // len(r.segments))
    best = mpq(0)
    for seg, ((t0, _), (t1, _)) in zip(r.segments, r.ends):
        for k in range(per + 1):
            s = mpq(2 * k + 1, 2 * per + 2) if k < per else mpq(1)  # interior points and the end
            u, v = domain.evaluate(t0 + s * (t1 - t0))
            best = max(best, _dist_sq(surface.evaluate(u, v), seg.evaluate(s)))
    return best


# ----------------------------------------------------------------------------- (a), (b), (c)
@pytest.mark.parametrize("case", list(CASES))
def test_bound_covers_the_exact_distance(case):
    surface, domain = CASES[case]()
    r = approximate(surface, domain, "1e-3", method="fit")
    assert r.method == "fit" and r.continuity == "C0" and r.distance_bound <= mpq(1, 1000)
    assert all(isinstance(s, BezierCurve) and s.dimension == 3 and not s.is_rational for s in r.segments)
    assert all(s.degree == r.degree for s in r.segments)
    true_sq = _max_true_error_sq(r, surface, domain)
    assert true_sq > 0  # not on the surface: a real error to bound
    assert true_sq <= r.distance_bound**2


@pytest.mark.parametrize("rational", [False, True])
@pytest.mark.parametrize("tol", ["1e-2", "1e-3", "1e-4", "1e-5", "1e-6"])
def test_bound_below_tolerance(rational, tol):
    surface = _bicubic(rational)
    r = approximate(surface, DOMAIN, tol, method="fit")
    assert r.distance_bound <= mpq(tol) and r.tolerance == mpq(tol)
    assert 1 <= len(r) <= 4 and r.degree <= 14
    assert _max_true_error_sq(r, surface, DOMAIN, count=40) <= r.distance_bound**2


@pytest.mark.parametrize("case", list(CASES))
def test_pieces_join_exactly(case):
    surface, domain = CASES[case]()
    r = approximate(surface, domain, "1e-4", method="fit")
    segs = r.segments
    for a, b in zip(segs[:-1], segs[1:]):
        assert a.evaluate(1) == b.evaluate(0)
    assert segs[0].evaluate(0) == surface.evaluate(*domain.evaluate(r.ends[0][0][0]))
    assert segs[-1].evaluate(1) == surface.evaluate(*domain.evaluate(r.ends[-1][1][0]))
    if r.closed:
        assert segs[-1].evaluate(1) == segs[0].evaluate(0)


def test_spline_case_uses_several_patches_and_domain_pieces():
    surface, domain = CASES["NURBS surface, closed spline curve"]()
    r = approximate(surface, domain, "1e-4", method="fit")
    assert len(set(r.patches)) > 2 and len(r.domain_segments) == len(r.segments)
    for seg, dom, ((t0, _), (t1, _)) in zip(r.segments, r.domain_segments, r.ends):
        assert dom.evaluate(mpq(1, 3)) == domain.evaluate(t0 + (t1 - t0) / 3)


# ----------------------------------------------------------------------------- (d) samples are not a proof
def _vanishing_at(params) -> tuple:
    """Bernstein coefficients of ``omega(t) = prod (t - s)`` over the exact values of ``params``."""
    omega = flint.fmpq_poly([1])
    for s in sorted({mpq(*float(x).as_integer_ratio()) for x in params}):
        omega *= flint.fmpq_poly([-flint.fmpq(int(s.numerator), int(s.denominator)), 1])
    power = [mpq(int(c.p), int(c.q)) for c in omega.coeffs()]
    return bz.from_power(power, omega.degree()), omega


def _curve_with_hidden_error(params, size):
    """``F = c + size * omega / max|omega| * e_z`` with a cubic ``c``: ``F = c`` at every parameter in ``params``."""
    coeffs, omega = _vanishing_at(params)
    n = coeffs.shape[0] - 1
    grid = [mpq(k, 1000) for k in range(1001)]
    peak = max(abs(omega(flint.fmpq(int(t.numerator), int(t.denominator)))) for t in grid)
    scale = mpq(size) / mpq(int(peak.p), int(peak.q))
    cubic = bz.as_coefficients([[0, 0, 0], [1, 2, 0], [2, -1, "1/2"], [3, 0, 0]])
    base = bz.elevate(cubic, n - 3)
    base[:, 2] = base[:, 2] + scale * coeffs
    return base, cubic, omega, scale


def test_certified_bound_sees_error_between_the_samples():
    fit_params, check_params = fit.sample_parameters()
    F, cubic, omega, scale = _curve_with_hidden_error(np.concatenate([fit_params, check_params]), "1/100")
    hom = np.concatenate([F, np.full((F.shape[0], 1), mpq(1), dtype=object)], axis=1)
    curve_f, curve_c = BezierCurve.from_homogeneous(hom), BezierCurve(cubic)

    def err_sq(t):  # |F(t) - c(t)|^2 = (scale * omega(t))^2
        w = omega(flint.fmpq(int(t.numerator), int(t.denominator)))
        return (scale * mpq(int(w.p), int(w.q))) ** 2

    for t in (mpq(1, 3), mpq(5, 7)):  # the construction, checked with the foundation's evaluator
        assert _dist_sq(curve_f.evaluate(t), curve_c.evaluate(t)) == err_sq(t)
    # the error is exactly zero at every sampled parameter ...
    assert all(err_sq(mpq(*float(s).as_integer_ratio())) == 0 for s in list(fit_params) + list(check_params))
    # ... but not in between; the certificate must see it
    true_sq = max(err_sq(mpq(k, 1000)) for k in range(1001))
    assert true_sq >= mpq(1, 10**4)
    assert fit.certified_bound(hom, cubic) ** 2 >= true_sq
    assert fit.certified_bound(hom, cubic, target=mpq(1, 10**3)) ** 2 >= true_sq


def test_fit_does_not_accept_a_curve_that_is_exact_only_at_its_samples(monkeypatch):
    # few samples: the cubic interpolates F at all of them, so a bound from samples would be ~0
    nodes = np.array([0.0, 0.125, 0.375, 0.625, 0.875, 1.0])
    monkeypatch.setattr(fit, "sample_parameters", lambda: (nodes, nodes[1:-1]))
    F, cubic, omega, scale = _curve_with_hidden_error(nodes, "1/10")
    hom = np.concatenate([F, np.full((F.shape[0], 1), mpq(1), dtype=object)], axis=1)
    tol = mpq(1, 1000)
    pieces = fit.fit_curve(hom, tol)
    curve_f = BezierCurve.from_homogeneous(hom)
    for (a, b), ctrl, bound in pieces:
        assert bound <= tol
        c = BezierCurve(ctrl)
        true_sq = max(_dist_sq(curve_f.evaluate(a + (b - a) * mpq(k, 200)), c.evaluate(mpq(k, 200))) for k in range(201))
        assert true_sq <= bound**2


# ----------------------------------------------------------------------------- inputs
def test_rational_weights_and_exact_control_points():
    r = approximate(_bicubic(True), DOMAIN, "1e-5", method="fit")
    for seg in r.segments:
        assert all(isinstance(x, type(mpq(0))) for p in seg.control_points for x in p)


@pytest.mark.parametrize("tol", [0, "-1/10"])
def test_nonpositive_tolerance(tol):
    with pytest.raises(InputError):
        approximate(_bicubic(False), DOMAIN, tol, method="fit")


def test_bad_max_degree():
    with pytest.raises(InputError):
        approximate(_bicubic(False), DOMAIN, "1e-3", method="fit", max_degree=0)
    for bad in (True, 2.0, -3):
        with pytest.raises(InputError, match="max_degree"):
            approximate(_bicubic(False), DOMAIN, "1e-3", method="fit", max_degree=bad)


def test_max_degree_forces_more_segments():
    low = approximate(_bicubic(False), DOMAIN, "1e-4", method="fit", max_degree=5)
    assert low.degree <= 5 and len(low) > 1 and low.distance_bound <= mpq(1, 10**4)


def test_irrational_stationary_point_needs_no_cut():
    """D'(t) = 0 at the irrational t = 1/sqrt(2): x' = (2t^2 - 1)/4, y' = t (2t^2 - 1)/2.  The
    on-surface methods refuse it (a G1 approximation is undefined there); the fit is C0 and
    parametric, so it needs no cut there, and its bound still covers the exact distance."""
    import sympy as sp

    from exactcagd.errors import DomainError

    t = sp.Symbol("t")
    x = sp.Rational(1, 2) + (sp.Rational(2, 3) * t**3 - t) / 4
    y = sp.Rational(1, 2) + (t**4 / 2 - t**2 / 2) / 2
    # Bernstein coefficients of degree 4 from the power form (sympy, independent of the package)
    points = []
    for i in range(5):
        coords = []
        for f in (x, y):
            a = sp.Poly(f, t).all_coeffs()[::-1] + [0] * 5
            coords.append(str(sum(sp.binomial(i, k) / sp.binomial(4, k) * a[k] for k in range(i + 1))))
        points.append(coords)
    domain = BezierCurve(points)
    assert domain.evaluate("1/3") == tuple(mpq(str(f.subs(t, sp.Rational(1, 3)))) for f in (x, y))
    surface = _bicubic(False)
    with pytest.raises(DomainError, match="singular point"):
        approximate(surface, domain, "1e-3", method="parabola")
    r = approximate(surface, domain, "1e-3", method="fit")
    assert r.distance_bound <= mpq(1, 1000)
    assert _max_true_error_sq(r, surface, domain) <= r.distance_bound**2


# ----------------------------------------------------------------------------- ball first (issue 18)
@pytest.mark.parametrize("rational", [False, True])
def test_certify_catches_a_planted_violation_just_above_the_bound(rational):
    """C = F + (delta, 0, 0): max |F - C| = delta exactly (the construction is the reference).
    F is written with weights W(t) = 1 + t (rational route) or W = 1 (polynomial route);
    delta = tol (1 + 2^-50) must not certify <= tol; delta = tol = 2^-12 must (the squared
    error's Bernstein coefficients are delta^2 (polynomial) or delta^2 times those of W^2
    (rational), so the hull bound on [0, 1] is exactly delta^2)."""
    from exactcagd.composition import ball

    pts = np.array([[mpq(0), mpq(0), mpq(1)], [mpq(1, 3), mpq(2), mpq(0)], [mpq(1), mpq(-1), mpq(1, 5)]], dtype=object)
    if rational:  # H = W F, W = 1 + t, by hand in degree 3 (product formula, notes 9.3)
        p0, p1, p2 = pts
        rows = [p0, (2 * p1 + 2 * p0) / 3, (p2 + 4 * p1) / 3, 2 * p2]
        weights = [mpq(1), mpq(4, 3), mpq(5, 3), mpq(2)]
        hom = np.array([list(r) + [w] for r, w in zip(rows, weights)], dtype=object)
    else:
        hom = np.concatenate([pts, np.full((3, 1), mpq(1), dtype=object)], axis=1)
    tol = mpq(1, 2**12)
    for delta, ok in ((tol * (1 + mpq(1, 2**50)), False), (tol, True)):
        ctrl = pts.copy()
        ctrl[:, 0] = ctrl[:, 0] + delta
        bound, decided_by = fit.certify(hom, ctrl, target=tol)
        assert decided_by in (ball.BALL, ball.EXACT)
        assert bound >= delta  # never below the true maximum
        assert (bound <= tol) == ok
    # the ball decides the ordinary case (not a property of the bound: of the speed)
    ctrl = pts.copy()
    ctrl[:, 0] = ctrl[:, 0] + tol / 2
    assert fit.certify(hom, ctrl, target=tol)[1] == ball.BALL


def test_result_reports_which_arithmetic_certified():
    r = approximate(_bicubic(False), DOMAIN, "1e-3", method="fit")
    assert sum(r.certified_by.values()) == len(r) and set(r.certified_by) <= {"ball", "exact"}


def test_corners_of_a_closed_polygon_without_end_directions():
    """The fit route asks for joints without the open curve's end directions; a closed curve
    still gets its closure checked.  Reference: a closed triangle (degree-1 B-spline), whose
    three vertices are its corners by construction (the closure counted at both ends), and
    an open smooth cubic, which has none."""
    from exactcagd import BSplineCurve
    from exactcagd.curves_on_surfaces.domain import DomainCurve

    a, b, c = (mpq(1, 5), mpq(1, 5)), (mpq(4, 5), mpq(1, 5)), (mpq(1, 2), mpq(4, 5))
    triangle = BSplineCurve([list(a), list(b), list(c), list(a)], [0, 0, "1/3", "2/3", 1, 1])
    r = approximate(_bicubic(False), triangle, "1e-3", method="fit")
    assert r.closed and r.corners == [a, b, c, a]
    assert approximate(_bicubic(False), DOMAIN, "1e-3", method="fit").corners == []
    ends = DomainCurve(DOMAIN).joints((0, 1), (0, 1), None, "split", monotone=False, end_directions=False)
    assert [j.point for j in ends] == [(mpq(1, 10), mpq(1, 5)), (mpq(9, 10), mpq(4, 5))]  # D(0), D(1)
    assert ends[0].dir_out is None and ends[-1].dir_in is None


def test_domain_point_is_the_fraction_de_casteljau_point():
    """DomainCurve.point (the fit route's joints and domain checks) against the de Casteljau
    triangle of the homogeneous control points in Fractions, rational and polynomial pieces."""
    from exactcagd.curves_on_surfaces.domain import DomainCurve

    rng = random.Random(11)
    for trial in range(40):
        n = rng.randint(1, 5)
        pts = [[Fr(rng.randint(0, 1000), 1000), Fr(rng.randint(0, 1000), 997)] for _ in range(n + 1)]
        ws = [Fr(rng.randint(1, 9), rng.randint(1, 5)) for _ in range(n + 1)] if trial % 2 else [Fr(1)] * (n + 1)
        curve = DomainCurve(BezierCurve([[str(x) for x in p] for p in pts], [str(w) for w in ws]))
        for t in (Fr(0), Fr(1, 2), Fr(rng.randint(1, 99), 100), Fr(rng.randint(1, 2**70 - 1), 2**70), Fr(1)):
            level = [[w * p[0], w * p[1], w] for p, w in zip(pts, ws)]
            while len(level) > 1:
                level = [[(1 - t) * a + t * b for a, b in zip(r0, r1)] for r0, r1 in zip(level[:-1], level[1:])]
            x, y, w = level[0]
            assert curve.point(0, mpq(t.numerator, t.denominator)) == (mpq(x / w), mpq(y / w))


@pytest.mark.parametrize("method", ["fit", "parabola"])
def test_constant_domain_curve_is_refused(method):
    """A domain curve whose control points coincide (rational weights do not matter) is a
    point, not a curve: refused on every route."""
    from exactcagd.errors import DomainError

    point = BezierCurve([["1/3", "1/4"]] * 4, weights=[1, 2, 3, 1])
    with pytest.raises(DomainError, match="constant"):
        approximate(_bicubic(False), point, "1e-3", method=method)


def test_dyadic_domain_piece_is_the_restricted_curve():
    """The domain piece of a bisected fit segment, [k, k + 1] / 2^j, is the curve restricted and
    reparametrized: its homogeneous de Casteljau value at s equals the original's at
    a + (b - a) s (Fractions, up to the common homogeneous factor: compared dehomogenized)."""
    rng = random.Random(8)

    def value(rows, t):
        level = [list(r) for r in rows]
        while len(level) > 1:
            level = [[(1 - t) * p + t * q for p, q in zip(r0, r1)] for r0, r1 in zip(level[:-1], level[1:])]
        return [c / level[0][-1] for c in level[0][:-1]]

    for trial in range(30):
        n = rng.randint(1, 5)
        rows = [[Fr(rng.randint(-99, 99), rng.randint(1, 9)) for _ in range(2)] + [Fr(rng.randint(1, 9), rng.randint(1, 9)) if trial % 2 else Fr(1)]
                for _ in range(n + 1)]
        hom = np.array([[mpq(x.numerator, x.denominator) for x in r] for r in rows], dtype=object)
        j = rng.randint(1, 5)
        k = rng.randint(0, 2**j - 1)
        a, b = Fr(k, 2**j), Fr(k + 1, 2**j)
        piece = fit._dyadic_piece(hom, mpq(k, 2**j), mpq(k + 1, 2**j))
        got = [[Fr(int(x.numerator), int(x.denominator)) for x in r] for r in piece.tolist()]
        for s in (Fr(0), Fr(1, 3), Fr(1)):
            assert value(got, s) == value(rows, a + (b - a) * s)
