"""boltzone from Python: where two bolted plates stay in contact, and under what pressure.

The Rust library boltzone (Gould & Mikic, MIT 1970, rebuilt) bound with PyO3: no subprocess,
no JSON text. A scene is the dict of a scene file (``examples/scenes/*.toml``) with the file's
keys and units; ``solve`` answers one, ``solve_many`` a table of them in parallel.

Units: every number of a scene is in its ``units`` (``"in-psi-lbf"`` default, ``"mm-MPa-N"``,
``"m-Pa-N"``): lengths in in / mm / m, stresses in psi / MPa / Pa, forces in lbf / N; every
result comes back in the same units (``length_unit`` says which).

>>> import boltzone
>>> s = boltzone.Scene(model="slab", hole={"radius": 0.1},
...                    load={"outer_radius": 0.31, "pressure": 1.0},
...                    plates=[{"thickness": 0.1}])
>>> r = boltzone.solve(s)
>>> r.converged and 0.31 < r.r_o < 0.6
True

Exceptions: ``InputError`` (bad input; ``.key`` names the scene key), ``SolverError`` (a
solver failed on valid input), ``NotConverged`` (only with ``strict=True``; ``.result``),
``Interrupted`` (a ``KeyboardInterrupt`` raised by ``solve_many`` on Ctrl-C; ``.partial`` holds
the finished rows).
"""

import copy
import math
import os
import sys
import tempfile
import time
from pathlib import Path
from typing import Any, Callable, Dict, List, Mapping, Optional, Union

from . import _boltzone as _core
from ._boltzone import InputError, SolverError

__all__ = [
    "Scene",
    "Result",
    "solve",
    "solve_many",
    "materials",
    "table1",
    "table2",
    "reference",
    "InputError",
    "SolverError",
    "NotConverged",
    "Interrupted",
    "MANY_COLUMNS",
]

__version__ = "0.1.0"


class NotConverged(RuntimeError):
    """``solve(..., strict=True)`` on a result whose error estimate missed the tolerance.

    ``.result`` is the :class:`Result` (``r_o``, ``r_o_error`` in ``length_unit``)."""

    def __init__(self, result: "Result"):
        self.result = result
        super().__init__(
            "R_o = %r +- %r %s did not reach the relative tolerance %r"
            % (result.r_o, result.r_o_error, result.length_unit, result.inputs["tolerance"])
        )


class Interrupted(KeyboardInterrupt):
    """Ctrl-C during ``solve_many``: raised within 1 s; ``.partial`` is the DataFrame of the
    rows that had finished (same columns as a full result, the input's index kept)."""

    def __init__(self, partial):
        self.partial = partial
        super().__init__("solve_many interrupted: %d rows finished" % len(partial))


