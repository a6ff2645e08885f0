"""The example scripts' pictures (issue 19): one legend entry per item, a surface in every
3-D view, labelled axes; the scene pictures' legends lie inside the saved figure."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import matplotlib
import pytest

matplotlib.use("Agg")
import matplotlib.figure  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"


def _load(name: str):
    sys.path.insert(0, str(EXAMPLES))
    spec = importlib.util.spec_from_file_location(f"example_{name}", EXAMPLES / f"{name}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def saved(monkeypatch):
    """Figures saved by the code under test (kept open for inspection, nothing written)."""
    figures, close = [], plt.close
    monkeypatch.setattr(matplotlib.figure.Figure, "savefig", lambda self, *a, **k: figures.append(self))
    monkeypatch.setattr(plt, "close", lambda *a, **k: None)
    yield figures
    close("all")


def _labels(ax) -> list[str]:
    legend = ax.get_legend()
    return [t.get_text() for t in legend.get_texts()] if legend else []


def test_yang_figure_has_a_legend_and_the_surface(saved, tmp_path):
    yang = _load("yang_tables")
    from exactcagd.curves_on_surfaces import approximate
    from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve

    surface, curve = analytic_surface(5, 5, "face"), closed_domain_curve(8)
    result = approximate(surface, curve, "1e-1", "parabola", angle_tol=1)
    yang.OUT = tmp_path
    yang.plot("face", "parabola", "1e-1", surface, curve, result)
    (fig,) = saved
    domain, space = fig.axes
    kinds = sorted(set(result.kinds))
    assert _labels(domain) == ["domain curve D(t)", *[f"{k} ({result.kinds.count(k)})" for k in kinds], "segment joints"]
    assert _labels(space) == ["surface S (wireframe)", *[f"image of {k} segments" for k in kinds]]
    assert (space.get_xlabel(), space.get_ylabel(), space.get_zlabel()) == ("x", "y", "z")
    assert space.collections, "the surface wireframe is drawn"


def test_lasser_figure_one_entry_per_curve_image_and_approximation(saved, tmp_path):
    lasser = _load("lasser_figures")
    lasser.draw_figure(4, lasser.Fraction(1, 50), tmp_path)
    (fig,) = saved
    domain, space = fig.axes
    assert _labels(domain) == ["K1(t)", "K2(t)"]
    labels = _labels(space)
    assert labels[-1] == "surface F(u, v) (iso-curves)" and len(labels) == 5
    assert [lab.split(" ")[0] for lab in labels[:4]] == ["F(K1(t))", "G1", "F(K2(t))", "G1"]
    assert (space.get_xlabel(), space.get_ylabel(), space.get_zlabel()) == ("x", "y", "z")


def test_scene_picture_legends_lie_inside_the_figure():
    from exactcagd.scenes import pictures
    from exactcagd.scenes.runner import Runner
    from exactcagd.scenes.spec import load_scene

    runner = Runner(load_scene(EXAMPLES / "scenes" / "hill_trim.toml"), Path("/nonexistent-out"), use_cache=False)
    product = next(p for p in runner.scene.products if p["name"] == "overview")
    names = [n for n in product["of"] if n not in runner.objects]
    results = {}
    for p in runner.scene.products:
        if p.get("name") in names:
            from exactcagd.scenes.products import compute

            results[p["name"]] = compute(p, runner, results)[0]
    fig = pictures.draw(product, runner.objects, results, {p["name"]: p for p in runner.scene.products})
    fig.canvas.draw()
    box = fig.bbox
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    assert len(legends) == 2
    for legend in legends:
        extent = legend.get_window_extent()
        assert box.x0 <= extent.x0 and extent.x1 <= box.x1 and box.y0 <= extent.y0 and extent.y1 <= box.y1
    pictures.close(fig)
