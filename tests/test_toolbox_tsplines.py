"""exactcagd.toolbox.tsplines: Rule 1 on a hand-drawn T-mesh, evaluation against Cox-de Boor
products, equivalence with the foundation's B-spline surfaces, refinement and standardness.

The expected knot vectors below were read off the mesh drawing by hand; evaluation
references use ``_sympy_ref.cox_de_boor`` (Fractions), never exactcagd's basis functions.
"""

from fractions import Fraction

import numpy as np
import pytest
from _sympy_ref import cox_de_boor
from gmpy2 import mpq
from hypothesis import given, settings
from hypothesis import strategies as st

from exactcagd import BSplineSurface
from exactcagd.errors import DomainError, InputError, KnotError, WeightError
from exactcagd.toolbox.tsplines import TMesh, refine_indexed

FAST = settings(max_examples=8, deadline=None)

T_VALUES = [0, 1, 2, 3, 5, 6]


def mesh(weights=False, seed=0):
    """Columns s = 0..6, rows t = 0, 1, 2, 3, 5, 6.

    Column 3 exists only between rows 0-1 and 4-5; row 3 (t = 3) runs from column 0 to 2
    (a T-junction at (2, 3)); every other line is full.
    """
    pts, w = {}, {}
    for c in range(7):
        for r in range(6):
            if (c == 3 and r in (2, 3)) or (r == 3 and c > 2):
                continue
            pts[(c, r)] = (c, r, (c * 3 + r * 5 + seed) % 7 - 3)
            w[(c, r)] = 1 + (c + 2 * r + seed) % 3
    se = [(c, 0, 5) for c in range(7) if c != 3] + [(3, 0, 1), (3, 4, 5)]
    te = [(r, 0, 6) for r in (0, 1, 2, 4, 5)] + [(3, 0, 2)]
    return TMesh(range(7), T_VALUES, pts, se, te, w if weights else None)


EXPECTED_RULE1 = {
    (2, 2): ((0, 1, 2, 4, 5), (0, 1, 2, 3, 5)),
    (2, 3): ((0, 1, 2, 4, 5), (1, 2, 3, 5, 6)),
    (3, 1): ((1, 2, 3, 4, 5), (0, 0, 1, 2, 5)),
    (0, 0): ((0, 0, 0, 1, 2), (0, 0, 0, 1, 2)),
    (6, 5): ((4, 5, 6, 6, 6), (2, 5, 6, 6, 6)),
    (4, 2): ((1, 2, 4, 5, 6), (0, 1, 2, 5, 6)),
}


def test_rule1_by_hand():
    m = mesh()
    for node, (s, t) in EXPECTED_RULE1.items():
        assert m.knot_vectors(node) == (s, t), node


def N(knots, x):
    """Cubic basis function by Cox-de Boor (half-open; x strictly inside a span of the support)."""
    ks = [Fraction(int(k.numerator), int(k.denominator)) if hasattr(k, "numerator") else Fraction(k) for k in knots]
    return cox_de_boor(0, 3, ks + [ks[-1] + 1], x)


INSIDE = [(Fraction(5, 2), Fraction(5, 2)), (Fraction(13, 4), Fraction(7, 4)), (Fraction(3, 2), Fraction(7, 2)), (Fraction(11, 3), Fraction(23, 5))]


def test_evaluate_matches_cox_de_boor_products():
    m = mesh(weights=True)
    for s, t in INSIDE:
        num, den = [Fraction(0)] * 3, Fraction(0)
        for node, p in m.points.items():
            sk, tk = m.knot_vectors(node)
            w = Fraction(int(m.weight(node)))
            b = w * N(sk, s) * N(tk, t)
            num = [a + b * Fraction(int(x)) for a, x in zip(num, p)]
            den += b
        got = m.evaluate(s, t)
        assert tuple(Fraction(int(x.numerator), int(x.denominator)) for x in got) == tuple(x / den for x in num)


