"""Exact layer: rational scalars and Bernstein polynomial arithmetic."""
