"""Type stubs of the `flapwright` package (see its module docstring)."""

import os
from collections.abc import Iterator, Mapping
from typing import Any, Iterable, Optional, Sequence, Union

__version__: str

Scene = Union[str, os.PathLike[str], dict[str, Any]]

class DesignError(Exception):
    """A design that could not be made; the message holds the whole chain of causes."""

class SceneError(DesignError):
    """A scene with problems."""

    problems: tuple[tuple[Optional[str], Optional[int], Optional[int], str, str], ...]
    """Each problem as (file, line, col, key, message); file, line and col are None where
    the problem has no place in a file."""

class Record(Mapping[str, Any]):
    """A read-only mapping whose keys are also attributes, nested; values converted when
    first read (lists to numpy arrays or Tables)."""

    def __init__(self, raw: Optional[dict[str, Any]] = ..., **values: Any) -> None: ...
    def __getitem__(self, key: str) -> Any: ...
    def __iter__(self) -> Iterator[str]: ...
    def __len__(self) -> int: ...
    def __getattr__(self, name: str) -> Any: ...
    def to_dict(self) -> dict[str, Any]:
        """The values as the report has them (plain dicts, lists and numbers)."""
    @staticmethod
    def wrap(value: Any) -> Any: ...

class Table(Record):
    """Rows of one shape as columns: each key a numpy array (or a Table) with a value a row."""

    def __init__(self, rows: list[dict[str, Any]]) -> None: ...
    @property
    def rows(self) -> int: ...
    def row(self, i: int) -> Record: ...
    def to_frame(self) -> Any: ...

def design(scene: Scene) -> Record:
    """Designs the scene in memory: the report (docs/report.md)."""

def check(scene: Scene) -> Record:
    """Runs only what the interference check needs: the report."""

def study(scene: Scene, kinds: Sequence[str] = ..., stations: Sequence[str] = ...) -> Record:
    """The trade study of the synthesised kinds (study.json)."""

def sweep(
    scene: Scene,
    vary: Union[str, Iterable[str], None] = ...,
    variants: Any = ...,
    shard: Optional[str] = ...,
) -> Any:
    """Every variant designed in parallel: a pandas DataFrame (CSV text without pandas)."""

def thesis_sweep(samples: int = ..., load: str = ...) -> Record:
    """The thesis track's lean deployment sweep: numpy columns by name, and ``stopped``."""
