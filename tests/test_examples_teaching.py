"""Every teaching script in ``examples/`` runs, prints its worked values and saves a picture.

The printed values are checked against numbers derived independently: by hand in the notes,
or with sympy (Rodrigues' rotation formula, the curvature of the rational quadratic from its
quotient-rule derivatives, Lagrange interpolation, the area integral int y dx by expansion).
About 20 s together; they run by default so a script a teacher relies on cannot rot unseen.
"""

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

SCRIPTS = {
    "teach_01_basics.py": ("ch01_basics.png", ["cross = (11, 3, -5)", "P' = C + r = (5/3, 13/3, 23/3)"]),
    "teach_02_bezier_extras.py": ("ch02_extras.png", ["general curvature formula at t = 0: 2/25", "area = 3/2"]),
    "teach_04_05_differencing_blending.py": ("ch04_05.png", ["f(4) = 8"]),
    "teach_06_splines.py": ("ch06_splines.png", ["[1, 2, 5, 11]", "construction = polar-form insertion: True", "3/4 N(0, 1, 2, 3, 4) + 1/2 N(1, 2, 3, 4, 5)"]),
    # P' = (1 - t^2, 2t) integrates to P = (t - t^3/3, t^2): P(1/3) = (26/81, 1/9)
    "teach_08_offsets.py": ("ch08_offsets.png", ["= P(1/3) = (mpq(26,81), mpq(1,9))"]),
    "teach_10_11_interpolation_fitting.py": ("ch10_11.png", ["P(2) from the Newton form: (25/6, 4)", "level 3: [(25/6, 4)]"]),
    "teach_15_16_surfaces.py": ("ch15_surfaces.png", ["M1^2, M2^2, M3^2 = (2304, 1296, 1296)", "n_s = 150, n_t = 130", "C^2"]),
    "teach_15_7_tsplines.py": ("ch15_tsplines.png", ["f(3,3,3) = 11/24", "N[0,1,3,5,6](4) = 23/60", "253/1440"]),
    "teach_15_9_curvature.py": ("ch15_curvature.png", ["k = 1/2 * 1/1 * 1/1 = 1/2", "K = 4, H^2 = 4", "K = 1/4, H^2 = 25/64"]),
    "teach_20_integrals.py": ("ch20_integrals.png", ["int y dx = 21/4"]),
}


def test_every_teaching_script_is_covered():
    assert {p.name for p in EXAMPLES.glob("teach_*.py")} - {"teach_splines_surfaces.py"} == set(SCRIPTS)


@pytest.mark.parametrize("script", sorted(SCRIPTS))
def test_teaching_script_runs(script):
    picture, expected = SCRIPTS[script]
    target = EXAMPLES / "output" / "teach" / picture
    target.unlink(missing_ok=True)
    out = subprocess.run([sys.executable, str(EXAMPLES / script)], capture_output=True, text=True, timeout=120, cwd=EXAMPLES)
    assert out.returncode == 0, out.stderr
    for text in expected:
        assert text in out.stdout, text
    assert target.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
