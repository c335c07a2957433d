"""PNG plots of a results.json (matplotlib, Agg): colour populations, strong scaling, quality."""
import os

import matplotlib
import matplotlib.ticker

matplotlib.use("Agg")
import matplotlib.pyplot as pyplot  # noqa: E402
import numpy  # noqa: E402

from lib import quality  # noqa: E402

METHOD_COLOURS = {"template": "tab:blue", "delaunay": "tab:green", "tetgen": "hotpink",
                  "subdivide": "grey"}
COLORING_STYLES = {"greedy": "-", "greedy-lu": ":"}
COLORING_MARKERS = {"greedy": "o", "greedy-lu": "s"}


def runs_of(case, method, coloring):
    return sorted((r for r in case["runs"]
                   if r["method"] == method and r["coloring"] == coloring),
                  key=lambda r: r["threads"])


def colour_populations(results, path):
    cases = results["cases"]
    figure, axes = pyplot.subplots(1, len(cases), figsize=(5 * len(cases), 3.8), squeeze=False)
    for axis, case in zip(axes[0], cases):
        width = 0.4
        for offset, coloring in ((-width / 2, "greedy"), (width / 2, "greedy-lu")):
            run = runs_of(case, "template", coloring)[0]
            population = run["stats"]["partitionsPerColor"]
            axis.bar(numpy.arange(len(population)) + offset, population, width,
                     label="%s (%d colours, balance %.2f)"
                     % (coloring, len(population), run["stats"]["colorBalance"]))
        axis.set_title("%s: %d partitions" % (case["title"], run["stats"]["partitions"]))
        axis.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        axis.set_xlabel("colour id")
        axis.set_ylabel("partitions")
        axis.legend(fontsize=8)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    pyplot.close(figure)


def strong_scaling(results, path):
    cases = results["cases"]
    figure, axes = pyplot.subplots(len(cases), 2, figsize=(11, 3.8 * len(cases)),
                                   squeeze=False)
    simulated_threads = results["simulatedThreads"]
    for row, case in zip(axes, cases):
        runtime_axis, speedup_axis = row
        for method in ("template", "delaunay"):
            for coloring in ("greedy", "greedy-lu"):
                series = runs_of(case, method, coloring)
                if not series:
                    continue
                threads = [r["threads"] for r in series]
                seconds = [r["stats"]["seconds"]["total"] for r in series]
                label = "%s, %s" % (method, coloring)
                style = dict(color=METHOD_COLOURS[method], linestyle=COLORING_STYLES[coloring],
                             marker=COLORING_MARKERS[coloring])
                runtime_axis.plot(threads, seconds, label=label, **style)
                if series[0]["threads"] == 1:
                    speedup_axis.plot(threads, [seconds[0] / s for s in seconds],
                                      label=label + " (measured)", **style)
                simulated = case["models"].get("%s/%s" % (method, coloring))
                if simulated:
                    speedup_axis.plot(
                        simulated_threads,
                        [simulated["threads"][str(t)]["speedup"] for t in simulated_threads],
                        color=METHOD_COLOURS[method], linestyle=COLORING_STYLES[coloring],
                        marker=COLORING_MARKERS[coloring], markerfacecolor="none", alpha=0.5,
                        label=label + " (simulated)")
        if "tetgen" in case:
            runtime_axis.axhline(case["tetgen"]["stats"]["seconds"]["tetgen"],
                                 color=METHOD_COLOURS["tetgen"], linestyle="--",
                                 label="TetGen Orig. (serial)")
        runtime_axis.set_title("%s: filter seconds" % case["title"])
        runtime_axis.set_xlabel("threads")
        runtime_axis.set_ylabel("seconds")
        runtime_axis.set_xticks(sorted({r["threads"] for r in case["runs"]}))
        runtime_axis.set_ylim(bottom=0)
        runtime_axis.legend(fontsize=7)
        speedup_axis.plot(simulated_threads, simulated_threads, color="black", linewidth=0.7,
                          label="ideal")
        speedup_axis.set_xscale("log", base=2)
        speedup_axis.set_yscale("log", base=2)
        speedup_axis.set_xticks(simulated_threads)
        speedup_axis.set_xticklabels([str(t) for t in simulated_threads])
        speedup_axis.set_yticks(simulated_threads)
        speedup_axis.set_yticklabels([str(t) for t in simulated_threads])
        speedup_axis.set_title("%s: speedup (filled: measured, open: simulated)"
                               % case["title"])
        speedup_axis.set_xlabel("threads")
        speedup_axis.set_ylabel("speedup over 1 thread")
        speedup_axis.legend(fontsize=6, ncol=2)
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    pyplot.close(figure)


