"""Exact JSON for results: rationals as ``"p/q"`` strings, algebraic numbers with their
defining polynomial and isolating interval, and correctly rounded float64 companions.

>>> from exactcagd.scenes.serialize import to_json_value
>>> from exactcagd.exact.scalars import to_rational
>>> to_json_value(to_rational("1/3"))
{'exact': '1/3', 'float': 0.3333333333333333}
"""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np

from .. import outputs as _outputs
from ..exact.algebraic import RealAlgebraic
from ..exact.scalars import Rational, rational_str, to_float
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface

__all__ = ["to_json_value", "atomic_write_text", "atomic_write_bytes"]


def _floats(nested):
    if isinstance(nested, (list, tuple, np.ndarray)):
        return [_floats(x) for x in nested]
    # exact non-rational entries (Q(sqrt D) numbers) round through their own high-precision __float__
    return to_float(nested) if isinstance(nested, (Rational, int)) else float(nested)


def to_json_value(obj):
    """Convert a result (curves, surfaces, numbers, dicts, lists) to JSON-ready data."""
    if isinstance(obj, Rational):
        return {"exact": rational_str(obj), "float": to_float(obj)}
    if isinstance(obj, RealAlgebraic):
        data = obj.to_dict()
        data["float"] = float(obj)
        return data
    if isinstance(obj, BezierCurve) and getattr(obj, "radicand", None) is not None:  # a curve over Q(sqrt D)
        data = to_json_value(obj.to_dict())
        points, weights = obj.to_float()
        data["type"] = "field_bezier_curve"
        data["control_points_float"] = np.asarray(points, dtype=float).tolist()
        data["weights_float"] = np.asarray(weights, dtype=float).tolist()
        return data
    if isinstance(obj, BezierCurve):
        data = obj.to_dict()
        data["type"] = "bezier_curve"
        data["control_points_float"] = _floats(obj.points_array())
        if obj.is_rational:
            data["weights_float"] = _floats(obj.weights_array())
        return data
    if isinstance(obj, BezierSurface):
        data = obj.to_dict()
        data["type"] = "bezier_surface"
        data["control_net_float"] = _floats(obj.net_array())
        if obj.is_rational:
            data["weights_float"] = _floats(obj.weights_array())
        return data
    if isinstance(obj, dict):
        return {str(k): to_json_value(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [to_json_value(v) for v in obj]
    if isinstance(obj, (str, int, float, bool)) or obj is None:
        return obj
    if hasattr(obj, "to_dict"):
        data = obj.to_dict()
        if isinstance(data, dict) and isinstance(data.get("pieces"), list):
            _piece_companions(obj, data)
        if isinstance(data, dict):  # "p/q" fields of the object (tolerance, distance_bound): float companions
            for key in [k for k, v in data.items() if isinstance(v, str) and isinstance(getattr(obj, k, None), Rational)]:
                data[f"{key}_float"] = to_float(getattr(obj, key))
        for key in ("segments", "domain_segments"):  # keep the curve objects: they get float companions
            items = getattr(obj, key, None)
            if isinstance(data, dict) and key in data and isinstance(items, list):
                data[key] = list(items)
        return to_json_value(data)
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {f.name: to_json_value(getattr(obj, f.name)) for f in dataclasses.fields(obj)}
    if type(obj).__module__.startswith("sympy"):
        return str(obj.as_expr() if hasattr(obj, "as_expr") else obj)
    raise TypeError(f"no exact JSON form for {type(obj).__name__}")


def _piece_companions(obj, data: dict) -> None:
    """Pieces of an image curve (``compose_spline``): each piece's curve keeps its object (so it
    gets ``control_points_float``), each exact interval end and joint parameter gets ``"float"``."""
    pieces = getattr(obj, "pieces", None) or []
    for item, piece in zip(data["pieces"], pieces):
        if isinstance(item, dict) and "curve" in item and isinstance(getattr(piece, "curve", None), BezierCurve):
            item["curve"] = piece.curve
            for entry, value in zip(item.get("interval", []), getattr(piece, "interval", ())):
                entry["float"] = to_float(value) if isinstance(value, Rational) else float(value)
    for item, joint in zip(data.get("joints") or [], getattr(obj, "joints", None) or []):
        if isinstance(item, dict) and isinstance(item.get("parameter"), dict):
            value = joint.parameter
            item["parameter"]["float"] = to_float(value) if isinstance(value, Rational) else float(value)


def atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` atomically, creating its folder (see :func:`exactcagd.outputs.atomic_write_bytes`:
    only an absent path or a regular file is replaced)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    _outputs.atomic_write_bytes(path, data)


def atomic_write_text(path: Path, text: str) -> None:
    atomic_write_bytes(path, text.encode())
