"""Run the four teaching walk-throughs of notes chapters 6, 15 and 16 in a row.

* ``teach_06_splines.py`` -- periodic B-splines, end conditions, polar form, Bézier chains,
  knot intervals, basis functions (chapter 6);
* ``teach_15_16_surfaces.py`` -- corner derivatives, tessellation, C^n and NURBS surfaces,
  efficient points and tangents (15.1-15.6, 15.8, chapter 16);
* ``teach_15_7_tsplines.py`` -- T-splines (15.7);
* ``teach_15_9_curvature.py`` -- curvature from control points (15.9).

Each prints its derivation steps and saves a picture under ``examples/output/teach/``.

Run:  python examples/teach_splines_surfaces.py
"""

from __future__ import annotations

import teach_06_splines
import teach_15_7_tsplines
import teach_15_9_curvature
import teach_15_16_surfaces

if __name__ == "__main__":
    for module in (teach_06_splines, teach_15_16_surfaces, teach_15_7_tsplines, teach_15_9_curvature):
        print(f"\n######## {module.__name__}")
        module.main()
