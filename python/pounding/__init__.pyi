"""Type stubs of pounding (written by python/make_stubs.py)."""

from typing import Any, Mapping, NamedTuple, Optional, Sequence, Tuple, Union

__version__: str

class Field(NamedTuple):
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

class Params:
    """The parameter table (one table, the command line's): every key with
    its symbol, meaning, range and default (set 1's value).

    >>> pounding.Params.keys()[:3]
    >>> pounding.Params.omega1.range, pounding.Params.omega1.default
    >>> pounding.Params.field("gap").allowed
    """

    fields: Tuple[Field, ...]
    mass_ratio: Field
    """Π_m: mass ratio m1/m2; [0.001, 1000], default 0.5"""
    omega1: Field
    """Π_ω1: left frequency ω1/ωp; [0, 1000], default 1.05"""
    omega2: Field
    """Π_ω2: right frequency ω2/ωp; [0, 1000], default 2.36"""
    yield1: Field
    """Π_uy1: left yield displacement; [0.0001, 1e6] or inf, default 0.9"""
    yield2: Field
    """Π_uy2: right yield displacement; [0.0001, 1e6] or inf, default 0.8"""
    damping: Field
    """Π_ξ: damping ratio ξ; [0, 1], default 0.05"""
    alpha: Field
    """Π_α: post-yield stiffness; [0, 1], default 0.1"""
    contact_omega: Field
    """Π_ωcon: contact frequency ω̄/ωp; [1, 1e6], default 50.0"""
    restitution: Field
    """Π_e: restitution e; [0.001, 1], default 0.4"""
    gap: Field
    """Π_d: initial gap d ωp²/ap; [0, 1e6] or inf, default 0.2"""
    hertz_stiffness: Field
    """Π_K: Hertz stiffness (0: from Π_ωcon); [0, 1e16], default 0.0"""
    model: Field
    """model: contact element; kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley, default improved-kelvin"""
    excitation: Field
    """g(τ): ground motion; sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH, default sine"""
    record_scale: Field
    """s: record scale factor; [1e-6, 1000], default 1.0"""
    record_amplitude: Field
    """a_p: record a_p in m/s² (0: peak); [0, 1000], default 0.0"""
    record_omega: Field
    """ω_p: record ω_p in rad/s (0: dominant); [0, 1000], default 0.0"""
    method: Field
    """method: time integrator; newmark|exact, default newmark"""
    contact_tolerance: Field
    """tol: exact: contact tolerance; [1e-16, 1e-8], default 1e-11"""
    cycles: Field
    """cycles: excitation cycles; [1, 100000], default 8"""
    dt: Field
    """Δτ: Newmark time step; [1e-6, 0.3142], default 0.001"""
    min_impact_velocity: Field
    """v₀min: floor on approach velocity; [1e-6, 0.1], default 0.001"""
    @classmethod
    def keys(cls) -> list[str]: ...
    @classmethod
    def field(cls, key: str) -> Field: ...
    @classmethod
    def defaults(cls) -> dict[str, Any]: ...
    @classmethod
    def table(cls) -> str: ...

def presets() -> list[dict[str, Any]]:
    """The built-in presets: name, description, and whether it has a [physical] table."""

def target_spectrum(target: str, periods: Any) -> Any:
    """Sa (g, 5 % damped) of a target spectrum at each of ``periods`` (s).

    target: ``asce7:SDS=…,SD1=…,TL=…`` (ASCE 7-16 §11.4.6), ``asce7-mce:…``
    (1.5 times it), ``ec8:ag=…,ground=A|B|C|D|E,type=1|2[,importance=…]``
    (EN 1998-1 §3.2.2.2), or ``file:PATH`` (two columns T s, Sa g,
    interpolated log-log). A period outside the target's raises ValueError.
    """

def scale_suite(
    suite: str,
    target: str,
    period: float,
    *,
    range: Optional[str] = ...,
    code: Optional[str] = ...,
    out: Optional[str] = ...,
    check: bool = False,
) -> dict[str, Any]:
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

