"""Free-form deformation (Lasser & Bonneau section VII; Sederberg's notes chapter 14)."""

from __future__ import annotations

from fractions import Fraction as Fr

import numpy as np
import pytest
from test_composition_reference import same_as_reference

from exactcagd import BezierCurve, BezierSurface, BSplineCurve
from exactcagd.composition import ffd
from exactcagd.composition.ffd import identity_lattice
from exactcagd.composition.paper_examples import figure9
from exactcagd.errors import DimensionError, DomainError, InputError


def test_identity_lattice_is_identity_14_3():
    """(14.3): undisplaced lattice with unit weights -> FFD is the identity."""
    region = ((Fr(-1), Fr(2)), (Fr(3), Fr(5)))
    lattice = identity_lattice(3, 2, region)
    curve = BezierCurve([[0, Fr(5, 2)], [Fr(5, 2), 3], [1, Fr(9, 2)]], weights=[1, 2, 1])
    image = ffd(lattice, curve, region)
    assert image.degree == 2 * 5
    assert image.reduce().same_curve(curve)


def test_figure9_degrees():
    """Section VII: iso lines -> quintic, general lines -> degree 10 (printed: 20), quadratics -> 20."""
    fig = figure9()
    lattice = fig["surface"]
    expected = [5, 5, 10, 20, 20, 5]
    images = ffd(lattice, fig["curves"])
    assert [c.degree for c in images] == expected
    assert [c.true_degree() for c in images] == expected
    general = [ffd(lattice, c, shortcut=False) for c in fig["curves"]]
    assert [c.degree for c in general] == [10, 10, 10, 20, 20, 10]
    assert [c.true_degree() for c in general] == expected
    for curve, image in zip(fig["curves"], images):
        assert same_as_reference(image, lattice, curve)


def test_figure9_boundary_stays_closed():
    fig = figure9()
    images = ffd(fig["surface"], fig["curves"])
    for a, b in zip(images, images[1:] + images[:1]):
        assert a.evaluate(1) == b.evaluate(0)


def test_notes_14_0_1_deformed_vertical_line():
    """A vertical line s = 0.6 maps to the degree-n curve with control points H_j(0.6)."""
    rng = np.random.default_rng(5)
    net = [[[Fr(i, 3) + Fr(int(rng.integers(-5, 6)), 50), Fr(j, 2) + Fr(int(rng.integers(-5, 6)), 50)] for j in range(3)] for i in range(4)]
    lattice = BezierSurface(net)  # m = 3 columns in s (degree 3), n = 2 rows in t (degree 2)
    line = BezierCurve([[Fr(3, 5), 0], [Fr(3, 5), 1]])
    image = ffd(lattice, line)
    rows = [BezierCurve([net[i][j] for i in range(4)]) for j in range(3)]  # H_j(s), control points P_0j..P_3j
    assert image.degree == 2
    assert list(image.control_points) == [rows[j].evaluate(Fr(3, 5)) for j in range(3)]


def test_rational_lattice_and_bspline_shape():
    lattice = BezierSurface([[[i, j + (i * j) % 2] for j in range(3)] for i in range(3)], [[1, 2, 1], [1, 3, 1], [2, 1, 1]])
    shape = BSplineCurve([[Fr(1, 10), Fr(1, 10)], [Fr(9, 10), Fr(1, 5)], [Fr(1, 2), Fr(9, 10)], [Fr(1, 5), Fr(3, 5)]], [0, 0, 0, Fr(1, 2), 1, 1, 1])
    result = ffd(lattice, shape)
    assert len(result.pieces) == 2 and all(p.curve.is_rational and p.exact for p in result.pieces)
    for t in (Fr(1, 7), Fr(1, 2), Fr(5, 6)):
        assert result.evaluate(t) == lattice.evaluate(*shape.evaluate(t))
    assert result.joints[0].measured == 1


def test_bad_input():
    lattice = identity_lattice(2, 2)
    with pytest.raises(DomainError):
        ffd(lattice, BezierCurve([[0, 0], [2, 2]]))
    with pytest.raises(DimensionError):
        ffd(lattice, BezierCurve([[0, 0, 0], [1, 1, 1]]))
    with pytest.raises(InputError):
        ffd(lattice, "circle")
    with pytest.raises(InputError):
        ffd("lattice", BezierCurve([[0, 0], [1, 1]]))
    with pytest.raises(DomainError):
        ffd(lattice, BezierCurve([[0, 0], [1, 1]]), region=((1, 1), (0, 0)))
