"""report.md of a results.json."""
import os

PHASES = ("partition", "graph", "color", "heal", "adapt", "post", "improve", "merge", "quality")



def partitioner_text(results):
    """Which partitioner each method's runs used, from their stats (runs before the stats named
    it used METIS)."""
    used = {}
    for case in results["cases"]:
        for run in case["runs"]:
            name = (run.get("stats") or {}).get("partitioner", "metis")
            used.setdefault(run["method"], set()).add({"metis": "METIS",
                                                       "hilbert": "Hilbert"}.get(name, name))
    return ", ".join("%s: %s" % (method.capitalize(), " and ".join(sorted(names)))
                     for method, names in sorted(used.items(), reverse=True))

def runs_of(case, method, coloring):
    return sorted((r for r in case["runs"]
                   if r["method"] == method and r["coloring"] == coloring),
                  key=lambda r: r["threads"])


def speedups(series):
    """Measured speedup over the 1-thread run of the same series (None without one)."""
    base = series[0]["stats"]["seconds"]["total"] if series[0]["threads"] == 1 else None
    return {r["threads"]: (base / r["stats"]["seconds"]["total"] if base else None)
            for r in series}


def refinement_seconds(run):
    """Our seconds comparable with TetGen's: the filter total without the quality arrays."""
    seconds = run["stats"]["seconds"]
    return seconds["total"] - seconds["quality"]


def fmt(value, digits=2):
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, int):
        return "{:,}".format(value)
    return "%.*f" % (digits, value)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join("---" if i == 0 else "---:" for i in range(len(header))) + "|"]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    return lines


def machine_lines(results):
    machine = results["machine"]
    lines = ["Machine: %s, %d cores (`nproc`; %d usable), %.1f GiB memory, Linux %s, host `%s`."
             % (machine["cpu"], machine["nproc"], machine["usableCores"], machine["memoryGiB"],
                machine["kernel"], machine["hostname"]),
             "",
             "Run: %s study, started %s, finished %s, %.0f s in all; threads %s; binary `%s`%s."
             % (results["study"], results["started"], results.get("finished", "-"),
                results.get("studySeconds", 0), ", ".join(str(t) for t in results["threads"]),
                os.path.relpath(results["cgmesh"], results.get("repository", "/")),
                (" at commit %s%s" % (results["git"]["commit"][:10],
                                      " (uncommitted changes in: %s)"
                                      % ", ".join(results["git"].get("dirtyFiles", ["?"]))
                                      if results["git"]["dirty"] else ""))
                if results.get("git") else "")]
    busy_runs = [r for case in results["cases"] for r in case["runs"] if r["otherWork"]]
    busy_runs += [case["tetgen"] for case in results["cases"]
                  if "tetgen" in case and case["tetgen"]["otherWork"]]
    if results["otherWorkAtStart"] or busy_runs or results.get("otherWorkAtEnd"):
        seen = sorted({w.split(":", 1)[1].strip().split()[0] for r in busy_runs
                       for w in r["otherWork"]} |
                      {w.split(":", 1)[1].strip().split()[0]
                       for w in results["otherWorkAtStart"] + results.get("otherWorkAtEnd", [])})
        lines += ["", "**Other work ran alongside this study**: %d of the timed runs started "
                  "while other processes (%s) were running; load average at the start %s. "
                  "Timings of those runs are disturbed (the machine has only %d cores)."
                  % (len(busy_runs), ", ".join(seen) or "-",
                     " / ".join("%.2f" % v for v in results["loadAverageAtStart"]),
                     results["machine"]["nproc"])]
    else:
        lines += ["", "No other `cgmesh`, `ctest`, `ninja`, `cc1plus` or `pvbatch` process was "
                  "running at the start of any timed run (load average at the start %s)."
                  % " / ".join("%.2f" % v for v in results["loadAverageAtStart"])]
    return lines


