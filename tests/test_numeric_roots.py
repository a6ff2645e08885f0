"""Bernstein root finding (notes ch. 9): float methods with certified enclosures, exact VCA.

References are independent of the code under test: flint's certified complex root
isolation (``exact.algebraic.real_roots``), sympy factorization/expansion, and
polynomials built from planted roots.
"""

import math
import random

import numpy as np
import pytest
import sympy
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BezierCurve
from exactcagd.errors import DimensionError, InputError
from exactcagd.exact.algebraic import real_roots
from exactcagd.exact.bernstein import as_coefficients, from_power, product
from exactcagd.numeric.descartes import isolate_exact, sign_variations
from exactcagd.numeric.roots import (
    bernstein_roots,
    deflate_left,
    deflate_right,
    isolating_roots,
    line_roots,
    marching_roots,
)

T = sympy.Symbol("t")
METHODS = ("marching", "isolate", "exact")


def flint_roots(coeffs):
    """Exact real roots in [0, 1] with multiplicities, via the power basis and flint."""
    n = len(coeffs) - 1
    poly = sympy.Poly(
        sympy.expand(sum(sympy.Rational(str(c)) * sympy.binomial(n, i) * T**i * (1 - T) ** (n - i) for i, c in enumerate(coeffs))), T
    )
    power = [mpq(str(c)) for c in reversed(poly.all_coeffs())]
    return real_roots(power, 0, 1)


def planted(roots_mults, lead=1):
    c = as_coefficients([lead])
    for r, m in roots_mults:
        r = mpq(r)
        for _ in range(m):
            c = product(c, as_coefficients([-r, 1 - r]))
    return c


def check_enclosures(coeffs, found):
    exact = flint_roots(list(coeffs))
    for r, m in exact:
        assert any(x.contains(r) for x in found), (str(r), found)
    for x in found:
        inside = [(r, m) for r, m in exact if x.contains(r)]
        if x.certified:
            assert len(inside) == 1 and inside[0][1] == x.multiplicity, (x, [str(r) for r, _ in inside])
        if x.exists:
            assert inside, x
    return exact


# ------------------------------------------------------------------ fixed examples
@pytest.mark.parametrize("method", METHODS)
def test_quadratic_irrational_roots(method):
    # 8t^2 - 8t + 1: roots (2 -+ sqrt 2)/4
    found = bernstein_roots([1, -3, 1], method=method)
    assert [r.certified for r in found] == [True, True]
    exact = [(2 - sympy.sqrt(2)) / 4, (2 + sympy.sqrt(2)) / 4]
    for r, e in zip(found, exact):
        lo, hi = r.interval
        assert sympy.Rational(lo) <= e <= sympy.Rational(hi)
        assert abs(r.t - float(e)) < 1e-13
        assert r.width < 1e-10


@pytest.mark.parametrize("method", METHODS)
def test_notes_figure_9_2_example(method):
    """Notes 9.2, Fig. 9.2: degree 5, simple roots 0, 0.2, 1 and a double root 0.6."""
    c = planted([(0, 1), ("1/5", 1), ("3/5", 2), (1, 1)])
    found = bernstein_roots(c, method=method)
    check_enclosures(c, found)
    ends = [r for r in found if r.interval in ((0.0, 0.0), (1.0, 1.0))]
    assert [(r.t, r.multiplicity, r.certified) for r in ends] == [(0.0, 1, True), (1.0, 1, True)]
    simple = [r for r in found if r.certified and r.multiplicity == 1 and r.interval[0] > 0 and r.interval[1] < 1]
    assert len(simple) == 1 and abs(simple[0].t - 0.2) < 1e-12
    double = [r for r in found if r.contains(mpq(3, 5))]
    assert len(double) == 1 and abs(double[0].t - 0.6) < 1e-6
    if method == "exact":  # exact isolation also proves the double root
        assert double[0].certified and double[0].multiplicity == 2


def test_isolating_detects_double_root_multiplicity():
    c = planted([("1/3", 2), ("3/4", 1)])
    raw = isolating_roots([float(x) for x in c])
    mults = {round(t, 6): m for t, m in raw}
    assert mults.get(round(1 / 3, 6)) == 2 and mults.get(0.75) == 1


