"""Bad input from Python raises InputError naming the key; no Rust panic ever reaches Python
(a seeded fuzz of 1,500 mutated scene dicts through Scene, solve and solve_many)."""

import math
import random

import pytest

import boltzone
from conftest import random_scene

GOOD = {"model": "slab", "hole": {"radius": 0.1},
        "load": {"outer_radius": 0.31, "pressure": 1.0}, "plates": [{"thickness": 0.1}]}


def with_(path, value):
    """GOOD with the dotted `path` set to `value` (through the binding's own dotted keys)."""
    return {**GOOD, path: value}


@pytest.mark.parametrize("path,value", [
    ("plates[0].thickness", "thick"),       # wrong type
    ("hole.radius", [0.1]),                 # wrong type
    ("load.outer_radius", {"x": 1}),        # wrong type
    ("model", 3),                           # wrong type
    ("plates[0].thickness", -0.1),          # negative thickness
    ("plates[0].thickness", math.nan),      # NaN
    ("hole.radius", math.inf),              # infinite
    ("load.pressure", math.nan),            # NaN
    ("tolerance", 0.0),                     # out of range
    ("units", "furlongs"),                  # unknown unit system
    ("plates[0].material", "unobtainium"),  # unknown material
])
def test_bad_value_names_its_key(path, value):
    with pytest.raises(boltzone.InputError) as e:
        boltzone.Scene(with_(path, value))
    assert e.value.key == path, e.value
    assert path in str(e.value)


@pytest.mark.parametrize("path", ["load.presure", "bogus", "plates[0].thicknes", "joint.mus"])
def test_unknown_key_is_named(path):
    with pytest.raises(boltzone.InputError) as e:
        boltzone.Scene(with_(path, 1.0))
    assert e.value.key == path, e.value
    assert "unknown field" in str(e.value)


def test_keyword_form_and_objects_that_are_not_values():
    with pytest.raises(boltzone.InputError) as e:
        boltzone.Scene(GOOD, tolerance=object())
    assert e.value.key == "tolerance"
    with pytest.raises(boltzone.InputError):
        boltzone.Scene(42)
    with pytest.raises(boltzone.InputError) as e:
        boltzone.Scene(GOOD, **{"plates[3].thickness": 0.1})  # index past the end
    assert e.value.key == "plates[3].thickness"


def test_toml_errors_name_key_and_line(tmp_path):
    p = tmp_path / "bad.toml"
    p.write_text("model = \"slab\"\n[hole]\nradius = -1.0\n[load]\nouter_radius = 0.31\n"
                 "pressure = 1.0\n[[plates]]\nthickness = 0.1\n")
    with pytest.raises(boltzone.InputError) as e:
        boltzone.Scene.from_toml(p)
    assert e.value.key == "hole.radius" and "line 3" in str(e.value), e.value


def test_bad_rows_of_a_batch_are_rows_with_their_error():
    import pandas as pd

    frame = pd.DataFrame({"plates[0].thickness": [0.1, -1.0, math.nan, 0.2]})
    out = boltzone.solve_many(frame, base={k: v for k, v in GOOD.items() if k != "plates"},
                              progress=False)
    assert list(out["error"].isna()) == [True, False, False, True]
    assert all("plates[0].thickness" in m for m in out["error"].dropna())
    assert list(out["converged"]) == [True, False, False, True]


def _junk(rng):
    return rng.choice([None, -1.0, 0.0, 1e308, -1e308, math.nan, math.inf, -math.inf, 1, -7,
                       2 ** 70, "", "steel-304", "peak-a", "two-plate", True, [], [1.0], {},
                       {"E": -1.0, "nu": 0.6}, {"E": 1e-300, "nu": -0.99}, 1e-300, 0.5])


def _mutate(rng, d, depth=0):
    """`d` with one random change somewhere: a value replaced, a key removed or added."""
    d = dict(d)
    if not d or rng.random() < 0.15:
        d[rng.choice(["x", "force", "nut_displacement", "mu", "fixed_edge", "interface",
                      "profile", "outer_radius", "material"])] = _junk(rng)
        return d
    key = rng.choice(sorted(d))
    v = d[key]
    if isinstance(v, dict) and depth < 3 and rng.random() < 0.7:
        d[key] = _mutate(rng, v, depth + 1)
    elif isinstance(v, list) and v and isinstance(v[0], dict) and rng.random() < 0.7:
        d[key] = [_mutate(rng, x, depth + 1) for x in v]
    elif rng.random() < 0.2:
        del d[key]
    else:
        d[key] = _junk(rng)
    return d


def test_fuzz_never_lets_a_panic_or_foreign_error_through():
    rng = random.Random(341)
    dicts = []
    for _ in range(1500):
        d = random_scene(rng)
        for _ in range(rng.randint(1, 3)):
            d = _mutate(rng, d)
        if d.get("model") == "two-plate":
            d["tolerance"] = 5e-2  # keep the FE runs of a CI test short
        dicts.append(d)
    outcomes = {"input": 0, "solver": 0, "ok": 0}
    valid = []
    for d in dicts:
        try:
            boltzone.Scene(d)
        except boltzone.InputError as e:
            assert e.key, e
            outcomes["input"] += 1
            continue
        valid.append(d)
    for d in valid[:300]:
        try:
            r = boltzone.solve(d)
            assert math.isfinite(r.r_o) and math.isfinite(r.r_o_error), d
            outcomes["ok"] += 1
        except (boltzone.InputError, boltzone.SolverError):
            outcomes["solver"] += 1
    out = boltzone.solve_many(dicts[:300], progress=False)
    assert len(out) == 300 and (out["error"].notna() | out["r_o"].notna()).all()
    # the fuzz reaches both sides: rejected input and solved joints
    assert outcomes["input"] > 100 and outcomes["ok"] > 50, outcomes