def parameter_lines(results):
    rows = []
    for case in results["cases"]:
        parameters = case["parameters"]
        rows.append([
            case["title"], fmt(case["input"]["cells"]), fmt(case["input"]["points"]),
            "%d iteration(s), factor %g (threshold %s)" % (
                parameters["template"]["iterations"],
                parameters["template"]["edgeLengthFactor"],
                fmt(runs_of(case, "template", "greedy")[0]["stats"]["edgeLengthThreshold"], 4)),
            "%d iteration(s), factor %g (V = %.4g)" % (
                parameters["delaunay"]["iterations"], parameters["delaunay"]["volumeFactor"],
                runs_of(case, "delaunay", "greedy")[0]["stats"]["volumeBound"]),
            parameters["regionArray"] or "-"])
    return table(["case", "input tets", "input points", "template", "Delaunay",
                  "region array"], rows)


def headline_lines(results):
    top = max(results["threads"])
    rows = []
    for case in results["cases"]:
        tetgen = case.get("tetgen")
        for method in ("template", "delaunay"):
            row = ["%s, %s" % (case["title"], method)]
            measured, simulated = [], []
            for coloring in ("greedy", "greedy-lu"):
                series = runs_of(case, method, coloring)
                measured.append(fmt(speedups(series).get(top)))
                model = case["models"].get("%s/%s" % (method, coloring))
                simulated.append(fmt(model["threads"]["16"]["speedup"]) if model else "-")
            ours = runs_of(case, method, "greedy-lu")
            best = [r for r in ours if r["threads"] == top][0]
            row += [" / ".join(measured), " / ".join(simulated)]
            if tetgen:
                tetgen_seconds = tetgen["stats"]["seconds"]["tetgen"]
                row.append("%s s vs %s s (%sx)" % (
                    fmt(refinement_seconds(best)), fmt(tetgen_seconds),
                    fmt(tetgen_seconds / refinement_seconds(best))))
                q, t = ours[0]["quality"], tetgen["quality"]
                row.append("%s / %s vs %s / %s" % (
                    fmt(q["minDihedralAngle"]["p1"], 1), fmt(q["edgeRatio"]["p99"]),
                    fmt(t["minDihedralAngle"]["p1"], 1), fmt(t["edgeRatio"]["p99"])))
                row.append("%s vs %s" % (fmt(q["tets"]), fmt(t["tets"])))
            else:
                row += ["-", "-", "-"]
            rows.append(row)
    return table(["case, method", "speedup %d threads, measured (greedy / greedy-lu)" % top,
                  "speedup 16 threads, simulated (greedy / greedy-lu)",
                  "ours at %d threads (greedy-lu) vs serial TetGen, speed-up" % top,
                  "min dihedral p1 (deg) / edge ratio p99: ours vs TetGen",
                  "tets: ours vs TetGen"], rows)


def model_check_lines(results):
    checks = [t for t in results["threads"] if t > 1]
    rows = []
    for case in results["cases"]:
        for method in ("template", "delaunay"):
            for coloring in ("greedy", "greedy-lu"):
                model = case["models"].get("%s/%s" % (method, coloring))
                series = runs_of(case, method, coloring)
                measured = speedups(series)
                if not model:
                    continue
                for threads in checks:
                    run = [r for r in series if r["threads"] == threads][0]
                    tasks_1 = sum(series[0]["stats"].get("partitionTaskSeconds", []))
                    tasks_t = sum(run["stats"].get("partitionTaskSeconds", []))
                    rows.append([
                        "%s, %s, %s" % (case["title"], method, coloring), str(threads),
                        fmt(measured[threads]), fmt(model["threads"][str(threads)]["speedup"]),
                        fmt(run["stats"]["seconds"]["total"]),
                        fmt(model["threads"][str(threads)]["seconds"]),
                        fmt(tasks_t / tasks_1 if tasks_1 else None)])
    return table(["case, method, colouring", "threads", "measured speedup",
                  "simulated speedup", "measured s", "simulated s",
                  "task seconds at T / at 1 thread"], rows)


