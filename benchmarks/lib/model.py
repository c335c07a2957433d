"""Simulated many-core run time of one refinement from its measured partition tasks.

The colour loop refines, per iteration and per colour, all partitions of that colour
concurrently, with a barrier after each colour. Given the measured seconds of every partition's
refinement task (stats `partitionTaskSeconds`, entry iteration * partitions + partition) and the
colour of every partition (`colorOfPartition`), the expected run time on T threads is

    serial + sum over iterations and colours of makespan(tasks of that colour, T) + rest / T

where makespan is greedy list scheduling with the longest task first (LPT) on T threads,
`serial` is the seconds that run on one thread, counted once, and `rest` is the remainder of the
measured total (whatever of adapt lies outside the tasks included) taken as perfectly parallel.

`serial` is measured where runs of the same configuration at more threads are given: per
phase, Amdahl's law t(T) = s + p / T is fitted to the seconds of every given thread count by least
squares in 1/T (with the 1- and 2-thread runs alone that is s = 2 t(2) - t(1)), s clamped to
[0, t(1)] (the colour loop's adapt phase is left to the task model). A fit through many thread
counts is not thrown by one noisy run. Without them, the phases that have serial parts
(SERIAL_PHASES) count as serial whole. With T = 1 the model gives back the measured total exactly.
"""
import heapq

SERIAL_PHASES = ("prepare", "partition", "graph", "color", "post", "merge", "input")
NOT_PHASES = ("total", "read", "write", "adapt")


def amdahl_serial(points):
    """Serial part s of t(T) = s + p / T fitted by least squares to (threads, seconds) points."""
    xs = [1.0 / threads for threads, _ in points]
    ys = [seconds for _, seconds in points]
    mean_x, mean_y = sum(xs) / len(xs), sum(ys) / len(ys)
    spread = sum((x - mean_x) ** 2 for x in xs)
    if spread == 0.0:
        return mean_y
    slope = sum((x - mean_x) * (y - mean_y) for x, y in zip(xs, ys)) / spread
    return mean_y - slope * mean_x


def serial_seconds(seconds, more=()):
    """Seconds on one thread: the Amdahl fit per phase through the 1-thread `seconds` and the
    (threads, seconds) of `more` runs, else SERIAL_PHASES whole."""
    if not more:
        return sum(seconds.get(phase, 0.0) for phase in SERIAL_PHASES)
    total = 0.0
    for phase in seconds:
        if phase in NOT_PHASES:
            continue
        points = [(1, seconds[phase])] + [(threads, other.get(phase, 0.0))
                                          for threads, other in more]
        total += min(seconds[phase], max(0.0, amdahl_serial(points)))
    return total


def lpt_makespan(tasks, threads):
    """Makespan of greedy list scheduling, longest task first, on `threads` identical threads."""
    if not tasks:
        return 0.0
    if threads <= 1:
        return float(sum(tasks))
    loads = [0.0] * min(threads, len(tasks))
    heapq.heapify(loads)
    for seconds in sorted(tasks, reverse=True):
        heapq.heappush(loads, heapq.heappop(loads) + seconds)
    return max(loads)


def colour_groups(task_seconds, colour_of_partition, partitions):
    """Lists of task seconds per (iteration, colour), in loop order."""
    iterations = len(task_seconds) // partitions
    colours = max(colour_of_partition) + 1
    groups = []
    for iteration in range(iterations):
        per_colour = [[] for _ in range(colours)]
        for partition in range(partitions):
            per_colour[colour_of_partition[partition]].append(
                task_seconds[iteration * partitions + partition])
        groups.extend(per_colour)
    return groups


def simulate(stats, thread_counts, more_runs=()):
    """Model of one run (its stats JSON, normally the 1-thread run): a dict with the serial,
    task and rest seconds and, per thread count, the modelled seconds and speedup over the
    measured total. `more_runs`, the stats of the same configuration at more threads, measure
    the serial seconds. None when the stats lack the per-partition task times."""
    tasks = stats.get("partitionTaskSeconds")
    colours = stats.get("colorOfPartition")
    if not tasks or not colours:
        return None
    seconds = stats["seconds"]
    partitions = len(colours)
    groups = colour_groups(tasks, colours, partitions)
    more = [(run.get("threads", 1), run["seconds"]) for run in more_runs
            if run.get("threads", 1) > 1]
    serial = serial_seconds(seconds, more)
    task_total = float(sum(tasks))
    rest = max(0.0, seconds["total"] - serial - task_total)
    measured_threads = stats.get("threads", 1)
    model = {"measuredThreads": measured_threads, "measuredTotal": seconds["total"],
             "serialMeasured": bool(more),
             "serialFitThreads": [1] + [threads for threads, _ in more],
             "serialSeconds": serial, "taskSeconds": task_total, "restSeconds": rest,
             "longestTask": max(tasks), "steps": len(groups), "threads": {}}
    for threads in thread_counts:
        # Tasks measured at more than one thread are taken as they are (a 1-thread run is the
        # normal input; its tasks run without contention).
        makespan = sum(lpt_makespan(group, threads) for group in groups)
        total = serial + makespan + rest * measured_threads / threads
        model["threads"][str(threads)] = {
            "seconds": total, "colourLoopSeconds": makespan,
            "speedup": seconds["total"] / total if measured_threads == 1 else None,
            "loopEfficiency": task_total / (threads * makespan) if makespan > 0 else None}
    return model