class Scene:
    """A joint and the question: the keys of a scene file, in the scene's units.

    ``Scene(dict)``, ``Scene(**keys)`` or both (keyword arguments win). Top-level keys may be
    dotted paths, as in a ``[sweep]``: ``Scene(base, **{"plates[0].thickness": 0.2})``. A key
    set to ``None`` is left out (the file's default). The scene is checked at once: bad input
    raises :class:`InputError` naming the key.

    Keys (see ``docs/python.md`` and ``docs/scenes``): ``units``, ``model`` (``two-plate``,
    ``single-plate``, ``slab``), ``method`` (``auto``, ``fem``, ``hankel``, ``table``), ``tolerance``
    (relative, default 5e-4), ``hole.radius`` (length), ``load.outer_radius`` (length),
    ``load.force`` (force) | ``load.pressure`` (stress) | ``load.nut_displacement`` (length),
    ``load.profile``, ``plates`` (list of ``{thickness (length), material (name or
    {E (stress), nu})}``), ``joint.outer_radius`` (length), ``joint.interface``, ``joint.mu``,
    ``joint.fixed_edge``, ``outputs`` (``interface_pressure``, ``field``, ``midplane``: paths),
    ``heat``, ``temperature``.
    """

    __slots__ = ("_data", "_understood", "_core")

    def __init__(self, scene: Union[None, "Scene", Mapping[str, Any]] = None, **keys: Any):
        if scene is None:
            data: Dict[str, Any] = {}
        elif isinstance(scene, Scene):
            data = copy.deepcopy(scene._data)
        elif isinstance(scene, Mapping):
            data = copy.deepcopy(dict(scene))
        else:
            raise _input_error("(scene)", "a %s is not a scene (a dict or a Scene)"
                               % type(scene).__name__)
        data.update(keys)
        self._data = data
        self._core, self._understood = _core.check_scene(data)

    @classmethod
    def from_toml(cls, path: Union[str, os.PathLike]) -> "Scene":
        """The scene of a TOML scene file (errors name the key and the line)."""
        text = Path(path).read_text(encoding="utf-8")
        return cls(_core.scene_file(text))

    def to_dict(self) -> Dict[str, Any]:
        """The scene as understood: every default filled in (the ``inputs`` of a result)."""
        return copy.deepcopy(self._understood)

    def replace(self, **keys: Any) -> "Scene":
        """A copy with ``keys`` set (dotted keys allowed: ``**{"load.force": 200.0}``)."""
        return Scene(self, **keys)

    def __getitem__(self, key: str) -> Any:
        return self._understood[key]

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Scene) and self._understood == other._understood

    def __repr__(self) -> str:
        return "Scene(%r)" % (self._data,)

    def __getstate__(self):
        return self._data

    def __setstate__(self, data):
        self._data = data
        self._core, self._understood = _core.check_scene(data)