def run(
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    history: bool = False,
    repeat: int = ...,
    allow_large: bool = False,
    allow_unreliable: bool = False,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """One simulation: the dict of ``pounding run --format json``.

    history: also every accepted state, as numpy arrays under ``"history"``
        (tau, x1, v1, a1, x2, v2, a2, fs1, fs2, fp, in_contact, ag, vg, ug).
    repeat: run N times and report the median time.
    allow_unreliable: return an unreliable result (flagged) instead of raising.
    buildings: a row of buildings instead (a built-in row, a path, or a dict
        of a row preset's shape), with excitation, scale and tail as for
        ``pounding run --buildings``.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity

    Raises ValueError for bad input, RuntimeError for an unreliable result.
    """

def spectrum(
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    omega1: Optional[str] = ...,
    mu: Union[float, str, None] = ...,
    family: Optional[str] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """Response spectra over Π_ω1: the dict of ``pounding spectrum --format json``.

    Each curve's points are numpy arrays (``curves[i]["left"]["peak_displacement"]``
    over ``curves[i]["omega1"]``); with one curve, the same arrays at the top:
    ``result["left"]["peak_displacement"]``.

    omega1: the Π_ω1 grid, START:STOP:STEP (here a flag, not the key).
    mu: frequency ratio, Π_ω2 = μ Π_ω1.
    family: one curve per value of a key, e.g. ``"gap=0.2,1.5,inf"``.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """

def map(
    x: str,
    y: str,
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    mu: Union[float, str, None] = ...,
    suite: Optional[str] = ...,
    im: Optional[str] = ...,
    level: Union[float, str, None] = ...,
    target: Optional[str] = ...,
    code: Optional[str] = ...,
    range: Optional[str] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """The left structure's regions over two parameters: ``pounding map --format json``.

    x, y: the axes, ``KEY=START:STOP:STEP`` (a Π key or mu).
    mu: frequency ratio on an omega1 axis.
    suite, im, level: over a suite of records, P(pounding) and the median
        amplification, the axes then physical quantities of the preset's
        [physical] table (m1, m2, period1, period2, yield1, yield2, gap, …).
    The cells are numpy arrays of shape (y points, x points).
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """

def gap(
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    x: Optional[str] = ...,
    mu: Union[float, str, None] = ...,
    suite: Optional[str] = ...,
    probability: Optional[str] = ...,
    im: Optional[str] = ...,
    level: Union[float, str, None] = ...,
    buildings: Union[str, Mapping[str, Any], None] = ...,
    target: Optional[str] = ...,
    code: Optional[str] = ...,
    range: Optional[str] = ...,
    period: Union[float, str, None] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """The smallest gap that prevents pounding: ``pounding gap --format json``.

    x: sweep one parameter, ``KEY=START:STOP:STEP``; mu: frequency ratio.
    suite, im, level, probability: the separation over a suite of records.
    buildings: a row of buildings (a built-in row, a path, or a dict of a
        row preset's shape: its keys, ``building`` and ``joint`` lists): per joint its
        gap, or with suite its separation at each probability.
    The points (or records) are numpy arrays.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """

def suite(
    suite: str,
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    im: Optional[str] = ...,
    level: Union[float, str, None] = ...,
    allow_unreliable: bool = False,
    buildings: Union[str, Mapping[str, Any], None] = ...,
    target: Optional[str] = ...,
    code: Optional[str] = ...,
    range: Optional[str] = ...,
    period: Union[float, str, None] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """One physical pair under a suite of records: ``pounding suite --format json``.

    suite: a directory, a list file, or ``synthetic:N[@SEED]``.
    im: pga or sa:T; level: scale every record to this intensity (g).
    buildings: a row of buildings instead (``"block-and-frame"``, a path or a dict):
        per record each building's and joint's demands; im ``sa`` is Sa(T1)
        of its leftmost building.
    allow_unreliable: return unreliable results (flagged) instead of raising.
    The records are numpy arrays.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """

def ida(
    suite: str,
    levels: str,
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    im: Optional[str] = ...,
    level: Union[float, str, None] = ...,
    allow_unreliable: bool = False,
    ductility: Optional[str] = ...,
    acceleration: Optional[str] = ...,
    force: Optional[str] = ...,
    buildings: Union[str, Mapping[str, Any], None] = ...,
    drift: Optional[str] = ...,
    building: Optional[str] = ...,
    collapse: bool = False,
    target: Optional[str] = ...,
    code: Optional[str] = ...,
    range: Optional[str] = ...,
    period: Union[float, str, None] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """Incremental dynamic analysis: ``pounding ida --format json``.

    suite: the records; levels: intensities in g, START:STOP:STEP or X1,X2,…
    im: pga or sa:T; ductility, acceleration, force: limit states beside pounding.
    buildings: a row of buildings; drift (storey drift ratios), acceleration
        and force items ``[NAME:]VALUE``, building: the one they read by default;
        collapse=True: each P-Δ building's collapse fragility (its θ is Ŝ_CT).
    target (with period, code, range): the records scaled to a design spectrum
        by the code's rule, then the suite as a whole to each level (FEMA P-695).
    Each level's records, the levels, and each limit state's counts are numpy arrays.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """

def fragility(
    suite: str,
    levels: str,
    *,
    preset: Optional[str] = ...,
    model: Optional[str] = ...,
    excitation: Optional[str] = ...,
    method: Optional[str] = ...,
    dt: Union[float, str, None] = ...,
    cycles: Optional[int] = ...,
    no_pounding: bool = False,
    presets: Optional[str] = ...,
    allow_long: bool = False,
    set: Union[str, Sequence[str], None] = ...,
    im: Optional[str] = ...,
    level: Union[float, str, None] = ...,
    allow_unreliable: bool = False,
    ductility: Optional[str] = ...,
    acceleration: Optional[str] = ...,
    force: Optional[str] = ...,
    buildings: Union[str, Mapping[str, Any], None] = ...,
    drift: Optional[str] = ...,
    building: Optional[str] = ...,
    collapse: bool = False,
    target: Optional[str] = ...,
    code: Optional[str] = ...,
    range: Optional[str] = ...,
    period: Union[float, str, None] = ...,
    mass_ratio: Union[float, str, None] = ...,
    omega1: Union[float, str, None] = ...,
    omega2: Union[float, str, None] = ...,
    yield1: Union[float, str, None] = ...,
    yield2: Union[float, str, None] = ...,
    damping: Union[float, str, None] = ...,
    alpha: Union[float, str, None] = ...,
    contact_omega: Union[float, str, None] = ...,
    restitution: Union[float, str, None] = ...,
    gap: Union[float, str, None] = ...,
    hertz_stiffness: Union[float, str, None] = ...,
    record_scale: Union[float, str, None] = ...,
    record_amplitude: Union[float, str, None] = ...,
    record_omega: Union[float, str, None] = ...,
    contact_tolerance: Union[float, str, None] = ...,
    min_impact_velocity: Union[float, str, None] = ...,
    **keys: Any,
) -> dict[str, Any]:
    """The fragility of each limit state, with and without pounding: the
    IDA's ``fragility`` and metadata, its levels as ``levels`` (an array, g).

    Each entry of ``fragility`` has ``limit_state``, ``counts`` (numpy arrays
    ``level``, ``runs``, ``exceeded``) and ``fragility`` (θ and β of the
    lognormal fit when fitted), and the same for the pair without contact.
    preset: a built-in preset (``pounding.presets()``) or a preset file [default: set1].
    model: contact law, kelvin, improved-kelvin, hertz, hertzdamp, jankowski or hunt-crossley.
    excitation: sine, pulse-a, pulse-b, pulse-c1, pulse-c2 or ``record:PATH[@UNIT]``.
    method: newmark or exact.
    dt, cycles: Newmark's Δτ and the duration in excitation cycles.
    no_pounding: no contact at all (gap = inf).
    presets: directory of the user's own presets.
    allow_long: run even when the estimated work exceeds 1e10 steps.
    **keys: any key of the parameter table, e.g. ``omega1=1.2``:
    mass_ratio           Π_m    [0.001, 1000]  (default 0.5): mass ratio m1/m2
    omega1               Π_ω1   [0, 1000]  (default 1.05): left frequency ω1/ωp
    omega2               Π_ω2   [0, 1000]  (default 2.36): right frequency ω2/ωp
    yield1               Π_uy1  [0.0001, 1e6] or inf  (default 0.9): left yield displacement
    yield2               Π_uy2  [0.0001, 1e6] or inf  (default 0.8): right yield displacement
    damping              Π_ξ    [0, 1]  (default 0.05): damping ratio ξ
    alpha                Π_α    [0, 1]  (default 0.1): post-yield stiffness
    contact_omega        Π_ωcon [1, 1e6]  (default 50.0): contact frequency ω̄/ωp
    restitution          Π_e    [0.001, 1]  (default 0.4): restitution e
    gap                  Π_d    [0, 1e6] or inf  (default 0.2): initial gap d ωp²/ap
    hertz_stiffness      Π_K    [0, 1e16]  (default 0.0): Hertz stiffness (0: from Π_ωcon)
    model                model  kelvin|improved-kelvin|hertz|hertzdamp|jankowski|hunt-crossley  (default improved-kelvin): contact element
    excitation           g(τ)   sine|pulse-a|pulse-b|pulse-c1|pulse-c2|record:PATH  (default sine): ground motion
    record_scale         s      [1e-6, 1000]  (default 1.0): record scale factor
    record_amplitude     a_p    [0, 1000]  (default 0.0): record a_p in m/s² (0: peak)
    record_omega         ω_p    [0, 1000]  (default 0.0): record ω_p in rad/s (0: dominant)
    method               method newmark|exact  (default newmark): time integrator
    contact_tolerance    tol    [1e-16, 1e-8]  (default 1e-11): exact: contact tolerance
    cycles               cycles [1, 100000]  (default 8): excitation cycles
    dt                   Δτ     [1e-6, 0.3142]  (default 0.001): Newmark time step
    min_impact_velocity  v₀min  [1e-6, 0.1]  (default 0.001): floor on approach velocity
    """
