"""Certified float evaluation (exactcagd.numeric.evaluate) against an independent exact reference.

The reference is the Bernstein sum ``sum_i b_i C(n,i) (1-t)^(n-i) t^i`` evaluated in
``gmpy2.mpq`` at the exact binary value of each float parameter, written out here (no
exactcagd evaluation code involved).  Every component of every point must satisfy
``|exact - value| <= radius``; separate tests check that the radii are not absurdly
loose, so the suite can fail in both directions.
"""

import math
from fractions import Fraction

import numpy as np
import pytest
from gmpy2 import mpq
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import exactcagd.numeric
from exactcagd import BezierCurve, BezierSurface
from exactcagd.errors import DomainError, InexactInputError, InputError
from exactcagd.numeric.evaluation import METHODS, evaluate, evaluate_surface

SETTINGS = settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])


# ---------------------------------------------------------------------------- reference
def q(x: float) -> mpq:
    return mpq(*float(x).as_integer_ratio())


def bernstein_values(n: int, t: mpq) -> list:
    s = 1 - t
    return [math.comb(n, i) * s ** (n - i) * t**i for i in range(n + 1)]


def exact_point(points, weights, t: mpq) -> list:
    n = len(points) - 1
    basis = bernstein_values(n, t)
    w = [mpq(1)] * (n + 1) if weights is None else weights
    den = sum(w[i] * basis[i] for i in range(n + 1))
    return [sum(w[i] * points[i][j] * basis[i] for i in range(n + 1)) / den for j in range(len(points[0]))]


def exact_surface_point(net, weights, u: mpq, v: mpq) -> list:
    bu, bv = bernstein_values(len(net) - 1, u), bernstein_values(len(net[0]) - 1, v)
    rows, cols = range(len(net)), range(len(net[0]))
    w = weights if weights is not None else [[mpq(1)] * len(net[0]) for _ in rows]
    den = sum(w[i][j] * bu[i] * bv[j] for i in rows for j in cols)
    return [sum(w[i][j] * net[i][j][k] * bu[i] * bv[j] for i in rows for j in cols) / den for k in range(len(net[0][0]))]


def check_bounds(exact_values, values, radii):
    """Assert the certificate for every component; return the largest err/radius ratio."""
    worst = 0.0
    for ex_row, val_row, rad_row in zip(exact_values, values, radii):
        for ex, val, rad in zip(ex_row, val_row, rad_row):
            if math.isinf(rad):
                continue
            assert math.isfinite(val)
            err = abs(ex - q(val))
            assert err <= q(rad), f"certificate violated: err {float(err):.3e} > radius {rad:.3e}"
            if rad > 0:
                worst = max(worst, float(err / q(rad)))
    return worst


# ---------------------------------------------------------------------------- strategies
@st.composite
def rationals(draw, scale_exp=(-20, 20)):
    num = draw(st.integers(-(2**40), 2**40))
    den = draw(st.integers(1, 2**20))
    e = draw(st.integers(*scale_exp))
    return mpq(num, den) * mpq(2) ** e


@st.composite
def curves(draw, max_degree=20, rational=None):
    n = draw(st.integers(0, max_degree))
    d = draw(st.integers(1, 3))
    pts = [[draw(rationals()) for _ in range(d)] for _ in range(n + 1)]
    is_rational = draw(st.booleans()) if rational is None else rational
    weights = None
    if is_rational:
        weights = [mpq(draw(st.integers(1, 2**16)), draw(st.integers(1, 2**16))) for _ in range(n + 1)]
    return BezierCurve(pts, weights)


unit_floats = st.floats(0, 1, allow_nan=False)
wide_floats = st.floats(-3, 4, allow_nan=False)


