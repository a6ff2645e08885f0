"""Bad input of compose(): clear exactcagd errors; the exact domain test at its edges."""

from __future__ import annotations

import numpy as np
import pytest

from exactcagd import BezierCurve, BezierSurface, BSplineCurve, BSplineSurface, compose
from exactcagd.composition import compose_homogeneous
from exactcagd.composition.domain import check_inside, nonnegative_on_unit
from exactcagd.errors import DimensionError, DomainError, InputError, NotSupportedError, WeightError
from exactcagd.exact.bernstein import as_coefficients

SURFACE = BezierSurface([[[0, 0, 0], [0, 1, 1]], [[1, 0, 1], [1, 1, 0]]])


def test_dimension_error_for_space_curves():
    with pytest.raises(DimensionError):
        compose(SURFACE, BezierCurve([[0, 0, 0], [1, 1, 1]]))


def test_domain_error_names_the_side():
    with pytest.raises(DomainError, match=r"u\(t\) > 1"):
        compose(SURFACE, BezierCurve([[0, 0], ["11/10", "1/2"]]))
    with pytest.raises(DomainError, match=r"v\(t\) < 0"):
        compose(SURFACE, BezierCurve([[0, "1/2"], ["1/2", "-1"], [1, "1/2"]]))
    compose(SURFACE, BezierCurve([[0, "1/2"], ["1/2", "-1/2"], [1, "1/2"]]))  # touches v = 0 at t = 1/2


def test_allow_outside_composes_the_extension():
    curve = BezierCurve([[0, 0], ["3/2", "1/2"]])
    image = compose(SURFACE, curve, allow_outside=True)
    assert image.evaluate(1) == SURFACE.evaluate("3/2", "1/2", extrapolate=True)


def test_control_polygon_outside_but_curve_inside_is_accepted():
    # v(t) = 2t(1-t)*(-1/4)*... : control point v = -1/8 but the curve only touches v = 0 at ends
    curve = BezierCurve([[0, 0], ["1/2", "-1/8"], [1, 0]])
    with pytest.raises(DomainError):
        compose(SURFACE, curve)  # v(t) = -t(1-t)/4 < 0 inside: really outside
    inside = BezierCurve([["1/2", 0], [2, "1/2"], ["1/2", 1]])  # u(t) = 1/2 + 3t(1-t) <= 5/4: outside
    with pytest.raises(DomainError):
        compose(SURFACE, inside)
    ok = BezierCurve([["1/2", "1/2"], ["-1/10", "1/2"], ["1/2", "1/2"], ["1/2", "1/2"]])  # u = 1/2 - 9/5 t(1-t)^2 >= 0.233
    compose(SURFACE, ok)


def test_tangent_to_the_boundary_from_inside_is_inside():
    # u(t) = (1 - 2t)^2 touches u = 0 at t = 1/2 (double root): inside
    touching = BezierCurve([[1, 0], [-1, "1/2"], [1, 1]])
    assert nonnegative_on_unit(as_coefficients([1, -1, 1]))[0]
    compose(SURFACE, touching)


def test_exact_witness_is_an_odd_root():
    ok, witness = nonnegative_on_unit(as_coefficients([1, -2, 1]))  # 1 - 6t + 6t^2
    assert not ok and str(witness).startswith("root of 6*t^2 - 6*t + 1")


def test_weight_error_when_the_curve_weight_vanishes():
    hom = np.array([[0, 0, 1], [0, 0, -3], [1, 1, 1]], dtype=object)
    from gmpy2 import mpq

    hom = np.vectorize(mpq, otypes=[object])(hom)
    curve = BezierCurve.from_homogeneous(hom)
    with pytest.raises(WeightError, match="vanishes"):
        compose(SURFACE, curve)


def test_negative_weights_of_constant_sign_are_fine():
    from gmpy2 import mpq

    hom = np.vectorize(mpq, otypes=[object])(np.array([[0, 0, -1], [-1, -1, -2]], dtype=object))
    curve = BezierCurve.from_homogeneous(hom)  # points (0, 0), (1/2, 1/2), weights -1, -2
    image = compose(SURFACE, curve)
    assert image.evaluate(1) == SURFACE.evaluate("1/2", "1/2")


def test_surface_with_a_pole_on_the_curve():
    from gmpy2 import mpq

    hom = np.empty((2, 2, 2), dtype=object)
    values = [[[0, 1], [0, 1]], [[1, -1], [1, -1]]]  # weight 1 - 2u vanishes at u = 1/2
    for i in range(2):
        for j in range(2):
            hom[i, j] = [mpq(x) for x in values[i][j]]
    surface = BezierSurface.from_homogeneous(hom)
    with pytest.raises(WeightError):
        compose(surface, BezierCurve([[0, 0], [1, 1]]))


def test_zero_bernstein_weight_is_reported_and_homogeneous_form_available():
    # Positive surface weights, a curve inside [0,1]^2 whose control point u = 3/2 lies outside:
    # the weight blossom omega(0, 2) = 0 gives Omega_1 = 0.
    surface = BezierSurface([[[0, 0]], [[1, 0]], [[2, 0]]], [[2], [1], [2]])  # degree (2, 0)
    curve = BezierCurve([[0, "1/2"], [2, "1/2"], [0, "1/2"]])  # u(t) = 4t(1-t) <= 1
    with pytest.raises(WeightError, match="compose_homogeneous"):
        compose(surface, curve, shortcut=False)
    hom = compose_homogeneous(surface, curve)
    assert any(w == 0 for w in hom[:, -1])


def test_type_errors():
    with pytest.raises(InputError):
        compose("surface", BezierCurve([[0, 0], [1, 1]]))
    with pytest.raises(InputError):
        compose(SURFACE, [[0, 0], [1, 1]])
    with pytest.raises(InputError):
        compose(SURFACE, BezierCurve([[0, 0], [1, 1]]), method="magic")
    with pytest.raises(InputError):
        compose(SURFACE, BezierCurve([[0, 0], [1, 1]]), strategy="magic", shortcut=False)
    spline = BSplineCurve([[0, 0], ["1/2", 1], [1, 0]], [0, 0, 0, 1, 1, 1])
    with pytest.raises(NotSupportedError):
        compose(SURFACE, spline)
    bs = BSplineSurface([[[0, 0], [0, 1]], [[1, 0], [1, 1]]], [0, 0, 1, 1], [0, 0, 1, 1])
    with pytest.raises(NotSupportedError):
        compose(bs, BezierCurve([[0, 0], [1, 1]]))


def test_check_inside_custom_box():
    hom = BezierCurve([[1, 1], [2, 3]]).homogeneous()
    check_inside(hom, ((1, 2), (1, 3)))
    with pytest.raises(DomainError):
        check_inside(hom, ((1, 2), (1, 2)))
