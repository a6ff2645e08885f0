"""The approximation error panel plots the true distance to the exact image (issue 19).

References are independent of the plotting code: the exact image comes from exact
composition (Lasser & Bonneau) and exact subdivision, and the planted offset is a
translation perpendicular to the plane that holds the image, whose distance is known
in closed form.
"""

from types import SimpleNamespace

import numpy as np
import pytest

from exactcagd import BezierCurve, BezierSurface
from exactcagd.composition import compose
from exactcagd.scenes.pictures import ERROR_FLOOR, approximation_error_profile

pytest.importorskip("matplotlib")

DOMAIN = BezierCurve([["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "-1/10"], ["9/10", "4/5"]])


def _curved_surface() -> BezierSurface:
    net = [[[i, j, (i * (3 - i) + j * j - 2 * i * j) % 5] for j in range(4)] for i in range(4)]
    return BezierSurface(net, weights=[[1, 2, 1, 3], [2, 1, 1, 1], [1, 1, 2, 1], [3, 1, 1, 2]])


def _pieces(curve: BezierCurve, cuts) -> list:
    """Exact sub-curves of ``curve`` between consecutive parameters in ``cuts``."""
    pieces, rest, start = [], curve, 0
    from fractions import Fraction

    for cut in cuts:
        local = Fraction(cut - start) / Fraction(1 - start)
        left, rest = rest.subdivide(local)
        pieces.append(left)
        start = cut
    return pieces + [rest]


def test_exact_sub_curves_plot_at_float_noise():
    surface = _curved_surface()
    image = compose(surface, DOMAIN)
    from fractions import Fraction

    segments = _pieces(image, [Fraction(1, 3), Fraction(1, 2), Fraction(4, 5)])
    result = SimpleNamespace(segments=segments, distance_bound=Fraction(0))
    _, distances, joints = approximation_error_profile(result, surface, DOMAIN, samples=200)
    scale = max(np.abs(np.array([[float(x) for x in p] for p in image.points_array()])).max(), 1.0)
    assert distances.max() < 1e-13 * scale  # the old sampled panel drew ~1e-4 here
    assert len(distances) >= 200
    assert np.allclose(joints, [1 / 3, 1 / 2, 4 / 5], atol=1e-12)  # compose keeps D's parameter


@pytest.mark.parametrize("offset", [1e-6, 1e-9])
def test_planted_offset_plots_at_its_size(offset):
    plane = BezierSurface([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 0]]])
    image = compose(plane, DOMAIN)  # lies in z = 0
    shifted = [[x, y, z + offset] for x, y, z in (tuple(float(c) for c in p) for p in image.points_array())]
    result = SimpleNamespace(segments=[BezierCurve(shifted)], distance_bound=offset)
    _, distances, _ = approximation_error_profile(result, plane, DOMAIN, samples=300)
    assert np.all(np.abs(distances - offset) <= 0.01 * offset)


def test_floor_is_below_any_meaningful_distance():
    assert ERROR_FLOOR <= 1e-15