# ---------------------------------------------------------------------------- certificates
@SETTINGS
@given(curves(), st.lists(unit_floats, min_size=1, max_size=12))
def test_certificate_all_methods_unit_interval(curve, ts):
    exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
    for method in METHODS:
        values, radii = evaluate(curve, ts, method=method)
        assert values.shape == radii.shape == (len(ts), curve.dimension)
        check_bounds(exact, values, radii)


@SETTINGS
@given(curves(max_degree=12), st.lists(wide_floats, min_size=1, max_size=10))
def test_certificate_extrapolation(curve, ts):
    exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
    for method in ("horner", "power"):
        values, radii = evaluate(curve, ts, method=method)
        check_bounds(exact, values, radii)


@settings(max_examples=40, deadline=None)
@given(st.data())
def test_certificate_surfaces(data):
    l, m = data.draw(st.integers(0, 5)), data.draw(st.integers(0, 5))
    d = data.draw(st.integers(1, 3))
    net = [[[data.draw(rationals((-10, 10))) for _ in range(d)] for _ in range(m + 1)] for _ in range(l + 1)]
    weights = None
    if data.draw(st.booleans()):
        weights = [[mpq(data.draw(st.integers(1, 999)), data.draw(st.integers(1, 99))) for _ in range(m + 1)] for _ in range(l + 1)]
    surface = BezierSurface(net, weights)
    us = data.draw(st.lists(unit_floats, min_size=1, max_size=6))
    vs = data.draw(st.lists(unit_floats, min_size=len(us), max_size=len(us)))
    exact = [exact_surface_point(surface.control_net, surface.weights, q(u), q(v)) for u, v in zip(us, vs)]
    for method in METHODS:
        values, radii = evaluate_surface(surface, us, vs, method=method)
        assert values.shape == (len(us), d)
        check_bounds(exact, values, radii)
    wide_u = [3 * u - 1 for u in us]
    wide_v = [2 * v - 0.5 for v in vs]
    exact = [exact_surface_point(surface.control_net, surface.weights, q(u), q(v)) for u, v in zip(wide_u, wide_v)]
    for method in ("horner", "power"):
        check_bounds(exact, *evaluate_surface(surface, wide_u, wide_v, method=method))


def test_certificate_extreme_scales():
    """Subnormal parameters and coefficients, huge coefficients (overflow -> inf radius)."""
    ts = [0.0, 5e-324, 2.0**-1060, 2.0**-1030, 1e-300, 2.0**-53, 0.5, 1 - 2.0**-53, 1.0]
    tiny = BezierCurve([[q(1e-310)], [q(-3e-315)], [q(5e-324)], [mpq(1, 10**320)], [mpq(-7, 10**312)]])
    usual = BezierCurve([[1, -2], [-3, "1/3"], ["1/3", 5], [7, 0], [2, "-1/7"]], weights=[1, 2, "1/3", 5, 1])
    huge = BezierCurve([[q(1e308)], [q(-1.7e308)], [q(1e308)]])
    for curve in (tiny, usual, huge):
        exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
        for method in METHODS:
            check_bounds(exact, *evaluate(curve, ts, method=method))
    _, radii = evaluate(tiny, ts)
    assert radii.max() < 1e-320  # the absolute underflow term stays tiny
    _, radii = evaluate(huge, ts, method="power")
    assert np.isinf(radii).all()  # 2 * 1.7e308 overflows in the power coefficients
    wide = [-1e5, -7.5, -1e-310, 1e-310, 3.25, 1e5]
    exact = [exact_point(usual.control_points, usual.weights, q(t)) for t in wide]
    for method in ("horner", "power"):
        check_bounds(exact, *evaluate(usual, wide, method=method))


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(st.integers(40, 60), st.data())
def test_certificate_high_degree(n, data):
    pts = [[data.draw(rationals((-5, 5)))] for _ in range(n + 1)]
    weights = None if data.draw(st.booleans()) else [mpq(data.draw(st.integers(1, 99))) for _ in range(n + 1)]
    curve = BezierCurve(pts, weights)
    ts = data.draw(st.lists(unit_floats, min_size=1, max_size=8))
    exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
    for method in METHODS:
        check_bounds(exact, *evaluate(curve, ts, method=method))


