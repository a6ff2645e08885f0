"""Pictures of scenes: the parameter domain on the left, the 3-D view on the right.

Surfaces are drawn as sampled wireframes, domain curves in the domain and (sampled
through the surface) in 3-D, exact result curves sampled from their exact control
data, approximations as separate coloured segments (their domain curves dashed in the
domain), exact intersection points as markers.  When the picture shows an
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
from ..numeric.sampling import sample_curve, sample_curve_on_surface, sample_surface

__all__ = ["draw", "close"]


def _figure(error_panel: bool = False):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    columns = 3 if error_panel else 2
    fig = plt.figure(figsize=(6 * columns, 5.5))
    axes = [fig.add_subplot(1, columns, 1), fig.add_subplot(1, columns, 2, projection="3d")]
    if error_panel:
        axes.append(fig.add_subplot(1, columns, 3))
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


def _draw_exact_curves(ax3, label, curves, color=None) -> None:
    first = True
    for i, (curve, (s0, s1)) in enumerate(curves):
        pts = sample_curve(curve, np.linspace(s0, s1, 200))
        c = color or f"C{i % 10}"
        ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2] if pts.shape[1] > 2 else 0 * pts[:, 0], color=c, lw=2, label=label if first else None)
        first = False


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


def _draw_intersections(ax2, name, result) -> None:
    points = [item.point for item in result if getattr(item, "point", None) is not None]
    if points:
        xy = np.array([[float(x), float(y)] for x, y in points])
        ax2.plot(xy[:, 0], xy[:, 1], "kx", ms=9, mew=2, label=f"{name} ({len(points)}, exact)")


def _draw_domain_segments(ax2, name, result) -> None:
    first = True
    for curve in result.domain_segments:
        pts = sample_curve(curve, np.linspace(0.0, 1.0, 60))
        ax2.plot(pts[:, 0], pts[:, 1], "--", lw=1, color="C3", label=f"{name} domain" if first else None)
        first = False


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
    positions : ndarray
        Segment index plus local parameter (``k + s``, ``s`` in [0, 1]).
    distances : ndarray
        The distances, same length.
    """
    from ..numeric.closest_point import distance_to_curve_on_surface

    per_segment = max(16, samples // max(1, len(result.segments)))
    local = np.linspace(0.0, 1.0, per_segment)
    positions, distances = [], []
    for k, segment in enumerate(result.segments):
        gaps, _ = distance_to_curve_on_surface(surface, curve, sample_curve(segment, local))
        positions.append(k + local)
        distances.append(gaps)
    return np.concatenate(positions), np.concatenate(distances)


def _tolerance(spec: dict):
    """The tolerance a scene asked of an approximation, as a float (None when absent)."""
    return None if spec.get("tol") is None else float(to_rational(spec["tol"]))


def _draw_error(axe, name, result, surface, curve, samples: int, color, tol=None) -> None:
    """Log plot of the true distance, with the certified bound, the tolerance and the joints."""
    positions, distances = approximation_error_profile(result, surface, curve, samples)
    axe.semilogy(positions, np.maximum(distances, ERROR_FLOOR), lw=1.2, color=color, label=f"{name}: distance to exact image")
    axe.axhline(float(result.distance_bound), color=color, ls=":", lw=1.5, label=f"{name}: certified bound {float(result.distance_bound):.2g}")
    if tol is not None:
        axe.axhline(float(tol), color=color, ls="--", lw=0.8, alpha=0.6, label=f"{name}: tolerance {float(tol):.2g}")
    for joint in range(1, len(result.segments)):
        axe.axvline(joint, color="0.8", lw=0.6, zorder=0)
    axe.axhline(ERROR_FLOOR, color="0.6", lw=0.6, ls="-.", label="float64 resolution (distances below drawn here)")
    axe.set_xlabel("segment index + local parameter (grey lines: joints)")
    axe.set_ylabel("distance to the exact image S(D(t))")


def draw(product: dict, objects: dict, results: dict, specs: dict | None = None):
    """Build the matplotlib figure of a ``picture`` product.

    ``specs`` maps product names to their scene entries (to find the surface and
    curve of an approximation for the error panel).
    """
    specs = specs or {}
    approximations = [n for n in product["of"] if _is_approximation(results.get(n)) and n in specs]
    fig, axes = _figure(error_panel=bool(approximations))
    ax2, ax3 = axes[0], axes[1]
    ax2.set_title("parameter domain")
    ax3.set_title(product.get("title", product["name"]))
    names = product["of"]
    surfaces = [n for n in names if isinstance(objects.get(n), (BezierSurface, BSplineSurface))]
    for name in surfaces:
        _draw_surface(ax2, ax3, name, objects[name])
    samples = product.get("samples", 400)
    for name in names:
        obj = objects.get(name)
        if isinstance(obj, (BezierCurve, BSplineCurve)):
            lo, hi = (0.0, 1.0) if isinstance(obj, BezierCurve) else (float(obj.domain[0]), float(obj.domain[1]))
            pts = sample_curve(obj, np.linspace(lo, hi, samples))
            if obj.dimension == 2:
                ax2.plot(pts[:, 0], pts[:, 1], lw=1.5, label=name)
                for s in surfaces:
                    img = sample_curve_on_surface(objects[s], obj, samples)
                    ax3.plot(img[:, 0], img[:, 1], img[:, 2], "k--", lw=1, label=f"{name} on {s} (sampled)")
            else:
                ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2], lw=1.5, label=name)
        elif name in results:
            result = results[name]
            if isinstance(result, list) and result and hasattr(result[0], "point"):
                _draw_intersections(ax2, name, result)
                continue
            if _is_approximation(result):
                _draw_domain_segments(ax2, name, result)
            curves = _curves_of(result)
            if curves:
                label = f"{name} ({len(curves)} segments)" if _is_approximation(result) else f"{name} (exact data)"
                _draw_exact_curves(ax3, label, curves)
    for k, name in enumerate(approximations):
        spec = specs[name]
        _draw_error(axes[2], name, results[name], objects[spec["surface"]], objects[spec["curve"]], samples, f"C{3 + k}", _tolerance(spec))
    if approximations:
        axes[2].set_title("approximation error")
        axes[2].legend(loc="best", fontsize=7)
    ax2.set_aspect("equal", adjustable="box")
    ax2.legend(loc="best", fontsize=8)
    ax3.legend(loc="upper left", fontsize=7)
    fig.tight_layout()
    return fig