def test_marching_steps_from_the_left_never_past_a_root():
    """Notes 9.1: marching approaches each root from the left and cannot skip one."""
    c = planted([("1/10", 1), ("1/9", 1), ("1/2", 1), ("51/100", 1)])
    raw = marching_roots([float(x) for x in c])
    assert [round(t, 10) for t, _ in raw] == [0.1, round(1 / 9, 10), 0.5, 0.51]


def test_exact_endpoint_roots_and_multiplicity():
    c = planted([(0, 3), ("1/2", 1), (1, 2)])
    found = bernstein_roots(c)
    assert found[0].interval == (0.0, 0.0) and found[0].multiplicity == 3 and found[0].certified
    assert found[-1].interval == (1.0, 1.0) and found[-1].multiplicity == 2
    check_enclosures(c, found)


def test_no_roots_and_constant():
    assert bernstein_roots([1, 2, 3]) == []
    assert bernstein_roots([5]) == []


def test_certify_false_returns_raw_estimates():
    raw = bernstein_roots([1, -3, 1], certify=False)
    assert [r.certified for r in raw] == [False, False] and raw[0].interval == (raw[0].t, raw[0].t)


# ------------------------------------------------------------------ deflation (9.1)
@pytest.mark.parametrize("n", [1, 2, 3, 5, 8])
def test_deflation_formula_against_sympy(n):
    rng = random.Random(n)
    c = as_coefficients([0] + [rng.randint(-9, 9) for _ in range(n)])
    d = deflate_left(c)
    bern = lambda cs, m: sum(sympy.Rational(str(x)) * sympy.binomial(m, i) * T**i * (1 - T) ** (m - i) for i, x in enumerate(cs))
    assert sympy.expand(bern(c, n) - T * bern(d, n - 1)) == 0
    c2 = as_coefficients([rng.randint(-9, 9) for _ in range(n)] + [0])
    d2 = deflate_right(c2)
    assert sympy.expand(bern(c2, n) - (1 - T) * bern(d2, n - 1)) == 0


# ------------------------------------------------------------------ 9.4 line / rational curve
def test_line_meets_rational_quarter_circle_exactly_once():
    arc = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    (r,) = line_roots(arc, (1, -1, 0))
    assert r.certified
    # the curve at the root is (sqrt2/2, sqrt2/2): x(t) = y(t); check with sympy
    x, y = arc.to_sympy(T)
    sols = [s for s in sympy.solve(sympy.together(x - y), T) if s.is_real and 0 <= s <= 1]
    assert len(sols) == 1 and r.interval[0] <= float(sols[0]) <= r.interval[1]


def test_line_roots_bad_input():
    arc = BezierCurve([[1, 0], [1, 1], [0, 1]])
    with pytest.raises(InputError):
        line_roots(arc, (0, 0, 1))
    with pytest.raises(InputError):
        line_roots(arc, (1, 0))
    with pytest.raises(InputError):
        line_roots(BezierCurve([[0, 0], [1, 0]]), (0, 1, 0))  # the curve lies on the line
    with pytest.raises(DimensionError):
        line_roots(BezierCurve([[0, 0, 0], [1, 0, 0]]), (1, 0, 0))


def test_bad_input():
    with pytest.raises(InputError):
        bernstein_roots([0, 0, 0])
    with pytest.raises(InputError):
        bernstein_roots([1, -1], method="newton")
    with pytest.raises(InputError):
        bernstein_roots([1, -1], tol=0)
    with pytest.raises(DimensionError):
        bernstein_roots([[1, 2], [3, 4]])
    with pytest.raises(InputError):
        isolate_exact([0, 0])


# ------------------------------------------------------------------ exact VCA
def test_sign_variations():
    assert sign_variations([1, 0, -2, 0, 3, 3, -1]) == 3
    assert sign_variations([0, 0]) == 0


def test_vca_worked_example():
    found = isolate_exact(planted([(0, 2), ("1/2", 1), ("1/3", 3)]))
    assert [(str(r.lo), str(r.hi), r.multiplicity) for r in found if r.is_rational] == [("0", "0", 2), ("1/2", "1/2", 1)]
    (third,) = [r for r in found if not r.is_rational]
    assert third.multiplicity == 3 and third.lo < mpq(1, 3) < third.hi


