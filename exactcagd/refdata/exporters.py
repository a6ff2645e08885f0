"""Exporters: exact exactcagd objects into other kernels' objects and files.

Targets (all optional; ``pip install 'exactcagd[peers]'`` installs them):

* **geomdl** -- :func:`to_geomdl` gives a ``geomdl.BSpline``/``NURBS`` ``Curve`` or
  ``Surface``; :func:`to_geomdl_json` / :func:`write_geomdl_json` give geomdl's own JSON
  exchange file, which ``geomdl.exchange.import_json`` reads back;
* **bezier** -- :func:`to_bezier_nodes` gives the ``nodes`` array of ``bezier.Curve``
  (Fortran-ordered, one *column* per control point, shape ``(d, n + 1)``) and
  :func:`to_bezier` the curve itself;
* **OpenCASCADE** (``cadquery-ocp``) -- :func:`to_occ` gives a ``Geom_BSplineCurve``
  (``Geom2d_BSplineCurve`` for planar curves) or ``Geom_BSplineSurface``, and
  :func:`write_step` writes curves and surfaces as STEP edges and faces.

Rounding: each exact number reaches the peer as its correctly rounded float64 (round
to nearest, ties to even, :func:`exactcagd.refdata.records.f64_float`), rounded *once*
from the exact value.  For rational objects given to a peer in homogeneous form
(geomdl's ``ctrlptsw``, bezier's homogeneous nodes) the products ``w P`` are formed
exactly and then rounded, never as a product of two rounded floats.  A Bézier object
becomes the one-span clamped B-spline on [0, 1] with knots ``0^(n+1) 1^(n+1)``
(Sederberg's notes 6.3: a B-spline with these knots *is* the Bézier curve).

A peer that is not installed gives :class:`exactcagd.errors.NotSupportedError`
naming the missing package and the ``peers`` extra; nothing is imported before use.

>>> from exactcagd import BezierCurve
>>> from exactcagd.refdata.exporters import to_bezier_nodes
>>> to_bezier_nodes(BezierCurve([[0, 0], ["1/2", 1], [1, 0]]))
array([[0. , 0.5, 1. ],
       [0. , 1. , 0. ]])
"""

from __future__ import annotations

import importlib
import json
import tempfile
from pathlib import Path

import numpy as np

from ..errors import InputError, NotSupportedError
from ..geometry.bezier_curve import BezierCurve
from ..geometry.bezier_surface import BezierSurface
from ..geometry.bspline import BSplineCurve, BSplineSurface
from .records import f64_float

__all__ = [
    "require_peer",
    "to_geomdl",
    "to_geomdl_json",
    "write_geomdl_json",
    "to_bezier_nodes",
    "to_bezier",
    "to_occ",
    "write_step",
]

#: pip package that provides each importable peer module.
PEER_PACKAGES = {"geomdl": "geomdl", "bezier": "bezier", "OCP": "cadquery-ocp"}

CURVES = (BezierCurve, BSplineCurve)
SURFACES = (BezierSurface, BSplineSurface)


def require_peer(module: str):
    """Import an optional peer kernel, or raise a clear error naming the package and extra.

    >>> require_peer("json").__name__
    'json'
    """
    try:
        return importlib.import_module(module)
    except ImportError as exc:
        package = PEER_PACKAGES.get(module.split(".")[0], module.split(".")[0])
        raise NotSupportedError(
            f"the optional package {package!r} is not installed (needed for {module}); "
            f"install it with: pip install 'exactcagd[peers]'  (or: pip install {package})"
        ) from exc