# ---------------------------------------------------------------------------- tightness
def _moderate_curve(rng, n, d=2):
    return BezierCurve([[Fraction(int(x), 1 << 20) for x in rng.integers(-(1 << 20), 1 << 20, d)] for _ in range(n + 1)])


@pytest.mark.parametrize("method,limit", [("decasteljau", 1e-13), ("horner", 1e-13), ("power", 1e-10)])
def test_radius_is_tight_for_well_scaled_curves(method, limit):
    rng = np.random.default_rng(7)
    ts = rng.random(200)
    ratios = []
    for n in (1, 2, 3, 5, 8):
        curve = _moderate_curve(rng, n)
        values, radii = evaluate(curve, ts, method=method)
        assert radii.max() < limit, (n, radii.max())
        exact = [exact_point(curve.control_points, None, q(t)) for t in ts]
        ratios.append(check_bounds(exact, values, radii))
    # the bound is within a factor of ~100 of the worst observed error
    assert max(ratios) > 0.01


def test_radius_scales_with_degree_and_is_small_for_degree_20():
    rng = np.random.default_rng(11)
    curve = _moderate_curve(rng, 20, d=1)
    ts = rng.random(500)
    _, r_dc = evaluate(curve, ts)
    _, r_h = evaluate(curve, ts, method="horner")
    _, r_p = evaluate(curve, ts, method="power")
    assert r_dc.max() < 1e-12 and r_h.max() < 1e-12
    assert r_p.mean() > 100 * r_dc.mean()  # power basis: cancellation, certified honestly