def assert_vca_matches(coeffs):
    vca = isolate_exact(coeffs)
    ref = flint_roots(list(coeffs))
    assert len(vca) == len(ref)
    for r, m in ref:
        hits = [x for x in vca if x.contains(r)]
        assert len(hits) == 1 and hits[0].multiplicity == m


coeff_lists = st.lists(st.integers(-9, 9), min_size=2, max_size=9).filter(lambda c: any(c))
root_lists = st.lists(st.tuples(st.fractions(0, 1, max_denominator=12), st.integers(1, 3)), min_size=1, max_size=4)


@settings(max_examples=40, deadline=None)
@given(coeff_lists)
def test_vca_matches_flint_random(coeffs):
    assert_vca_matches(as_coefficients(coeffs))


@settings(max_examples=25, deadline=None)
@given(root_lists)
def test_vca_matches_flint_planted(rm):
    assert_vca_matches(planted(rm))


# ------------------------------------------------------------------ properties of the float methods
@settings(max_examples=15, deadline=None)
@given(coeff_lists, st.sampled_from(METHODS))
def test_enclosures_hold_random(coeffs, method):
    check_enclosures(as_coefficients(coeffs), bernstein_roots(coeffs, method=method))


@settings(max_examples=10, deadline=None)
@given(root_lists, st.sampled_from(METHODS))
def test_enclosures_hold_planted(rm, method):
    c = planted(rm)
    found = bernstein_roots(c, method=method)
    exact = check_enclosures(c, found)
    # simple, well separated planted roots are certified and accurate
    for r, m in exact:
        if m == 1 and all(abs(float(r) - float(o)) > 1e-3 for o, _ in exact if o != r):
            hit = [x for x in found if x.contains(r)]
            assert hit[0].certified and abs(hit[0].t - float(r)) < 1e-9


@pytest.mark.parametrize("method", METHODS)
def test_linear_roots_certified(method):
    """Regression (found by CI): on a linear piece both hull clips of the two-sided march
    are the root itself, and rounding can cross them by one ulp; marching then returned
    the window's midpoint (0.5 for the root 1/5).  Reference: the planted root p/q."""
    for q in range(2, 30):
        for p in range(1, q):
            (hit,) = bernstein_roots(planted([(mpq(p, q), 1)]), method=method)
            assert hit.certified and hit.contains(mpq(p, q)) and abs(hit.t - p / q) < 1e-12, (p, q, hit)


# ------------------------------------------------------------------ rounding-fragile spots (deterministic)
NEAR_ENDS = [mpq(1, 2**53), mpq(1, 2**60), mpq(1, 2**100), mpq(1, 3 * 2**70), 1 - mpq(1, 2**53), 1 - mpq(1, 2**60), 1 - mpq(1, 2**40)]


@pytest.mark.parametrize("method", METHODS)
def test_dyadic_roots_certified(method):
    """Every dyadic root p/2^k (k <= 9): the halving steps of 9.2 and the hull clips of 9.1
    land exactly on the root.  Reference: the planted root."""
    for k in range(1, 10):
        for p in range(1, 2**k, 2):
            r = mpq(p, 2**k)
            (hit,) = bernstein_roots(planted([(r, 1)]), method=method)
            assert hit.certified and hit.contains(r), (method, str(r), hit)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("r", NEAR_ENDS, ids=str)
def test_roots_within_rounding_of_an_end_are_certified(method, r):
    """A root within ~1e-16 of 0 or 1 leaves an end coefficient at the noise level: the
    sign-variation count of 9.2 saw no change there (nothing proposed, the root only came
    back as a wide uncertified box), and the march of 9.1 took the noisy sliver [r, 1] for a
    second root.  Alone and next to a root at 1/2 the root must come back certified."""
    for rm in ([(r, 1)], [(r, 1), (mpq(1, 2), 1)]):
        found = bernstein_roots(planted(rm), method=method)
        exact = check_enclosures(planted(rm), found)
        assert len(found) == len(exact) == len(rm), (method, str(r), found)
        assert all(x.certified and x.multiplicity == 1 for x in found), (method, str(r), found)


@pytest.mark.parametrize("method", METHODS)
def test_root_next_to_a_root_near_one(method):
    """Regression: roots 1023/1024 and 1 - 2^-40 (marching reported 1 - 2^-40 twice, as an
    uncertified double root; after a first fix isolate proposed both 1 - 1e-12 and 1)."""
    rm = [(mpq(1023, 1024), 1), (1 - mpq(1, 2**40), 1)]
    found = bernstein_roots(planted(rm), method=method)
    check_enclosures(planted(rm), found)
    assert len(found) == 2 and all(x.certified for x in found), found


