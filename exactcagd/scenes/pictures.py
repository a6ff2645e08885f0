"""Pictures of scenes: the parameter domain on the left, the 3-D view on the right.

Every item has one colour in every panel.  Surfaces are drawn as sampled wireframes,
domain curves solid in the domain and (float samples through the surface) dashed in 3-D,
exact result curves solid from their exact control data with their joints as dots,
approximations likewise (their domain segments dashed in the domain), exact intersection
points as numbered crosses in the domain (an inset zooms in where they crowd) and lifted
through the surface in 3-D.  When the picture shows an
approximation, a third panel plots its true distance to the exact image ``S(D(t))``
(closest-point refinement, float64) under the certified bound (exact, from the product)
and the requested tolerance, with the joints marked.
"""

from __future__ import annotations

import numpy as np

from ..exact.scalars import to_rational
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from ..numeric.sampling import sample_curve, sample_curve_on_surface, sample_points_on_surface, sample_surface

__all__ = ["draw", "close"]


def _figure(error_panel: bool = False):
    from ..plotting import pyplot

    plt = pyplot(headless=True)

    columns = 3 if error_panel else 2
    fig = plt.figure(figsize=(6 * columns, 7.3), layout="constrained")
    # a row of its own under the panels for the legends, so no legend is cut off or covers data
    grid = fig.add_gridspec(2, columns, height_ratios=[6.0, 0.9])
    axes = [fig.add_subplot(grid[0, 0]), fig.add_subplot(grid[0, 1], projection="3d")]
    if error_panel:
        axes.append(fig.add_subplot(grid[0, 2]))
    for column in range(columns):  # legend holders, after the panels in fig.axes
        fig.add_subplot(grid[1, column]).axis("off")
    return fig, axes


def close(fig) -> None:
    import matplotlib.pyplot as plt

    plt.close(fig)


def _surface_domain(surface):
    if isinstance(surface, BezierSurface):
        return (0.0, 1.0), (0.0, 1.0)
    (u0, u1), (v0, v1) = surface.domain
    return (float(u0), float(u1)), (float(v0), float(v1))


def _draw_surface(ax2, ax3, name, surface, lines: int = 24) -> None:
    (u0, u1), (v0, v1) = _surface_domain(surface)
    us, vs = np.linspace(u0, u1, lines), np.linspace(v0, v1, lines)
    fine_u, fine_v = np.linspace(u0, u1, 4 * lines), np.linspace(v0, v1, 4 * lines)
    for u in us:
        pts = sample_surface(surface, np.array([u]), fine_v)[0]
        ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2] if pts.shape[1] > 2 else 0 * pts[:, 0], color="0.75", lw=0.5)
    for v in vs:
        pts = sample_surface(surface, fine_u, np.array([v]))[:, 0]
        ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2] if pts.shape[1] > 2 else 0 * pts[:, 0], color="0.75", lw=0.5)
    if isinstance(surface, BSplineSurface):
        bu, bv = surface.breakpoints()
        if len(bu) * len(bv) <= 4000:
            for k in bu:
                ax2.axvline(float(k), color="0.85", lw=0.5)
            for k in bv:
                ax2.axhline(float(k), color="0.85", lw=0.5)
    ax2.set_xlim(u0, u1)
    ax2.set_ylim(v0, v1)
    ax3.plot([], [], color="0.75", label=f"surface {name}")


def _xyz(pts: np.ndarray):
    """Coordinates for a 3-D plot (planar points are drawn at z = 0)."""
    return pts[:, 0], pts[:, 1], pts[:, 2] if pts.shape[1] > 2 else 0 * pts[:, 0]


def _draw_exact_curves(ax3, label, curves, color) -> None:
    """Exact result pieces in one colour and one legend entry; joints as small dots."""
    for i, (curve, (s0, s1)) in enumerate(curves):
        pts = sample_curve(curve, np.linspace(s0, s1, 200))
        ax3.plot(*_xyz(pts), color=color, lw=2.2, alpha=0.9, label=label if i == 0 else None)
        if len(curves) > 1:
            ax3.plot(*_xyz(pts[:1]), "o", color=color, ms=2.5)


