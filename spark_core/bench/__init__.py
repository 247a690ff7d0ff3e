"""Benchmarks: suites, batch runners and reports."""
