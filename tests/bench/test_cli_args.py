"""`spark bench` arguments as the benchmarks issue names them."""

from spark_core.cli import build_parser


def test_segmenter_is_the_resolver_under_the_name_the_issue_uses():
    args = build_parser().parse_args(["bench", "capbench", "--segmenter", "sim", "--trials", "3"])
    assert args.resolver == "sim" and args.trials == 3
    assert build_parser().parse_args(["bench", "capbench"]).resolver == "privileged"
