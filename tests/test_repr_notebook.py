"""Notebook-friendly objects: reprs show degree, dimension and the first control points;
``_repr_latex_`` is sympy's LaTeX of a curve checked against an independent Bernstein sum;
``.plot()`` gives one legend entry per item and labelled axes; B-spline objects compare
and hash by value (a pickle round trip compares equal)."""

from __future__ import annotations

import pickle

import matplotlib
import pytest
import sympy as sp

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface, compose  # noqa: E402


@pytest.fixture(autouse=True)
def _close_figures():
    yield
    plt.close("all")


def test_repr_shows_degree_dimension_and_first_points():
    c = BezierCurve([[0, 0], ["1/2", 2], [2, 0], [3, 1], [4, "-7/3"]])
    assert repr(c) == "<BezierCurve degree=4 dimension=2 points=[(0, 0), (1/2, 2), (2, 0), ... 2 more]>"
    s = BezierSurface([[[0, 0, 0], [0, 1, "1/3"]], [[1, 0, 0], [1, 1, 1]]])
    assert repr(s) == "<BezierSurface degree=(1, 1) dimension=3 net[0]=[(0, 0, 0), (0, 1, 1/3)]>"
    b = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], [0, 0, 0, "1/2", 1, 1, 1])
    assert "degree=2" in repr(b) and "dimension=2" in repr(b) and "[(0, 0), (1, 1), (2, 0), ... 1 more]" in repr(b)


def test_repr_latex_is_the_curve_typeset():
    points, weights = [[0, 0], ["1/2", 2], [2, 0]], [1, 2, 1]
    c = BezierCurve(points, weights=weights)
    t = sp.Symbol("t")
    B = [sp.binomial(2, i) * t**i * (1 - t) ** (2 - i) for i in range(3)]
    w = [sp.Integer(x) for x in weights]
    P = [[sp.Rational(x) for x in p] for p in points]
    den = sum(B[i] * w[i] for i in range(3))
    independent = sp.Matrix([sum(B[i] * w[i] * P[i][k] for i in range(3)) / den for k in range(2)])
    latex = c._repr_latex_()
    assert latex.startswith("$P(t) = ") and latex.endswith("$")
    assert sp.simplify(c.to_sympy() - independent) == sp.zeros(2, 1)
    assert latex == f"$P(t) = {sp.latex(c.to_sympy())}$"
    s = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    u, v = sp.symbols("u v")
    assert s._repr_latex_() == f"$S(u, v) = {sp.latex(sp.Matrix([u, v, u * v]))}$"


def _legend(ax) -> list[str]:
    return [t.get_text() for t in ax.get_legend().get_texts()]


def test_plot_curve_and_surface_on_one_axes_one_entry_each():
    patch = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])
    ax = patch.plot(label="patch F")
    image = compose(patch, BezierCurve([["1/4", "1/4"], ["3/4", "1/2"]]))
    image.plot(ax=ax, label="F(K(t))", polygon=False)
    assert _legend(ax) == ["patch F", "F(K(t))"]
    assert (ax.get_xlabel(), ax.get_ylabel(), ax.get_zlabel()) == ("x", "y", "z")


