"""The public names issues 2 and 3 promise to outside checks (keep them stable).

Issue 2: ``BezierCurve``, ``BezierSurface``, ``BSplineCurve``, ``BSplineSurface`` with their
methods, ``to_rational`` and the float policy, ``exactcagd.errors``.  Issue 3:
``exactcagd.compose(surface, curve)`` (and ``method="lasser"``) returning a ``BezierCurve``,
rational when any input is; ``BezierCurve.degree`` (stored) and ``true_degree()`` /
``reduce()`` (exact lowest degree).  Values are checked against sympy substitution.
"""

from __future__ import annotations

import inspect

import pytest
import sympy

import exactcagd
from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface, compose, errors

T, U, V = sympy.symbols("t u v")

API = {
    BezierCurve: ["degree", "dimension", "is_rational", "evaluate", "subdivide", "elevate", "derivative", "reparametrize", "to_sympy", "true_degree", "reduce", "blossom", "control_points", "weights"],
    BezierSurface: ["degree", "dimension", "is_rational", "evaluate", "iso_u", "iso_v", "subdivide_u", "subdivide_v", "derivative_u", "derivative_v", "elevate", "corner_normals", "to_sympy"],
    BSplineCurve: ["degree", "knots", "domain", "evaluate", "insert_knot", "to_bezier"],
    BSplineSurface: ["degree", "knots_u", "knots_v", "domain", "evaluate", "insert_knot_u", "insert_knot_v", "to_bezier_patches"],
}


@pytest.mark.parametrize("cls", list(API), ids=lambda c: c.__name__)
def test_public_methods_exist(cls):
    missing = [name for name in API[cls] if not hasattr(cls, name)]
    assert not missing


def test_top_level_names_and_error_family():
    for name in ["compose", "to_rational", "float_policy", "set_float_policy", "BezierCurve", "BezierSurface", "BSplineCurve", "BSplineSurface", "errors"]:
        assert name in exactcagd.__all__ and hasattr(exactcagd, name)
    for name in ["InputError", "InexactInputError", "WeightError", "KnotError", "DomainError", "DegreeError", "DimensionError", "NotSupportedError"]:
        assert issubclass(getattr(errors, name), errors.ExactCAGDError)
    params = inspect.signature(compose).parameters
    assert list(params)[:3] == ["surface", "curve", "method"] and params["method"].default == "fast"


@pytest.mark.parametrize("rs,rc", [(False, False), (False, True), (True, False), (True, True)])
def test_compose_public_contract(rs, rc):
    """Four combinations (Remark 3): BezierCurve, degree N(l+m), rational iff an input is, both routes equal sympy."""
    net = [[[0, 0, 1], [0, 1, 0], [0, 2, 1]], [[1, 0, 0], [1, 1, 2], [1, 2, 0]]]  # (l, m) = (1, 2)
    surface = BezierSurface(net, [[1, 2, 1], [3, 1, 2]] if rs else None)
    curve = BezierCurve([["1/5", "1/10"], ["4/5", "1/2"], ["1/3", 1]], [1, "5/2", 2] if rc else None)  # N = 2
    fast, lasser = compose(surface, curve), compose(surface, curve, method="lasser")
    assert isinstance(fast, BezierCurve) and fast == lasser
    assert fast.degree == 2 * (1 + 2) and fast.true_degree() == 6
    assert fast.is_rational == (rs or rc)
    sub = surface.to_sympy(U, V).subs({U: curve.to_sympy(T)[0], V: curve.to_sympy(T)[1]}, simultaneous=True)
    assert all(sympy.cancel(a - b) == 0 for a, b in zip(sub, fast.to_sympy(T)))


def test_true_degree_and_reduce_on_a_degree_raised_input():
    """compose on a degree-raised domain line: stored N(l+m), true degree and reduce() the lower one."""
    surface = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]])  # z = u v
    line = BezierCurve([[0, 1], [1, 0]]).elevate(2)  # stored N = 3, really a line
    image = compose(surface, line)
    assert image.degree == 3 * 2 and image.true_degree() == 2
    reduced = image.reduce()
    assert reduced.degree == 2
    expected = sympy.Matrix([T, 1 - T, sympy.expand(T * (1 - T))])
    assert sympy.expand(reduced.to_sympy(T) - expected) == sympy.zeros(3, 1)