def simulated_lines(results):
    threads = results["simulatedThreads"]
    rows = []
    for case in results["cases"]:
        for key, model in sorted(case["models"].items()):
            rows.append(["%s, %s" % (case["title"], key.replace("/", ", ")),
                         fmt(model["serialSeconds"]), fmt(model["taskSeconds"]),
                         fmt(model["restSeconds"]), fmt(model["longestTask"], 3),
                         str(model["steps"])] +
                        ["%s (%s)" % (fmt(model["threads"][str(t)]["speedup"]),
                                      fmt(model["threads"][str(t)]["loopEfficiency"]))
                         for t in threads[1:]])
    return table(["case, method, colouring", "serial s", "task s", "rest s", "longest task s",
                  "colour steps"] + ["T=%d" % t for t in threads[1:]], rows)


def runs_lines(results):
    rows = []
    for case in results["cases"]:
        for method in ("template", "delaunay"):
            for coloring in ("greedy", "greedy-lu"):
                series = runs_of(case, method, coloring)
                measured = speedups(series)
                for run in series:
                    stats = run["stats"]
                    seconds = stats["seconds"]
                    speedup = measured[run["threads"]]
                    rows.append([
                        "%s, %s, %s" % (case["title"], method, coloring), str(run["threads"]),
                        fmt(stats["output"]["cells"]), fmt(stats["output"]["points"]),
                        str(stats["colors"]), fmt(seconds["total"]), fmt(speedup),
                        fmt(speedup / run["threads"] if speedup else None)] +
                        [fmt(seconds[p]) for p in PHASES] +
                        [fmt(seconds["write"]), fmt(run["wallSeconds"]),
                         fmt(run["peakRssKiB"] / 1024.0, 0),
                         fmt(run["outputBytes"] / 1e6, 1),
                         fmt(stats.get("delaunayFallbacks", 0)),
                         fmt(run["identicalToFirst"])])
    return table(["case, method, colouring", "T", "tets", "points", "colours", "total s",
                  "speedup", "efficiency"] + ["%s s" % p for p in PHASES] +
                 ["write s", "process wall s", "peak RSS MiB", "output MB", "fallbacks",
                  "output = first T's"], rows)


def baseline_lines(results):
    top = max(results["threads"])
    rows = []
    for case in results["cases"]:
        tetgen = case.get("tetgen")
        if tetgen:
            stats = tetgen["stats"]
            rows.append([case["title"], "serial TetGen `%s`" % stats.get("switches", "-"),
                         fmt(tetgen["quality"]["tets"]), fmt(stats["seconds"]["tetgen"]),
                         fmt(tetgen["wallSeconds"]), fmt(tetgen["peakRssKiB"] / 1024.0, 0),
                         fmt(tetgen["outputBytes"] / 1e6, 1), "yes (one mesh)"])
        for method in ("template", "delaunay"):
            run = [r for r in runs_of(case, method, "greedy-lu") if r["threads"] == top][0]
            rows.append([case["title"], "cgmesh %s, greedy-lu, %d threads" % (method, top),
                         fmt(run["stats"]["output"]["cells"]), fmt(refinement_seconds(run)),
                         fmt(run["wallSeconds"]), fmt(run["peakRssKiB"] / 1024.0, 0),
                         fmt(run["outputBytes"] / 1e6, 1), "yes (merged, healed)"])
        subdivide = case.get("subdivideTetra")
        if subdivide:
            conformity = subdivide["conformity"]
            rows.append([case["title"], "vtkSubdivideTetra (serial)",
                         fmt(subdivide["outputCells"]), fmt(subdivide["seconds"]),
                         fmt(subdivide["processWallSeconds"]),
                         fmt(subdivide["peakRssKiB"] / 1024.0, 0),
                         fmt(subdivide["outputBytes"] / 1e6, 1),
                         "%s: %s faces shared by 1 tet, %s by more than 2; once-shared area "
                         "%.4g vs boundary %.4g (%+.1f%%)" % (
                             "yes" if conformity["conforming"] else "**no**",
                             fmt(conformity["facesSharedOnce"]),
                             fmt(conformity["facesSharedMore"]),
                             conformity["onceSharedFaceArea"], conformity["inputBoundaryArea"],
                             100 * conformity["boundaryAreaChange"])])
    return table(["case", "run", "tets", "seconds", "process wall s", "peak RSS MiB",
                  "output MB", "conforming"], rows)


