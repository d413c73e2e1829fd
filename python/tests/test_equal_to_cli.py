"""The module's results are the command line's, value for value and bit for bit."""

import csv
import io
import math

import numpy as np

import pounding


def same(a, b, path="result"):
    """`a` equals `b` exactly: floats bit for bit, every key and item."""
    if isinstance(a, dict):
        assert isinstance(b, dict), path
        assert a.keys() == b.keys(), (path, a.keys() ^ b.keys())
        for k in a:
            same(a[k], b[k], f"{path}[{k!r}]")
    elif isinstance(a, list):
        assert isinstance(b, list) and len(a) == len(b), path
        for i, (x, y) in enumerate(zip(a, b)):
            same(x, y, f"{path}[{i}]")
    elif isinstance(a, float):
        assert isinstance(b, float), (path, a, b)
        assert a.hex() == b.hex(), (path, a, b)
    else:
        assert type(a) is type(b) and a == b, (path, a, b)


def without_time(d: dict) -> dict:
    return {k: v for k, v in d.items() if k != "elapsed_ms"}


def test_run_set1_exact_is_the_cli_json(cli):
    ours = pounding.run(preset="set1", method="exact")
    theirs = cli.json("run", "--preset", "set1", "--method", "exact")
    same(without_time(ours), without_time(theirs))
    assert ours["impacts"] > 0 and ours["left"]["peak_displacement"] > 0


def test_run_defaults_and_keys_are_the_cli_json(cli):
    same(without_time(pounding.run()), without_time(cli.json("run")))
    ours = pounding.run(preset="set2", omega1=1.2, gap=0.5, model="hertzdamp")
    theirs = cli.json(
        "run", "--preset", "set2", "--set", "omega1=1.2", "--set", "gap=0.5", "--model", "hertzdamp"
    )
    same(without_time(ours), without_time(theirs))


def test_a_row_of_buildings_is_the_cli_json(cli):
    # The row's report (floors and floor pairs, SPEC §13) through the same emit.
    record = "record:presets/synthetic.at2"
    ours = pounding.run(buildings="block-and-frame", excitation=record)
    theirs = cli.json("run", "--buildings", "block-and-frame", "--excitation", record)
    same(without_time(ours), without_time(theirs))
    assert ours["impacts"] > 0 and [b["name"] for b in ours["buildings"]] == ["block", "frame"]
    gap = pounding.gap(buildings="block-and-frame", excitation=record)
    same(gap, cli.json("gap", "--buildings", "block-and-frame", "--excitation", record))


def test_run_history(cli):
    r = pounding.run(preset="set1", method="exact", history=True)
    h = r["history"]
    assert h["tau"][0] == 0.0 and np.all(np.diff(h["tau"]) > 0)
    assert abs(np.max(np.abs(h["x1"])) - r["left"]["peak_displacement"]) <= 1e-12
    for name in ("x1", "v1", "a1", "x2", "v2", "a2", "fs1", "fs2", "fp", "ag", "vg", "ug"):
        assert h[name].dtype == np.float64 and h[name].shape == h["tau"].shape
    assert h["in_contact"].dtype == np.bool_ and h["in_contact"].any()


def test_spectrum_arrays_are_the_cli_csv(cli):
    s = pounding.spectrum(preset="set1", omega1="0.2:2.0:0.05")
    out = cli("spectrum", "--preset", "set1", "--omega1", "0.2:2.0:0.05", "--format", "csv")
    assert out.returncode == 0, out.stderr
    rows = list(csv.DictReader(io.StringIO(out.stdout)))
    assert len(rows) == len(s["omega1"]) == s["grid"]["points"]
    np.testing.assert_array_equal(s["omega1"], [float(r["omega1"]) for r in rows])
    for side in ("left", "right", "free_left", "free_right"):
        for q in ("peak_displacement", "peak_velocity"):
            column = [float(r[f"{side}_{q}"]) for r in rows]
            assert [v.hex() for v in s[side][q]] == [v.hex() for v in column], (side, q)
    np.testing.assert_array_equal(s["impacts"], [int(r["impacts"]) for r in rows])
    assert s["region"] == [r["region"] for r in rows]
    # The same arrays under the one curve, and the JSON's metadata beside them.
    assert s["curves"][0]["points"]["left"]["peak_displacement"] is s["left"]["peak_displacement"]
    theirs = cli.json("spectrum", "--preset", "set1", "--omega1", "0.2:2.0:0.05")
    for key in ("version", "preset", "params", "mu", "model", "method", "grid", "omega1_grid"):
        same(s[key], theirs[key])


