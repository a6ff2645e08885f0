"""Reference data: deterministic for a seed, identical from the local pool and from a Dask LocalCluster,
and its exact values are right (checked by independent substitution)."""
import json

import pytest
import sympy as sp

from exactcagd.cli import main
from exactcagd.errors import InputError
from exactcagd.scenes.refdata import generate


def _bernstein(points, t):
    n = len(points) - 1
    return [sum(sp.binomial(n, i) * t**i * (1 - t) ** (n - i) * points[i][k] for i in range(n + 1)) for k in range(len(points[0]))]


def test_compose_records_are_exact_and_deterministic():
    lines = generate("compose", 3, seed=7, degrees=(2, 1, 2), jobs=1)
    assert lines == generate("compose", 3, seed=7, degrees=(2, 1, 2), jobs=2)
    assert lines != generate("compose", 3, seed=8, degrees=(2, 1, 2), jobs=1)
    for line in lines:
        rec = json.loads(line)
        curve = [[sp.Rational(c) for c in p] for p in rec["curve"]["control_points"]]
        net = [[[sp.Rational(c) for c in p] for p in row] for row in rec["surface"]["control_net"]]
        image = [[sp.Rational(c) for c in p] for p in rec["image"]["control_points"]]
        assert rec["image"]["degree"] == 2 * (1 + 2)
        t = sp.Rational(2, 7)
        u, v = _bernstein(curve, t)
        l, m = len(net) - 1, len(net[0]) - 1
        surface_point = [
            sum(sp.binomial(l, i) * u**i * (1 - u) ** (l - i) * sp.binomial(m, j) * v**j * (1 - v) ** (m - j) * net[i][j][k]
                for i in range(l + 1) for j in range(m + 1))
            for k in range(3)
        ]
        assert _bernstein(image, t) == surface_point
        # float companions are the correctly rounded values
        assert rec["image"]["control_points_float"][0][2] == float(sp.Rational(rec["image"]["control_points"][0][2]))


def test_local_pool_and_dask_local_cluster_are_byte_identical():
    pytest.importorskip("distributed")
    local = generate("compose", 4, seed=11, degrees=(1, 2, 1), jobs=2)
    on_dask = generate("compose", 4, seed=11, degrees=(1, 2, 1), dask_local=True)
    assert "\n".join(local).encode() == "\n".join(on_dask).encode()


def test_refdata_cli_and_bad_arguments(tmp_path, capsys):
    out = tmp_path / "ref.jsonl"
    assert main(["refdata", "compose", "--count", "2", "--seed", "1", "--degree", "1", "--out", str(out), "--jobs", "1"]) == 0
    assert len(out.read_text().splitlines()) == 2
    assert main(["refdata", "compose", "--degree", "x"]) == 2
    assert "--degree" in capsys.readouterr().err
    with pytest.raises(InputError):
        generate("compose", 0, seed=1, degrees=(1,))
