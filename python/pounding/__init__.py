"""Pounding of two adjacent inelastic structures in earthquakes (Buckingham-Π form).

One function per command of the ``pounding`` command line, with keyword
arguments named like its flags (``allow_long`` for ``--allow-long``) and
every key of the parameter table accepted as a keyword (``omega1=1.2`` is
``--set omega1=1.2``). Each returns the dict that ``--format json`` prints,
value for value, with its lists of points, cells and records turned into
numpy arrays. Bad input raises ``ValueError`` with the command line's
message; a failed run raises ``RuntimeError``.

>>> import pounding
>>> r = pounding.run(preset="set1", method="exact")
>>> r["left"]["peak_displacement"]
>>> s = pounding.spectrum(preset="set1", omega1="0.1:3:0.01")
>>> s["omega1"], s["left"]["peak_displacement"]        # numpy arrays over Π_ω1
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import tempfile
from typing import Any, Iterator, NamedTuple, Optional, Tuple

from . import _native

__version__: str = _native.__version__

__all__ = [
    "run",
    "spectrum",
    "map",
    "gap",
    "suite",
    "ida",
    "fragility",
    "target_spectrum",
    "scale_suite",
    "presets",
    "Params",
    "Field",
]


class Field(NamedTuple):
    """One key of the parameter table."""

    key: str
    symbol: str
    ascii: str
    meaning: str
    group: str
    kind: str
    range: str
    allowed: str
    default: Any
    min: Optional[float]
    max: Optional[float]
    choices: Optional[Tuple[str, ...]]


def _field(d: dict) -> Field:
    choices = d.get("choices")
    return Field(
        key=d["key"],
        symbol=d["symbol"],
        ascii=d["ascii"],
        meaning=d["meaning"],
        group=d["group"],
        kind=d["kind"],
        range=d["range"],
        allowed=d["allowed"],
        default=d["default"],
        min=d.get("min"),
        max=d.get("max"),
        choices=tuple(choices) if choices is not None else None,
    )


class Params:
    """The parameter table (one table, the command line's): every key with
    its symbol, meaning, range and default (set 1's value).

    >>> pounding.Params.keys()[:3]
    >>> pounding.Params.omega1.range, pounding.Params.omega1.default
    >>> pounding.Params.field("gap").allowed
    """

    fields: Tuple[Field, ...] = tuple(_field(d) for d in _native.parameter_table())

    @classmethod
    def keys(cls) -> list:
        """Every key, in the table's order."""
        return [f.key for f in cls.fields]

    @classmethod
    def field(cls, key: str) -> Field:
        """The row of ``key``; ``KeyError`` if there is none."""
        for f in cls.fields:
            if f.key == key:
                return f
        raise KeyError(key)

    @classmethod
    def defaults(cls) -> dict:
        """Every key's default (set 1's value)."""
        return {f.key: f.default for f in cls.fields}

    @classmethod
    def table(cls) -> str:
        """The table as text, as the docstrings show it."""
        return _KEYS


for _f in Params.fields:
    setattr(Params, _f.key, _f)


def _keys_text() -> str:
    width = max(len(f.key) for f in Params.fields)
    lines = []
    for f in Params.fields:
        lines.append(
            f"    {f.key:<{width}}  {f.symbol:<6} {f.range}  (default {f.default}): {f.meaning}"
        )
    return "\n".join(lines)


_KEYS = _keys_text()

_COMMON = """preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
"""


def _toml_value(key: str, v: Any) -> str:
    """One value of a row preset as TOML: a number, a string or a list of them."""
    if isinstance(v, bool):
        raise ValueError(f"buildings: `{key}` = {v!r}: must be a number, a string or a list")
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return ("inf" if v > 0 else "-inf") if math.isinf(v) else repr(v)
    if isinstance(v, str):
        return json.dumps(v)
    if isinstance(v, (list, tuple)):
        return "[" + ", ".join(_toml_value(key, x) for x in v) + "]"
    raise ValueError(f"buildings: `{key}` = {v!r}: must be a number, a string or a list")


def _row_toml(row: dict) -> str:
    """A row of buildings given as a dict of the preset's shape (its top-level
    keys, ``building``: a list of dicts, ``joint``: a list of dicts) as the
    TOML text of a row preset (SPEC §13)."""
    lines = []
    tables = []
    for key, value in row.items():
        if key in ("building", "joint"):
            if not isinstance(value, (list, tuple)) or not all(isinstance(t, dict) for t in value):
                raise ValueError(f"buildings: `{key}` must be a list of dicts, one per {key}")
            tables += [(key, t) for t in value]
        else:
            lines.append(f"{key} = {_toml_value(key, value)}")
    for name, table in tables:
        lines += ["", f"[[{name}]]"]
        lines += [f"{k} = {_toml_value(k, v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


@contextlib.contextmanager
def _row_file(keys: dict) -> Iterator[dict]:
    """``keys`` with a ``buildings`` dict written to a temporary row preset
    file and named by its path for the command line's parser, which checks
    it as it checks a file; the file is removed afterwards."""
    row = keys.get("buildings")
    if not isinstance(row, dict):
        yield keys
        return
    fd, path = tempfile.mkstemp(prefix="pounding-row-", suffix=".toml")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(_row_toml(row))
        yield {**keys, "buildings": path}
    finally:
        with contextlib.suppress(OSError):
            os.remove(path)


def _doc(f):
    f.__doc__ = f.__doc__.replace("{common}", _COMMON.rstrip() + "\n" + _KEYS)
    return f


@_doc
def run(
    *,
    preset: Optional[str] = None,
    method: Optional[str] = None,
    history: bool = False,
    **keys: Any,
) -> dict:
    """One simulation: the dict of ``pounding run --format json``.

    history: also every accepted state, as numpy arrays under ``"history"``
        (tau, x1, v1, a1, x2, v2, a2, fs1, fs2, fp, in_contact, ag, vg, ug).
    repeat: run N times and report the median time.
    allow_unreliable: return an unreliable result (flagged) instead of raising.
    buildings: a row of buildings instead (a built-in row, a path, or a dict
        of a row preset's shape), with excitation, scale and tail as for
        ``pounding run --buildings``.
    {common}

    Raises ValueError for bad input, RuntimeError for an unreliable result.
    """
    with _row_file(keys) as keys:
        return _native.run(preset=preset, method=method, history=history, **keys)


@_doc
def spectrum(*, preset: Optional[str] = None, **keys: Any) -> dict:
    """Response spectra over Π_ω1: the dict of ``pounding spectrum --format json``.

    Each curve's points are numpy arrays (``curves[i]["left"]["peak_displacement"]``
    over ``curves[i]["omega1"]``); with one curve, the same arrays at the top:
    ``result["left"]["peak_displacement"]``.

    omega1: the Π_ω1 grid, START:STOP:STEP (here a flag, not the key).
    mu: frequency ratio, Π_ω2 = μ Π_ω1.
    family: one curve per value of a key, e.g. ``"gap=0.2,1.5,inf"``.
    {common}
    """
    return _native.spectrum(preset=preset, **keys)


@_doc
def map(x: str, y: str, *, preset: Optional[str] = None, **keys: Any) -> dict:  # noqa: A001
    """The left structure's regions over two parameters: ``pounding map --format json``.

    x, y: the axes, ``KEY=START:STOP:STEP`` (a Π key or mu).
    mu: frequency ratio on an omega1 axis.
    suite, im, level: over a suite of records, P(pounding) and the median
        amplification, the axes then physical quantities of the preset's
        [physical] table (m1, m2, period1, period2, yield1, yield2, gap, …).
    The cells are numpy arrays of shape (y points, x points).
    {common}
    """
    return _native.map(x=x, y=y, preset=preset, **keys)


@_doc
def gap(*, preset: Optional[str] = None, **keys: Any) -> dict:
    """The smallest gap that prevents pounding: ``pounding gap --format json``.

    x: sweep one parameter, ``KEY=START:STOP:STEP``; mu: frequency ratio.
    suite, im, level, probability: the separation over a suite of records.
    buildings: a row of buildings (a built-in row, a path, or a dict of a
        row preset's shape: its keys, ``building`` and ``joint`` lists): per joint its
        gap, or with suite its separation at each probability.
    The points (or records) are numpy arrays.
    {common}
    """
    with _row_file(keys) as keys:
        return _native.gap(preset=preset, **keys)


@_doc
def suite(suite: str, *, preset: Optional[str] = None, **keys: Any) -> dict:
    """One physical pair under a suite of records: ``pounding suite --format json``.

    suite: a directory, a list file, or ``synthetic:N[@SEED]``.
    im: pga or sa:T; level: scale every record to this intensity (g).
    buildings: a row of buildings instead (``"block-and-frame"``, a path or a dict):
        per record each building's and joint's demands; im ``sa`` is Sa(T1)
        of its leftmost building.
    allow_unreliable: return unreliable results (flagged) instead of raising.
    The records are numpy arrays.
    {common}
    """
    with _row_file(keys) as keys:
        return _native.suite(suite=suite, preset=preset, **keys)


@_doc
def ida(suite: str, levels: str, *, preset: Optional[str] = None, **keys: Any) -> dict:
    """Incremental dynamic analysis: ``pounding ida --format json``.

    suite: the records; levels: intensities in g, START:STOP:STEP or X1,X2,…
    im: pga or sa:T; ductility, acceleration, force: limit states beside pounding.
    buildings: a row of buildings; drift (storey drift ratios), acceleration
        and force items ``[NAME:]VALUE``, building: the one they read by default;
        collapse=True: each P-Δ building's collapse fragility (its θ is Ŝ_CT).
    target (with period, code, range): the records scaled to a design spectrum
        by the code's rule, then the suite as a whole to each level (FEMA P-695).
    Each level's records, the levels, and each limit state's counts are numpy arrays.
    {common}
    """
    with _row_file(keys) as keys:
        return _native.ida(suite=suite, levels=levels, preset=preset, **keys)


@_doc
def fragility(suite: str, levels: str, *, preset: Optional[str] = None, **keys: Any) -> dict:
    """The fragility of each limit state, with and without pounding: the
    IDA's ``fragility`` and metadata, its levels as ``levels`` (an array, g).

    Each entry of ``fragility`` has ``limit_state``, ``counts`` (numpy arrays
    ``level``, ``runs``, ``exceeded``) and ``fragility`` (θ and β of the
    lognormal fit when fitted), and the same for the pair without contact.
    {common}
    """
    with _row_file(keys) as keys:
        r = _native.ida(suite=suite, levels=levels, preset=preset, **keys)
    r["levels"] = r["levels"]["level_g"]
    return r


def target_spectrum(target: str, periods: Any) -> "numpy.ndarray":
    """Sa (g, 5 % damped) of a target spectrum at each of ``periods`` (s).

    target: ``asce7:SDS=…,SD1=…,TL=…`` (ASCE 7-16 §11.4.6), ``asce7-mce:…``
    (1.5 times it), ``ec8:ag=…,ground=A|B|C|D|E,type=1|2[,importance=…]``
    (EN 1998-1 §3.2.2.2), or ``file:PATH`` (two columns T s, Sa g,
    interpolated log-log). A period outside the target's raises ValueError.
    """
    import numpy as np

    flat = np.asarray(periods, dtype=float)
    return _native.target_spectrum(target, flat.ravel().tolist()).reshape(flat.shape)


def scale_suite(
    suite: str,
    target: str,
    period: float,
    *,
    range: Optional[str] = None,  # noqa: A002
    code: Optional[str] = None,
    out: Optional[str] = None,
    check: bool = False,
) -> dict:
    """A suite's records scaled to a target spectrum by the code's rule:
    ``pounding records scale --format json``.

    Each record's least-squares factor in ln Sa over ``range`` (multiples
    of T1 = ``period``, ``"0.2:2.0"`` by default), then one common factor so
    that the suite meets the rule of ``code`` (``"ec8"``, EN 1998-1
    §3.2.3.1.2; ``"asce7"``, ASCE 7-16 §16.2.3; the target's own by
    default). ``out`` writes the suite list; ``check=True`` applies the rule
    to the list's own scales instead. The dict holds ``periods`` (s),
    ``target``, ``mean``, ``p16`` and ``p84`` (g) as numpy arrays, the
    records as columns (``spectrum`` a 2-D array, a row a record) and
    ``check`` (``holds``, ``min_ratio``, ``at_period_s``, ``failures``):
    a rule that does not hold is returned, not raised.
    """
    import numpy as np

    r = _native.records_scale(
        suite=suite,
        target=target,
        period=str(period),
        range=range,
        code=code,
        out=out,
        check=check,
    )
    for key in ("periods", "target", "mean", "p16", "p84"):
        r[key] = np.asarray(r[key], dtype=float)
    records = r["records"]
    if isinstance(records, dict) and "spectrum" in records:
        records["spectrum"] = np.asarray(records["spectrum"], dtype=float)
    return r


def presets() -> list:
    """The built-in presets: name, description, and whether it has a [physical] table."""
    return _native.presets()
