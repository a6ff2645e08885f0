"""Packaging facts (issue 14): declared floors equal the tested ones, the light entry points
stay light, optional pictures fail clearly, ``bench`` needs a checkout and writes where told,
and (slow) a fresh wheel works from an empty directory without writing into site-packages.

References are independent of the code under test: ``pyproject.toml`` parsed as TOML,
``sys.modules`` of a separate interpreter, the file system.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path
from types import SimpleNamespace

import pytest

import exactcagd
from exactcagd.errors import NotSupportedError, OutputError

ROOT = Path(__file__).resolve().parents[1]

try:
    import tomllib
except ModuleNotFoundError:  # Python 3.10
    import tomli as tomllib

PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())
HEAVY = ("sympy", "numpy", "flint", "gmpy2", "mpmath", "matplotlib")


def _floors_declared() -> dict:
    floors = {}
    extras = PYPROJECT["project"]["optional-dependencies"]
    deps = PYPROJECT["project"]["dependencies"] + extras["plots"] + extras["fast"]
    for dep in deps:
        m = re.fullmatch(r"([A-Za-z0-9_.-]+)>=([0-9.]+)(?:,<[0-9.]+)?(;.*)?", dep.replace(" ", ""))
        assert m, f"dependency without a floor: {dep}"
        floors[m.group(1).lower()] = m.group(2)
    return floors


def _floors_pinned() -> dict:
    """Pins of .ci/constraints-floor.txt that apply to the Python 3.11+ floor job."""
    pins = {}
    for line in (ROOT / ".ci" / "constraints-floor.txt").read_text().splitlines():
        line = line.split("#", 1)[0].strip()
        if not line or 'python_version < "3.11"' in line:
            continue
        m = re.fullmatch(r"([A-Za-z0-9_.-]+)==([0-9.]+)(;.*)?", line.replace(" ", ""))
        assert m, f"constraint is not an exact pin: {line}"
        pins[m.group(1).lower()] = m.group(2)
    return pins


def _version_tuple(v: str) -> tuple:
    """Release numbers compared as PEP 440 does (0.8 == 0.8.0)."""
    parts = [int(p) for p in v.split(".")]
    return tuple(parts + [0] * (3 - len(parts)))


def test_constraint_pins_are_the_declared_floors():
    declared, pinned = _floors_declared(), _floors_pinned()
    declared.pop("tomli")  # only on 3.10; its pin carries a marker
    assert set(pinned) == set(declared)
    for name, floor in declared.items():
        assert _version_tuple(pinned[name]) == _version_tuple(floor), name


def test_known_bad_versions_are_excluded():
    """The versions the issue found broken must not satisfy the declared ranges."""
    floors = _floors_declared()
    assert _version_tuple(floors["python-flint"]) > (0, 7, 1)  # 0.7.x: no fmpz_poly.resultant
    assert _version_tuple(floors["gmpy2"]) >= (2, 3, 0)  # 2.2.0-2.2.2 misround float(mpq)
    flint = next(d for d in PYPROJECT["project"]["dependencies"] if d.startswith("python-flint"))
    assert "<" in flint  # a 0.x dependency is capped


def test_gmpy2_float_of_mpq_is_correctly_rounded():
    """Why gmpy2 >= 2.3.0: float(mpq) must equal Python's correctly rounded int/int."""
    import random

    import gmpy2

    rng = random.Random(14)
    for _ in range(500):
        p, q = rng.getrandbits(rng.randint(1, 160)) - 2**80, rng.getrandbits(rng.randint(1, 160)) or 1
        assert float(gmpy2.mpq(p, q)) == p / q


def test_matplotlib_is_an_extra_and_license_ships():
    assert not any(d.startswith("matplotlib") for d in PYPROJECT["project"]["dependencies"])
    assert any(d.startswith("matplotlib") for d in PYPROJECT["project"]["optional-dependencies"]["test-core"])
    assert "exactcagd[test-core,fast]" in PYPROJECT["project"]["optional-dependencies"]["test"]  # the kernel is tested
    assert "MIT License" in (ROOT / "LICENSE").read_text()
    assert (ROOT / "exactcagd" / "py.typed").is_file()
    assert "py.typed" in PYPROJECT["tool"]["setuptools"]["package-data"]["exactcagd"]


