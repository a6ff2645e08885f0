"""Quick pictures of exact objects and results for notebooks: ``obj.plot(ax=None)``.

Curves (Bézier, B-spline, NURBS) are drawn with their control polygon; surfaces as a light
wireframe in 3-D; results (exact image curves, approximations, intersections) as one
legend entry each.  Drawing uses float samples (:mod:`exactcagd.numeric.sampling`); the
objects themselves stay exact.  Needs matplotlib (``pip install 'exactcagd[plots]'``).

>>> import matplotlib
>>> matplotlib.use("Agg")
>>> from exactcagd import BezierCurve
>>> ax = BezierCurve([[0, 0], ["1/2", 2], [2, 0]]).plot()
>>> [line.get_label() for line in ax.get_lines()]
['curve', 'control polygon']
>>> ax.get_xlabel(), ax.get_ylabel()
('x', 'y')
"""

from __future__ import annotations

import numpy as np

from .errors import NotSupportedError
from .geometry.bezier_curve import BezierCurve
from .geometry.bezier_surface import BezierSurface
from .geometry.bspline import BSplineCurve, BSplineSurface
from .numeric.sampling import parameter_domain, sample_curve, sample_surface

__all__ = ["plot", "axes_for", "pyplot"]


def pyplot(headless: bool = False):
    """``matplotlib.pyplot``, or a clear error naming the ``plots`` extra when it is missing.

    The one place exactcagd imports matplotlib (pictures, conformance plots, ``.plot()``);
    ``headless=True`` selects the Agg backend first, for code that only writes files.
    """
    try:
        import matplotlib

        if headless:
            matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as exc:  # pragma: no cover - depends on the installation
        raise NotSupportedError("plots need matplotlib, an optional extra: pip install 'exactcagd[plots]'") from exc
    return plt


def axes_for(dimension: int, ax=None):
    """``ax`` if given, else new axes: 3-D with labelled x, y, z for ``dimension == 3``."""
    if ax is not None:
        return ax
    plt = pyplot()
    fig = plt.figure(figsize=(5.5, 4.5))
    if dimension == 3:
        ax = fig.add_subplot(projection="3d")
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_zlabel("z")
    else:
        ax = fig.add_subplot()
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.set_aspect("equal")
    return ax


def _coords(points: np.ndarray):
    return [points[:, k] for k in range(points.shape[1])]


def _curve(curve, ax, label="curve", color=None, polygon=True, samples=300, **style):
    lo, hi = parameter_domain(curve)
    points = sample_curve(curve, np.linspace(lo, hi, samples))
    ax = axes_for(curve.dimension, ax)
    (line,) = ax.plot(*_coords(points), color=color, label=label, **style)
    if polygon:
        net = np.array([[float(x) for x in p] for p in curve.control_points])
        ax.plot(*_coords(net), "o--", color=line.get_color(), alpha=0.45, lw=0.8, ms=3, label="control polygon")
    return ax


def _surface(surface, ax, label="surface", color="0.6", lines=17, **style):
    ax = axes_for(3, ax)
    if isinstance(surface, BezierSurface):
        (u0, u1), (v0, v1) = (0.0, 1.0), (0.0, 1.0)
    else:
        (u0, u1), (v0, v1) = ((float(a), float(b)) for a, b in surface.domain)
    grid = sample_surface(surface, np.linspace(u0, u1, lines), np.linspace(v0, v1, lines))
    ax.plot_wireframe(grid[..., 0], grid[..., 1], grid[..., 2], color=color, lw=0.5, **style)
    ax.plot([], [], color=color, lw=0.5, label=label)
    return ax


def _result(result, ax, label=None, color=None, **style):
    from .scenes.pictures import _curves_of, _intersection_points, _is_intersection_list

    if _is_intersection_list(result) or getattr(result, "overlaps", None) is not None:
        xy = _intersection_points(list(result))
        ax = axes_for(2, ax)
        ax.plot(xy[:, 0], xy[:, 1], "x", color=color, ms=8, mew=2, label=label or f"{len(xy)} intersection(s)")
        for k, (x, y) in enumerate(xy, start=1):
            ax.annotate(str(k), (x, y), textcoords="offset points", xytext=(4, 4), fontsize=8)
        return ax
    curves = _curves_of(result)
    if not curves:
        raise NotSupportedError(f"nothing to plot in a {type(result).__name__}")
    dimension = max(getattr(c, "dimension", 3) for c, _ in curves)
    ax = axes_for(dimension, ax)
    bound = getattr(result, "distance_bound", None)
    label = label or (f"{len(curves)} piece(s)" + (f", bound {float(bound):.2g}" if bound is not None else ""))
    for k, (curve, (s0, s1)) in enumerate(curves):
        points = sample_curve(curve, np.linspace(s0, s1, 120)) if not getattr(curve, "radicand", None) else _field_points(curve)
        (line,) = ax.plot(*_coords(points), color=color, label=label if k == 0 else None, **style)
        color = line.get_color()  # one colour and one legend entry for all pieces
    return ax


def _field_points(curve, samples: int = 120) -> np.ndarray:
    """Float points of a curve over Q(sqrt D) (approximation segments): its float companion."""
    points, weights = curve.to_float()
    float_curve = BezierCurve([[float(x) for x in p] for p in points], weights=[float(w) for w in weights])
    return sample_curve(float_curve, np.linspace(0.0, 1.0, samples))


def plot(obj, ax=None, **style):
    """Draw an exact object or result on ``ax`` (new axes when ``None``) and return the axes.

    Parameters
    ----------
    obj : BezierCurve, BSplineCurve, BezierSurface, BSplineSurface, or a result
        Results: an image curve (``compose``, ``compose_spline``), an approximation
        (``approximate``, ``approximate_cubic``), a list of intersections.
    ax : matplotlib axes, optional
        2-D axes for planar curves and intersections, 3-D axes otherwise.
    **style
        Passed to matplotlib (``color``, ``label``, ``lw``, ...); ``polygon=False`` hides a
        curve's control polygon.
    """
    if isinstance(obj, (BezierCurve, BSplineCurve)) and not getattr(obj, "radicand", None):
        ax = _curve(obj, ax, **style)
    elif isinstance(obj, (BezierSurface, BSplineSurface)):
        ax = _surface(obj, ax, **style)
    else:
        ax = _result(obj, ax, **style)
    ax.legend(fontsize=8, loc="best")
    return ax
