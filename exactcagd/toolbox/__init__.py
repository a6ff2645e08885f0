"""The rest of the CAGD toolbox from Sederberg's notes, exact.

Constructions layer (above :mod:`exactcagd.exact` and :mod:`exactcagd.geometry`).  The
modules are imported on demand (``from exactcagd.toolbox import fitting``); this package
file imports nothing.

Part A (notes chapters 1, 2, 4, 5, 10, 11, 20):

* :mod:`~exactcagd.toolbox.basics` -- ch. 1: vectors, exact rotation about an axis
  (rational cos/sin, quaternions, quadratic fields), lines and distances, conics
  (classification, implicit <-> parametric).
* :mod:`~exactcagd.toolbox.bezier_extras` -- ch. 2: convex hull, distance between curves,
  rational end derivatives and curvature, C^k / G^k continuity, exact circular arcs,
  rational (Möbius) reparametrization, explicit curves, Bernstein integrals.
* :mod:`~exactcagd.toolbox.forward_diff` -- ch. 4: forward differencing, exact and in
  binary64 with a certified error bound; choosing delta for rasterization.
* :mod:`~exactcagd.toolbox.blending` -- ch. 5: blending-function properties; Timmer, Ball
  and Overhauser curves and their Bézier forms.
* :mod:`~exactcagd.toolbox.interpolation` -- ch. 10: undetermined coefficients, Lagrange,
  Newton, Neville, error bounds, Chebyshev nodes, points and normals.
* :mod:`~exactcagd.toolbox.fitting` -- ch. 11: least-squares B-spline fitting, fairing,
  interpolation constraints, box-constrained fairing (exact QP).
* :mod:`~exactcagd.toolbox.integrals` -- ch. 20: hybrid curves, areas / moments / volumes,
  certified integrals of rational curves.

Part B (chapters 6, 15, 16): ``bspline_extras``, ``knot_intervals``, ``surfaces``,
``triangular``, ``tsplines``, ``curvature``.

Private helpers: ``_exact`` (exact linear algebra, polynomial extrema as real algebraic
numbers, LP feasibility) and ``_qp`` (exact convex QP by Lemke's algorithm).
"""
