"""Flapwright from Python: design, check, study and sweep a wing's flap mechanisms.

Each function takes a scene as a path to a TOML file, as TOML text, or as a dict of the
same tables, and designs it in memory (no files written). Results are `Record`s: dicts
whose keys are also attributes (``d.interference.passes``), with the report's lists of
numbers as they are in ``report.json`` (docs/report.md). ``sweep`` returns a pandas
DataFrame with the columns of ``flapwright sweep``'s table (docs/commands.md).

Problems with a scene raise ``SceneError``, whose ``problems`` lists
``(file, line, col, key, message)`` as the command line prints them; any other failure
raises ``DesignError`` (its base class).
"""

from __future__ import annotations

import io
import json
import os
from typing import Any, Iterable, Optional, Sequence, Union

from . import _native
from ._native import DesignError, SceneError

__all__ = ["design", "check", "study", "sweep", "Record", "DesignError", "SceneError", "__version__"]
__version__ = _native.__version__

Scene = Union[str, "os.PathLike[str]", dict]


class Record(dict):
    """A dict whose keys are also attributes, nested (``report.interference.passes``)."""

    def __getattr__(self, name: str) -> Any:
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    @staticmethod
    def wrap(value: Any) -> Any:
        if isinstance(value, dict):
            return Record((k, Record.wrap(v)) for k, v in value.items())
        if isinstance(value, list):
            return [Record.wrap(v) for v in value]
        return value


def _scene(scene: Scene) -> tuple[str, str, Optional[str]]:
    """The scene's TOML text, the label its problems name, and the folder of its files."""
    if isinstance(scene, dict):
        return _native.toml_of_json(json.dumps(scene)), "(dict)", None
    if isinstance(scene, os.PathLike) or (isinstance(scene, str) and "\n" not in scene and "=" not in scene):
        path = os.fspath(scene)
        with open(path, encoding="utf-8") as f:
            text = f.read()
        return text, path, os.path.dirname(os.path.abspath(path))
    if isinstance(scene, str):
        return scene, "(text)", None
    raise TypeError(f"a scene is a path, TOML text or a dict, not {type(scene).__name__}")


def design(scene: Scene) -> Record:
    """Designs the scene (every output its ``[outputs]`` ask for, kept in memory): the report."""
    text, label, folder = _scene(scene)
    return Record.wrap(json.loads(_native.design_json(text, label, folder, "design")))


def check(scene: Scene) -> Record:
    """Runs only what the interference check needs: the report (``.interference.passes``)."""
    text, label, folder = _scene(scene)
    return Record.wrap(json.loads(_native.design_json(text, label, folder, "check")))


def study(scene: Scene, kinds: Sequence[str] = (), stations: Sequence[str] = ()) -> Record:
    """The trade study of the synthesised kinds at the scene's stations (``study.json``)."""
    text, label, folder = _scene(scene)
    return Record.wrap(json.loads(_native.study_json(text, label, folder, list(kinds), list(stations))))


def sweep(
    scene: Scene,
    vary: Union[str, Iterable[str], None] = None,
    variants: Any = None,
    shard: Optional[str] = None,
):
    """Every variant of the scene designed in parallel: a pandas DataFrame, one row each.

    ``vary``: ``"KEY=START:STOP:STEP"`` or ``"KEY=A,B,C"`` (several: their product, the first
    varied slowest). ``variants``: instead, a DataFrame, a dict of columns or CSV text whose
    columns are key paths, a row per variant. ``shard``: ``"I/N"``, every N-th variant.
    Without pandas, the table's CSV text.
    """
    text, label, folder = _scene(scene)
    if isinstance(vary, str):
        vary = [vary]
    table = None
    if variants is not None:
        if isinstance(variants, str):
            table = variants
        else:
            try:
                import pandas
            except ImportError as e:  # pragma: no cover - pandas is what a table needs
                raise DesignError("variants other than CSV text need pandas") from e
            frame = variants if isinstance(variants, pandas.DataFrame) else pandas.DataFrame(variants)
            table = frame.to_csv(index=False)
    csv_text = _native.sweep_csv(text, label, folder, list(vary or []), table, shard)
    try:
        import pandas
    except ImportError:
        return csv_text
    # Keys and values as text (as given), the figures as numbers.
    keys = csv_text.split("\n", 1)[0].split(",")
    text_columns = {k: str for k in keys if k not in _FIGURES and k not in ("variant", "warnings")}
    text_columns.update({"scene_sha256": str, "verdict": str, "error": str})
    frame = pandas.read_csv(io.StringIO(csv_text), dtype=text_columns, keep_default_na=False, na_values={c: [""] for c in _FIGURES})
    return frame


# The table's numeric figures: its columns after the keys but the hash, the verdict, the
# warnings count and the error.
_FIGURES = tuple(c for c in _native.FIGURE_COLUMNS if c not in ("scene_sha256", "verdict", "warnings", "error"))
