#!/usr/bin/env python3
"""Issue 9's measures on one shape, taken in one run: the tool against the peers,
and its thread scaling, with the speed of each CPU.

    python3 benchmark/Progressive_medial_axis_2/ratio_peers.py [--rounds N] [--tool-runs K]
        [--no-peers] [--scaling] [--build DIR] FILE

Peers: ROUNDS rounds (default 7), each of K whole tool processes (default 5,
their median: a plain run, the one-shot on all threads, output to /dev/null),
then one construction of `Segment_Delaunay_graph_2` (filtered) and one of
Boost.Polygon's voronoi, timed in-process by bench_time (built with
-DPMA_BUILD_BENCHMARKS=ON).  Interleaving the three puts each round's tool and
peers in the same state of the machine; the script prints the medians, their
ratios, and each round's ratio.

--scaling: ROUNDS rounds of the tool with --threads 1 then --threads 2
(alternating the order), then one-thread runs pinned to each CPU (taskset):
on the 2-core VM of RESULTS.md one CPU was at times a third slower than the
other, which moves the one-thread time, and so the scaling, by the CPU that
run lands on.
"""
import argparse
import os
import statistics
import subprocess
import time

here = os.path.dirname(os.path.abspath(__file__))
root = os.path.normpath(os.path.join(here, "..", ".."))

ap = argparse.ArgumentParser()
ap.add_argument("file")
ap.add_argument("--rounds", type=int, default=7)
ap.add_argument("--tool-runs", type=int, default=5)
ap.add_argument("--no-peers", action="store_true")
ap.add_argument("--scaling", action="store_true")
ap.add_argument("--build", default=os.path.join(root, "build"))
a = ap.parse_args()
tool = os.path.join(a.build, "tool", "Progressive_medial_axis_2", "progressive_medial_axis")
bench = os.path.join(a.build, "benchmark", "Progressive_medial_axis_2", "bench_time")


def whole(args, prefix=()):
    t0 = time.perf_counter()
    subprocess.run(list(prefix) + [tool] + list(args) + [a.file], stdout=subprocess.DEVNULL, check=True)
    return time.perf_counter() - t0


def peer(method):
    out = subprocess.run([bench, "--runs", "1", "--no-baseline", "--methods", method, a.file],
                         capture_output=True, text=True, check=True).stdout.strip().split("\n")
    header, row = out[0].split("\t"), out[-1].split("\t")
    return float(row[header.index("median_seconds")])


def med(xs):
    return statistics.median(xs)


if not a.no_peers:
    ours, sdg, boost = [], [], []
    for r in range(a.rounds):
        ours.append(med([whole([]) for _ in range(a.tool_runs)]))
        sdg.append(peer("sdg"))
        boost.append(peer("boost_voronoi"))
        print("round %d: tool %.3f s  SDG %.3f s  Boost.Polygon %.3f s" % (r, ours[-1], sdg[-1], boost[-1]), flush=True)
    print("medians: tool %.3f s  SDG %.3f s  Boost.Polygon %.3f s" % (med(ours), med(sdg), med(boost)))
    print("SDG / tool %.2f  Boost.Polygon / tool %.2f" % (med(sdg) / med(ours), med(boost) / med(ours)))
    print("each round, SDG / tool:", " ".join("%.2f" % (s / t) for s, t in zip(sdg, ours)))
    print("each round, Boost.Polygon / tool:", " ".join("%.2f" % (b / t) for b, t in zip(boost, ours)))

if a.scaling:
    one, two = [], []
    for r in range(a.rounds):
        for n in ((1, 2) if r % 2 == 0 else (2, 1)):
            (one if n == 1 else two).append(whole(["--threads", str(n)]))
    print("threads 1: %.3f s  threads 2: %.3f s  scaling %.2f" % (med(one), med(two), med(one) / med(two)))
    for cpu in range(os.cpu_count() or 1):
        ts = [whole(["--threads", "1"], ("taskset", "-c", str(cpu))) for _ in range(3)]
        print("threads 1 pinned to CPU %d: %.3f s (median of 3)" % (cpu, med(ts)))