def histogram_axis(axis, bins, series, xlabel):
    centres = 0.5 * (bins[:-1] + bins[1:])
    width = bins[1] - bins[0]
    peak = 0.0
    for label, counts, colour, filled in series:
        counts = numpy.asarray(counts, dtype=float)
        share = 100.0 * counts / max(1.0, counts.sum())
        peak = max(peak, share.max())
        if filled:
            axis.bar(centres, share, width=width, color=colour, alpha=0.55, label=label)
        else:
            axis.step(centres, share, where="mid", color=colour, linewidth=1.0, label=label)
    if peak > 25.0:
        # the cubes' few distinct tet shapes make spikes that would flatten everything else
        axis.set_yscale("log")
        axis.set_ylim(bottom=1e-3)
    axis.set_xlabel(xlabel)
    axis.set_ylabel("% of tets")
    axis.legend(fontsize=7)


def initial_quality(results, path):
    cases = results["cases"]
    figure, axes = pyplot.subplots(len(cases), 2, figsize=(11, 3.3 * len(cases)),
                                   squeeze=False)
    for row, case in zip(axes, cases):
        summary = case["input"]["quality"]
        label = "%s (%d tets)" % (case["title"], summary["tets"])
        histogram_axis(row[0], quality.EDGE_RATIO_BINS,
                       [(label, summary["edgeRatioHistogram"], "tab:purple", True)],
                       "edge ratio (1 = equilateral; last bin: larger)")
        histogram_axis(row[1], quality.DIHEDRAL_BINS,
                       [(label, summary["minDihedralHistogram"], "tab:purple", True)],
                       "minimum dihedral angle (degrees; regular: 70.5)")
        row[0].set_title("%s input: edge ratio" % case["title"])
        row[1].set_title("%s input: minimum dihedral angle" % case["title"])
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    pyplot.close(figure)


def final_quality(results, path):
    cases = results["cases"]
    figure, axes = pyplot.subplots(len(cases), 2, figsize=(11, 3.5 * len(cases)),
                                   squeeze=False)
    for row, case in zip(axes, cases):
        series_ratio, series_angle = [], []
        for method in ("template", "delaunay"):
            run = runs_of(case, method, "greedy-lu")[0]
            summary = run["quality"]
            label = "%s, greedy-lu (%d tets)" % (method, summary["tets"])
            series_ratio.append((label, summary["edgeRatioHistogram"],
                                 METHOD_COLOURS[method], True))
            series_angle.append((label, summary["minDihedralHistogram"],
                                 METHOD_COLOURS[method], True))
        if "tetgen" in case:
            summary = case["tetgen"]["quality"]
            label = "TetGen Orig. (%d tets)" % summary["tets"]
            series_ratio.append((label, summary["edgeRatioHistogram"],
                                 METHOD_COLOURS["tetgen"], True))
            series_angle.append((label, summary["minDihedralHistogram"],
                                 METHOD_COLOURS["tetgen"], True))
        if "subdivideTetra" in case:
            summary = case["subdivideTetra"]["quality"]
            label = "vtkSubdivideTetra (%d tets)" % summary["tets"]
            series_ratio.append((label, summary["edgeRatioHistogram"],
                                 METHOD_COLOURS["subdivide"], False))
            series_angle.append((label, summary["minDihedralHistogram"],
                                 METHOD_COLOURS["subdivide"], False))
        histogram_axis(row[0], quality.EDGE_RATIO_BINS, series_ratio,
                       "edge ratio (last bin: larger)")
        histogram_axis(row[1], quality.DIHEDRAL_BINS, series_angle,
                       "minimum dihedral angle (degrees)")
        row[0].set_title("%s output: edge ratio" % case["title"])
        row[1].set_title("%s output: minimum dihedral angle" % case["title"])
    figure.tight_layout()
    figure.savefig(path, dpi=110)
    pyplot.close(figure)


def write_all(results, folder):
    colour_populations(results, os.path.join(folder, "colour-populations.png"))
    strong_scaling(results, os.path.join(folder, "strong-scaling.png"))
    initial_quality(results, os.path.join(folder, "initial-quality.png"))
    final_quality(results, os.path.join(folder, "final-quality.png"))