def quality_lines(results):
    rows = []

    def add(case, label, summary):
        rows.append([case["title"], label, fmt(summary["tets"]),
                     fmt(summary["minDihedralAngle"]["min"], 2),
                     fmt(summary["minDihedralAngle"]["p1"], 2),
                     fmt(summary["minDihedralAngle"]["median"], 2),
                     fmt(100 * summary["shareMinDihedralBelow10"], 3),
                     fmt(summary["edgeRatio"]["median"], 3), fmt(summary["edgeRatio"]["p99"], 3),
                     fmt(summary["edgeRatio"]["max"], 2) if summary["edgeRatio"]["max"] < 1e6
                     else "%.0e" % summary["edgeRatio"]["max"],
                     fmt(100 * summary["shareAboveBound"], 3)
                     if "shareAboveBound" in summary else "-",
                     fmt(summary.get("degenerateTets"))])

    for case in results["cases"]:
        add(case, "input", case["input"]["quality"])
        for method in ("template", "delaunay"):
            for coloring in ("greedy", "greedy-lu"):
                add(case, "%s, %s" % (method, coloring), runs_of(case, method, coloring)[0]["quality"])
        if "tetgen" in case:
            add(case, "serial TetGen", case["tetgen"]["quality"])
        if "subdivideTetra" in case:
            add(case, "vtkSubdivideTetra", case["subdivideTetra"]["quality"])
    header = ["case", "mesh", "tets", "min dihedral min", "p1", "median", "% below 10 deg",
              "edge ratio median", "p99", "max", "% tets above V", "tets with edge ratio > 1e6"]
    if all(row[-1] == "-" for row in rows):   # results written before the count existed
        header, rows = header[:-1], [row[:-1] for row in rows]
    return table(header, rows)


def array_check_lines(results):
    rows = []
    for case in results["cases"]:
        meshes = [("%s, %s" % (r["method"], r["coloring"]), r["quality"])
                  for r in case["runs"] if "quality" in r]
        if "tetgen" in case:
            meshes.append(("serial TetGen", case["tetgen"]["quality"]))
        for label, summary in meshes:
            check = summary.get("minDihedralArrayCheck")
            if check:
                rows.append([case["title"], label, fmt(100 * check["shareDiffering"], 1),
                             fmt(check["arrayMin"]), fmt(check["computedMin"]),
                             fmt(check["arrayP1"]), fmt(check["computedP1"]),
                             fmt(check["arrayMax"]), fmt(check["computedMax"])])
    if not rows:
        return []
    return ["", "The minimum dihedral angles above are computed from the tets' face normals "
            "(benchmarks/lib/quality.py), not read from the files' `MinDihedralAngle` arrays: "
            "those come from Verdict's tet minimum angle in ParaView 5.11's VTK (the same "
            "values as `vtkMeshQuality` `SetTetQualityMeasureToMinAngle`) and hold values up "
            "to about 86 degrees, above the regular tet's 70.53 that no minimum dihedral angle "
            "exceeds. Array against computed angle (degrees):", ""] + table(
        ["case", "mesh", "% tets differing", "array min", "computed min", "array p1",
         "computed p1", "array max", "computed max"], rows)


