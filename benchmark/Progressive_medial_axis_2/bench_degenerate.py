#!/usr/bin/env python3
"""Degenerate-input benchmark: exact ties of integer grids, symmetric shapes,
regular polygons and glyphs, against Epick and Segment_Delaunay_graph_2.

    benchmark/Progressive_medial_axis_2/bench_degenerate.py [--before TOOL] [--runs N]
                                                            [--timeout S] [--quick] [--out FILE]

Needs a build in build/ (scripts/test.sh or cmake --build build).  Generates
the shapes with make_degenerate (the sizes of the degenerate table and about
10 times them, in benchmark/Progressive_medial_axis_2/data/degenerate/) and
make_glyphs.py (several fonts, data/glyphs/, and with 80 segments a curve and
2 decimals, about 10 times the vertices, data/glyphs10/), then measures for
every shape:

- ours: the whole `progressive_medial_axis` process with the default traits
  (exact decisions), median of N runs (at least 21 for processes under
  50 ms; ours, Epick and before run in turn), and its per-stage decision counts
  from --stats (one-root, MPFR and nested-root stages; a run of its own);
- Epick: the same process with --traits epick;
- SDG: Segment_Delaunay_graph_2 filtered construction alone (bench_time
  --methods sdg, in-process), median of N runs;
- before (with --before TOOL): the same process with another build of the
  tool, e.g. an older commit, under the time limit.

Prints a Markdown table (and writes it to --out).  Glyphs are summarised per
font: the whole process on all glyphs of the font in one file (a
GEOMETRYCOLLECTION, one axis per glyph), Epick the same, against the sum of
SDG's construction times over the glyphs; and in-process, glyph by glyph,
the one-shot on one thread against SDG (bench_time, same run): the sum and
the worst ratio.  Times are seconds.
"""

import argparse
import os
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
BUILD = os.path.join(ROOT, "build")
TOOL = os.path.join(BUILD, "tool/Progressive_medial_axis_2/progressive_medial_axis")
BENCH_TIME = os.path.join(BUILD, "benchmark/Progressive_medial_axis_2/bench_time")
MAKE_DEGENERATE = os.path.join(BUILD, "benchmark/Progressive_medial_axis_2/make_degenerate")
DATA = os.path.join(ROOT, "benchmark/Progressive_medial_axis_2/data")
FONTS = "DejaVuSans,DejaVuSerif-Bold,LiberationSerif-Regular,FreeMono,FreeSerif"


# The time of a process that exited with an error (None: it ran out of time).
FAILED = False


def run_process(cmd, timeout):
    """Wall time of one process, None if it ran out of time, or FAILED (its
    error on stderr of this script) if it exited with an error."""
    start = time.perf_counter()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, timeout=timeout, text=True)
    except subprocess.TimeoutExpired:
        return None, ""
    if p.returncode != 0:
        print("%s: exit status %d: %s" % (" ".join(cmd), p.returncode, p.stderr.strip()[:300]), file=sys.stderr)
        return FAILED, p.stderr.strip()
    return time.perf_counter() - start, p.stdout


def median_process(cmd, runs, timeout):
    times, out = [], ""
    for _ in range(runs):
        t, o = run_process(cmd, timeout)
        if t is None or t is FAILED:
            return t, o
        times.append(t)
        out = o
    return statistics.median(times), out


def median_processes(cmds, runs, timeout):
    """Medians of the wall times of several commands, run in turn (one run of
    each, then the next round), so that a slower or faster spell of the
    machine falls on all of them.  Processes of under 50 ms get at least 21
    rounds: at 5 to 15 ms they move by 20% from run to run.  A command that
    runs out of time gives None, one that fails FAILED (and is not run
    again)."""
    times = [[] for _ in cmds]
    rounds = runs
    r = 0
    while r < rounds:
        for i, cmd in enumerate(cmds):
            if times[i] is None or times[i] is FAILED:
                continue
            t, _ = run_process(cmd, timeout)
            if t is None or t is FAILED:
                times[i] = t
            else:
                times[i].append(t)
        if r == 0:
            firsts = [ts[0] for ts in times if ts]
            if firsts and max(firsts) < 0.05:
                rounds = max(runs, 21)
        r += 1
    return [ts if ts is None or ts is FAILED else statistics.median(ts) for ts in times]


def stats_of(text):
    d = {}
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 2:
            d[parts[0]] = parts[1]
    return d