# ----------------------------------------------------------------------------- common form
def _spline_form(obj) -> dict:
    """Knots, degrees and exact homogeneous data of any geometry object (Bézier = one span).

    Returns ``{"degree": (p,) or (p, q), "knots": [list per direction], "points": exact
    array, "weights": exact array or None}``.
    """
    if isinstance(obj, BezierCurve):
        n = obj.degree
        return {"degree": (n,), "knots": [[0] * (n + 1) + [1] * (n + 1)], "points": obj.points_array(),
                "weights": None if not obj.is_rational else obj.weights_array()}
    if isinstance(obj, BSplineCurve):
        return {"degree": (obj.degree,), "knots": [list(obj.knots)], "points": np.array(obj.control_points, dtype=object),
                "weights": None if not obj.is_rational else np.array(obj.weights, dtype=object)}
    if isinstance(obj, BezierSurface):
        l, m = obj.degree
        return {"degree": (l, m), "knots": [[0] * (l + 1) + [1] * (l + 1), [0] * (m + 1) + [1] * (m + 1)],
                "points": np.array(obj.control_net, dtype=object),
                "weights": None if not obj.is_rational else np.array(obj.weights, dtype=object)}
    if isinstance(obj, BSplineSurface):
        return {"degree": obj.degree, "knots": [list(obj.knots_u), list(obj.knots_v)],
                "points": np.array(obj.control_net, dtype=object),
                "weights": None if not obj.is_rational else np.array(obj.weights, dtype=object)}
    raise InputError(
        f"obj: expected a BezierCurve, BezierSurface, BSplineCurve or BSplineSurface, got {type(obj).__name__}"
    )


def _floats(array) -> np.ndarray:
    """Correctly rounded float64 of every exact entry."""
    array = np.asarray(array, dtype=object)
    return np.vectorize(f64_float, otypes=[float])(array) if array.size else np.zeros(array.shape)


def _homogeneous_floats(points, weights) -> np.ndarray:
    """``(w P, w)`` formed exactly, then rounded once per entry."""
    hom = np.concatenate([points * weights[..., None], weights[..., None]], axis=-1)
    return _floats(hom)


# ----------------------------------------------------------------------------- geomdl
def to_geomdl(obj):
    """A geomdl ``BSpline``/``NURBS`` ``Curve`` or ``Surface`` equal to ``obj`` up to rounding.

    Rational objects set ``ctrlptsw`` (geomdl's weighted points ``(w x, w y, .., w)``);
    surfaces list the net row by row with ``u`` the slow index (geomdl's
    ``ctrlpts2d[u][v]``).  Knot values are rounded to float64 like the points.

    >>> from exactcagd import BezierCurve
    >>> crv = to_geomdl(BezierCurve([[0, 0], [1, 2], [2, 0]], weights=[1, 2, 1]))
    >>> type(crv).__module__, crv.degree, crv.knotvector
    ('geomdl.NURBS', 2, [0.0, 0.0, 0.0, 1.0, 1.0, 1.0])
    >>> [round(x, 12) for x in crv.evaluate_single(0.5)]
    [1.0, 1.333333333333]
    """
    form = _spline_form(obj)
    BSpline = require_peer("geomdl.BSpline")
    NURBS = require_peer("geomdl.NURBS")
    rational = form["weights"] is not None
    module = NURBS if rational else BSpline
    pts = _homogeneous_floats(form["points"], form["weights"]) if rational else _floats(form["points"])
    if len(form["degree"]) == 1:
        geo = module.Curve()
        geo.degree = form["degree"][0]
        if rational:
            geo.ctrlptsw = pts.tolist()
        else:
            geo.ctrlpts = pts.tolist()
        geo.knotvector = _floats(form["knots"][0]).tolist()
        return geo
    geo = module.Surface()
    geo.degree_u, geo.degree_v = form["degree"]
    n_u, n_v = pts.shape[:2]
    geo.set_ctrlpts(pts.reshape(n_u * n_v, -1).tolist(), n_u, n_v)
    geo.knotvector_u = _floats(form["knots"][0]).tolist()
    geo.knotvector_v = _floats(form["knots"][1]).tolist()
    return geo


def to_geomdl_json(*objs) -> str:
    """geomdl's JSON exchange text for one or more curves (or surfaces), as ``export_json`` writes it.

    All objects must be of one parametric dimension (curves, or surfaces), as geomdl's
    format requires.

    >>> from exactcagd import BezierCurve
    >>> text = to_geomdl_json(BezierCurve([[0, 0], [1, 1]]))
    >>> json.loads(text)["shape"]["type"]
    'curve'
    """
    if not objs:
        raise InputError("to_geomdl_json: give at least one object")
    if len({isinstance(o, CURVES) for o in objs}) > 1:
        raise InputError("to_geomdl_json: mix of curves and surfaces; geomdl's JSON holds one kind per file")
    exchange = require_peer("geomdl._exchange")
    multi = require_peer("geomdl.multi")
    geos = [to_geomdl(o) for o in objs]
    container = multi.CurveContainer(geos) if geos[0].pdimension == 1 else multi.SurfaceContainer(geos)
    return exchange.export_dict_str(obj=container, callback=lambda data: json.dumps(data, indent=4))


