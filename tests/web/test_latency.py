"""The executor-to-browser latency benchmark (its own module: one sync Playwright session at a time)."""


def test_latency_benchmark_measures_live_events_in_the_browser():
    from spark_cli.console_bench.latency import run, section

    r = run(trials=1)
    assert r["events"] >= 8 and 0 < r["p50_ms"] <= r["p99_ms"]  # every live event of the plan was timed
    assert "headless chromium" in section(r, "spark bench latency")
