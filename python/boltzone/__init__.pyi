"""Type stubs of boltzone (units: see the module docstring and docs/python.md)."""

import os
from typing import Any, Callable, Dict, Iterable, List, Mapping, Optional, Union

import pandas

from ._boltzone import InputError as InputError, SolverError as SolverError

__version__: str
MANY_COLUMNS: Dict[str, str]

class NotConverged(RuntimeError):
    result: "Result"
    def __init__(self, result: "Result") -> None: ...

class Interrupted(KeyboardInterrupt):
    partial: pandas.DataFrame
    def __init__(self, partial: pandas.DataFrame) -> None: ...

class Scene:
    def __init__(self, scene: Union[None, "Scene", Mapping[str, Any]] = ..., **keys: Any) -> None: ...
    @classmethod
    def from_toml(cls, path: Union[str, "os.PathLike[str]"]) -> "Scene": ...
    def to_dict(self) -> Dict[str, Any]: ...
    def replace(self, **keys: Any) -> "Scene": ...
    def __getitem__(self, key: str) -> Any: ...

class Result:
    r_o: float
    """Separation radius R_o (length unit)."""
    r_o_error: float
    """Estimated absolute error of R_o (length unit)."""
    converged: bool
    units: str
    length_unit: str
    model: str
    method: str
    version: str
    inputs: Dict[str, Any]
    plan: List[Dict[str, Any]]
    command: str
    seconds: float
    full_contact: bool
    nut_deflection: float
    joint_conductance: float
    conductance_unit: str
    heat_passes: int
    heat_flow: float
    heat_flow_unit: str
    def to_dict(self) -> Dict[str, Any]: ...
    @property
    def interface(self) -> Optional[pandas.DataFrame]: ...
    @property
    def midplane(self) -> Optional[pandas.DataFrame]: ...
    @property
    def field(self) -> Any: ...  # meshio.Mesh | None

def solve(scene: Union[Scene, Mapping[str, Any]], strict: bool = ...) -> Result: ...
def solve_many(
    scenes: Union[pandas.DataFrame, Iterable[Union[Scene, Mapping[str, Any]]]],
    threads: Optional[int] = ...,
    progress: Union[bool, Callable[[int, int], Any]] = ...,
    base: Union[None, Scene, Mapping[str, Any]] = ...,
) -> pandas.DataFrame: ...
def materials() -> pandas.DataFrame: ...
def table1(tol: float = ..., hankel: bool = ..., raw: bool = ...) -> Any: ...
def table2(tol: float = ..., interface: str = ..., raw: bool = ...) -> Any: ...
def reference() -> Dict[str, Any]: ...
