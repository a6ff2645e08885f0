"""mpq entries must stay exact when mixed with sympy objects, whatever the import order."""
import subprocess
import sys

import pytest

CHECK = (
    "import sympy\nfrom gmpy2 import mpq\nx = sympy.Symbol('x')\n"
    "r = mpq(1, 3) * x\nassert r == x / 3 and not r.has(sympy.Float), r\n"
    "assert sympy.sympify(mpq(2, 7)) == sympy.Rational(2, 7)\n"
)


@pytest.mark.parametrize("first", ["import exactcagd\n", "import sympy\nimport exactcagd\n"])
def test_mpq_times_symbol_is_exact(first):
    result = subprocess.run([sys.executable, "-c", first + CHECK], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr


def test_bernstein_elevation_on_symbols_is_exact():
    import numpy as np
    import sympy

    from exactcagd.exact import bernstein as bz
    from exactcagd.exact.scalars import to_rational

    a, b = sympy.symbols("a b")
    out = bz.elevate(np.array([a, b], dtype=object), 2)
    assert list(out) == [a, 2 * a / 3 + b / 3, a / 3 + 2 * b / 3, b]
    assert not any(sympy.sympify(c).has(sympy.Float) for c in out)
    assert to_rational("1/3") * a == a / 3