def sdg_time(path, runs, timeout):
    p = subprocess.run([BENCH_TIME, "--runs", str(runs), "--timeout", str(timeout), "--no-baseline",
                        "--methods", "sdg", path], stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
    for line in p.stdout.splitlines()[1:]:
        f = line.split("\t")
        if len(f) > 4 and f[3] == "sdg":
            v = float(f[4])
            return v if v >= 0 else None
    return None


def fmt(t, limit=None):
    if t is FAILED:
        return "failed"
    if t is None:
        return "over %g s" % limit if limit else "failed"
    return "%.3g" % t if t >= 0.001 else "%.1e" % t


def glyph_rows(a, lines, glyphs, make_args, label):
    """Rows of the glyph table: the glyphs of every font of FONTS written by
    make_glyphs.py (with `make_args`) into `glyphs`, one row a font."""
    subprocess.run([sys.executable, os.path.join(ROOT, "benchmark/Progressive_medial_axis_2/make_glyphs.py"),
                    glyphs, "--fonts", FONTS] + make_args, check=True, stdout=subprocess.DEVNULL)
    by_font = {}
    for f in sorted(os.listdir(glyphs)):
        if f.endswith(".wkt") and not f.endswith("_all.wkt"):
            by_font.setdefault(f.split("_")[0], []).append(os.path.join(glyphs, f))
    for font, files in sorted(by_font.items()):
        # all glyphs of the font in one file, as a CAM user hands a
        # font's outlines to the tool: one process, one axis per glyph
        # (ids p<k>:...), in parallel over the glyphs
        polygons = []
        for path in files:
            with open(path) as g:
                polygons.append(g.read().strip())
        whole = os.path.join(glyphs, font + "_all.wkt")
        with open(whole, "w") as g:
            g.write("GEOMETRYCOLLECTION (" + ", ".join(polygons) + ")\n")
        ours, _ = median_process([TOOL, whole], a.runs, a.timeout)
        epick, _ = median_process([TOOL, "--traits", "epick", whole], a.runs, a.timeout)
        s = stats_of(median_process([TOOL, "--stats", whole], 1, a.timeout)[1])
        nested = int(s.get("filter_exact_evaluations", 0)) + int(s.get("filter_exact_comparisons", 0))
        # in-process, glyph by glyph: the one-shot on one thread and SDG's
        # construction, same bench_time run
        p = subprocess.run([BENCH_TIME, "--runs", str(a.runs), "--timeout", str(a.timeout), "--no-baseline",
                            "--methods", "pma_oneshot_1,sdg"] + files,
                           stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
        per = {}
        vmax = 0
        for line in p.stdout.splitlines()[1:]:
            f = line.split("\t")
            if len(f) > 4:
                per.setdefault(f[0], {})[f[3]] = float(f[4])
                vmax = max(vmax, int(f[1]))
        sdg_sum = sum(v.get("sdg", 0) for v in per.values())
        ours_sum = sum(v.get("pma_oneshot_1", 0) for v in per.values())
        worst = max((v["pma_oneshot_1"] / v["sdg"] for v in per.values()
                     if v.get("sdg", 0) > 0 and "pma_oneshot_1" in v), default=0)
        row = "| %s%s | %d | %d | %s | %s | %.3g | %s | %.3g | %.2f | %d |" % (
            font, label, len(files), vmax, fmt(ours, a.timeout), fmt(epick, a.timeout), sdg_sum,
            "%.2f" % (ours / sdg_sum) if ours and sdg_sum else "-", ours_sum, worst, nested)
        print(row, flush=True)
        lines.append(row)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--before", help="another build of progressive_medial_axis to compare with")
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--timeout", type=float, default=60)
    ap.add_argument("--quick", action="store_true", help="only the sizes of the table, no glyphs")
    ap.add_argument("--out", help="also write the table to this file")
    a = ap.parse_args()

    degenerate = os.path.join(DATA, "degenerate")
    subprocess.run([MAKE_DEGENERATE, degenerate], check=True, stdout=subprocess.DEVNULL)
    shapes = sorted(os.path.join(degenerate, f) for f in os.listdir(degenerate) if f.endswith(".wkt"))
    if not a.quick:
        big = os.path.join(DATA, "degenerate10")
        subprocess.run([MAKE_DEGENERATE, big, "--scale10"], check=True, stdout=subprocess.DEVNULL)
        shapes += sorted(os.path.join(big, f) for f in os.listdir(big) if f.endswith(".wkt"))

    lines = []
    lines.append("| shape | vertices | holes | before | ours (default) | ours, Epick | SDG filtered | ours / Epick | ours / SDG | one-root | MPFR | nested |")
    lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for path in shapes:
        name = os.path.relpath(path, DATA)[:-4]
        # (--stats in a run of its own: in one-shot mode it also counts the
        # region-growing steps, a triangulation after the timed work)
        s = stats_of(median_process([TOOL, "--stats", path], 1, a.timeout)[1])
        before = None
        cmds = [[TOOL, path], [TOOL, "--traits", "epick", path]]
        if a.before:
            # (an older build can take minutes: then once)
            before, _ = median_process([a.before, path], 1, a.timeout)
            if isinstance(before, float) and before < 1:
                cmds.append([a.before, path])
        times = median_processes(cmds, a.runs, a.timeout)
        ours, epick = times[0], times[1]
        if len(times) > 2:
            before = times[2]
        sdg = sdg_time(path, max(a.runs, 21) if isinstance(ours, float) and ours < 0.05 else a.runs, a.timeout)
        stage = lambda k: int(s.get("filter_%s_evaluations" % k, 0)) + int(s.get("filter_%s_comparisons" % k, 0))
        ratio = lambda x, y: "%.2f" % (x / y) if x and y else "-"
        row = "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %d | %d | %d |" % (
            name, s.get("input_vertices", "?"), s.get("holes", "?"),
            fmt(before, a.timeout) if a.before else "-", fmt(ours, a.timeout), fmt(epick, a.timeout),
            fmt(sdg, a.timeout), ratio(ours, epick), ratio(ours, sdg),
            stage("rational"), stage("mpfr"), stage("exact"))
        print(row, flush=True)
        lines.append(row)

    if not a.quick:
        lines.append("")
        lines.append("| glyph font | glyphs | vertices (max) | ours, one process | Epick, one process | SDG, sum of glyphs | ours / SDG | ours in-process, sum | in-process ours / SDG, worst glyph | nested decisions |")
        lines.append("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        # the glyphs as make_glyphs.py writes them by default (8 segments a
        # curve, integer coordinates), and about 10 times as many vertices
        # (80 segments a curve, 2 decimals: finely flattened curves, where
        # the one-shot takes boundary evolution)
        glyph_rows(a, lines, os.path.join(DATA, "glyphs"), [], "")
        glyph_rows(a, lines, os.path.join(DATA, "glyphs10"), ["--segments", "80", "--decimals", "2"], " x10")

    if a.out:
        with open(a.out, "w") as f:
            f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