def test_exact_points_have_tiny_radius():
    curve = BezierCurve([[0, 0], [1, 2], [2, 0]])
    values, radii = evaluate(curve, [0.0, 0.5, 1.0])
    assert values.tolist() == [[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]
    assert radii.max() < 1e-14


def test_rational_quarter_circle():
    quarter = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    ts = np.linspace(0, 1, 1001)
    for method in METHODS:
        values, radii = evaluate(quarter, ts, method=method)
        assert radii.max() < 1e-14
        assert np.abs(np.hypot(values[:, 0], values[:, 1]) - 1).max() < 1e-15 + 2 * radii.max()


def test_weight_enclosure_containing_zero_gives_infinite_radius():
    # homogeneous weights 1, -1: W(t) = 1 - 2t vanishes at t = 1/2
    curve = BezierCurve.from_homogeneous(np.array([[mpq(1), mpq(1)], [mpq(-1), mpq(-1)]], dtype=object))
    ts = [0.25, 0.5, 0.75]
    for method in METHODS:
        values, radii = evaluate(curve, ts, method=method)
        assert np.isinf(radii[1, 0]) and np.isfinite(radii[[0, 2], 0]).all()
        check_bounds([exact_point(curve.control_points, curve.weights, q(t)) for t in (0.25, 0.75)],
                     values[[0, 2]], radii[[0, 2]])


# ---------------------------------------------------------------------------- api & inputs
def test_public_entry_point_and_bound_false():
    curve = BezierCurve([[0], [1], [3]])
    v1, r1 = exactcagd.numeric.evaluate(curve, [0.25, 0.75])
    from exactcagd.numeric import evaluate as ev

    v2 = ev(curve, np.array([0.25, 0.75]), bound=False)
    assert isinstance(v2, np.ndarray) and np.array_equal(v1, v2)
    assert r1.shape == (2, 1)


def test_chunking_gives_identical_results(monkeypatch):
    import exactcagd.numeric.evaluation as module

    curve = BezierCurve([[1, 2, 3], [-1, 0, 2], ["1/3", 5, -2], [0, 1, 1]], weights=[1, 3, 2, 1])
    ts = np.random.default_rng(3).random(1000)
    full = evaluate(curve, ts, method="horner")
    monkeypatch.setattr(module, "_CHUNK_FLOATS", 50)
    monkeypatch.setattr(module, "_MIN_CHUNK", 7)
    chunked = evaluate(curve, ts, method="horner")
    assert all(np.array_equal(a, b) for a, b in zip(full, chunked))


def test_parameter_inputs():
    curve = BezierCurve([[0], [2]])
    assert evaluate(curve, [0, 1, Fraction(1, 4), "0.5"], bound=False).ravel().tolist() == [0.0, 2.0, 0.5, 1.0]
    assert evaluate(curve, np.float32(0.25), bound=False).shape == (1, 1)
    assert evaluate(curve, [], bound=False).shape == (0, 1)
    with pytest.raises(InexactInputError):
        evaluate(curve, [Fraction(1, 3)])
    with pytest.raises(InexactInputError):
        evaluate(curve, ["0.1"])
    for bad in (float("nan"), float("inf"), -float("inf")):
        with pytest.raises(InexactInputError):
            evaluate(curve, [0.5, bad], method="horner")
    with pytest.raises(InputError):
        evaluate(curve, [[0.1, 0.2]])
    with pytest.raises(InputError):
        evaluate(curve, [True])
    with pytest.raises(InputError):
        evaluate(curve, [0.5], method="clenshaw")
    with pytest.raises(InputError):
        evaluate([[0], [1]], [0.5])
    with pytest.raises(DomainError):
        evaluate(curve, [0.5, 1.5])
    with pytest.raises(DomainError):
        evaluate(curve, [-1e-300])
    surface = BezierSurface([[[0], [1]], [[1], [2]]])
    with pytest.raises(InputError):
        evaluate_surface(surface, [0.5], [0.5, 0.25])
    with pytest.raises(InputError):
        evaluate_surface(curve, [0.5], [0.5])
    with pytest.raises(DomainError):
        evaluate_surface(surface, [0.5], [2.0])


def test_many_parameters_is_vectorized_and_fast():
    import time

    curve = BezierCurve([[i, (-1) ** i * i * i] for i in range(11)])
    ts = np.linspace(0, 1, 200_000)
    evaluate(curve, ts[:8192])  # a numba kernel compiles at its first call (seconds): not what is timed
    start = time.perf_counter()
    values, radii = evaluate(curve, ts)
    assert time.perf_counter() - start < 5.0
    assert np.isfinite(radii).all() and values.shape == (200_000, 2)


# ---------------------------------------------------------------------------- fast paths
def test_up_nonnegative_is_nextafter():
    from exactcagd.numeric.fp_error import up, up_nonnegative

    x = np.array([0.0, -0.0, 5e-324, 2.0**-1022 - 5e-324, 2.0**-1022, 0.1, 1.0, 2.0**52, 1.7976931348623157e308])
    with np.errstate(over="ignore"):
        assert np.array_equal(up_nonnegative(x), np.where(x == 0, 5e-324, up(x)))
    assert up_nonnegative(1.0) == np.nextafter(1.0, 2.0)
    assert np.isnan(up_nonnegative(np.array([np.inf, np.nan]))).all()  # callers map these to inf


def test_rational_extreme_weights_at_interval_ends():
    """Certificates at 0, 1 and next to them, for weights spanning 32 orders of magnitude."""
    ts = [0.0, 5e-324, 2.0**-60, 0.5, np.nextafter(0.5, 1.0), 1 - 2.0**-52, 1 - 2.0**-53, 1.0]
    curve = BezierCurve([[1, -2, 3], ["1/3", 5, -7], [2, "-1/7", 0], [-4, 1, 1]],
                        weights=[mpq(1, 10**16), 10**16, mpq(3, 10**16), 7])
    exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
    for method in METHODS:
        values, radii = evaluate(curve, ts, method=method)
        # the power basis cancels catastrophically near t = 1 (inf radius there, honestly)
        assert method == "power" or np.isfinite(radii).all()
        check_bounds(exact, values, radii)


def test_results_independent_of_order_chunks_threads_and_scratch():
    """Sorted vs shuffled parameters (slice vs index paths of the Horner halves), reuse of
    the per-thread scratch memory across curves and surfaces, and concurrent threads."""
    from concurrent.futures import ThreadPoolExecutor

    rng = np.random.default_rng(17)
    ts = np.concatenate([rng.random(3000), [0.0, 0.5, 1.0]])
    order = np.argsort(ts)
    curves = [_moderate_curve(rng, n, d=3) for n in (2, 9, 23)]
    curves.append(BezierCurve([[1, 2], [3, -1], [0, 5]], weights=[1, "1/1000", 1000]))
    surface = BezierSurface([[[0, 0, 0], [0, 1, 2]], [[1, 0, 1], [1, 1, -3]], [[2, 1, 0], [3, 3, 3]]])
    reference = {(i, m): evaluate(c, ts, method=m) for i, c in enumerate(curves) for m in METHODS}

    def check(i, m):
        values, radii = evaluate(curves[i], ts[order], method=m)
        evaluate_surface(surface, ts[::-1], ts, method=m)  # reuses the scratch memory in between
        assert np.array_equal(values, reference[i, m][0][order])
        assert np.array_equal(radii, reference[i, m][1][order])
        assert np.array_equal(evaluate(curves[i], ts, method=m, bound=False), reference[i, m][0])

    jobs = [key for key in reference] * 2
    with ThreadPoolExecutor(2) as pool:
        list(pool.map(lambda key: check(*key), jobs))


def test_cached_float_coefficients_are_read_only():
    import exactcagd.numeric.evaluation as module

    curve = BezierCurve([[0, 1], [2, 3]])
    evaluate(curve, [0.5])
    for array in module._curve_coefficients(curve, "decasteljau"):
        with pytest.raises(ValueError):
            array[0] = 7.0


# ---------------------------------------------------------------------------- default: compiled kernel
def _numpy_fallback(monkeypatch, curve, ts):
    import exactcagd.numeric.evaluation as module

    monkeypatch.setattr(module, "KERNEL", False)
    try:
        return evaluate(curve, ts, method="horner")
    finally:
        monkeypatch.setattr(module, "KERNEL", True)


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.function_scoped_fixture])
@given(curves(max_degree=25), st.lists(unit_floats, min_size=1, max_size=30))
def test_default_kernel_is_bit_identical_to_numpy_horner(monkeypatch, curve, ts):
    """issue 18: the compiled default (numba) does the numpy Horner path's float operations;
    its values and radii are the same bits, and certified against exact evaluation."""
    import exactcagd.numeric.evaluation as module
    from exactcagd.numeric import _horner_kernel

    if not _horner_kernel.AVAILABLE:
        pytest.skip("numba not installed: the default runs the numpy path itself")
    monkeypatch.setattr(module, "KERNEL_MIN_POINTS", 0)  # the kernel even for a few points
    ts = ts + [0.0, 5e-324, 2.0**-1060, 0.5, np.nextafter(0.5, 1.0), 1 - 2.0**-53, 1.0]
    values, radii = evaluate(curve, ts)
    ref_values, ref_radii = _numpy_fallback(monkeypatch, curve, ts)
    assert np.array_equal(values, ref_values, equal_nan=True)
    assert np.array_equal(radii, ref_radii)
    exact = [exact_point(curve.control_points, curve.weights, q(t)) for t in ts]
    check_bounds(exact, values, radii)
    assert np.array_equal(evaluate(curve, ts, bound=False), ref_values, equal_nan=True)