def test_float_methods_see_exact_and_noisy_end_roots():
    """The raw float methods (public) on data with exact zeros at the ends; reference by hand."""
    cases = {
        (1.0, 0.0): [1.0],  # 1 - t
        (0.0, 1.0, 0.0): [0.0, 1.0],  # 2t(1 - t)
        (1.0, -1.0, 0.0): [1 / 3, 1.0],  # (1 - t)(1 - 3t)
        (1e-300, -1.0): [1e-300 / (1 + 1e-300)],
        (1.0, -0.5, 8.67e-19): [0.5, 1.0],  # roots 1/2 and 1 - 2^-60 (float data)
    }
    for y, roots in cases.items():
        for finder in (marching_roots, isolating_roots):
            got = [t for t, _ in finder(list(y))]
            assert len(got) == len(roots) and all(abs(a - b) < 1e-9 for a, b in zip(got, roots)), (finder.__name__, y, got)


@pytest.mark.parametrize(
    "roots",
    [
        [("1/3", 3), ("1/2", 1), ("2/3", 2)],                      # multiple roots
        [("1/2", 1), (mpq(1, 2) + mpq(1, 2**40), 1)],               # a cluster 2^-40 wide
        [(mpq(k, 20), 1) for k in range(1, 20)],                    # Wilkinson-like, degree 19
    ],
)
def test_exact_method_certifies_what_floats_cannot(roots):
    """method="exact": every root certified with its exact multiplicity, even where the float
    methods must leave an uncertified cluster.  Reference: sympy's exact real roots (CRootOf)
    of the expanded Bernstein sum, counted with multiplicity, compared exactly."""
    from collections import Counter

    coeffs = planted([(mpq(r), m) for r, m in roots])
    found = bernstein_roots(coeffs, method="exact", tol=1e-14)
    n = len(coeffs) - 1
    expr = sum(sympy.Rational(str(c)) * sympy.binomial(n, i) * T**i * (1 - T) ** (n - i) for i, c in enumerate(coeffs))
    reference = Counter(r for r in sympy.Poly(sympy.expand(expr), T).real_roots() if 0 <= r <= 1)
    assert len(found) == len(reference) and all(r.certified for r in found)
    for root, mult in reference.items():
        (hit,) = [r for r in found if sympy.Rational(r.interval[0]) <= root <= sympy.Rational(r.interval[1])]
        assert hit.multiplicity == mult and hit.width <= 1e-14


def test_exact_method_is_exact_on_irrational_roots():
    # 8t^2 - 8t + 1 = [1, -3, 1] in Bernstein form: roots (2 -+ sqrt 2)/4; enclosures of width
    # <= tol, widened only by the outward rounding to floats (one float step at each end)
    for tol in (1e-6, 1e-12, 1e-15):
        found = bernstein_roots([1, -3, 1], method="exact", tol=tol)
        exact = [(2 - sympy.sqrt(2)) / 4, (2 + sympy.sqrt(2)) / 4]
        assert [r.certified for r in found] == [True, True]
        for r, e in zip(found, exact):
            assert sympy.Rational(r.interval[0]) <= e <= sympy.Rational(r.interval[1])
            assert r.width <= tol + 2 * math.ulp(r.t)