def write(results, folder):
    top = max(results["threads"])
    lines = ["# cgmesh benchmark study", ""]
    lines += machine_lines(results)
    lines += ["", "Reproduce: `benchmarks/run%s` (README, Benchmarks). Everything below comes "
              "from `results.json` in this folder; `benchmarks/run --replot results.json` "
              "redraws the plots and this report." % (" --quick" if results["study"] == "quick"
                                                      else ""), ""]
    if results.get("notes"):
        lines += ["## Deviations and notes", ""] + ["- " + n for n in results["notes"]] + [""]
    lines += ["## Cases and parameters", "",
              "1,024 partitions (%s); colourings greedy and greedy-lu; every configuration "
              "at %s thread(s)." % (partitioner_text(results),
                                    ", ".join(str(t) for t in results["threads"])), ""]
    lines += parameter_lines(results)
    lines += ["", "## Headline", "",
              "Speedups are filter totals (`seconds.total` of the stats: partition to quality "
              "arrays, no file I/O) over the 1-thread run of the same method and colouring. "
              "Against TetGen the compared seconds are the refinement without quality arrays "
              "and file I/O: our total minus `quality` against TetGen's `tetgen` seconds "
              "(conversions and the TetGen call); speed-up > 1 means ours is faster. Quality: "
              "the 1st percentile of the minimum dihedral angle (higher is better) and the "
              "99th percentile of the edge ratio (lower is better).", ""]
    lines += headline_lines(results)
    lines += ["", "## Simulated many-core speedup", "",
              "Model (benchmarks/lib/model.py) from the 1-thread run's `partitionTaskSeconds` "
              "and `colorOfPartition`: per iteration and colour, the colour's partition tasks "
              "are list-scheduled (longest first) on T threads with a barrier after the "
              "colour; the serial seconds count once: per phase, Amdahl's law fitted to the "
              "measured thread counts' seconds (with 1 and 2 threads: s = 2 t(2) - t(1)), "
              "clamped to [0, t(1)], so a phase that did not speed up counts as serial "
              "whole; the rest of the "
              "measured total (the phases' parallel parts and the colour loop's time outside "
              "the tasks) is taken as perfectly parallel (/T). Speedup = measured "
              "1-thread total / modelled total; in brackets the colour loop's efficiency "
              "(task seconds / (T x loop makespan)). The model ignores memory bandwidth, so it "
              "is an upper bound where tasks slow down when they run side by side.", ""]
    lines += simulated_lines(results)
    lines += ["", "Check against the measured runs (last column: the tasks' summed seconds at "
              "T threads over 1 thread; above 1 means the tasks slow each other down, which "
              "the model does not see):", ""]
    lines += model_check_lines(results)
    lines += ["", "![strong scaling](strong-scaling.png)", "",
              "## Colour populations", "",
              "Partitions per colour (identical for both methods: the colouring is of the "
              "input's partition graph).", "", "![colour populations](colour-populations.png)",
              "", "## All runs", "",
              "Seconds per phase from the stats JSON; `total` excludes reading and writing; "
              "process wall includes both and the process start; peak RSS is /usr/bin/time's "
              "maximum resident set (for Delaunay: the largest of the main process and its "
              "TetGen worker processes, not their sum); output MB: the zlib-compressed .vtu. "
              "The last column says whether the output file is byte-identical to the one of "
              "the first thread count.", ""]
    lines += runs_lines(results)
    lines += ["", "## Baselines", "",
              "Serial TetGen refines the whole mesh once with the Delaunay run's absolute "
              "volume bound (switches `rQq2a<V>`). vtkSubdivideTetra splits every tet into 12 "
              "on its own; a conforming tet mesh has every interior face shared by exactly two "
              "tets, so the area of the faces shared by only one tet equals the input's "
              "boundary area; more area means hanging faces. Ours: the greedy-lu run at %d "
              "threads (seconds without quality arrays)." % top, ""]
    lines += baseline_lines(results)
    lines += ["", "## Quality", "",
              "MinDihedralAngle in degrees (regular tet 70.53), EdgeRatio (1 = equilateral); "
              "refined meshes from the first thread count's run. `%% tets above V`: share of "
              "tets whose volume exceeds the Delaunay bound.", ""]
    lines += quality_lines(results)
    lines += array_check_lines(results)
    lines += ["", "![initial quality](initial-quality.png)", "",
              "![final quality](final-quality.png)", ""]
    with open(os.path.join(folder, "report.md"), "w") as handle:
        handle.write("\n".join(lines))
