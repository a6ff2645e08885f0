"""Scene validation: every malformed or hostile scene is rejected before any work, naming the key."""
import copy
import json

import pytest

from exactcagd.errors import InputError
from exactcagd.scenes.build import parse_height
from exactcagd.scenes.runner import Runner
from exactcagd.scenes.spec import SceneError, load_scene, parse_scene
from exactcagd.exact.scalars import to_rational

BASE = {
    "scene": {"name": "t", "float_policy": "reject"},
    "surfaces": {
        "s": {
            "type": "bspline",
            "knots_u": [0, 0, 0, 1, 1, 1],
            "knots_v": [0, 0, 1, 1],
            "control_net": {"generator": "grid", "size": [3, 2], "z": "x*y"},
        }
    },
    "curves": {"k": {"type": "bezier", "control_points": [["1/4", "1/4"], ["3/4", "1/2"]]}},
    "products": [{"kind": "patches", "surface": "s"}],
}


def scene_with(path, value):
    data = copy.deepcopy(BASE)
    target = data
    for key in path[:-1]:
        target = target[key]
    if value is KeyError:
        del target[path[-1]]
    else:
        target[path[-1]] = value
    return data


def test_base_scene_is_valid_and_builds_exact_objects(tmp_path):
    scene = parse_scene(copy.deepcopy(BASE))
    runner = Runner(scene, tmp_path)
    surface = runner.objects["s"]
    # grid generator: control point (i/2, j/1, x*y) exactly
    assert surface.control_net[1][1] == (to_rational("1/2"), to_rational(1), to_rational("1/2"))


@pytest.mark.parametrize(
    "path, value, fragment",
    [
        (("scene", "colour"), "red", "scene.colour: unknown key"),
        (("surfaces", "s", "knots_u"), [0, 0, 1, 1, 1, 1], "knots_u"),
        (("surfaces", "s", "knots_u"), [0, 0, 0, 1, 1, 1, 1] * 10, "degree"),
        (("surfaces", "s", "type"), "nurbs", "surfaces.s.type"),
        (("surfaces", "s", "control_net"), [[[0, 0, 0]], [[1, 0, 0], [1, 1, 1]]], "ragged"),
        (("surfaces", "s", "control_net"), {"generator": "grid", "size": [100000, 2]}, "size"),
        (("surfaces", "s", "control_net"), {"generator": "grid", "size": [3, 2], "z": "__import__('os')"}, "only numbers"),
        (("surfaces", "s", "control_net"), {"generator": "grid", "size": [3, 2], "z": "x**1000"}, "exponent"),
        (("curves", "k", "control_points"), [[0.25, "1/4"], ["3/4", "1/2"]], "reject"),
        (("curves", "k", "control_points"), [["nan", 0], [1, 1]], "not a finite"),
        (("curves", "k", "weights"), [1, 0], "positive"),
        (("curves", "k", "weights"), [1], "weights"),
        (("products",), [], "products"),
        (("products",), [{"kind": "patches", "surface": "nope"}], "no surface named 'nope'"),
        (("products",), [{"kind": "explode"}], "kind"),
        (("products",), [{"kind": "patches", "surface": "s", "name": "../../etc/passwd"}], "names are"),
        (("products",), [{"kind": "patches", "surface": "s", "extra": 1}], "unknown key"),
        (("products",), [{"kind": "approximation", "surface": "s", "curve": "k", "tol": "-1"}], "positive"),
        (("products",), [{"kind": "picture", "of": ["ghost"]}], "ghost"),
        (("products",), [{"kind": "patches", "surface": "s"}] * 100, "limit"),
    ],
)
def test_bad_scenes_are_rejected_with_the_key(path, value, fragment, tmp_path):
    with pytest.raises(SceneError) as info:
        Runner(parse_scene(scene_with(path, value)), tmp_path)
    assert fragment in str(info.value)
    assert isinstance(info.value, InputError)
    assert not any(tmp_path.iterdir()), "nothing may be written for a bad scene"


def test_json_nan_and_bad_suffix(tmp_path):
    bad = tmp_path / "s.json"
    bad.write_text('{"scene": {"name": "x"}, "products": [NaN]}')
    with pytest.raises(SceneError, match="NaN"):
        load_scene(bad)
    other = tmp_path / "s.yaml"
    other.write_text("x: 1")
    with pytest.raises(SceneError, match="end in"):
        load_scene(other)


def test_exact_float_policy_takes_binary_value(tmp_path):
    data = scene_with(("curves", "k", "control_points"), [[0.1, 0.25], [0.75, 0.5]])
    data["scene"]["float_policy"] = "exact"
    runner = Runner(parse_scene(data), tmp_path)
    assert runner.objects["k"].control_points[0][0] == to_rational("3602879701896397/36028797018963968")


def test_height_expression_is_exact_and_safe():
    f = parse_height("(x - 1/3)**2 * y", "z")
    assert f(to_rational(1), to_rational(3)) == to_rational("4/3")
    for hostile in ("open('x')", "x.__class__", "[x]", "x if y else 1", "lambda: 1"):
        with pytest.raises(SceneError):
            parse_height(hostile, "z")


def test_shipped_scenes_validate():
    from pathlib import Path

    scenes = sorted((Path(__file__).resolve().parents[1] / "examples" / "scenes").glob("*.toml"))
    assert scenes
    for path in scenes:
        assert load_scene(path).products
    json.dumps([str(p) for p in scenes])


def test_json_schema_agrees_with_the_validator():
    """The published JSON Schema accepts every shipped scene and rejects the hostile ones the
    validator rejects for shape reasons (unknown keys, bad names, bad kinds)."""
    jsonschema = pytest.importorskip("jsonschema")
    try:
        import tomllib
    except ModuleNotFoundError:  # Python 3.10: tomllib is the standard library's copy of tomli
        import tomli as tomllib
    from pathlib import Path

    import exactcagd.scenes as pkg

    schema = json.loads((Path(pkg.__file__).parent / "scene.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    for path in (Path(__file__).resolve().parents[1] / "examples" / "scenes").glob("*.toml"):
        assert not list(validator.iter_errors(tomllib.loads(path.read_text()))), path
    assert not list(validator.iter_errors(BASE))
    for path, value in [
        (("scene", "colour"), "red"),
        (("products",), [{"kind": "explode"}]),
        (("products",), [{"kind": "patches", "surface": "s", "name": "../x"}]),
        (("curves", "k", "control_points"), [["one", 0], [1, 1]]),
    ]:
        data = scene_with(path, value)
        assert list(validator.iter_errors(data)), path
        with pytest.raises(SceneError):
            Runner(parse_scene(data), Path("/nonexistent"))