@pytest.mark.parametrize("degree,rational", [(3, False), (11, False), (3, True), (11, True)])
def test_default_kernel_long_input_and_planted_violation(degree, rational):
    """Many parameters (several kernel blocks) certified against exact evaluation; for
    every checked point and coordinate, an "exact" value planted at the radius times
    (1 + 2^-50) from the computed one, on either side, is caught by the certificate check."""
    rng = np.random.default_rng(5 + degree)
    points = [[Fraction(int(x), 1 << 12) for x in rng.integers(-4096, 4096, 3)] for _ in range(degree + 1)]
    weights = [Fraction(int(w), 8) for w in rng.integers(4, 16, degree + 1)] if rational else None
    curve = BezierCurve(points, weights)
    ts = rng.random(5000)  # above KERNEL_MIN_POINTS: the compiled path, several blocks
    values, radii = evaluate(curve, ts)
    idx = rng.choice(ts.size, 24, replace=False)
    assert np.isfinite(radii[idx]).all() and (radii[idx] > 0).all()  # else the check below is vacuous
    exact = [exact_point(curve.control_points, curve.weights, q(ts[i])) for i in idx]
    check_bounds(exact, values[idx], radii[idx])
    for i in idx:
        for j in range(3):
            for side in (1, -1):
                planted = [q(values[i, j]) + side * q(radii[i, j]) * (1 + mpq(1, 2**50))]
                with pytest.raises(AssertionError, match="certificate violated"):
                    check_bounds([planted], [[values[i, j]]], [[radii[i, j]]])


