"""Bad input raises ValueError with the command line's one-line message."""

import pytest

import pounding


@pytest.mark.parametrize(
    "kwargs, argv",
    [
        ({"omega1": -1}, ["--set", "omega1=-1"]),
        ({"omega1": "fast"}, ["--set", "omega1=fast"]),
        ({"no_such_key": 1}, ["--set", "no_such_key=1"]),
        ({"method": "rk4"}, ["--method", "rk4"]),
        ({"model": "rubber"}, ["--model", "rubber"]),
        ({"preset": "no-such-preset"}, ["--preset", "no-such-preset"]),
        ({"excitation": "record:/no/such/file.at2"}, ["--excitation", "record:/no/such/file.at2"]),
        ({"cycles": 0}, ["--cycles", "0"]),
        ({"repeat": 0}, ["--repeat", "0"]),
    ],
)
def test_run_errors_are_the_cli_messages(cli, kwargs, argv):
    with pytest.raises(ValueError) as e:
        pounding.run(**kwargs)
    assert str(e.value) == cli.error("run", *argv)


def test_spectrum_and_suite_errors_are_the_cli_messages(cli):
    with pytest.raises(ValueError) as e:
        pounding.spectrum(omega1="3:1:0.1")
    assert str(e.value) == cli.error("spectrum", "--omega1", "3:1:0.1")
    with pytest.raises(ValueError) as e:
        pounding.suite(suite="synthetic:2", preset="set1")
    assert str(e.value) == cli.error("suite", "--suite", "synthetic:2", "--preset", "set1")
    with pytest.raises(ValueError) as e:
        pounding.ida(suite="synthetic:2", levels="0.3:0.1:0.1", preset="two-buildings")
    assert str(e.value) == cli.error(
        "ida", "--suite", "synthetic:2", "--levels", "0.3:0.1:0.1", "--preset", "two-buildings"
    )


def test_a_switch_takes_a_bool():
    with pytest.raises(ValueError, match="no_pounding: a switch"):
        pounding.run(no_pounding="yes")
    assert pounding.run(no_pounding=True)["impacts"] == 0
    assert pounding.run(no_pounding=False)["impacts"] > 0


def test_format_is_not_an_option():
    with pytest.raises(ValueError, match="format: the module returns the report itself"):
        pounding.run(format="csv")


@pytest.mark.parametrize("key", ["shard", "part", "skip_done"])
def test_shards_are_cut_from_the_command_line_only(key):
    # A part records the command line that made it, for the merge to replay.
    value = True if key == "skip_done" else ("1/2" if key == "shard" else "p.part")
    with pytest.raises(ValueError, match=f"{key}: the module runs whole sweeps"):
        pounding.spectrum(**{key: value})
