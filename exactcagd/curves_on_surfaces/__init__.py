"""Curves on surfaces: the G1 parabola approximation of Yang et al. (004) and its baselines.

``approximate(surface, domain_curve, tol, method="parabola"|"hyperbola"|"polyline"|"fit")``
returns a :class:`CurveOnSurface`:

* ``.segments``: exact rational Bézier curves (``BezierCurve`` instances; those with
  coefficients in ``Q(sqrt(Delta))`` are :class:`FieldBezierCurve`, a ``BezierCurve``
  subclass) lying *exactly* on the surface -- each is
  ``X(u(t), v(t))`` for a patch ``X`` and an exact domain curve; a parabola segment is the
  iso-line ``s = 1/2`` of an exact cubic reparameterization (eq. (5)) of its patch,
  degree ``max(2m + n, m + 2n)``; hyperbola and polyline segments have degree ``m + n``;
* ``.domain_segments``: the approximating domain curves (global ``(u, v)``);
* ``.distance_bound``: a certified upper bound (exact rational) of the Hausdorff distance
  to the exact image ``S(D(t))``, always ``<= tol``;
* ``.degree``, ``.continuity`` (``"G1"`` checked exactly for the parabola method),
  ``.patches``, ``.kinds``, ``.timings``, ``.ends`` (parameters of ``D`` at both ends of each
  segment and whether the segment interpolates ``D``'s point and tangent direction exactly
  there -- always, except at irrational cuts and rounded joints, see ``snap_bits``).

How exactness is kept (details in the modules):

* ``sqrt(Delta)`` of eq. (16) is carried in ``Q(sqrt(Delta))``
  (:mod:`exactcagd.exact.quadratic`); such segments are :class:`FieldBezierCurve`.
  Homogeneous Möbius weights avoid field divisions.
* Irrational cut parameters (knot-line crossings, extrema of ``u(t)``/``v(t)``) are
  carried by isolating intervals of width ``2^-64``; the joint there gets an exact
  rational point (on the knot line when it is a crossing) and an exact direction
  shared by both neighbours (axis-parallel at an extremum), so G1 is exact; joints
  made at irrational cuts and at shoulder points are rounded to ``2^-snap_bits``
  (``snap_bits=None`` keeps exact curve data), and every such deviation is part of
  the certified bound.
* Distances are certified in rational arithmetic (a rational proxy of the field
  parabola with an explicit ``delta``), see :mod:`.hausdorff` and
  ``proofs/yang_hausdorff.py``.

Degenerate input: ``tol <= 0``, a non-planar domain curve or an unknown method ->
:class:`~exactcagd.errors.InputError`; a domain curve leaving the surface domain, a
constant curve, an irrational stationary point -> :class:`~exactcagd.errors.DomainError`;
a cusp or corner of the domain curve -> ``DomainError`` unless ``on_corner="split"``
(then a G0 joint listed in ``.corners``); an iso-parametric piece is approximated by
itself (exact, zero distance).

``method="fit"`` (:mod:`.fit`, fit then certify) is a different product: compact polynomial
Bézier curves (degree <= ``max_degree``, usually one segment) *near* the surface, C0 at
joints, fitted in binary64 to the exact image ``S(D(t))``, converted exactly to rationals,
with a proven bound of ``max_t |S(D(t)) - C(t)|`` as ``.distance_bound`` (``<= tol``).

Modules: :mod:`.domain` (cuts and joints), :mod:`.fit` (fit then certify), :mod:`.approximants` (Theorem 1, baselines),
:mod:`.hausdorff` (certified bounds), :mod:`.surface_grid` (patches, derivative bounds),
:mod:`.field_curve` (curves over ``Q(sqrt(D))``), :mod:`.driver` (section 2),
:mod:`.samples` (the stand-in models of the Table 1-4 analogues).
"""

from .driver import METHODS, CurveOnSurface, approximate
from .field_curve import FieldBezierCurve, make_curve

__all__ = ["approximate", "CurveOnSurface", "FieldBezierCurve", "make_curve", "METHODS"]
