"""Helpers of benchmarks/run: machine description, timed runs, mesh quality, the many-core
makespan model, plots and the Markdown report."""
