"""Python and the CLI give bit-identical answers: every JSON key of `boltzone solve --json`,
`table1 --json` and `table2 --json` (timing keys and the command line aside), compared with
`==` on the parsed floats (the CLI prints shortest round-trip decimals, so equal text is equal
bits)."""

import random

import boltzone
from conftest import REPO, cli_json, random_scene, to_toml, untimed


def test_table1_is_the_cli_table1():
    assert untimed(boltzone.table1(raw=True)) == untimed(cli_json("table1", "--json"))


def test_table2_is_the_cli_table2_both_interfaces():
    assert untimed(boltzone.table2(raw=True)) == untimed(cli_json("table2", "--json"))
    py = boltzone.table2(interface="frictionless", raw=True)
    assert untimed(py) == untimed(cli_json("table2", "--json", "--interface", "frictionless"))


def test_table1_frame_holds_the_raw_rows():
    frame, raw = boltzone.table1(), boltzone.table1(raw=True)
    assert len(frame) == len(raw) == 12
    assert list(frame["ours.two.value"]) == [r["ours"]["two"]["value"] for r in raw]


def test_example_scenes_equal_the_cli(tmp_path, monkeypatch):
    # the scenes' outputs (relative paths) land in a scratch folder, not the repository
    monkeypatch.chdir(tmp_path)
    for path in sorted((REPO / "examples" / "scenes").glob("*.toml")):
        scene = boltzone.Scene.from_toml(path)
        if scene["sweep"] if "sweep" in scene.to_dict() else False:
            continue
        want = untimed(cli_json("solve", "--json", path))
        got = boltzone.solve(scene).to_dict()
        assert set(got) == set(want) | {"seconds", "command"}, path
        assert untimed(got) == want, path


def test_fifty_random_scenes_equal_the_cli(tmp_path):
    rng = random.Random(34)
    models = set()
    for i in range(50):
        scene = random_scene(rng)
        path = tmp_path / ("scene_%d.toml" % i)
        path.write_text(to_toml(scene))
        want = untimed(cli_json("solve", "--json", path))
        from_dict = boltzone.solve(boltzone.Scene(scene)).to_dict()
        from_file = boltzone.solve(boltzone.Scene.from_toml(path)).to_dict()
        assert set(from_dict) == set(want) | {"seconds", "command"}, scene
        assert untimed(from_dict) == want, scene
        assert untimed(from_file) == want, scene
        models.add((want["model"], want["method"]))
    # the draw reaches every model and both two-plate routes' selection logic
    assert {m for m, _ in models} == {"slab", "single-plate", "two-plate"}, models
