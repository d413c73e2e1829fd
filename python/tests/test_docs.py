"""Docstrings and stubs show every key with its range."""

import importlib.util
import pathlib
import pydoc

import pounding

PYTHON = pathlib.Path(__file__).resolve().parents[1]


def test_help_shows_every_key_and_range():
    text = pydoc.render_doc(pounding.run, renderer=pydoc.plaintext)
    for f in pounding.Params.fields:
        assert f.key in text and f.range in text, f.key
    assert "Π_ω1" in text


def test_stubs_are_what_make_stubs_writes():
    spec = importlib.util.spec_from_file_location("make_stubs", PYTHON / "make_stubs.py")
    make_stubs = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_stubs)
    assert (PYTHON / "pounding" / "__init__.pyi").read_text() == make_stubs.render(), (
        "stale stubs: run python python/make_stubs.py"
    )
    assert (PYTHON / "pounding" / "py.typed").exists()