def test_plot_of_a_many_piece_result_is_one_legend_entry():
    from exactcagd.composition.splines import compose_spline

    surface = BSplineSurface([[[i / 3, j / 3, (i * j) / 9] for j in range(4)] for i in range(4)],
                             [0, 0, 0, "1/2", 1, 1, 1], [0, 0, 0, "1/3", 1, 1, 1])
    trim = BezierCurve([["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "-1/10"], ["9/10", "4/5"]])
    result = compose_spline(surface, trim)
    assert len(result.pieces) > 1
    ax = result.plot()
    assert _legend(ax) == [f"{len(result.pieces)} piece(s)"]
    colours = {line.get_color() for line in ax.get_lines() if line.get_label() != "_nolegend_"}
    assert len(colours) == 1, "every piece in the one colour of its legend entry"


def test_bspline_classes_compare_and_hash_by_value():
    b = BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], [0, 0, 0, "1/2", 1, 1, 1], weights=[1, 2, 1, 1])
    again = pickle.loads(pickle.dumps(b))
    assert again == b and hash(again) == hash(b) and again is not b
    assert BSplineCurve.from_dict(b.to_dict()) == b
    assert b != BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], [0, 0, 0, "1/2", 1, 1, 1])  # weights differ
    assert b != BSplineCurve([[0, 0], [1, 1], [2, 0], [3, 1]], [0, 0, 0, "1/3", 1, 1, 1], weights=[1, 2, 1, 1])
    s = BSplineSurface([[[i, j, i * j] for j in range(3)] for i in range(3)], [0, 0, 0, 1, 1, 1], [0, 0, 0, 1, 1, 1])
    assert pickle.loads(pickle.dumps(s)) == s and len({s, pickle.loads(pickle.dumps(s))}) == 1


def test_plot_of_intersections_and_approximations():
    from exactcagd.curves_on_surfaces import approximate
    from exactcagd.numeric.intersection import intersect

    a = BezierCurve([["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "-1/10"], ["9/10", "4/5"]])
    b = BezierCurve([["1/5", "3/5"], ["9/10", "1/10"], ["9/10", "9/10"], ["1/5", "2/5"]], weights=[1, "1/2", "1/2", 1])
    points = intersect(a, b)
    ax = points.plot()
    assert _legend(ax) == [f"{len(points)} intersection(s)"] and len(points) == 2
    assert sorted(t.get_text() for t in ax.texts) == ["1", "2"]
    surface = BSplineSurface([[[i / 3, j / 3, (i * j) / 9] for j in range(4)] for i in range(4)],
                             [0, 0, 0, "1/2", 1, 1, 1], [0, 0, 0, "1/3", 1, 1, 1])
    approx = approximate(surface, a, "1/100", "parabola")
    ax = approx.plot()
    assert _legend(ax) == [f"{len(approx.segments)} piece(s), bound {float(approx.distance_bound):.2g}"]
    assert ax.get_zlabel() == "z"


def _de_boor_sympy(points, knots, weights, t):
    """Independent reference: the Cox-de Boor recursion (notes 6.14) in sympy at a rational t."""
    knots = [sp.Rational(str(k)) for k in knots]
    p = len(knots) - len(points) - 1

    def N(i, k):
        if k == 0:
            last = knots[i + 1] == knots[-1] and knots[i] < knots[i + 1]
            return sp.Integer(1) if (knots[i] <= t < knots[i + 1]) or (last and t == knots[-1]) else sp.Integer(0)
        left = (t - knots[i]) / (knots[i + k] - knots[i]) * N(i, k - 1) if knots[i + k] != knots[i] else 0
        right = (knots[i + k + 1] - t) / (knots[i + k + 1] - knots[i + 1]) * N(i + 1, k - 1) if knots[i + k + 1] != knots[i + 1] else 0
        return left + right

    basis = [N(i, p) * sp.Rational(str(w)) for i, w in enumerate(weights)]
    return [sum(b * sp.Rational(str(pt[d])) for b, pt in zip(basis, points)) / sum(basis) for d in range(len(points[0]))]


def test_bspline_to_sympy_and_latex_match_de_boor():
    points = [[0, 0], [1, 2], ["5/2", 3], [4, "1/2"], [5, 2]]
    knots = [0, 0, 0, "1/3", "1/2", 1, 1, 1]
    weights = [1, 2, "1/2", 1, 3]
    curve = BSplineCurve(points, knots, weights=weights)
    t = sp.Symbol("t")
    expr = curve.to_sympy()
    for value in [sp.Rational(k, 12) for k in range(13)]:
        assert list(expr.subs(t, value)) == _de_boor_sympy(points, knots, weights, value), value
    assert curve._repr_latex_() == f"$P(t) = {sp.latex(expr)}$"
