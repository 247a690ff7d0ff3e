"""The CLI's choices come from the one catalog, under one name for the perception backend: `segmenter`."""

import pytest

from spark_cli import build_parser
from spark_core.catalog import SEGMENTERS


def test_segmenter_is_the_one_name_and_its_choices_are_the_catalogs():
    args = build_parser().parse_args(["bench", "capbench", "--segmenter", "sim", "--trials", "3"])
    assert args.segmenter == "sim" and args.trials == 3
    assert build_parser().parse_args(["bench", "capbench"]).segmenter == "learned"  # the camera-only default
    for name in SEGMENTERS:
        assert build_parser().parse_args(["run", "lift_block", "--segmenter", name]).segmenter == name


@pytest.mark.parametrize(
    "argv",
    [
        ["bench", "capbench", "--resolver", "sim"],
        ["run", "lift_block", "--resolver", "sim"],
        ["run", "lift_block", "--segmenter", "privileged"],
    ],
)
def test_old_names_are_refused(argv, capsys):
    with pytest.raises(SystemExit):
        build_parser().parse_args(argv)
    err = capsys.readouterr().err
    assert "unrecognized arguments: --resolver" in err or "invalid choice: 'privileged'" in err
