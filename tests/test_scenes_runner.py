"""End-to-end scene runs: plan shows skipped work, outputs are exact and complete, rerun hits the cache,
a failing product leaves nothing half-written."""
import copy
import json

import pytest
import sympy as sp

from exactcagd.cli import main
from exactcagd.errors import ExactCAGDError
from exactcagd.scenes.runner import Runner
from exactcagd.scenes.spec import parse_scene

SCENE = {
    "scene": {"name": "small", "float_policy": "reject"},
    "surfaces": {
        "s": {
            "type": "bspline",
            "knots_u": [0, 0, 0, "1/2", 1, 1, 1],
            "knots_v": [0, 0, 0, "1/2", 1, 1, 1],
            "control_net": {"generator": "grid", "size": [4, 4], "z": "x*y"},
        }
    },
    "curves": {"k": {"type": "bezier", "control_points": [["1/8", "1/8"], ["1/4", "3/8"], ["3/8", "1/8"]]}},
    "products": [
        {"kind": "patches", "name": "crossed", "surface": "s", "only_crossed_by": "k"},
        {"kind": "image_curve", "name": "image", "surface": "s", "curve": "k"},
        {"kind": "picture", "name": "pic", "of": ["s", "k", "image"]},
    ],
}


def test_plan_reports_skipped_patches(tmp_path, capsys):
    path = tmp_path / "small.json"
    path.write_text(json.dumps(SCENE))
    assert main(["plan", str(path), "--out", str(tmp_path / "out")]) == 0
    out = capsys.readouterr().out
    assert "1 patch(es) crossed by k" in out
    assert "3 of 4 patches not crossed" in out
    assert not (tmp_path / "out").exists(), "plan must not compute or write"