def _curves_of(result) -> list:
    """``[(BezierCurve, (s0, s1))]``: exact result curves and the float parameter range to draw
    (a spline piece with an irrational end is drawn only over its exact interval)."""
    if isinstance(result, list):
        return [(c, (0.0, 1.0)) for c in result if isinstance(c, BezierCurve)]
    out = []
    for item in getattr(result, "pieces", None) or getattr(result, "segments", None) or []:
        curve = getattr(item, "curve", item)
        if hasattr(item, "local_interval"):
            s0, s1 = item.local_interval()
            out.append((curve, (float(s0), float(s1))))
        elif isinstance(curve, BezierCurve):  # curves over Q(sqrt D) are BezierCurves too
            out.append((curve, (0.0, 1.0)))
    return out


def _is_approximation(result) -> bool:
    return hasattr(result, "domain_segments") and hasattr(result, "distance_bound")


def _is_intersection_list(result) -> bool:
    return isinstance(result, list) and bool(result) and hasattr(result[0], "point")


def _intersection_points(result) -> np.ndarray:
    points = [item.point for item in result if getattr(item, "point", None) is not None]
    return np.array([[float(x), float(y)] for x, y in points]).reshape(-1, 2)


def _closest_pair_gap(xy: np.ndarray) -> float:
    if len(xy) < 2:
        return np.inf
    gaps = np.linalg.norm(xy[:, None, :] - xy[None, :, :], axis=2)
    return float(gaps[~np.eye(len(xy), dtype=bool)].min())


def _draw_intersections(ax2, ax3, name, result, color, lift) -> None:
    """Numbered markers in the domain, lifted through the surface in 3-D; an inset zooms
    in when two points are closer than 4% of the domain panel."""
    xy = _intersection_points(result)
    if not len(xy):
        return
    label = f"{name}: {len(xy)} exact intersection(s)"
    ax2.plot(xy[:, 0], xy[:, 1], "x", color=color, ms=9, mew=2, label=label, zorder=5)
    for k, (x, y) in enumerate(xy, start=1):
        ax2.annotate(str(k), (x, y), textcoords="offset points", xytext=(6, 6 if k % 2 else -12), fontsize=8, color=color)
    if lift is not None:
        ax3.plot(*_xyz(sample_points_on_surface(lift, xy)), "x", color=color, ms=8, mew=2, label=label)
    span = max(np.ptp(ax2.get_xlim()), np.ptp(ax2.get_ylim()))
    if _closest_pair_gap(xy) < 0.04 * span:
        _zoom_inset(ax2, xy, color)


def _zoom_inset(ax2, xy: np.ndarray, color) -> None:
    """An inset around the crowded points, in the panel corner farthest from them, redrawing
    every line of the domain panel."""
    centre = xy.mean(axis=0)
    half = max(np.ptp(xy, axis=0).max(), 1e-12) * 1.5
    (x0, x1), (y0, y1) = ax2.get_xlim(), ax2.get_ylim()
    right = centre[0] < 0.5 * (x0 + x1)
    top = centre[1] < 0.5 * (y0 + y1)
    inset = ax2.inset_axes([0.58 if right else 0.04, 0.58 if top else 0.04, 0.38, 0.38])
    for line in ax2.get_lines():
        inset.plot(line.get_xdata(), line.get_ydata(), line.get_linestyle(), color=line.get_color(), lw=line.get_linewidth(), marker=line.get_marker(), ms=line.get_markersize(), mew=line.get_markeredgewidth())
    for k, (x, y) in enumerate(xy, start=1):
        inset.annotate(str(k), (x, y), textcoords="offset points", xytext=(5, 5), fontsize=8, color=color)
    inset.set_xlim(centre[0] - half, centre[0] + half)
    inset.set_ylim(centre[1] - half, centre[1] + half)
    inset.tick_params(labelsize=6)
    inset.set_title("zoom", fontsize=7)
    ax2.indicate_inset_zoom(inset, edgecolor="0.4")