def test_spectrum_family_gives_one_curve_each(cli):
    s = pounding.spectrum(preset="set1", omega1="0.5:1.5:0.25", family="gap=0.5,inf")
    assert [c["family"] for c in s["curves"]] == [{"gap": 0.5}, {"gap": "inf"}]
    free = s["curves"][1]["points"]
    np.testing.assert_array_equal(free["impacts"], 0)


def test_map_cells_are_a_grid(cli):
    m = pounding.map(x="omega1=0.5:1.5:0.5", y="gap=0.5:1.0:0.25", preset="set1")
    theirs = cli.json("map", "--preset", "set1", "--x", "omega1=0.5:1.5:0.5", "--y", "gap=0.5:1.0:0.25")
    cells = m["cells"]
    assert cells["left"]["peak_displacement"].shape == (3, 3)
    flat = [c["left"]["peak_displacement"] for c in theirs["cells"]]
    assert [v.hex() for v in cells["left"]["peak_displacement"].ravel()] == [v.hex() for v in flat]
    np.testing.assert_array_equal(cells["x"][0], [0.5, 1.0, 1.5])
    np.testing.assert_array_equal(cells["y"][:, 0], [0.5, 0.75, 1.0])


def test_gap_is_the_cli_json(cli):
    ours = pounding.gap(preset="set1")
    theirs = cli.json("gap", "--preset", "set1")
    # One point: its columns are arrays of one value.
    assert ours["points"]["exact"][0].hex() == theirs["points"][0]["exact"].hex()
    line = pounding.gap(preset="set1", x="omega1=0.5:1.5:0.25")
    assert line["points"]["exact"].shape == (5,)


def test_suite_ida_and_fragility(cli):
    args = ("--preset", "two-buildings", "--suite", "synthetic:4")
    s = pounding.suite(suite="synthetic:4", preset="two-buildings", level=0.2)
    theirs = cli.json("suite", *args, "--level", "0.2")
    assert list(s["records"]["record"]) == [r["record"] for r in theirs["records"]]
    assert [v.hex() for v in s["records"]["left"]["peak_displacement_m"]] == [
        r["left"]["peak_displacement_m"].hex() for r in theirs["records"]
    ]
    i = pounding.ida(suite="synthetic:4", levels="0.05:0.2:0.05", preset="two-buildings")
    np.testing.assert_array_equal(i["levels"]["level_g"], [0.05, 0.1, 0.15, 0.2])
    f = pounding.fragility(suite="synthetic:4", levels="0.05:0.2:0.05", preset="two-buildings")
    theirs = cli.json("ida", *args, "--levels", "0.05:0.2:0.05")
    np.testing.assert_array_equal(f["levels"], [0.05, 0.1, 0.15, 0.2])
    assert f["fragility"][0]["limit_state"] == "pounding"
    np.testing.assert_array_equal(
        f["fragility"][0]["counts"]["exceeded"], [c["exceeded"] for c in theirs["fragility"][0]["counts"]]
    )
    same(f["fragility"][0]["fragility"], theirs["fragility"][0]["fragility"])


def test_a_rows_suite_ida_and_gap_are_the_cli_json(cli):
    # A row of buildings (SPEC §13) under a suite: the same reports as the command line's.
    row = ("--buildings", "block-and-frame", "--suite", "synthetic:3")
    s = pounding.suite(suite="synthetic:3", buildings="block-and-frame", level=0.3)
    theirs = cli.json("suite", *row, "--level", "0.3")
    assert list(s["records"]["record"]) == [r["record"] for r in theirs["records"]]
    assert [v.hex() for v in s["records"]["scale"]] == [r["scale"].hex() for r in theirs["records"]]
    for ours, their in zip(s["records"]["buildings"], theirs["records"]):
        same(ours, their["buildings"])
    same(s["statistics"], theirs["statistics"])
    same(s["buildings"], theirs["buildings"])
    levels = "0.1:0.3:0.1"
    i = pounding.ida(suite="synthetic:3", levels=levels, buildings="block-and-frame", drift="0.005,0.01")
    theirs = cli.json("ida", *row, "--levels", levels, "--drift", "0.005,0.01")
    np.testing.assert_array_equal(i["levels"]["level_g"], [0.1, 0.2, 0.3])
    assert [f["limit_state"] for f in i["fragility"]] == [f["limit_state"] for f in theirs["fragility"]]
    for ours, their in zip(i["fragility"], theirs["fragility"]):
        same(ours["fragility"], their["fragility"])
        np.testing.assert_array_equal(ours["counts"]["exceeded"], [c["exceeded"] for c in their["counts"]])
    f = pounding.fragility(suite="synthetic:3", levels=levels, buildings="block-and-frame", drift="frame:0.01")
    assert f["fragility"][1]["limit_state"] == "drift>0.01 (frame)"
    g = pounding.gap(suite="synthetic:3", buildings="block-and-frame", level=0.3)
    same(g["joints"], cli.json("gap", *row, "--level", "0.3")["joints"])