@given(st.integers(4, 6), st.integers(4, 6), st.data())
@FAST
def test_full_grid_is_the_bspline_surface(nu, nv, data):
    gaps_u = data.draw(st.lists(st.integers(1, 3), min_size=nu - 3, max_size=nu - 3))
    gaps_v = data.draw(st.lists(st.integers(1, 3), min_size=nv - 3, max_size=nv - 3))
    ku = [0] * 4 + list(np.cumsum(gaps_u)[:-1]) + [sum(gaps_u)] * 4
    kv = [0] * 4 + list(np.cumsum(gaps_v)[:-1]) + [sum(gaps_v)] * 4
    ku, kv = [int(x) for x in ku], [int(x) for x in kv]
    net = data.draw(st.lists(st.lists(st.tuples(st.integers(-3, 3), st.integers(-3, 3), st.integers(-3, 3)), min_size=nv, max_size=nv), min_size=nu, max_size=nu))
    w = data.draw(st.lists(st.lists(st.integers(1, 4), min_size=nv, max_size=nv), min_size=nu, max_size=nu))
    B = BSplineSurface([[list(p) for p in row] for row in net], ku, kv, weights=w)
    M = TMesh.from_bspline([[list(p) for p in row] for row in net], ku, kv, weights=w)
    for i in range(4):
        s, t = Fraction(ku[-1] * i, 3), Fraction(kv[-1] * (3 - i), 3)
        assert M.evaluate(s, t) == B.evaluate(s, t)
    assert M.classify() == "standard"
    tb = M.to_bspline()
    assert tuple(tb.S) == tuple(ku) and tuple(tb.T) == tuple(kv)
    surf = tb.to_bspline_surface()
    assert surf.evaluate(Fraction(ku[-1], 2), Fraction(kv[-1], 3)) == B.evaluate(Fraction(ku[-1], 2), Fraction(kv[-1], 3))


def test_to_bspline_and_refine_reproduce_the_surface():
    m = mesh(weights=True)
    B = m.to_bspline()
    R = m.refine([(3, 2)])
    assert sorted(set(R.points) - set(m.points)) == [(3, 2), (3, 3)]
    full = m.refine([(c, r) for c in range(7) for r in range(6)])
    assert len(full.points) == 42
    for s, t in INSIDE:
        ref = m.evaluate(s, t)
        assert B.evaluate(s, t) == ref and R.evaluate(s, t) == ref and full.evaluate(s, t) == ref
    assert np.all(full.to_bspline().hom == B.hom)


def test_classification():
    assert mesh().classify() == "non-standard"
    assert mesh().refine([(3, 2)]).classify() == "standard"
    grid = TMesh.full_grid(range(5), range(4), lambda c, r: (c, r, 0))
    assert grid.classify() == "standard"
    # partition of unity checked independently at a point of the domain
    total = sum(N(*[grid.knot_vectors(n)[0], Fraction(3, 2)]) * N(grid.knot_vectors(n)[1], Fraction(3, 2)) for n in grid.points)
    assert total == 1


def test_with_lines_changes_nothing():
    m = mesh(weights=True)
    m2 = m.with_s_line(mpq(7, 2)).with_t_line(4)
    for s, t in INSIDE:
        assert m2.evaluate(s, t) == m.evaluate(s, t)
    new_col = m2.s_values.index(mpq(7, 2))
    r = m2.refine([(new_col, 2)])  # a control point on a new knot line, inserted locally
    for s, t in INSIDE:
        assert r.evaluate(s, t) == m.evaluate(s, t)


def test_refine_indexed_zero_intervals():
    vals = [0, 1, 1, 2, 3, 4]
    value = lambda i: mpq(vals[i])  # noqa: E731
    parts = refine_indexed((0, 1, 3, 4, 5), 2, value)  # insert the second copy of knot 1
    assert [p[1] for p in parts] == [(0, 1, 2, 3, 4), (1, 2, 3, 4, 5)]
    assert refine_indexed((0, 1, 3, 4, 5), 1, value) == [(1, (0, 1, 3, 4, 5))]


def test_bad_input():
    with pytest.raises(KnotError):
        TMesh([0, 2, 1], [0, 1], {(0, 0): (0, 0, 0)})
    with pytest.raises(InputError):
        TMesh([0, 1], [0, 1], {(5, 0): (0, 0, 0)})
    with pytest.raises(InputError):
        TMesh([0, 1], [0, 1], {(0, 0): (0, 0, 0)}, s_edges=[(0, 1, 0)])
    with pytest.raises(WeightError):
        TMesh([0, 1], [0, 1], {(0, 0): (0, 0, 0)}, weights={(0, 0): 0})
    with pytest.raises(KnotError):
        TMesh([0, 1], [0, 1], {(0, 0): (0, 0, 0)}, phantom_s=([1, 2], [1, 1]))
    m = mesh()
    with pytest.raises(InputError):
        m.knot_vectors((3, 3))
    with pytest.raises(DomainError):
        TMesh.full_grid(range(2), range(2), lambda c, r: (c, r, 0)).evaluate(0, 0)
    with pytest.raises(InputError):
        m.refine([(9, 9)])
