"""Geometry layer: exact Bézier and B-spline/NURBS curves and surfaces."""