def test_bernstein_beats_power_form_on_wilkinson_roots():
    """Notes ch. 9 ([FR87]): for roots in [0, 1] the Bernstein form is better conditioned.

    Wilkinson-like p(t) = prod (t - k/20): the float roots from Bernstein coefficients
    are far more accurate than numpy's companion-matrix roots of the power form."""
    n = 20
    c = planted([(mpq(k, n), 1) for k in range(1, n)])
    found = bernstein_roots(c, method="isolate")
    err_b = max(abs(r.t - k / n) for r, k in zip(found, range(1, n)))
    power = [float(x) for x in np.polynomial.polynomial.polyfromroots([k / n for k in range(1, n)])]
    pr = np.sort(np.roots(power[::-1]).real)
    err_p = max(abs(pr - np.arange(1, n) / n))
    assert len(found) == n - 1 and all(r.certified for r in found)
    assert all(r.contains(mpq(k, n)) for r, k in zip(found, range(1, n)))
    # attainable accuracy: the first-order condition bound of the rounded Bernstein
    # coefficients, cond(r) u = u sum |c_i| B_i(r) / |p'(r)| (exact, independent of the code)
    # is ~4e-10 at r = 1/2, so the former 1e-12 threshold was below what float64
    # coefficients determine; each root must be within 4 cond(r) u.
    deg = len(c) - 1
    for r, k in zip(found, range(1, n)):
        x = mpq(k, n)
        size = sum(abs(c[i]) * math.comb(deg, i) * x**i * (1 - x) ** (deg - i) for i in range(deg + 1))
        slope = abs(math.prod(x - mpq(j, n) for j in range(1, n) if j != k))
        assert abs(r.t - k / n) <= 4 * float(size / slope) * 2.0**-53 + 1e-16
    assert err_b < 1e-10 and err_p > 100 * err_b


def test_marching_terminates_on_clustered_roots():
    """Regression: a stalled march used to recurse through marching on the derivative,
    the second derivative, ... (never finished on Wilkinson-like degree 15)."""
    n = 16
    c = planted([(mpq(k, n), 1) for k in range(1, n)])
    found = bernstein_roots(c, method="marching")
    assert all(any(r.contains(mpq(k, n)) for r in found) for k in range(1, n))
    assert sum(r.certified for r in found) == n - 1


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(4))
def test_enclosures_hold_many_random(seed):
    rng = random.Random(seed)
    for _ in range(250):
        kind = rng.randrange(3)
        if kind == 0:
            c = as_coefficients([rng.randint(-99, 99) for _ in range(rng.randint(2, 16))])
            if not any(c):
                continue
        else:
            c = planted([(mpq(rng.randint(0, 64), 64), rng.randint(1, 3 if kind == 2 else 1)) for _ in range(rng.randint(1, 6))])
        for method in METHODS:
            check_enclosures(c, bernstein_roots(c, method=method))
        assert_vca_matches(c)


def test_from_power_reference_is_consistent():
    # sanity of the test helper: planted roots come back from the flint route
    c = planted([("1/4", 1), ("2/3", 2)])
    assert [(str(r), m) for r, m in flint_roots(list(c))] == [("1/4", 1), ("2/3", 2)]
    assert from_power(as_coefficients([0, 1])).tolist() == [0, 1]


def test_marching_on_clustered_roots_hands_over_to_the_exact_route():
    """prod_{i=1..10} (t - i/64) kept convex hull marching busy for over 600 s (issue 15);
    with its work bound the march gives up (LimitError) and bernstein_roots answers
    exactly: the ten planted roots, each in its own certified enclosure."""
    import time

    from exactcagd.errors import LimitError

    poly = sympy.Poly(sympy.prod([T - sympy.Rational(i, 64) for i in range(1, 11)]), T)
    power = np.array([mpq(int(c.p), int(c.q)) for c in reversed(poly.all_coeffs())], dtype=object)
    coeffs = from_power(power)
    t0 = time.process_time()
    roots = bernstein_roots(coeffs, method="marching")
    assert time.process_time() - t0 < 10
    assert len(roots) == 10
    for r, i in zip(roots, range(1, 11)):
        assert r.certified and r.interval[0] <= i / 64 <= r.interval[1]
    with pytest.raises(LimitError):
        marching_roots(np.array([float(c) for c in coeffs]))


# ------------------------------------------------------------------ method="exact" from flint's root balls (issue 18)
def _sign(poly, q):
    value = poly.eval(q)
    return int(bool(value > 0)) - int(bool(value < 0))


def _cmp_root(g, a, b, q) -> int:
    """sign(r - q), exactly, for the one root ``r`` of the irreducible sympy polynomial ``g``
    (degree >= 2: no rational root) in its isolating interval ``[a, b]`` and a rational ``q``."""
    if q < a:
        return 1
    if q > b:
        return -1
    return 1 if _sign(g, a) == _sign(g, q) else -1  # g changes sign once in [a, b], at the root