def _draw_domain_segments(ax2, name, result, color) -> None:
    """An approximation's domain segments, dashed in its colour, joints as dots."""
    for k, curve in enumerate(result.domain_segments):
        pts = sample_curve(curve, np.linspace(0.0, 1.0, 60))
        ax2.plot(pts[:, 0], pts[:, 1], "--", lw=1.2, color=color, label=f"{name}: domain segments" if k == 0 else None)
        ax2.plot(pts[:1, 0], pts[:1, 1], "o", color=color, ms=2.5)


#: Distances below this are float64 noise on curves of unit size; they are drawn on this line.
ERROR_FLOOR = 1e-16


def approximation_error_profile(result, surface, curve, samples: int = 400):
    """True distance of each approximation segment to the exact image ``S(D(t))``.

    Each sampled point of a segment is measured against the image by closest-point
    refinement (:func:`exactcagd.numeric.closest_point.distance_to_curve_on_surface`),
    so a segment that *is* a piece of the image measures at float64 noise, and one offset
    by ``e`` measures at ``e``: there is no sampling floor.

    Returns
    -------
    parameters : ndarray
        Parameter ``t`` of the domain curve ``D`` at each sample's closest point, so
        approximations of one curve share the horizontal axis.
    distances : ndarray
        The distances, same length.
    joints : ndarray
        The parameters of the closest points to the segments' inner joints.
    """
    from ..numeric.closest_point import distance_to_curve_on_surface

    per_segment = max(16, samples // max(1, len(result.segments)))
    local = np.linspace(0.0, 1.0, per_segment)
    points = np.concatenate([sample_curve(segment, local) for segment in result.segments])
    distances, parameters = distance_to_curve_on_surface(surface, curve, points)
    joints = parameters[per_segment::per_segment]  # the first sample of every later segment
    return parameters, distances, joints


def _tolerance(spec: dict):
    """The tolerance a scene asked of an approximation, as a float (None when absent)."""
    return None if spec.get("tol") is None else float(to_rational(spec["tol"]))


def _draw_error(axe, name, result, surface, curve, samples: int, color, tol=None) -> None:
    """Log plot of the true distance against the domain curve's parameter, with the
    certified bound, the tolerance and the joints (short ticks at the bottom)."""
    ts, distances, joints = approximation_error_profile(result, surface, curve, samples)
    axe.semilogy(ts, np.maximum(distances, ERROR_FLOOR), lw=1.2, color=color, label=f"{name}: distance to exact image")
    axe.axhline(float(result.distance_bound), color=color, ls=":", lw=1.5, label=f"{name}: certified bound {float(result.distance_bound):.2g}")
    if tol is not None:
        axe.axhline(float(tol), color=color, ls="--", lw=0.8, alpha=0.6, label=f"{name}: tolerance {float(tol):.2g}")
    if len(joints):
        axe.plot(joints, np.full(len(joints), ERROR_FLOOR), "|", color=color, ms=10, mew=1.5, label=f"{name}: joints ({len(joints)})")


def _finish_error_panel(axe) -> None:
    axe.axhline(ERROR_FLOOR, color="0.6", lw=0.6, ls="-.", label="float64 resolution (smaller distances drawn here)")
    axe.set_xlabel("parameter t of the domain curve")
    axe.set_ylabel("distance to the exact image S(D(t))")
    axe.set_title("approximation error (true distance, log scale)")
    lines = [line.get_ydata() for line in axe.get_lines()]
    top = max(float(np.max(y)) for y in lines if len(y))
    axe.set_ylim(ERROR_FLOOR / 10, top * 10)  # the bound and tolerance lines inside, not on the frame


class _Colours:
    """One colour per item, the same in every panel (grey is kept for surfaces)."""

    def __init__(self):
        self._given: dict = {}

    def __call__(self, name: str) -> str:
        if name not in self._given:
            self._given[name] = f"C{[0, 1, 2, 3, 4, 5, 6, 8, 9][len(self._given) % 9]}"
        return self._given[name]


def _label_axes(ax2, ax3) -> None:
    ax2.set_xlabel("u")
    ax2.set_ylabel("v")
    ax3.set_xlabel("x")
    ax3.set_ylabel("y")
    ax3.set_zlabel("z")
    ax3.set_box_aspect(None, zoom=0.88)  # room for the z label, which matplotlib clips otherwise


def draw(product: dict, objects: dict, results: dict, specs: dict | None = None):
    """Build the matplotlib figure of a ``picture`` product.

    Every item of ``product["of"]`` gets one colour, used in every panel, and one
    legend entry per panel it appears in.  ``specs`` maps product names to their
    scene entries (to find the surface and curve of an approximation for the error
    panel).
    """
    specs = specs or {}
    colours = _Colours()
    approximations = [n for n in product["of"] if _is_approximation(results.get(n)) and n in specs]
    fig, axes = _figure(error_panel=bool(approximations))
    ax2, ax3 = axes[0], axes[1]
    ax2.set_title("parameter domain")
    ax3.set_title(product.get("title", product["name"]))
    names = product["of"]
    surfaces = [n for n in names if isinstance(objects.get(n), (BezierSurface, BSplineSurface))]
    for name in surfaces:
        _draw_surface(ax2, ax3, name, objects[name])
    lift = objects[surfaces[0]] if len(surfaces) == 1 else None
    samples = product.get("samples", 400)
    intersections = []
    exact_images = {(specs[n].get("surface"), specs[n].get("curve")) for n in names if n in specs and n in results}
    for name in names:
        obj = objects.get(name)
        if isinstance(obj, (BezierCurve, BSplineCurve)):
            colour = colours(name)
            lo, hi = (0.0, 1.0) if isinstance(obj, BezierCurve) else (float(obj.domain[0]), float(obj.domain[1]))
            pts = sample_curve(obj, np.linspace(lo, hi, samples))
            if obj.dimension == 2:
                ax2.plot(pts[:, 0], pts[:, 1], lw=1.5, color=colour, label=name)
                for s in surfaces:
                    if (s, name) in exact_images:
                        continue  # its exact image is drawn; a sampled copy would hide under it
                    img = sample_curve_on_surface(objects[s], obj, samples)
                    ax3.plot(*_xyz(img), "--", color=colour, lw=1, label=f"{name} on {s} (float samples)")
            else:
                ax3.plot(*_xyz(pts), lw=1.5, color=colour, label=name)
        elif name in results:
            result = results[name]
            if _is_intersection_list(result):
                intersections.append(name)  # drawn last, so an inset shows every curve
                continue
            colour = colours(name)
            if _is_approximation(result):
                _draw_domain_segments(ax2, name, result, colour)
            curves = _curves_of(result)
            if curves:
                kind = "segments" if _is_approximation(result) else "exact pieces"
                _draw_exact_curves(ax3, f"{name} ({len(curves)} {kind})", curves, colour)
    for name in intersections:
        _draw_intersections(ax2, ax3, name, results[name], colours(name), lift)
    for name in approximations:
        spec = specs[name]
        _draw_error(axes[2], name, results[name], objects[spec["surface"]], objects[spec["curve"]], samples, colours(name), _tolerance(spec))
    if approximations:
        _finish_error_panel(axes[2])
    _label_axes(ax2, ax3)
    ax2.set_aspect("equal", adjustable="box")
    holders = fig.axes[len(axes):len(axes) * 2]
    for ax, holder in zip(axes, holders):  # each panel's legend in the row below it
        handles, labels = ax.get_legend_handles_labels()
        if handles:
            holder.legend(handles, labels, loc="upper center", fontsize=7.5, ncol=2, frameon=False)
    return fig