def test_default_refuses_parameters_outside_unit_interval():
    curve = BezierCurve([[0, 0], [1, 2], [2, 0]])
    for bad in ([-1e-300], [0.5, 1.0000000000000002], [2.0]):
        with pytest.raises(DomainError, match="method='horner'"):
            evaluate(curve, bad)
        with pytest.raises(DomainError):
            evaluate_surface(BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]), bad, [0.5] * len(bad))
    assert np.isfinite(evaluate(curve, [2.0], method="horner")[1]).all()


def test_default_kernel_bit_identical_on_hard_inputs(monkeypatch):
    """issue 18: the kernel's blocks (first pass of 1-4 Horner steps, then 4 per pass), its
    in-block division by the weight and its stores (1-5 coordinates) against the numpy
    path, on inputs that reach every branch: degrees 0-13, block boundaries and a tail
    block, subnormal parameters (the tiny-ratio term), overflow and a weight enclosure containing 0 (infinite radii), weights
    over 32 orders of magnitude; certified against exact evaluation at the special
    parameters."""
    import exactcagd.numeric.evaluation as module
    from exactcagd.numeric import _horner_kernel

    if not _horner_kernel.AVAILABLE:
        pytest.skip("numba not installed: the default runs the numpy path itself")
    monkeypatch.setattr(module, "KERNEL_MIN_POINTS", 0)
    rng = np.random.default_rng(23)
    special = [0.0, 5e-324, 2.0**-1060, 2.0**-1030, 1e-300, 2.0**-53, 0.25, 0.5, np.nextafter(0.5, 1.0),
               1 - 2.0**-53, 1.0]
    hard = [
        BezierCurve([[q(1e-310)], [q(-3e-315)], [q(5e-324)], [mpq(1, 10**320)], [mpq(-7, 10**312)]]),
        BezierCurve([[q(1e308)], [q(-1.7e308)], [q(1e308)]]),  # 2 * 1.7e308 overflows
        BezierCurve.from_homogeneous(np.array([[mpq(1), mpq(1)], [mpq(-1), mpq(-1)]], dtype=object)),
        BezierCurve([[1, -2, 3], ["1/3", 5, -7], [2, "-1/7", 0], [-4, 1, 1]],
                    weights=[mpq(1, 10**16), 10**16, mpq(3, 10**16), 7]),
    ]
    hard += [_moderate_curve(rng, n, d=3) for n in (0, 1, 2, 3, 4, 5, 8, 9, 13)]
    hard += [_moderate_curve(rng, n, d=d) for n, d in ((2, 1), (6, 2), (3, 4), (7, 5))]  # every store of the kernel
    hard += [BezierCurve(_moderate_curve(rng, n, d=2).control_points,
                         weights=[int(w) for w in rng.integers(1, 50, n + 1)]) for n in (1, 4, 6, 11)]
    block = _horner_kernel.BLOCK
    for curve in hard:
        for size in (block - 1, block + 1, 2 * block + 37):
            ts = np.concatenate([special, rng.random(size - len(special))])
            values, radii = evaluate(curve, ts)
            ref_values, ref_radii = _numpy_fallback(monkeypatch, curve, ts)
            assert np.array_equal(values, ref_values, equal_nan=True)
            assert np.array_equal(radii, ref_radii)
            assert np.array_equal(evaluate(curve, ts, bound=False), ref_values, equal_nan=True)
        keep = [i for i, t in enumerate(special) if not (curve is hard[2] and t == 0.5)]  # W(1/2) = 0 there
        exact = [exact_point(curve.control_points, curve.weights, q(special[i])) for i in keep]
        check_bounds(exact, values[keep], radii[keep])
    assert np.isinf(evaluate(hard[1], special)[1]).any()  # overflow
    assert np.isinf(evaluate(hard[2], special)[1][7]).all() and np.isfinite(evaluate(hard[2], special)[1][:6]).all()