def test_version_and_cli_import_no_heavy_dependency():
    code = (
        "import sys, exactcagd.cli, exactcagd; print(exactcagd.__version__); "
        f"print([m for m in sys.modules if m.split('.')[0] in {HEAVY!r}])"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout.split("\n")
    assert out[0] == PYPROJECT_VERSION() and out[1] == "[]"


def PYPROJECT_VERSION() -> str:
    text = (ROOT / "exactcagd" / "_version.py").read_text()
    return re.search(r'__version__ = "([^"]+)"', text).group(1)


def test_public_names_resolve_lazily_to_their_definitions():
    from exactcagd.composition import compose
    from exactcagd.geometry.bspline import BSplineSurface

    assert exactcagd.compose is compose and exactcagd.BSplineSurface is BSplineSurface
    assert set(exactcagd.__all__) <= set(dir(exactcagd))
    with pytest.raises(AttributeError, match="no_such_name"):
        exactcagd.no_such_name  # noqa: B018


def test_pictures_without_matplotlib_name_the_extra(monkeypatch):
    from exactcagd.scenes import pictures

    monkeypatch.setitem(sys.modules, "matplotlib", None)  # import matplotlib -> ModuleNotFoundError
    with pytest.raises(NotSupportedError, match=r"exactcagd\[plots\]"):
        pictures._figure()


# ----------------------------------------------------------------------------- bench


def test_bench_outside_a_checkout_says_what_to_do(tmp_path, monkeypatch):
    from exactcagd.apps import bench

    monkeypatch.chdir(tmp_path)
    monkeypatch.setattr(exactcagd, "__file__", str(tmp_path / "site-packages" / "exactcagd" / "__init__.py"))
    assert bench.find_checkout() is None
    with pytest.raises(NotSupportedError, match="needs a repository checkout"):
        bench.main(SimpleNamespace(quick=True, only="none", out=None))


def test_bench_finds_the_checkout_from_a_subfolder(monkeypatch):
    from exactcagd.apps import bench

    monkeypatch.chdir(ROOT / "examples")
    assert bench.find_checkout() == ROOT


def test_bench_refuses_a_bad_out_before_running(tmp_path):
    from exactcagd.apps import bench

    f = tmp_path / "file"
    f.write_text("x")
    with pytest.raises(OutputError, match="--out"):
        bench.main(SimpleNamespace(quick=True, only="none", out=str(f)))
    assert f.read_text() == "x"


def test_bench_out_moves_every_result_file(tmp_path, monkeypatch):
    """--out sends tables (results_dir) and RUNS.md under the given folder, not benchmarks/results/."""
    monkeypatch.syspath_prepend(str(ROOT))
    from benchmarks import __main__ as runner
    from benchmarks import _common

    monkeypatch.setattr(_common, "RESULTS", _common.RESULTS)  # restored after the test
    before = sorted(p.name for p in (ROOT / "benchmarks" / "results").iterdir())
    _common.set_results_root(tmp_path / "r")
    assert _common.results_dir(quick=True) == tmp_path / "r"
    assert _common.results_dir(quick=False) == tmp_path / "r" / "full"
    runner.write_runs([["bench_x", "quick", "now", "ok", "0.1", "-"]], quick=True)
    assert (tmp_path / "r" / "RUNS.md").read_text().count("bench_x") == 1
    assert sorted(p.name for p in (ROOT / "benchmarks" / "results").iterdir()) == before


# ----------------------------------------------------------------------------- fresh wheel


@pytest.mark.slow
@pytest.mark.skipif(not (ROOT / ".git").exists(), reason="builds the wheel from the git checkout")
def test_fresh_wheel_from_an_empty_directory():
    """Build, install into a fresh venv, run --version / run / verify --fast / refdata / bench
    from an empty directory; nothing is written into site-packages (minutes: venv + install)."""
    env = dict(os.environ, PYTHON=sys.executable)
    done = subprocess.run([str(ROOT / ".ci" / "fresh_wheel.sh")], capture_output=True, text=True, env=env, timeout=1800)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    assert "fresh-wheel: ok" in done.stdout