def test_run_writes_exact_outputs_and_reruns_from_cache(tmp_path, capsys):
    path = tmp_path / "small.json"
    path.write_text(json.dumps(SCENE))
    out_dir = tmp_path / "out"
    assert main(["run", str(path), "--out", str(out_dir)]) == 0
    files = {p.name for p in (out_dir / "small").iterdir()}
    assert {"crossed.json", "image.json", "pic.png", "summary.json"} <= files
    assert (out_dir / "small" / "pic.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"

    # the exact image curve is F(K(t)): evaluate the stored exact control points (sympy Bernstein sum)
    # at t = 1/3 and compare with the surface evaluated by de Boor at the domain point K(1/3)
    data = json.loads((out_dir / "small" / "image.json").read_text())
    piece = data["result"]["pieces"][0]["curve"]
    pts = [[sp.Rational(c) for c in p] for p in piece["control_points"]]
    t = sp.Rational(1, 3)
    n = len(pts) - 1
    value = [sum(sp.binomial(n, i) * t**i * (1 - t) ** (n - i) * pts[i][k] for i in range(n + 1)) for k in range(3)]
    K = [(1 - t) ** 2 * sp.Rational(1, 8) + 2 * t * (1 - t) * sp.Rational(1, 4) + t**2 * sp.Rational(3, 8),
         (1 - t) ** 2 * sp.Rational(1, 8) + 2 * t * (1 - t) * sp.Rational(3, 8) + t**2 * sp.Rational(1, 8)]
    runner = Runner(parse_scene(copy.deepcopy(SCENE)), tmp_path / "x")
    expected = runner.objects["s"].evaluate(str(K[0]), str(K[1]))
    assert value == [sp.Rational(str(c)) for c in expected]
    assert len(data["result"]["pieces"]) == 1 and n == 2 * (2 + 2)

    capsys.readouterr()
    assert main(["run", str(path), "--out", str(out_dir)]) == 0
    assert capsys.readouterr().out.count("cached") >= 3


def test_readme_scene_reruns_from_cache(tmp_path, capsys):
    """The README's main command, twice: the second run takes every product and picture from the
    cache and writes the same bytes (exact JSON, pictures, summary; only timings.json differs)."""
    from pathlib import Path

    scene = Path(__file__).resolve().parents[1] / "examples" / "scenes" / "hill_trim.toml"
    out_dir = tmp_path / "out"
    assert main(["run", str(scene), "--out", str(out_dir)]) == 0
    first = {p.name: p.read_bytes() for p in (out_dir / "hill_trim").iterdir() if p.name != "timings.json"}
    capsys.readouterr()
    assert main(["run", str(scene), "--out", str(out_dir)]) == 0
    products = [r for r in json.loads((out_dir / "hill_trim" / "timings.json").read_text())["products"]]
    assert len(products) == 7 and all(r["status"] == "cached" for r in products), products
    second = {p.name: p.read_bytes() for p in (out_dir / "hill_trim").iterdir() if p.name != "timings.json"}
    assert second == first and {"trim_parabola.json", "overview.png", "approximation.png", "summary.json"} <= set(first)


def test_curve_leaving_the_domain_is_refused_before_any_work(tmp_path):
    """A trim curve leaving the surface domain is a scene error when the runner is built
    (it used to surface only when the composition ran, after other products)."""
    bad = copy.deepcopy(SCENE)
    bad["curves"]["k"]["control_points"] = [["1/8", "1/8"], ["3", "3/8"], ["3/8", "1/8"]]
    with pytest.raises(ExactCAGDError, match=r"products\[0\]\.only_crossed_by: .*leaves the parameter domain"):
        Runner(parse_scene(bad), tmp_path / "out")
    assert not (tmp_path / "out").exists()


def test_approximation_product_is_exact_with_float_companions(tmp_path):
    """An approximation product: segments over Q(sqrt D) stored as exact strings (parsed by sympy
    here, independently) with float64 companions; the picture gets an error panel."""
    scene = copy.deepcopy(SCENE)
    scene["curves"]["k"]["control_points"] = [["1/10", "1/5"], ["2/5", "9/10"], ["3/5", "1/10"], ["9/10", "4/5"]]
    scene["products"] = [
        {"kind": "approximation", "name": "approx", "surface": "s", "curve": "k", "tol": "1/100"},
        {"kind": "picture", "name": "pic", "of": ["s", "k", "approx"]},
    ]
    path = tmp_path / "small.json"
    path.write_text(json.dumps(scene))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    data = json.loads((tmp_path / "out" / "small" / "approx.json").read_text())["result"]
    assert data["method"] == "parabola" and sp.Rational(data["distance_bound"]) <= sp.Rational(1, 100)
    assert any("homogeneous" in segment for segment in data["segments"]), "no Q(sqrt D) segment exercised"
    for segment in data["segments"]:
        if "homogeneous" in segment:  # coefficients in Q(sqrt D): "a + b*sqrt(D)"
            rows = [[sp.sympify(c) for c in row] for row in segment["homogeneous"]]
            points = [[c / row[-1] for c in row[:-1]] for row in rows]
        else:
            points = [[sp.Rational(c) for c in p] for p in segment["control_points"]]
        for exact, approx in zip(points, segment["control_points_float"]):
            for e, x in zip(exact, approx):
                assert abs(sp.N(e, 30) - x) <= 1e-15 * max(1, abs(x))
    from PIL import Image

    width, _ = Image.open(tmp_path / "out" / "small" / "pic.png").size
    assert width > 1500  # three panels: domain, 3-D, error


def test_fit_approximation_product(tmp_path):
    """method = "fit" in a scene: exact rational segments within the certified bound; the first
    segment starts exactly at S(K(0)), evaluated here by de Boor on the scene's surface."""
    scene = copy.deepcopy(SCENE)
    scene["products"] = [{"kind": "approximation", "name": "approx", "surface": "s", "curve": "k", "tol": "1/1000", "method": "fit"}]
    path = tmp_path / "small.json"
    path.write_text(json.dumps(scene))
    assert main(["run", str(path), "--out", str(tmp_path / "out")]) == 0
    data = json.loads((tmp_path / "out" / "small" / "approx.json").read_text())["result"]
    assert data["method"] == "fit" and sp.Rational(data["distance_bound"]) <= sp.Rational(1, 1000)
    first = [sp.Rational(c) for c in data["segments"][0]["control_points"][0]]
    runner = Runner(parse_scene(copy.deepcopy(SCENE)), tmp_path / "x")
    assert first == [sp.Rational(str(c)) for c in runner.objects["s"].evaluate("1/8", "1/8")]


def test_outputs_get_the_usual_file_mode(tmp_path):
    """Atomic writes go through a private temporary file; the result must not stay 0600."""
    from exactcagd import outputs
    from exactcagd.scenes import serialize

    serialize.atomic_write_text(tmp_path / "x.json", "{}")
    assert (tmp_path / "x.json").stat().st_mode & 0o777 == 0o666 & ~outputs._UMASK