def write_geomdl_json(path, *objs) -> None:
    """Write :func:`to_geomdl_json` to ``path`` (checked and written atomically)."""
    from ..outputs import atomic_write_text, check_output_file

    target = check_output_file(path, argument="path")
    atomic_write_text(target, to_geomdl_json(*objs))


# ----------------------------------------------------------------------------- bezier
def to_bezier_nodes(curve: BezierCurve, homogeneous: bool = False) -> np.ndarray:
    """``bezier.Curve`` nodes: Fortran-ordered ``(d, n + 1)`` array, one column per control point.

    ``bezier`` has no rational curves: a rational curve needs ``homogeneous=True``, which
    gives the nodes ``(w P, w)`` of its homogeneous curve (``d + 1`` rows; the point is the
    first ``d`` rows divided by the last).
    """
    if not isinstance(curve, BezierCurve):
        raise InputError(f"curve: bezier.Curve holds Bézier curves only, got {type(curve).__name__} (extract Bézier pieces first)")
    if curve.is_rational and not homogeneous:
        raise NotSupportedError("bezier.Curve has no rational curves; pass homogeneous=True to get the nodes of (w P, w)")
    if homogeneous:
        nodes = _homogeneous_floats(curve.points_array(), curve.weights_array())
    else:
        nodes = _floats(curve.points_array())
    return np.asfortranarray(nodes.T)


def to_bezier(curve: BezierCurve, homogeneous: bool = False):
    """A ``bezier.Curve`` (degree stated, nodes from :func:`to_bezier_nodes`).

    >>> from exactcagd import BezierCurve
    >>> to_bezier(BezierCurve([[0, 0], [1, 2], [2, 0]])).evaluate(0.5).ravel().tolist()
    [1.0, 1.0]
    """
    nodes = to_bezier_nodes(curve, homogeneous)
    bezier = require_peer("bezier")
    return bezier.Curve(nodes, degree=curve.degree, copy=False)


# ----------------------------------------------------------------------------- OpenCASCADE
def _occ_knots(knots: list) -> tuple[list, list]:
    """Distinct knot values (float64) and their multiplicities, OCC's knot form."""
    values, mults = [], []
    for k in knots:
        if values and k == values[-1]:
            mults[-1] += 1
        else:
            values.append(k)
            mults.append(1)
    return _floats(values).tolist(), mults


def _occ_array1(C, kind: str, values: list):
    arr = getattr(C, kind)(1, len(values))
    for i, x in enumerate(values):
        arr.SetValue(i + 1, x)
    return arr