def sympy_reference(coeffs):
    """Real roots in [0, 1] of the expanded Bernstein sum, by sympy alone: irreducible factors
    (``factor_list``), rational roots of the linear ones, isolating intervals
    (``Poly.intervals``, exact rationals) of the others.  Returns sorted ``(locate, m)``,
    ``locate(q) = sign(root - q)`` exactly for rational ``q``."""
    n = len(coeffs) - 1
    poly = sum((sympy.Poly(sympy.Rational(str(c)) * sympy.binomial(n, i) * T**i * (1 - T) ** (n - i), T)
                for i, c in enumerate(coeffs)), sympy.Poly(0, T))
    roots = []
    for f, m in poly.factor_list()[1]:
        if f.degree() == 1:
            r = -f.nth(0) / f.nth(1)
            found = [(r, lambda q, r=r: int(bool(r > q)) - int(bool(r < q)))]
        else:
            found = []
            for (a, b), _ in f.intervals(eps=sympy.Rational(1, 2**80)):
                a, b = sympy.Rational(a), sympy.Rational(b)
                found.append((a, lambda q, f=f, a=a, b=b: _cmp_root(f, a, b, q)))
        roots += [(key, locate, m) for key, locate in found if locate(sympy.Integer(0)) >= 0 and locate(sympy.Integer(1)) <= 0]
    roots.sort(key=lambda root: root[0])
    return [(locate, m) for _, locate, m in roots]


def assert_exact_method_matches_sympy(coeffs):
    """bernstein_roots(method="exact") against :func:`sympy_reference`.  Every root lies in
    exactly one returned enclosure, a certified one holds exactly one root, of the stated
    multiplicity, in the smallest float interval that holds it (one float, or one float
    step), with ``t`` the root correctly rounded (strictly inside ``t``'s rounding cell; a
    rational tie rounds to even).  An uncertified one (``exists``) holds two or more roots
    within one float step of each other (no float interval separates them), with the sum of
    their multiplicities."""
    found = bernstein_roots(coeffs, method="exact")
    ref = sympy_reference(coeffs)
    inside = []
    for root in found:
        lo, hi = (sympy.Rational(v) for v in root.interval)
        held = [(locate, m) for locate, m in ref if locate(lo) >= 0 and locate(hi) <= 0]
        inside.append(held)
        assert root.exists and held and root.multiplicity == sum(m for _, m in held), (root, len(held))
        assert root.certified == (len(held) == 1), root
        if not root.certified:
            assert hi - lo <= 2 * sympy.Rational(math.ulp(root.interval[1])), root
            continue
        ((locate, _),) = held
        assert lo == hi or (math.nextafter(root.interval[0], math.inf) == root.interval[1] and locate(lo) > 0 and locate(hi) < 0), root
        t = root.t
        below = (sympy.Rational(t) + sympy.Rational(math.nextafter(t, -math.inf))) / 2
        above = (sympy.Rational(t) + sympy.Rational(math.nextafter(t, math.inf))) / 2
        s_below, s_above = locate(below), locate(above)
        even = (math.frexp(t)[0] * 2**53) % 2 == 0 if t else True
        assert s_below > 0 or (s_below == 0 and even), (t, root)
        assert s_above < 0 or (s_above == 0 and even), (t, root)
    assert sum(len(held) for held in inside) == len(ref)  # each root in exactly one enclosure
    return found


def _scaled(coeffs, exps):
    return as_coefficients([mpq(c) * mpq(2) ** e for c, e in zip(coeffs, exps)])


@settings(max_examples=40, deadline=None)
@given(st.lists(st.integers(-(2**20), 2**20), min_size=2, max_size=11).filter(any), st.integers(-300, 300))
def test_exact_method_matches_sympy_random(coeffs, shift):
    """Random integer coefficients, and the same scaled by 2^shift (|shift| <= 300): same
    roots, and the scaled output identical to the unscaled one."""
    found = assert_exact_method_matches_sympy(as_coefficients(coeffs))
    assert bernstein_roots(_scaled(coeffs, [shift] * len(coeffs)), method="exact") == found


@settings(max_examples=25, deadline=None)
@given(st.lists(st.tuples(st.integers(-99, 99), st.integers(-300, 300)), min_size=2, max_size=8).filter(lambda c: any(v for v, _ in c)))
def test_exact_method_matches_sympy_huge_coefficients(pairs):
    """Each coefficient scaled by its own 2^+-300: roots pressed within 2^-300 of 0 or 1."""
    assert_exact_method_matches_sympy(_scaled([v for v, _ in pairs], [e for _, e in pairs]))


