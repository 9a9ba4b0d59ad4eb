"""Flapwright from Python: design, check, study and sweep a wing's flap mechanisms.

Each function takes a scene as a path to a TOML file, as TOML text, or as a dict of the
same tables, and designs it in memory (no files written). Results are `Record`s:
read-only mappings whose keys are also attributes (``d.interference.passes``), converted
as they are read, with the report's figures (docs/report.md) as numpy arrays: a vector or
a point is a 1-d array, a list of points a 2-d one, and a list of rows (a load case's
samples, the interference pairs, the sized rods) a `Table`, whose keys are its columns
(``case.samples.actuator_load``, a value a row; ``table.row(i)`` gives a row back as the
report has it). ``sweep`` returns a pandas DataFrame with the columns of
``flapwright sweep``'s table (docs/commands.md).

Problems with a scene raise ``SceneError``, whose ``problems`` lists
``(file, line, col, key, message)`` as the command line prints them; any other failure
raises ``DesignError`` (its base class).
"""

from __future__ import annotations

import io
import json
import os
from collections.abc import Mapping
from typing import Any, Iterable, Optional, Sequence, Union

import numpy

from . import _native
from ._native import DesignError, SceneError

__all__ = [
    "design",
    "check",
    "study",
    "sweep",
    "thesis_sweep",
    "Record",
    "Table",
    "DesignError",
    "SceneError",
    "__version__",
]
__version__ = _native.__version__

Scene = Union[str, "os.PathLike[str]", dict]


class Record(Mapping):
    """A read-only mapping whose keys are also attributes, nested
    (``report.interference.passes``). Its values are converted when first read (a list to
    an array or a Table), so a report costs only what is looked at. ``to_dict()`` gives
    the plain values (for ``json.dumps``); records compare by them. A key that is also a
    mapping method (``values``, ``items``, ``keys``, ``get``) reads as ``record["values"]``."""

    __slots__ = ("_raw", "_done")

    def __init__(self, raw: Optional[dict] = None, **values: Any) -> None:
        self._raw = dict(raw or {}, **values)
        self._done: dict = {}

    def __getitem__(self, key: str) -> Any:
        try:
            return self._done[key]
        except KeyError:
            value = self._done[key] = Record.wrap(self._raw[key])
            return value

    def __iter__(self):
        return iter(self._raw)

    def __len__(self) -> int:
        return len(self._raw)

    def __getattr__(self, name: str) -> Any:
        if name.startswith("_"):
            raise AttributeError(name)
        try:
            return self[name]
        except KeyError:
            raise AttributeError(name) from None

    def __repr__(self) -> str:
        return f"{type(self).__name__}({dict(self.items())!r})"

    def __eq__(self, other: object) -> bool:
        # By the report's values (numpy arrays have no single truth value to compare by).
        if isinstance(other, Record):
            return self.to_dict() == other.to_dict()
        if isinstance(other, dict):
            return self.to_dict() == _plain(other)
        return NotImplemented

    __hash__ = None  # type: ignore[assignment]

    def to_dict(self) -> dict:
        """The values as the report has them (plain dicts, lists and numbers, as JSON)."""
        return _plain(self._raw)

    @staticmethod
    def wrap(value: Any) -> Any:
        """The report's JSON value with dicts as Records and lists as arrays or Tables."""
        if isinstance(value, dict):
            return Record(value)
        if isinstance(value, list):
            return _array(value)
        return value


class Table(Record):
    """Rows of one shape as columns: each key a column, a numpy array with a value a row
    (a list of numbers a 2-d array, text an array of str); a column of nested rows is a
    Table itself. ``rows`` is the number of rows; ``row(i)`` one row as a Record."""

    __slots__ = ("_rows",)

    def __init__(self, rows: list) -> None:
        # The report leaves out a row's absent figures: a key of any row is a column, None
        # (NaN among numbers) where a row lacks it.
        super().__init__({key: None for row in rows for key in row})
        self._rows = rows

    @property
    def rows(self) -> int:
        """Number of rows."""
        return len(self._rows)

    def __getitem__(self, key: str) -> Any:
        try:
            return self._done[key]
        except KeyError:
            if key not in self._raw:
                raise
            value = self._done[key] = _column([row.get(key) for row in self._rows])
            return value

    def row(self, i: int) -> Record:
        """Row ``i`` as a Record of the report's values (converted as they are read)."""
        if not -self.rows <= i < self.rows:
            raise IndexError(f"row {i} of {self.rows}")
        return Record(self._rows[i])

    def to_dict(self) -> dict:
        """The columns as lists (None where a row lacks a figure)."""
        return {key: [_plain(row.get(key)) for row in self._rows] for key in self._raw}

    def to_frame(self):
        """The table as a pandas DataFrame (one-dimensional columns only)."""
        import pandas

        return pandas.DataFrame({k: v for k, v in self.items() if isinstance(v, numpy.ndarray) and v.ndim == 1})


