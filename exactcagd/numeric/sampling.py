"""Fast float64 sampling of curves and surfaces for pictures and previews.

No error bounds here (see :mod:`exactcagd.numeric.evaluation` for certified values):
this is the vectorized Cox-de Boor basis (notes 6.14) evaluated in floats for many
parameters at once, with Bézier objects treated as single-span B-splines.

>>> import numpy as np
>>> from exactcagd import BezierCurve
>>> from exactcagd.numeric.sampling import sample_curve
>>> sample_curve(BezierCurve([[0, 0], [2, 2]]), np.array([0.25]))
array([[0.5, 0.5]])
"""

from __future__ import annotations

import numpy as np

from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface

__all__ = ["basis_matrix", "sample_curve", "sample_surface", "sample_curve_on_surface", "parameter_domain"]


def _float_array(nested) -> np.ndarray:
    return np.vectorize(float, otypes=[float])(np.asarray(nested, dtype=object))


def basis_matrix(knots, degree: int, ts: np.ndarray) -> np.ndarray:
    """Matrix ``B[k, i] = N_{i,p}(ts[k])`` of all B-spline basis values (Cox-de Boor)."""
    U = np.array([float(k) for k in knots])
    n = len(U) - degree - 1
    ts = np.asarray(ts, dtype=float)
    lo, hi = U[degree], U[n]
    ts = np.clip(ts, lo, hi)
    span = np.searchsorted(U, ts, side="right") - 1
    # at the right end use the last non-empty span (an unclamped hi may be a repeated knot)
    span = np.where(ts == hi, np.searchsorted(U, hi, side="left") - 1, span)
    span = np.clip(span, degree, n - 1)
    # de Boor-Cox triangle for the p + 1 non-zero functions of each parameter
    N = np.zeros((len(ts), degree + 1))
    N[:, 0] = 1.0
    left = np.zeros((len(ts), degree + 1))
    right = np.zeros((len(ts), degree + 1))
    for j in range(1, degree + 1):
        left[:, j] = ts - U[span + 1 - j]
        right[:, j] = U[span + j] - ts
        saved = np.zeros(len(ts))
        for r in range(j):
            denom = right[:, r + 1] + left[:, j - r]
            temp = np.where(denom != 0, N[:, r] / np.where(denom != 0, denom, 1), 0.0)
            N[:, r] = saved + right[:, r + 1] * temp
            saved = left[:, j - r] * temp
        N[:, j] = saved
    B = np.zeros((len(ts), n))
    for r in range(degree + 1):
        B[np.arange(len(ts)), span - degree + r] = N[:, r]
    return B


def _bezier_knots(n: int) -> list:
    return [0] * (n + 1) + [1] * (n + 1)


def _curve_data(curve):
    if isinstance(curve, BezierCurve):
        return _bezier_knots(curve.degree), curve.degree, _float_array(curve.points_array()), _float_array(curve.weights_array())
    weights = curve.weights if curve.is_rational else [1] * len(curve.control_points)
    return curve.knots, curve.degree, _float_array(curve.control_points), _float_array(weights)


def parameter_domain(obj) -> tuple[float, float]:
    """Float parameter interval of a curve (Bézier: (0, 1))."""
    if isinstance(obj, BezierCurve):
        return 0.0, 1.0
    return float(obj.domain[0]), float(obj.domain[1])


def _curve_points(data, ts: np.ndarray) -> np.ndarray:
    """Points at ``ts`` of a curve given by its float data (:func:`_curve_data`)."""
    knots, p, pts, w = data
    B = basis_matrix(knots, p, ts) * w[None, :]
    return (B @ pts) / B.sum(axis=1)[:, None]


def sample_curve(curve, ts: np.ndarray) -> np.ndarray:
    """Points of a Bézier or B-spline (NURBS) curve at float parameters, shape (len(ts), d)."""
    return _curve_points(_curve_data(curve), ts)


def _surface_data(surface):
    """Knots, degrees and the homogeneous float net ``[w P, w]`` of a surface."""
    if isinstance(surface, BezierSurface):
        l, m = surface.degree
        ku, kv, degree = _bezier_knots(l), _bezier_knots(m), (l, m)
        net, w = _float_array(surface.net_array()), _float_array(surface.weights_array())
    else:
        ku, kv, degree = surface.knots_u, surface.knots_v, surface.degree
        net = _float_array(surface.control_net)
        w = _float_array(surface.weights) if surface.is_rational else np.ones(net.shape[:2])
    return ku, kv, degree, np.concatenate([net * w[..., None], w[..., None]], axis=-1)


def sample_surface(surface, us: np.ndarray, vs: np.ndarray) -> np.ndarray:
    """Grid of points ``S(us[i], vs[j])``, shape (len(us), len(vs), d)."""
    ku, kv, (p, q), hom = _surface_data(surface)
    values = np.einsum("ai,ijk,bj->abk", basis_matrix(ku, p, us), hom, basis_matrix(kv, q, vs))
    return values[..., :-1] / values[..., -1:]


def _surface_points(data, uv: np.ndarray) -> np.ndarray:
    """Points ``S(u_k, v_k)`` of a surface given by its float data (:func:`_surface_data`)."""
    ku, kv, (p, q), hom = data
    values = np.einsum("ai,ijk,aj->ak", basis_matrix(ku, p, uv[:, 0]), hom, basis_matrix(kv, q, uv[:, 1]))
    return values[:, :-1] / values[:, -1:]


def sample_points_on_surface(surface, uv: np.ndarray) -> np.ndarray:
    """Points ``S(u_k, v_k)`` for parameter pairs ``uv`` of shape (k, 2)."""
    return _surface_points(_surface_data(surface), uv)


def curve_on_surface_evaluator(surface, curve):
    """A function ``ts -> S(D(ts))`` (float points, shape (len(ts), d)) whose control data
    are converted to floats once, for callers that evaluate many times."""
    curve_data, surface_data = _curve_data(curve), _surface_data(surface)
    return lambda ts: _surface_points(surface_data, _curve_points(curve_data, ts))


def sample_curve_on_surface(surface, curve, samples: int = 400) -> np.ndarray:
    """Float points of ``F(K(t))`` at ``samples`` parameters (no composition needed)."""
    lo, hi = parameter_domain(curve)
    return curve_on_surface_evaluator(surface, curve)(np.linspace(lo, hi, samples))
