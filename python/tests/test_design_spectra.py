"""Target spectra and records scaled to them: the codes' formulas worked by
hand, and the command line's `records scale` value for value."""

import math

import numpy as np
import pytest

import pounding


def test_asce7_branches_worked_by_hand():
    # S_DS = 1, S_D1 = 0.6, T_L = 8: T0 = 0.12 s, T_S = 0.6 s.
    t = np.array([0.0, 0.06, 0.12, 0.6, 2.0, 8.0, 10.0])
    want = np.array([0.4, 0.7, 1.0, 1.0, 0.3, 0.075, 0.6 * 8 / 100])
    got = pounding.target_spectrum("asce7:SDS=1,SD1=0.6,TL=8", t)
    assert isinstance(got, np.ndarray) and got.shape == t.shape
    assert np.allclose(got, want, rtol=1e-12, atol=0)
    mce = pounding.target_spectrum("asce7-mce:SDS=1,SD1=0.6,TL=8", t)
    assert np.allclose(mce, 1.5 * want, rtol=1e-12, atol=0)


def test_ec8_keeps_the_shape_of_the_periods():
    # ground C type 1: S = 1.15, T_B = 0.2, T_C = 0.6, T_D = 2; a_g = 0.2 g.
    t = np.array([[0.0, 0.2], [0.6, 3.0]])
    got = pounding.target_spectrum("ec8:ag=0.2,ground=C,type=1", t)
    plateau = 0.2 * 1.15 * 2.5
    want = np.array([[0.2 * 1.15, plateau], [plateau, plateau * 0.6 * 2.0 / 9.0]])
    assert got.shape == (2, 2)
    assert np.allclose(got, want, rtol=1e-12, atol=0)


def test_bad_targets_and_periods_raise_value_error():
    with pytest.raises(ValueError, match="ground `F`"):
        pounding.target_spectrum("ec8:ag=0.3,ground=F,type=1", [0.5])
    with pytest.raises(ValueError, match="5 s is outside the target's periods 0–4 s"):
        pounding.target_spectrum("ec8:ag=0.3,ground=B,type=1", [0.5, 5.0])
    with pytest.raises(ValueError, match="--target"):
        pounding.scale_suite("synthetic:3", "nbc:x=1", 0.5)


def test_scale_suite_is_the_cli_json(cli):
    ours = pounding.scale_suite("synthetic:11", "asce7:SDS=1,SD1=0.6,TL=8", 0.8)
    theirs = cli.json(
        "records", "scale", "--suite", "synthetic:11", "--target",
        "asce7:SDS=1,SD1=0.6,TL=8", "--period", "0.8",
    )
    for key in ("periods", "target", "mean", "p16", "p84"):
        assert isinstance(ours[key], np.ndarray)
        assert [v.hex() for v in ours[key].tolist()] == [float(v).hex() for v in theirs[key]]
    factors = [float(r["factor"]).hex() for r in theirs["records"]]
    assert [v.hex() for v in ours["records"]["factor"].tolist()] == factors
    assert ours["records"]["spectrum"].shape == (11, len(theirs["periods"]))
    assert ours["check"] == theirs["check"]
    assert ours["check"]["holds"] is True
    assert math.isclose(ours["check"]["min_ratio"], 0.9, rel_tol=1e-12)


def test_a_rule_that_fails_is_returned_not_raised():
    r = pounding.scale_suite("synthetic:3", "asce7:SDS=1,SD1=0.6,TL=8", 0.8)
    assert r["check"]["holds"] is False
    assert "at least 11" in r["check"]["failures"][0]