def _plain(value: Any) -> Any:
    if isinstance(value, dict):
        return {k: _plain(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    return value


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _flat(value: Any) -> bool:
    """A value a Table's cell may hold: a number, text, a flag, None, a list of numbers, or
    a dict of such (a row of its own, as a sample's reactions)."""
    if isinstance(value, dict):
        return all(_flat(v) for v in value.values())
    if isinstance(value, list):
        return all(_is_number(v) or v is None for v in value)
    return value is None or isinstance(value, (int, float, str, bool))


def _array(values: list) -> Any:
    """A list of the report as the most specific form that holds it whole: whole numbers an
    int64 array, numbers (None as NaN) a float array, equal-length lists of numbers a 2-d array, rows (dicts of flat
    values) a Table; anything else a list of wrapped values."""
    if values and all(isinstance(v, int) and not isinstance(v, bool) for v in values):
        try:
            return numpy.array(values, dtype=numpy.int64)
        except OverflowError:  # beyond 64 bits: kept whole, as Python ints
            objects = numpy.empty(len(values), dtype=object)
            objects[:] = values
            return objects
    if values and all(_is_number(v) or v is None for v in values) and any(_is_number(v) for v in values):
        return numpy.array([numpy.nan if v is None else v for v in values], dtype=float)
    if values and all(isinstance(v, list) for v in values):
        inner = [_array(v) for v in values]
        if all(isinstance(a, numpy.ndarray) and a.dtype.kind in "fi" for a in inner) and len({a.shape for a in inner}) == 1:
            return numpy.stack(inner)
        return inner
    if values and all(isinstance(v, dict) and all(_flat(x) for x in v.values()) for v in values):
        return Table(values)
    if values and all(isinstance(v, str) for v in values):
        return numpy.array(values, dtype=str)
    if values and all(isinstance(v, bool) for v in values):
        return numpy.array(values, dtype=bool)
    return [Record.wrap(v) for v in values]


def _column(values: list) -> Any:
    """One column of a Table: as `_array`, but text (or None) an array of str objects and
    anything mixed an object array, so that every column has a value a row."""
    if all(v is None or isinstance(v, dict) for v in values) and any(isinstance(v, dict) for v in values):
        return _array([{} if v is None else v for v in values])
    column = _array(values)
    if isinstance(column, (numpy.ndarray, Table)):
        return column
    objects = numpy.empty(len(values), dtype=object)
    objects[:] = column
    return objects


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


def thesis_sweep(samples: int = 1000, load: str = "landing") -> Record:
    """The thesis track's deployment (`000_...` Table 2, the published case) at ``samples``
    evenly spaced nut positions under its ``cruise`` or ``landing`` case, lean: the nut
    position and 21 figures (angles, rates, accelerations, points A and D with velocities
    and accelerations, the actuator force and the screw torques, SI units) as numpy
    columns, computed in Rust in one pass (``CircularArcTrack::lean_sweep``). ``stopped``
    says why the columns end early, or is None."""
    names, values, rows, stopped = _native.thesis_sweep(samples, load)
    columns = numpy.frombuffer(values, dtype="<f8").reshape(len(names), rows) if rows else numpy.empty((len(names), 0))
    record = Record({name: columns[i] for i, name in enumerate(names)})
    record._raw["stopped"] = stopped
    return record


# The table's numeric figures: its columns after the keys but the hash, the verdict, the
# warnings count and the error.
_FIGURES = tuple(c for c in _native.FIGURE_COLUMNS if c not in ("scene_sha256", "verdict", "warnings", "error"))
