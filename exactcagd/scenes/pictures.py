"""Pictures of scenes: the parameter domain on the left, the 3-D view on the right.

Surfaces are drawn as sampled wireframes, domain curves in the domain and (sampled
through the surface) in 3-D, exact result curves sampled from their exact control
data, approximations as separate coloured segments.
"""

from __future__ import annotations

import numpy as np

from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from ..numeric.sampling import sample_curve, sample_curve_on_surface, sample_surface

__all__ = ["draw", "close"]


def _figure():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(12, 5.5))
    return fig, fig.add_subplot(1, 2, 1), fig.add_subplot(1, 2, 2, projection="3d")


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
        elif isinstance(curve, BezierCurve):
            out.append((curve, (0.0, 1.0)))
    return out


def draw(product: dict, objects: dict, results: dict):
    """Build the matplotlib figure of a ``picture`` product."""
    fig, ax2, ax3 = _figure()
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
            curves = _curves_of(results[name])
            if curves:
                _draw_exact_curves(ax3, f"{name} (exact data)", curves)
    ax2.set_aspect("equal", adjustable="box")
    ax2.legend(loc="best", fontsize=8)
    ax3.legend(loc="upper left", fontsize=7)
    fig.tight_layout()
    return fig