class Result:
    """The answer to a scene, in the scene's units.

    Attributes are the keys of ``boltzone solve --json``: ``r_o`` and ``r_o_error`` (length
    unit), ``converged`` (whether ``r_o_error <= tolerance * r_o``), ``units``, ``length_unit``,
    ``model``, ``method`` (what ``auto`` picked), ``version``, ``inputs`` (the scene as
    understood), ``plan`` (routes run and skipped, ``seconds`` each), ``command``, ``seconds``
    (wall time of the call), and where they apply ``full_contact``, ``nut_deflection`` (length),
    ``joint_conductance`` (``conductance_unit``), ``heat_passes``, ``heat_flow``
    (``heat_flow_unit``). ``to_dict()`` gives them all; ``interface``, ``midplane`` (pandas
    DataFrames, unit-named columns) and ``field`` (a meshio Mesh) when the scene asks for them.
    """

    __slots__ = ("_answer",)

    def __init__(self, answer):
        self._answer = answer  # held in Rust: keys are converted when read

    def __getattr__(self, name: str) -> Any:
        if name.startswith("__"):
            raise AttributeError(name)
        try:
            return self._answer.get(name)
        except KeyError:
            raise AttributeError(name) from None

    def __dir__(self):
        return sorted(set(super().__dir__()) | set(self._answer.keys()))

    def __repr__(self) -> str:
        return "Result(r_o=%r +- %r %s, converged=%r, %s, %s)" % (
            self.r_o, self.r_o_error, self.length_unit, self.converged, self.model, self.method)

    def to_dict(self) -> Dict[str, Any]:
        """Every key of ``boltzone solve --json``, as a new dict."""
        return self._answer.to_dict()

    @property
    def interface(self):
        """The two-plate interface curve as a DataFrame: ``r [L]``, ``p [S]`` (pressure,
        compression > 0), ``g [L]`` (gap), ``tau [S]`` (interface shear on the upper plate, 0
        in the frictionless model) and with friction ``s [L]`` (slip u_upper − u_lower) and
        ``state [-]`` (0 open, 1 stick, 2 slip), L and S the scene's length and stress units
        (the columns of ``boltzone solve``'s CSV); ``None`` unless the scene sets
        ``outputs.interface_pressure``."""
        c = self._answer.interface()
        if c is None:
            return None
        import pandas as pd

        l, s = self._answer.symbols()
        columns = {"r [%s]" % l: c["radius"], "p [%s]" % s: c["pressure"],
                   "g [%s]" % l: c["gap"], "tau [%s]" % s: c["shear"]}
        if "slip" in c:
            columns.update({"s [%s]" % l: c["slip"], "state [-]": c["state"]})
        return pd.DataFrame(columns)

    @property
    def midplane(self):
        """The midplane normal stress as a DataFrame: ``r [L]``, ``sigma_z [S]`` (compression
        negative) and, from the slab, ``sigma_z_error [S]``; ``None`` unless asked."""
        m = self._answer.midplane()
        if m is None:
            return None
        import pandas as pd

        l, s = self._answer.symbols()
        cols = {"r [%s]" % l: m["radius"], "sigma_z [%s]" % s: m["sigma_z"]}
        if m["error"] is not None:
            cols["sigma_z_error [%s]" % s] = m["error"]
        return pd.DataFrame(cols)

    @property
    def field(self):
        """The finest mesh's field as a ``meshio.Mesh`` (x = r, y = z, z = 0; lengths in the
        length unit, stresses in the stress unit, compression negative); point data
        ``displacement`` and the scalars (``sigma_r``, ..., ``von_mises``), cell data ``plate``;
        ``None`` unless the scene sets ``outputs.field``."""
        g = self._answer.field()
        if g is None:
            return None
        import meshio
        import numpy as np

        pts = np.zeros((len(g["points"]), 3))
        pts[:, :2] = np.asarray(g["points"], dtype=float).reshape(-1, 2)
        disp = np.zeros_like(pts)
        disp[:, :2] = np.asarray(g["displacement"], dtype=float).reshape(-1, 2)
        blocks, plates = [], []
        for kind, n in (("quad", 4), ("quad9", 9)):
            idx = [i for i, c in enumerate(g["cells"]) if len(c) == n]
            if idx:
                blocks.append((kind, np.asarray([g["cells"][i] for i in idx], dtype=np.int64)))
                plates.append(np.asarray([g["plate"][i] for i in idx], dtype=np.int32))
        point_data = {"displacement": disp}
        point_data.update({k: np.asarray(v, dtype=float) for k, v in g["scalars"].items()})
        return meshio.Mesh(pts, blocks, point_data=point_data, cell_data={"plate": plates})


def _as_scene(scene: Union[Scene, Mapping[str, Any]]) -> Scene:
    return scene if isinstance(scene, Scene) else Scene(scene)