# rational points, including the ends and points a float step inside them
POINTS = st.one_of(st.fractions(0, 1, max_denominator=2**12).map(lambda f: mpq(f.numerator, f.denominator)),
                   st.sampled_from([mpq(0), mpq(1), mpq(1, 2**53), 1 - mpq(1, 2**53), 1 - mpq(1, 2**52), mpq(1, 2) + mpq(1, 2**54)]))


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(POINTS, st.integers(1, 3)), max_size=4),
       st.lists(st.tuples(POINTS, st.integers(20, 96), st.integers(1, 2)), max_size=2),
       st.lists(st.integers(-9, 9), min_size=1, max_size=4).filter(any))
def test_exact_method_matches_sympy_planted(rational, clusters, extra):
    """Planted rational roots (multiple, at 0 and 1, a float step inside), clusters: pairs of
    irrational roots c -+ 2^-k/2 (k <= 96: a float step apart at least) of multiplicity 1-2
    from (t - c)^2 - 2^-k, times a random integer factor."""
    c = product(planted(rational), as_coefficients(extra))
    for center, k, mult in clusters:
        quad = as_coefficients([center**2 - mpq(1, 2**k), center * (1 - center) - mpq(1, 2**k), (1 - center) ** 2 - mpq(1, 2**k)])
        for _ in range(mult):
            c = product(c, quad)
    assert_exact_method_matches_sympy(c)


@pytest.mark.parametrize("power", [
    [-1, 0, 2],                                     # 1/sqrt 2
    [-(2**300 + 1), 0, 2**300 * 4],                 # just above 1/2
    [-1, 0, 2**2100],                               # 2^-1050: a subnormal float
    [-(2**200 - 1), 0, 2**200],                     # within 2^-201 of 1
])
def test_exact_method_irrational_roots_at_the_float_limits(power):
    """Square roots at the edge of float resolution (near 1/2, 1 and subnormal): checked
    against sympy as above."""
    assert_exact_method_matches_sympy(from_power(as_coefficients(power)))


def test_exact_method_root_near_a_rounding_boundary_falls_back_to_bisection(monkeypatch):
    """A root within 2^-300 of the midpoint h between 1/2 and the next float: the balls at 64
    and 192 bits cannot decide the rounding, and the exact bisection route answers, with the
    root correctly rounded up (it exceeds h); the Descartes route (the default for these long
    coefficients) rounds it the same way.  Reference: sympy, as above."""
    import exactcagd.numeric.roots as roots_module

    h = mpq(1, 2) + mpq(1, 2**54)
    target = h * h + mpq(1, 2**300)
    power = as_coefficients([-target, 0, 1])  # t^2 - target: root just above h
    # its ~600-bit coefficients take the Descartes route by default: the same answer
    (root,) = assert_exact_method_matches_sympy(from_power(power))
    assert root.certified and root.t == math.nextafter(0.5, 1.0)
    calls = []
    original = roots_module._roots_by_bisection
    monkeypatch.setattr(roots_module, "_roots_by_bisection", lambda *a: calls.append(a) or original(*a))
    monkeypatch.setattr(roots_module, "LARGE_COEFFICIENT_BITS", 10**6)  # force the ball route
    (root,) = assert_exact_method_matches_sympy(from_power(power))
    assert calls and root.certified and root.t == math.nextafter(0.5, 1.0)


def test_round_ball_refuses_a_ball_reaching_a_rounding_boundary():
    """The certificate of the rounding: a ball 2^-71 below the midpoint h between 1/2 and the
    next float rounds to 1/2, in the float step [1/2, next]; the same ball 2^-140 wider
    reaches h (a planted violation just above the bound) and is refused, as are a ball that
    ends exactly at h and one that holds 1/2 (its float step is not decided)."""
    import flint

    from exactcagd.numeric.roots import _round_ball

    with flint.ctx.workprec(256):
        h = flint.arb(0.5) + flint.arb(2) ** -54
        mid, rad = h - flint.arb(2) ** -70, flint.arb(2) ** -71
        assert _round_ball(flint.arb(mid, rad)) == (0.5, 0.5, math.nextafter(0.5, 1.0))
        assert _round_ball(flint.arb(mid, rad + flint.arb(2) ** -71 + flint.arb(2) ** -140)) is None
        assert _round_ball(flint.arb(mid, flint.arb(2) ** -70)) is None  # ends exactly at h
        assert _round_ball(flint.arb(flint.arb(0.5) + flint.arb(2) ** -80, flint.arb(2) ** -79)) is None
        # mirrored: just above the midpoint between the float below 1/2 and 1/2
        low = flint.arb(0.5) - flint.arb(2) ** -55
        assert _round_ball(flint.arb(low + flint.arb(2) ** -70, rad)) == (0.5, math.nextafter(0.5, 0.0), 0.5)
        assert _round_ball(flint.arb(low + flint.arb(2) ** -70, rad + flint.arb(2) ** -71 + flint.arb(2) ** -140)) is None