def test_presets_and_params(cli):
    names = [p["name"] for p in pounding.presets()]
    assert names[:2] == ["set1", "set2"] and "two-buildings" in names
    keys = pounding.Params.keys()
    assert "omega1" in keys and "gap" in keys
    omega1 = pounding.Params.omega1
    assert omega1.symbol == "Π_ω1" and omega1.kind == "number"
    assert omega1.default == pounding.run(preset="set1")["params"]["omega1"]
    assert pounding.Params.field("model").choices and math.isfinite(omega1.max)


def test_gap_over_a_suite_is_the_cli_json(cli):
    ours = pounding.gap(suite="synthetic:5", preset="two-buildings", level=0.2)
    theirs = cli.json("gap", "--suite", "synthetic:5", "--preset", "two-buildings", "--level", "0.2")
    assert list(ours["records"]["record"]) == [r["record"] for r in theirs["records"]]
    assert [v.hex() for v in ours["records"]["min_gap_m"]] == [r["min_gap_m"].hex() for r in theirs["records"]]
    same(ours["study"], theirs["study"])


def test_map_over_a_suite_is_the_cli_json(cli):
    axes = {"x": "gap=0.01:0.05:0.02", "y": "period1=0.5:1.0:0.5"}
    ours = pounding.map(suite="synthetic:3", preset="two-buildings", **axes)
    theirs = cli.json(
        "map", "--suite", "synthetic:3", "--preset", "two-buildings", "--x", axes["x"], "--y", axes["y"]
    )
    p = ours["cells"]["pounding_probability"]
    assert p.shape == (2, 3)
    assert [v.hex() for v in p.ravel()] == [c["pounding_probability"].hex() for c in theirs["cells"]]
    same(ours["x"], theirs["x"])


def test_an_ida_to_collapse_is_the_cli_json(cli):
    # P-Δ and collapse (SPEC §15): the collapse fragility, with pounding and
    # apart, is the command line's, and a collapsed building's drift is ∞.
    row = ("--buildings", "block-and-frame-pdelta", "--suite", "synthetic:3@3")
    levels = "0.6,1.2"
    i = pounding.ida(suite="synthetic:3@3", levels=levels, buildings="block-and-frame-pdelta", collapse=True)
    theirs = cli.json("ida", *row, "--levels", levels, "--collapse")
    collapse = [f for f in i["fragility"] if f["limit_state"] == "collapse (frame)"]
    assert len(collapse) == 1
    their = [f for f in theirs["fragility"] if f["limit_state"] == "collapse (frame)"][0]
    same(collapse[0]["fragility"], their["fragility"])
    same(collapse[0]["no_pounding_fragility"], their["no_pounding_fragility"])
    np.testing.assert_array_equal(collapse[0]["counts"]["exceeded"], [c["exceeded"] for c in their["counts"]])
    assert collapse[0]["counts"]["exceeded"][-1] > 0


def test_an_ida_to_a_design_target_is_the_cli_json(cli):
    # A suite scaled to a design spectrum, then as a whole to each level.
    target = "asce7:SDS=1.0,SD1=0.6,TL=8"
    i = pounding.ida(suite="synthetic:3", levels="0.2,0.4", preset="two-buildings", target=target)
    theirs = cli.json("ida", "--preset", "two-buildings", "--suite", "synthetic:3", "--target", target, "--levels", "0.2,0.4")
    assert i["suite"] == theirs["suite"] and i["scaled_as_a_whole"] == theirs["scaled_as_a_whole"]
    # Each level's records as columns: the scales of level l are the CLI's.
    for ours, their in zip(i["levels"]["records"]["scale"], theirs["levels"]):
        assert [v.hex() for v in ours] == [r["scale"].hex() for r in their["records"]]