def _write_whole(path: Union[str, os.PathLike], frame) -> None:
    """Writes the DataFrame ``frame`` as CSV to ``path`` whole or not at all."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=str(path.parent or "."), prefix=path.name, suffix=".tmp")
    try:
        with os.fdopen(fd, "w", newline="") as f:
            frame.to_csv(f, index=False, float_format="%.17g")
        os.replace(tmp, path)
    except BaseException:
        os.unlink(tmp)
        raise


def solve(scene: Union[Scene, Mapping[str, Any]], strict: bool = False) -> Result:
    """Answers one scene (a :class:`Scene` or its dict) with the library, the GIL released.

    Writes the files the scene's ``[outputs]`` names, as ``boltzone solve`` does: ``field``
    (VTU), ``interface_pressure`` and ``midplane`` (CSV with the unit-named columns of
    ``Result.interface`` / ``Result.midplane``). ``strict=True`` raises :class:`NotConverged`
    when ``r_o_error`` missed the tolerance; otherwise check ``converged``."""
    scene = _as_scene(scene)
    result = Result(_core.solve(scene._core))
    outputs = scene._understood["outputs"]
    if "interface_pressure" in outputs or "midplane" in outputs:
        for key, frame in (("interface_pressure", "interface"), ("midplane", "midplane")):
            if outputs.get(key) is not None and getattr(result, frame) is not None:
                _write_whole(outputs[key], getattr(result, frame))
    if strict and not result.converged:
        raise NotConverged(result)
    return result


#: The columns ``solve_many`` adds to its input (keys of ``solve --json``; ``error`` is the
#: failure message of a row, None where it succeeded). Lengths in the row's ``length_unit``.
MANY_COLUMNS = {
    "r_o": "float64",
    "r_o_error": "float64",
    "converged": "bool",
    "full_contact": "boolean",
    "nut_deflection": "float64",
    "joint_conductance": "float64",
    "conductance_unit": "string",
    "heat_passes": "Int64",
    "heat_flow": "float64",
    "heat_flow_unit": "string",
    "units": "string",
    "length_unit": "string",
    "model": "string",
    "method": "string",
    "version": "string",
    "seconds": "float64",
    "error": "string",
}


class _Bar:
    """A one-line progress bar on stderr (``\\r``-updated; a notebook shows it too)."""

    def __init__(self):
        self.start = time.perf_counter()

    def __call__(self, done: int, total: int) -> None:
        width = 30
        k = width * done // max(total, 1)
        sys.stderr.write("\rsolve_many [%s%s] %d/%d joints, %.1f s" % (
            "#" * k, "." * (width - k), done, total, time.perf_counter() - self.start))
        if done == total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def _input_error(key: str, reason: str) -> InputError:
    err = InputError("key `%s`: %s" % (key, reason))
    err.key = key
    return err


def _base_dict(base) -> Dict[str, Any]:
    if base is None:
        return {}
    return copy.deepcopy(base._data if isinstance(base, Scene) else dict(base))


def _records(frame, base) -> List[Dict[str, Any]]:
    """One scene dict per DataFrame row: the base's keys, then the row's dotted keys."""
    base_dict = _base_dict(base)
    out = []
    for rec in frame.to_dict("records"):
        # a shallow copy: the scene reader only reads the dict, so the base's tables are shared
        d = dict(base_dict)
        d.update({k: v for k, v in rec.items() if v is not None})
        out.append(d)
    return out


def _frame(inputs, columns: Dict[str, Any], errors: List[Optional[str]], keep):
    """The DataFrame of ``keep`` rows (a sequence of row numbers, or None: all): the input's
    columns, then :data:`MANY_COLUMNS` built from the binding's ``columns`` (bytes for the
    ``float64`` and ``bool`` columns, lists for the others)."""
    import numpy as np
    import pandas as pd

    rows = None if keep is None else np.asarray(keep, dtype=np.intp)
    out: Dict[str, Any] = {}
    for k, dtype in MANY_COLUMNS.items():
        if k == "error":
            v: Any = errors
        elif dtype in ("float64", "bool"):
            v = np.frombuffer(columns[k], dtype="<f8" if dtype == "float64" else np.bool_)
        else:
            v = columns[k]
        if rows is not None:
            v = v[rows] if isinstance(v, np.ndarray) else [v[i] for i in rows]
        out[k] = pd.Series(v, dtype=dtype, copy=isinstance(v, np.ndarray))
    frame = pd.DataFrame(out)
    if inputs is not None:
        head = inputs.iloc[list(range(len(frame))) if rows is None else rows]
        frame.index = head.index
        frame = pd.concat([head, frame], axis=1)
    return frame


def solve_many(
    scenes,
    threads: Optional[int] = None,
    progress: Union[bool, Callable[[int, int], Any]] = True,
    base: Union[None, Scene, Mapping[str, Any]] = None,
):
    """Solves many joints in parallel in Rust (a rayon pool of ``threads`` threads, default
    all cores; the GIL released) and returns a pandas DataFrame, one row per joint.

    ``scenes``: a DataFrame whose columns are dotted scene keys (``hole.radius``,
    ``load.force``, ``plates[0].thickness``, ...; ``base`` gives the keys the columns leave
    out), or an iterable of :class:`Scene` / dicts. The result holds the input's columns (and
    index) followed by :data:`MANY_COLUMNS`: ``r_o``, ``r_o_error``, ``converged``, ... named
    as the keys of ``boltzone solve --json`` and in each row's ``length_unit``. A joint that
    fails is a row with ``error`` set (the message names the key) and ``converged`` False; the
    batch goes on. ``progress``: True draws a bar on stderr, a callable gets ``(done, total)``.

    Ctrl-C stops the batch within 1 s and raises :class:`Interrupted` (a KeyboardInterrupt)
    whose ``.partial`` holds the finished rows. A plain function of a pandas partition, so
    ``dask.dataframe.map_partitions(boltzone.solve_many, base=..., progress=False)`` runs it
    on a cluster (``python/examples/fleet_dask.py``)."""
    import pandas as pd

    if isinstance(scenes, pd.DataFrame):
        inputs = scenes
        dicts = _records(scenes, base)
    else:
        inputs = None
        dicts = []
        for s in scenes:
            if isinstance(s, Scene) and base is None:
                d = s._core
            elif isinstance(s, Scene):
                d = s._data
            elif isinstance(s, Mapping):
                d = dict(s)
            else:
                raise _input_error("(scenes)", "a %s is not a scene" % type(s).__name__)
            if base is not None:
                merged = _base_dict(base)
                merged.update(d)
                d = merged
            dicts.append(d)
    if threads is not None and (not isinstance(threads, int) or threads < 1):
        raise _input_error("threads", "%r must be a positive integer (or None: all cores)"
                               % (threads,))
    callback = _Bar() if progress is True else (progress or None)
    keys = [(k, d) for k, d in MANY_COLUMNS.items() if k != "error"]
    columns, state, errors, stopped = _core.solve_many(dicts, keys, threads or 0, callback)
    if stopped is not None:
        finished = [i for i, s in enumerate(state) if s != 0]
        if isinstance(stopped, KeyboardInterrupt):
            raise Interrupted(_frame(inputs, columns, errors, finished)) from stopped
        raise stopped
    return _frame(inputs, columns, errors, None)


def _flat(rows: List[Dict[str, Any]]):
    import pandas as pd

    return pd.json_normalize(rows)


def materials():
    """The scene material library as a DataFrame: ``name``, ``E [Pa]``, ``nu``,
    ``expansion [1/K]``, ``conductivity [W/(m K)]``, ``hardness [HB]``, ``source``."""
    import pandas as pd

    return pd.DataFrame(_core.materials())


def table1(tol: float = 5e-4, hankel: bool = True, raw: bool = False):
    """The report's Table 1 recomputed (R_o/A of the single plate and of the two-plate model,
    the discrepancy, the rules of thumb) at relative tolerance ``tol`` per R_o; lengths in
    inches. A DataFrame with dotted columns (``ours.two.value``, ``report.two``, ...), or with
    ``raw=True`` the rows exactly as ``boltzone table1 --json`` prints them."""
    rows = _core.table1(float(tol), bool(hankel))
    return rows if raw else _flat(rows)


def table2(tol: float = 5e-4, interface: str = "welded", raw: bool = False):
    """The report's Table 2 recomputed (unequal plate pairs; ``interface`` ``welded``, the
    report's, or ``frictionless``); lengths in inches. A DataFrame with dotted columns, or with
    ``raw=True`` the rows exactly as ``boltzone table2 --json`` prints them."""
    if interface not in ("welded", "frictionless"):
        raise _input_error("interface", "%r: welded or frictionless" % (interface,))
    rows = _core.table2(float(tol), interface == "welded")
    return rows if raw else _flat(rows)


def reference() -> Dict[str, Any]:
    """The report's printed Tables 1 and 2 (as printed in 1970; lengths in inches)."""
    return _core.reference()
