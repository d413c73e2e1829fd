"""A row of buildings given as a dict of a row preset's shape (SPEC §13):
the same reports as the preset it mirrors, bit for bit; a value the preset
would refuse is refused with the command line's line."""

import pathlib

import pytest

import pounding

from test_equal_to_cli import same, without_time

tomllib = pytest.importorskip("tomllib")

REPO = pathlib.Path(__file__).resolve().parents[2]
RECORD = "record:" + str(REPO / "presets" / "synthetic.at2")


def block_and_frame() -> dict:
    with open(REPO / "presets" / "buildings" / "block-and-frame.toml", "rb") as f:
        return tomllib.load(f)


def test_a_dict_runs_as_the_preset_it_mirrors():
    row = block_and_frame()
    ours = pounding.run(buildings=row, excitation=RECORD)
    theirs = pounding.run(buildings="block-and-frame", excitation=RECORD)
    # The report names its row; everything else is the same, bit for bit.
    ours.pop("row", None), theirs.pop("row", None)
    same(without_time(ours), without_time(theirs))
    assert ours["impacts"] > 0
    # An edit in the dict is the --set edit of the preset.
    row["joint"][0]["gap"] = 0.02
    wider = pounding.run(buildings=row, excitation=RECORD)
    edited = pounding.run(buildings="block-and-frame", excitation=RECORD, set="joint1.gap=0.02")
    wider.pop("row", None), edited.pop("row", None)
    same(without_time(wider), without_time(edited))
    assert wider["impacts"] < ours["impacts"]
    s = pounding.suite(suite="synthetic:2", buildings=block_and_frame(), level=0.3)
    t = pounding.suite(suite="synthetic:2", buildings="block-and-frame", level=0.3)
    assert [v.hex() for v in s["records"]["scale"]] == [v.hex() for v in t["records"]["scale"]]
    for a, b in zip(s["records"]["buildings"], t["records"]["buildings"]):
        same(a, b)


def test_a_bad_dict_is_refused_in_one_line():
    row = block_and_frame()
    row["building"][1]["mass"] = [1.0, 2.0]
    with pytest.raises(ValueError) as e:
        pounding.run(buildings=row, excitation=RECORD)
    message = str(e.value)
    assert "building `frame`: `mass` has 2 values" in message and "\n" not in message
    with pytest.raises(ValueError, match="`alpha` = True"):
        pounding.run(buildings={**block_and_frame(), "alpha": True})
    with pytest.raises(ValueError, match="`building` must be a list of dicts"):
        pounding.run(buildings={**block_and_frame(), "building": 3})
