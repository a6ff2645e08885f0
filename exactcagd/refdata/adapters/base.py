"""The kernel adapter interface of ``exactcagd conformance``.

An adapter is a small class: ``name``, the tuple ``kinds`` of record kinds it answers,
``version()``, and one method per kind.  Each method receives the record's ``input``
as a :class:`exactcagd.refdata.conformance.RecordInput` (the plain dict of the record
format, plus ``floats(name)`` for the correctly rounded float64 companions) and returns
a dict of floats shaped like the record's ``answer``:

==================  =====================================================================
kind                returned dict (lists nest like the answer; omit what the kernel lacks)
==================  =====================================================================
curve_eval          ``values``, ``first_derivatives``, ``second_derivatives``: ``[k][d]``
surface_eval        ``values``, ``normals`` (unnormalised ``S_u x S_v``): ``[k][3]``
bspline_eval        ``values``: ``[k][d]``
knot_insertion      ``knots``, ``control_points`` (``weights`` if rational)
bezier_extraction   ``segments``: ``[{"interval": [a, b], "control_points", "weights"?}]``
degree_elevation    ``control_points`` (``weights`` if rational)
subdivision         ``left`` / ``right``: ``{"control_points", "weights"?}``
inversion           ``params``: ``[k]``
intersect           ``intersections``: ``[[t1, t2], ...]`` in any order; ``overlap``: bool
roots               ``roots``: ``[t, ...]`` in any order (one entry per distinct root);
                    ``overlap``: bool (the kernel says the polynomial is zero on an interval)
compose             ``params``, ``points`` (samples of the kernel's curve on the surface),
                    ``claimed_error`` (the kernel's own error estimate)
==================  =====================================================================

Raise :class:`Unsupported` (with the reason) for a record the kernel cannot take by
design; any other exception is counted as a crash of the kernel.  A user kernel is
loaded with ``exactcagd conformance --kernel package.module:ClassName``.

>>> from exactcagd.refdata.adapters.base import Adapter, Unsupported
>>> class Echo(Adapter):
...     name, kinds = "echo", ("bspline_eval",)
...     def bspline_eval(self, inp):
...         raise Unsupported("echo evaluates nothing")
>>> Echo().version()
'unknown'
"""

from __future__ import annotations

from ...geometry.bezier_curve import BezierCurve
from ...geometry.bezier_surface import BezierSurface
from ...geometry.bspline import BSplineCurve, BSplineSurface
from ..conformance import RecordInput, Unsupported

__all__ = ["Adapter", "Unsupported", "RecordInput", "bezier_curve", "bezier_surface", "bspline_curve", "bspline_surface"]


class Adapter:
    """Base class of kernel adapters (subclass it; see the module docstring)."""

    #: Short name used in reports and on the command line.
    name = "adapter"
    #: Record kinds this adapter answers (one method of the same name each).
    kinds: tuple = ()

    def version(self) -> str:
        """Version string of the kernel (shown in the report)."""
        return "unknown"


# Exact objects from a record's input (the exporters then round each number once,
# which gives exactly the record's float64 companions).
def bezier_curve(inp: dict) -> BezierCurve:
    return BezierCurve(inp["control_points"], inp.get("weights"))


def bezier_surface(inp: dict) -> BezierSurface:
    return BezierSurface(inp["control_points"], inp.get("weights"))


def bspline_curve(inp: dict) -> BSplineCurve:
    return BSplineCurve(inp["control_points"], inp["knots"], inp.get("weights"))


def bspline_surface(inp: dict) -> BSplineSurface:
    return BSplineSurface(inp["control_points"], inp["knots_u"], inp["knots_v"], inp.get("weights"))
