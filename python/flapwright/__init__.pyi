"""Type stubs of the `flapwright` package (see its module docstring)."""

import os
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

class Record(dict[str, Any]):
    """A dict whose keys are also attributes, nested."""

    def __getattr__(self, name: str) -> Any: ...
    @staticmethod
    def wrap(value: Any) -> Any: ...

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
