"""The README's tour runs as printed, and the CLI basics answer."""
import re
import subprocess
import sys
from pathlib import Path

import pytest

from exactcagd.cli import main

ROOT = Path(__file__).resolve().parents[1]


def test_readme_tour_runs():
    text = (ROOT / "README.md").read_text()
    blocks = re.findall(r"```python\n(.*?)```", text, re.S)
    assert blocks, "README has no python tour"
    namespace: dict = {}
    for block in blocks:
        exec(compile(block, "README.md", "exec"), namespace)  # noqa: S102 - our own README (its asserts run)
    assert {"c", "quarter", "s"} <= set(namespace)


def test_readme_tour_printed_values():
    """The values written as comments in the README tour are the true ones (sympy reference)."""
    import sympy as sp

    t = sp.Symbol("t")
    x = 2 * t * (1 - t) * sp.Rational(1, 2) + t**2 * 2
    y = 2 * t * (1 - t) * 2
    assert (x.subs(t, sp.Rational(1, 3)), y.subs(t, sp.Rational(1, 3))) == (sp.Rational(4, 9), sp.Rational(8, 9))
    assert "(mpq(4,9), mpq(8,9))" in (ROOT / "README.md").read_text()


def test_version_and_info(capsys):
    assert main(["--version"]) == 0
    assert "exactcagd" in capsys.readouterr().out
    assert main(["info"]) == 0
    out = capsys.readouterr().out
    assert "python-flint" in out and "[yes] BezierCurve" in out


def test_console_script_installed():
    result = subprocess.run([sys.executable, "-m", "exactcagd.cli", "--version"], capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout.startswith("exactcagd ")


def test_ci_runs_the_readme_test_command():
    ci = (ROOT / ".ci" / "run").read_text()
    readme = (ROOT / "README.md").read_text()
    m = re.search(r"```sh\n(python -m pip install -e '\.\[test\]') && (python -m pytest -q)\n```", readme)
    assert m, "README test command not found"
    assert m.group(1) in ci and m.group(2) in ci


@pytest.mark.parametrize("argv", [["run", "does/not/exist.toml"], ["plan", "nope.json"]])
def test_cli_reports_missing_scene(argv, capsys):
    assert main(argv) == 2
    assert "does not exist" in capsys.readouterr().err


def test_readme_names_what_the_main_command_writes():
    """The README's main command writes a PNG per picture product of hill_trim.toml, summary.json
    and timings.json; the README names each of them (the run itself is tested in test_scenes_runner)."""
    import tomllib

    from exactcagd.scenes.spec import load_scene

    readme = (ROOT / "README.md").read_text()
    assert "exactcagd run examples/scenes/hill_trim.toml --out out" in readme
    scene = load_scene(ROOT / "examples" / "scenes" / "hill_trim.toml")
    pictures = {f"{p['name']}.png" for p in scene.products if p["kind"] == "picture"}
    assert pictures == {"overview.png", "approximation.png"}
    for name in sorted(pictures) + ["summary.json", "timings.json"]:
        assert f"`{name}`" in readme, name
    assert tomllib.loads((ROOT / "examples" / "scenes" / "hill_trim.toml").read_text())["scene"]["name"] == "hill_trim"
