"""Scene pictures show every item distinctly (issue 19): one colour and one legend entry per
item in each panel it appears in, every approximation in the error and domain panels,
intersections in 3-D, labelled axes."""

import matplotlib

matplotlib.use("Agg")

import pytest

from exactcagd import BezierCurve, BezierSurface
from exactcagd.algebra import intersect
from exactcagd.curves_on_surfaces import approximate
from exactcagd.scenes import pictures

SURFACE = BezierSurface([[[i, j, (i * j) % 3] for j in range(3)] for i in range(3)])
TRIM = BezierCurve([["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "-1/10"], ["9/10", "4/5"]])
LOOP = BezierCurve([["1/5", "3/5"], ["9/10", "1/10"], ["9/10", "9/10"], ["1/5", "2/5"]], weights=[1, "1/2", "1/2", 1])


@pytest.fixture(scope="module")
def figure():
    objects = {"s": SURFACE, "trim": TRIM, "loop": LOOP}
    results = {
        "x": intersect(TRIM, LOOP),
        "coarse": approximate(SURFACE, TRIM, "1/100"),
        "fine": approximate(SURFACE, TRIM, "1/10000"),
    }
    specs = {
        "coarse": {"name": "coarse", "kind": "approximation", "surface": "s", "curve": "trim", "tol": "1/100"},
        "fine": {"name": "fine", "kind": "approximation", "surface": "s", "curve": "trim", "tol": "1/10000"},
    }
    product = {"name": "pic", "kind": "picture", "of": ["s", "trim", "loop", "x", "coarse", "fine"]}
    fig = pictures.draw(product, objects, results, specs)
    yield fig
    pictures.close(fig)


def _labels(ax):
    return ax.get_legend_handles_labels()[1]


def test_one_legend_entry_per_item_and_panel(figure):
    domain, space, error = figure.axes[:3]
    for ax in (domain, space):
        labels = _labels(ax)
        assert len(labels) == len(set(labels)), labels
    assert {"trim", "loop"} <= set(_labels(domain))
    assert sum("x:" in label for label in _labels(domain)) == 1
    assert sum("x:" in label for label in _labels(space)) == 1  # intersections lifted into 3-D


def test_every_approximation_in_every_panel(figure):
    domain, space, error = figure.axes[:3]
    for name in ("coarse", "fine"):
        for ax in (domain, space, error):
            assert any(label.startswith(name) for label in _labels(ax)), (name, _labels(ax))


def test_colours_distinct_and_consistent(figure):
    domain, space, error = figure.axes[:3]

    def colour_of(ax, prefix):
        handles, labels = ax.get_legend_handles_labels()
        return {matplotlib.colors.to_hex(h.get_color()) for h, label in zip(handles, labels) if label.startswith(prefix)}

    assert colour_of(domain, "coarse") == colour_of(space, "coarse") == colour_of(error, "coarse: distance")
    assert colour_of(domain, "coarse").isdisjoint(colour_of(domain, "fine"))
    assert colour_of(domain, "trim").isdisjoint(colour_of(domain, "loop"))


def test_axes_labelled(figure):
    domain, space = figure.axes[:2]
    assert (domain.get_xlabel(), domain.get_ylabel()) == ("u", "v")
    assert (space.get_xlabel(), space.get_ylabel(), space.get_zlabel()) == ("x", "y", "z")