def test_default_kernel_checks_long_float_arrays_itself():
    """The default reads a long float64 array as it is (no copy) and the kernel checks
    0 <= t <= 1 itself: one bad parameter among 5000 raises the errors of the validation,
    and read-only, strided and list inputs give the same bits."""
    curve = BezierCurve([[1, 2, 3], [-1, 0, 2], ["1/3", 5, -2], [0, 1, 1]], weights=[1, 3, 2, 1])
    ts = np.linspace(0.0, 1.0, 5000)
    for bad, error in ((np.nan, InexactInputError), (np.inf, InexactInputError), (-np.inf, InexactInputError),
                       (-1e-300, DomainError), (1.0000000000000002, DomainError), (2.0, DomainError)):
        arr = ts.copy()
        arr[4321] = bad
        for bound in (True, False):
            with pytest.raises(error):
                evaluate(curve, arr, bound=bound)
    values, radii = evaluate(curve, ts)
    readonly = ts.copy()
    readonly.flags.writeable = False
    for variant in (readonly, np.repeat(ts, 2)[::2], ts.tolist()):
        other_values, other_radii = evaluate(curve, variant)
        assert np.array_equal(values, other_values) and np.array_equal(radii, other_radii)
    exact = [exact_point(curve.control_points, curve.weights, q(ts[i])) for i in (0, 1, 2500, 4999)]
    check_bounds(exact, values[[0, 1, 2500, 4999]], radii[[0, 1, 2500, 4999]])


def test_default_kernel_arguments_follow_the_curve():
    """Curves come and go (Python reuses a freed curve's id) and a curve built on an array
    its maker still owns can change in place: each evaluation must use the coefficients
    of the curve as it is."""
    import exactcagd.numeric.evaluation as module

    ts = np.full(5000, 0.5)  # s = t / (1 - t) = 1: every value below is exact
    for k in range(150):
        curve = BezierCurve([[k, -k], [k + 4, 3 * k]])  # freed at the next iteration ...
        values = evaluate(curve, ts, bound=False)
        assert values[0].tolist() == values[-1].tolist() == [k + 2, k]
        module._curve_coefficients.cache_clear()  # ... unless a cache keeps it
    first = BezierCurve([[0], [8]])
    equal = BezierCurve([[0], [8]])
    assert evaluate(first, ts, bound=False)[0, 0] == evaluate(equal, ts, bound=False)[0, 0] == 4.0
    first._points[1, 0] = mpq(16)  # in place, as internal code owning the array could
    assert evaluate(first, ts, bound=False)[0, 0] == 8.0
