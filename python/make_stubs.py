"""Writes pounding/__init__.pyi, the type stubs, from the installed module:
every command's flags and every key of the parameter table as a keyword,
with its range in the docstring, for editors' completion and type checkers.

    python python/make_stubs.py        # after `pip install ./python`

The tests check that the committed stubs are what this writes.
"""

import pathlib
import sys

HERE = pathlib.Path(__file__).resolve().parent
# The installed module, not its sources beside this file (they lack the extension).
sys.path = [p for p in sys.path if pathlib.Path(p or ".").resolve() != HERE]

import pounding  # noqa: E402

STUBS = HERE / "pounding" / "__init__.pyi"

COMMON = [
    ("preset", "Optional[str]"),
    ("model", "Optional[str]"),
    ("excitation", "Optional[str]"),
    ("method", "Optional[str]"),
    ("dt", "Union[float, str, None]"),
    ("cycles", "Optional[int]"),
    ("no_pounding", "bool"),
    ("presets", "Optional[str]"),
    ("allow_long", "bool"),
    ("set", "Union[str, Sequence[str], None]"),
]
TEXT = "Optional[str]"
NUMBER = "Union[float, str, None]"
SUITE = [("im", TEXT), ("level", NUMBER), ("allow_unreliable", "bool")]
LIMITS = [("ductility", TEXT), ("acceleration", TEXT), ("force", TEXT)]
ROW = [("buildings", "Union[str, Mapping[str, Any], None]")]
ROW_LIMITS = [("drift", TEXT), ("building", TEXT), ("collapse", "bool")]
DESIGN = [("target", TEXT), ("code", TEXT), ("range", TEXT)]
PERIOD = [("period", NUMBER)]

# Each function: its leading arguments, then its own flags (keyword-only).
COMMANDS = {
    "run": ([], [("history", "bool"), ("repeat", "int"), ("allow_large", "bool"), ("allow_unreliable", "bool")]),
    "spectrum": ([], [("omega1", TEXT), ("mu", NUMBER), ("family", TEXT)]),
    "map": ([("x", "str"), ("y", "str")], [("mu", NUMBER), ("suite", TEXT)] + SUITE[:2] + DESIGN),
    "gap": (
        [],
        [("x", TEXT), ("mu", NUMBER), ("suite", TEXT), ("probability", TEXT)]
        + SUITE[:2]
        + ROW
        + DESIGN
        + PERIOD,
    ),
    "suite": ([("suite", "str")], SUITE + ROW + DESIGN + PERIOD),
    "ida": ([("suite", "str"), ("levels", "str")], SUITE + LIMITS + ROW + ROW_LIMITS + DESIGN + PERIOD),
    "fragility": ([("suite", "str"), ("levels", "str")], SUITE + LIMITS + ROW + ROW_LIMITS + DESIGN + PERIOD),
}


def key_type(f) -> str:
    return {"number": NUMBER, "integer": "Optional[int]", "choice": TEXT}[f.kind]


def render() -> str:
    out = [
        '"""Type stubs of pounding (written by python/make_stubs.py)."""',
        "",
        "from typing import Any, Mapping, NamedTuple, Optional, Sequence, Tuple, Union",
        "",
        "__version__: str",
        "",
        "class Field(NamedTuple):",
    ]
    for name, kind in pounding.Field.__annotations__.items():
        out.append(f"    {name}: {getattr(kind, '__forward_arg__', kind)}")
    out += [
        "",
        "class Params:",
        f'    """{pounding.Params.__doc__}"""',
        "",
        "    fields: Tuple[Field, ...]",
    ]
    for f in pounding.Params.fields:
        out.append(f"    {f.key}: Field")
        out.append(f'    """{f.symbol}: {f.meaning}; {f.range}, default {f.default}"""')
    out += [
        "    @classmethod",
        "    def keys(cls) -> list[str]: ...",
        "    @classmethod",
        "    def field(cls, key: str) -> Field: ...",
        "    @classmethod",
        "    def defaults(cls) -> dict[str, Any]: ...",
        "    @classmethod",
        "    def table(cls) -> str: ...",
        "",
        "def presets() -> list[dict[str, Any]]:",
        f'    """{pounding.presets.__doc__}"""',
        "",
        "def target_spectrum(target: str, periods: Any) -> Any:",
        f'    """{pounding.target_spectrum.__doc__.rstrip()}\n    """',
        "",
        "def scale_suite(",
        "    suite: str,",
        "    target: str,",
        "    period: float,",
        "    *,",
        "    range: Optional[str] = ...,",
        "    code: Optional[str] = ...,",
        "    out: Optional[str] = ...,",
        "    check: bool = False,",
        ") -> dict[str, Any]:",
        f'    """{pounding.scale_suite.__doc__.rstrip()}\n    """',
        "",
    ]
    for name, (leading, own) in COMMANDS.items():
        flags = dict(COMMON)
        flags.update(dict(own))
        taken = {n for n, _ in leading} | set(flags)
        keys = [(f.key, key_type(f)) for f in pounding.Params.fields if f.key not in taken]
        args = [f"{n}: {t}" for n, t in leading]
        args.append("*")
        for n, t in list(flags.items()) + keys:
            default = "False" if t == "bool" else "..."
            args.append(f"{n}: {t} = {default}")
        args.append("**keys: Any")
        out.append(f"def {name}(")
        out += [f"    {a}," for a in args]
        out.append(") -> dict[str, Any]:")
        doc = getattr(pounding, name).__doc__.rstrip()
        out.append(f'    """{doc}\n    """')
        out.append("")
    return "\n".join(out)


if __name__ == "__main__":
    text = render()
    if "--check" in sys.argv:
        sys.exit(0 if STUBS.read_text() == text else 1)
    STUBS.write_text(text)
    print(f"wrote {STUBS}")
