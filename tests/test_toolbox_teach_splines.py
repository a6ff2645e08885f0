"""Smoke test of the chapter 6 / 15 / 16 teaching scripts: they run, print their worked values and save a picture.

Marked slow (about 20 s together); run with ``python -m pytest -m slow tests/test_toolbox_teach_splines.py``.
The printed values are checked against numbers derived by hand in the notes (not against the code).
"""

import subprocess
import sys
from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parent.parent / "examples"

SCRIPTS = {
    "teach_06_splines.py": ("ch06_splines.png", ["[1, 2, 5, 11]", "construction = polar-form insertion: True", "3/4 N(0, 1, 2, 3, 4) + 1/2 N(1, 2, 3, 4, 5)"]),
    "teach_15_16_surfaces.py": ("ch15_surfaces.png", ["M1^2, M2^2, M3^2 = (2304, 1296, 1296)", "n_s = 150, n_t = 130", "C^2"]),
    "teach_15_7_tsplines.py": ("ch15_tsplines.png", ["f(3,3,3) = 11/24", "N[0,1,3,5,6](4) = 23/60", "253/1440"]),
    "teach_15_9_curvature.py": ("ch15_curvature.png", ["k = 1/2 * 1/1 * 1/1 = 1/2", "K = 4, H^2 = 4", "K = 1/4, H^2 = 25/64"]),
}


@pytest.mark.slow
@pytest.mark.parametrize("script", sorted(SCRIPTS))
def test_teaching_script_runs(script):
    picture, expected = SCRIPTS[script]
    out = subprocess.run([sys.executable, str(EXAMPLES / script)], capture_output=True, text=True, timeout=120, cwd=EXAMPLES)
    assert out.returncode == 0, out.stderr
    for text in expected:
        assert text in out.stdout, text
    assert (EXAMPLES / "output" / "teach" / picture).stat().st_size > 0