def test_exact_method_roots_within_a_float_step_share_an_enclosure():
    """1 and 1/(1 + 2^-53) (a float step below 1, not a float): no float interval separates
    them, so they come back as one uncertified enclosure [prev(1), 1] with multiplicity 2
    (before, as two certified roots each claiming that enclosure).  Reference: sympy."""
    found = assert_exact_method_matches_sympy(_scaled([1, -1, 0], [0, -54, 0]))
    assert [(r.interval, r.multiplicity, r.certified) for r in found] == [((math.nextafter(1.0, 0.0), 1.0), 2, False)]


def test_exact_method_restores_flint_precision():
    import flint

    before = flint.ctx.prec
    bernstein_roots([1, -3, 1, 5, -2], method="exact")
    assert flint.ctx.prec == before


# ---------------------------------------------------------------------------- huge coefficients
def _sympy_roots_in_unit_interval(c):
    """Reference: sympy's real-root intervals (width <= 2^-90) of sum C(n,i) c_i t^i (1-t)^(n-i)."""
    t = sympy.Symbol("t")
    n = len(c) - 1
    poly = sympy.Poly(sympy.expand(sum(sympy.binomial(n, i) * c[i] * t**i * (1 - t) ** (n - i) for i in range(n + 1))), t)
    return [((a + b) / 2, m) for (a, b), m in poly.intervals(eps=sympy.Rational(1, 2**90)) if 0 <= a and b <= 1]


def test_huge_coefficients_answer_in_bounded_time():
    """Bernstein coefficients [c, -1, 1] with a 20,000-bit c: a complex pair within ~c^(-1/2)
    of t = 1 and no real root.  flint's complex_roots needs minutes for this from ~2000 bits
    (found by the slow fuzz run); the Descartes route answers at once, and agrees with sympy
    at 1000 bits."""
    import time

    rng = random.Random(11)
    for bits in (1000, 20_000):
        c = [rng.getrandbits(bits) << bits, -1, 1]
        start = time.perf_counter()
        assert bernstein_roots(c, method="exact") == []
        assert time.perf_counter() - start < 5.0
    c = [rng.getrandbits(1000) << 1000, -1, 1]
    assert _sympy_roots_in_unit_interval(c) == []


@pytest.mark.parametrize("seed", range(6))
def test_huge_coefficients_with_roots_match_sympy(seed):
    """Coefficients of 300-900 bits (the Descartes route) with planted rational and
    quadratic-irrational roots in (0, 1) (the irrational ones found by exact bisection into
    one float step): same roots and multiplicities as sympy, each float the correctly
    rounded root, each enclosure one float step around it."""
    rng = random.Random(seed)
    t = sympy.Symbol("t")
    big = 2 ** rng.randint(300, 900)
    factors = [(t - sympy.Rational(rng.randint(1, 99), 100)) ** rng.randint(1, 2), t**2 - sympy.Rational(rng.randint(2, 50), 97)]
    power = sympy.Poly(sympy.expand(big * sympy.Mul(*factors)), t)
    c = list(from_power(np.array([mpq(int(k.p), int(k.q)) for k in reversed(power.all_coeffs())], dtype=object)))
    ref = _sympy_roots_in_unit_interval(c)
    got = bernstein_roots(c, method="exact")
    assert [r.multiplicity for r in got] == [m for _, m in ref]
    for r, (x, _) in zip(got, ref):
        assert r.t == float(x)  # x within 2^-90 of the root: rounds as the root unless at a tie
        lo, hi = r.interval
        assert lo <= x <= hi and (lo == hi or hi == math.nextafter(lo, math.inf))