def to_occ(obj):
    """An OpenCASCADE ``Geom_BSplineCurve`` / ``Geom2d_BSplineCurve`` / ``Geom_BSplineSurface``.

    Curves of dimension 2 become ``Geom2d_BSplineCurve`` (what OCC's 2-D algorithms and
    curves on surfaces take), of dimension 3 ``Geom_BSplineCurve``; surfaces must be 3-D.
    Knots are given as distinct values with multiplicities (OCC's form); poles and
    weights separately (OCC stores them unweighted, like exactcagd), 1-based.

    >>> from exactcagd import BezierCurve
    >>> occ = to_occ(BezierCurve([[0, 0, 0], [1, 2, 0], [2, 0, 1]]))
    >>> p = occ.Value(0.5); (p.X(), p.Y(), p.Z())
    (1.0, 1.0, 0.25)
    """
    form = _spline_form(obj)
    require_peer("OCP")
    from OCP.OCP import collections as C

    dim = form["points"].shape[-1]
    pts = _floats(form["points"])
    w = None if form["weights"] is None else _floats(form["weights"])
    if len(form["degree"]) == 1:
        if dim not in (2, 3):
            raise InputError(f"obj: OpenCASCADE curves are 2-D or 3-D, got dimension {dim}")
        if dim == 2:
            from OCP.OCP.Geom2d import Geom2d_BSplineCurve as Spline
            from OCP.OCP.gp import gp_Pnt2d as Pnt

            poles = C.Array1_gp_Pnt2d(1, len(pts))
        else:
            from OCP.OCP.Geom import Geom_BSplineCurve as Spline
            from OCP.OCP.gp import gp_Pnt as Pnt

            poles = C.Array1_gp_Pnt(1, len(pts))
        for i, p in enumerate(pts):
            poles.SetValue(i + 1, Pnt(*p.tolist()))
        values, mults = _occ_knots(form["knots"][0])
        knots, mults = _occ_array1(C, "Array1_double", values), _occ_array1(C, "Array1_int", mults)
        if w is None:
            return Spline(poles, knots, mults, form["degree"][0])
        return Spline(poles, _occ_array1(C, "Array1_double", w.tolist()), knots, mults, form["degree"][0])
    if dim != 3:
        raise InputError(f"obj: OpenCASCADE surfaces are 3-D, got dimension {dim}")
    from OCP.OCP.Geom import Geom_BSplineSurface
    from OCP.OCP.gp import gp_Pnt

    n_u, n_v = pts.shape[:2]
    poles = C.Array2_gp_Pnt(1, n_u, 1, n_v)
    weights = C.Array2_double(1, n_u, 1, n_v)
    for i in range(n_u):
        for j in range(n_v):
            poles.SetValue(i + 1, j + 1, gp_Pnt(*pts[i, j].tolist()))
            weights.SetValue(i + 1, j + 1, 1.0 if w is None else float(w[i, j]))
    (ku, mu), (kv, mv) = _occ_knots(form["knots"][0]), _occ_knots(form["knots"][1])
    args = (_occ_array1(C, "Array1_double", ku), _occ_array1(C, "Array1_double", kv),
            _occ_array1(C, "Array1_int", mu), _occ_array1(C, "Array1_int", mv), *form["degree"])
    if w is None:
        return Geom_BSplineSurface(poles, *args)
    return Geom_BSplineSurface(poles, weights, *args)


def write_step(path, *objs) -> None:
    """Write curves (as edges) and surfaces (as faces) into one STEP file (OCC's ``STEPControl_Writer``).

    Planar curves are placed in the plane ``z = 0``.  The file is written to a temporary
    name and renamed into place; ``path`` is checked like every output path.  OCC's
    writer prints reals with 12 significant digits, so a STEP file carries the data to
    about 1e-12 relative, not to the last bit (measured: the knot 1/3 is written
    ``0.333333333333``); use :func:`to_occ` or geomdl's JSON for bit-exact float data.
    """
    if not objs:
        raise InputError("write_step: give at least one curve or surface")
    from ..outputs import atomic_write_bytes, check_output_file

    target = check_output_file(path, argument="path")
    require_peer("OCP")
    from OCP.OCP.BRep import BRep_Builder
    from OCP.OCP.BRepBuilderAPI import BRepBuilderAPI_MakeEdge, BRepBuilderAPI_MakeFace
    from OCP.OCP.IFSelect import IFSelect_ReturnStatus
    from OCP.OCP.STEPControl import STEPControl_StepModelType, STEPControl_Writer
    from OCP.OCP.TopoDS import TopoDS_Compound

    builder, compound = BRep_Builder(), TopoDS_Compound()
    builder.MakeCompound(compound)
    for obj in objs:
        if isinstance(obj, CURVES) and obj.dimension == 2:
            obj = _lift_to_3d(obj)
        geom = to_occ(obj)
        shape = (BRepBuilderAPI_MakeEdge(geom) if isinstance(obj, CURVES) else BRepBuilderAPI_MakeFace(geom, 1e-7)).Shape()
        builder.Add(compound, shape)
    writer = STEPControl_Writer()
    writer.Transfer(compound, STEPControl_StepModelType.STEPControl_AsIs)
    with tempfile.TemporaryDirectory() as tmp:  # OCC writes by name; the bytes then go in atomically
        scratch = str(Path(tmp) / "out.step")
        if writer.Write(scratch) != IFSelect_ReturnStatus.IFSelect_RetDone:
            raise NotSupportedError(f"OpenCASCADE's STEP writer failed on {path}")
        atomic_write_bytes(target, Path(scratch).read_bytes())


def _lift_to_3d(curve):
    """The planar curve in the plane ``z = 0`` (exact)."""
    data = curve.to_dict()
    data["control_points"] = [p + [0] for p in data["control_points"]]
    return type(curve).from_dict(data)
