"""Shared helpers of the Python tests: the CLI to compare with, a TOML writer for scene
dicts, a seeded generator of random valid scenes, and the timing keys to drop."""

import json
import math
import os
import random
import subprocess
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
MATERIALS = ["steel-304", "steel-1018", "aluminium-2024-t3", "aluminium-6061-t6",
             "titanium-ti-6al-4v", "copper-c11000"]
# mean-pressure scale of each unit system (stress unit), so loads stay of one size
STRESS = {"in-psi-lbf": 1.0e3, "mm-MPa-N": 7.0, "m-Pa-N": 7.0e6}
LENGTH = {"in-psi-lbf": 1.0, "mm-MPa-N": 25.4, "m-Pa-N": 0.0254}
TIMING = {"seconds", "command"}


def cli():
    """The boltzone binary built by `cargo test --release` / `cargo build --release`."""
    path = Path(os.environ.get("BOLTZONE_CLI", REPO / "target" / "release" / "boltzone"))
    if not path.exists():
        pytest.skip("no %s: run `cargo build --release` first" % path)
    return path


def cli_json(*args):
    """The JSON the CLI prints for `args`."""
    out = subprocess.run([str(cli()), *map(str, args)], capture_output=True, text=True,
                         check=False)
    assert out.returncode in (0, 3), out.stderr
    return json.loads(out.stdout)


def untimed(v):
    """`v` without the keys that differ by nature between two runs (wall times, the command
    line): `seconds`, `seconds_*` and `command`, at every depth."""
    if isinstance(v, dict):
        return {k: untimed(x) for k, x in v.items()
                if k not in TIMING and not k.startswith("seconds_")}
    if isinstance(v, list):
        return [untimed(x) for x in v]
    return v


def _toml_value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, dict):
        return "{ " + ", ".join("%s = %s" % (k, _toml_value(x)) for k, x in v.items()) + " }"
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    raise TypeError(v)


def to_toml(scene):
    """A scene dict as TOML text (top-level values, tables, then arrays of tables)."""
    lines, tables = [], []
    for k, v in scene.items():
        if isinstance(v, dict):
            tables.append("[%s]" % k)
            tables += ["%s = %s" % (kk, _toml_value(x)) for kk, x in v.items()]
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for item in v:
                tables.append("[[%s]]" % k)
                tables += ["%s = %s" % (kk, _toml_value(x)) for kk, x in item.items()]
        else:
            lines.append("%s = %s" % (k, _toml_value(v)))
    return "\n".join(lines + tables) + "\n"


def random_scene(rng: random.Random):
    """A random valid scene: any unit system, model and load kind, library or given materials,
    cheap tolerances (each solves in milliseconds to a few tens of them)."""
    units = rng.choice(list(STRESS))
    model = rng.choice(["slab", "single-plate", "single-plate", "two-plate", "two-plate"])
    l = LENGTH[units]
    a = rng.uniform(0.05, 0.2) * l
    b = a * rng.uniform(1.6, 4.0)
    d = a * rng.uniform(0.4, 3.0)
    scene = {"units": units, "model": model,
             "tolerance": rng.choice([5e-4, 1e-3, 5e-3]) if model != "two-plate" else 5e-3,
             "hole": {"radius": a}}
    load = {"outer_radius": b}
    if rng.random() < 0.5:
        load["pressure"] = STRESS[units] * rng.uniform(0.5, 2.0)
    else:
        load["force"] = STRESS[units] * rng.uniform(0.5, 2.0) * math.pi * (b * b - a * a)
    if rng.random() < 0.3:
        load["profile"] = rng.choice(["uniform", "peak-a", "peak-b"])
    scene["load"] = load
    if rng.random() < 0.5:
        mat = rng.choice(MATERIALS)
    else:
        mat = {"E": 2.0e4 * STRESS[units] * rng.uniform(0.5, 2.0), "nu": rng.uniform(0.2, 0.4)}
    plates = [{"thickness": d, "material": mat}]
    if model == "two-plate" and rng.random() < 0.3:
        plates.append({"thickness": d * rng.uniform(0.5, 2.0)})
    scene["plates"] = plates
    if model == "two-plate":
        scene["joint"] = {"outer_radius": b * rng.uniform(3.0, 6.0)}
    return scene
