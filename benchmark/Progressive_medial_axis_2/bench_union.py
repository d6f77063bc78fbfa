#!/usr/bin/env python3
"""Union of two precomputed axes (the paper's Fig. 24): the merge alone
against a one-shot of the union.

    benchmark/Progressive_medial_axis_2/bench_union.py [--runs N] [--sizes N,...]
                                                       [--chains C,...] [--out FILE]

Needs a build in build/.  For every size n and chain length c it makes a
star-shaped polygon of n vertices (random radii in [1, 2]) and splits it in
two along a chain of c edges through its interior (radially monotone runs
inside the disk of radius 0.5 that the polygon contains, so the chain is
simple), writes the two parts and the whole to
benchmark/Progressive_medial_axis_2/data/union/, and measures, median of N
runs of the tool (`--stats`):

- union: `--union` of the two parts; `time_union_merge` (the merges along
  the chain alone), `time_union_join` (finding the chain and the union's
  rings, validating the union, copying the two axes), and the whole process;
- one-shot: the whole polygon in one shot: `time_total` (reading to final
  axis) and the whole process.

Prints a Markdown table (and writes it to --out).  Times are seconds.
"""

import argparse
import math
import os
import random
import re
import statistics
import subprocess
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
TOOL = os.path.join(ROOT, "build/tool/Progressive_medial_axis_2/progressive_medial_axis")
DATA = os.path.join(ROOT, "benchmark/Progressive_medial_axis_2/data/union")


def wkt(ring):
    pts = ring + [ring[0]]
    return "POLYGON ((" + ", ".join("%r %r" % p for p in pts) + "))\n"


def star_split(n, chain, seed):
    """The whole star polygon, its two parts along a chain of about `chain`
    edges (at least 4), and the number of edges of the chain."""
    rng = random.Random(seed)
    th = [2 * math.pi * (i + 0.8 * rng.random()) / n for i in range(n)]
    rad = [rng.uniform(1, 2) for _ in range(n)]
    W = [(rad[i] * math.cos(th[i]), rad[i] * math.sin(th[i])) for i in range(n)]
    ia = n // 8
    ib = ia + n // 3
    ta, tb = th[ia], th[ib]
    sector = min(0.08, 0.25 * (tb - ta))

    def on_ray(i, r):
        return (W[i][0] * r / rad[i], W[i][1] * r / rad[i])

    def run(count, t):   # radially monotone from 0.5 down to 0 (the last point is the origin)
        out = []
        for k in range(1, count + 1):
            r = 0.5 * (1 - (k - rng.uniform(0, 0.5)) / count)
            a = t + rng.uniform(-sector, sector)
            out.append((0.0, 0.0) if k == count else (r * math.cos(a), r * math.sin(a)))
        return out

    inner = max(3, chain - 1)   # points inside the chain
    down = inner // 2
    up = inner - down
    pts = [on_ray(ia, 0.5)] + run(down - 1, ta) if down > 1 else [on_ray(ia, 0.5), (0.0, 0.0)]
    rise = [on_ray(ib, 0.5)] + run(up, tb)
    rise.pop()   # the origin is already in
    pts += rise[::-1]
    A = W[ia:ib + 1] + pts[::-1]
    B = W[ib:] + W[:ia + 1] + pts
    return W, A, B, len(pts) + 1


def stats_of(out):
    return {m.group(1): m.group(2) for m in re.finditer(r"^(\S+) (\S+)$", out, re.M)}


def timed(args):
    t = time.perf_counter()
    p = subprocess.run([TOOL, "--stats"] + args, capture_output=True, text=True)
    wall = time.perf_counter() - t
    if p.returncode != 0:
        sys.exit("tool failed: %s\n%s" % (" ".join(args), p.stderr))
    return wall, stats_of(p.stdout)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--runs", type=int, default=3)
    ap.add_argument("--sizes", default="20000,200000")
    ap.add_argument("--chains", default="10,100")
    ap.add_argument("--out")
    o = ap.parse_args()
    os.makedirs(DATA, exist_ok=True)
    rows = ["| vertices | chain edges | union merge | union join | union process | one-shot time_total | one-shot process | merge / one-shot time_total |",
            "|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for n in (int(x) for x in o.sizes.split(",")):
        for c in (int(x) for x in o.chains.split(",")):
            W, A, B, edges = star_split(n, c, seed=n + c)
            base = os.path.join(DATA, "star%d_chain%d" % (n, c))
            for suffix, ring in (("_a", A), ("_b", B), ("", W)):
                with open(base + suffix + ".wkt", "w") as f:
                    f.write(wkt(ring))
            merge, join, uproc, total, oproc = [], [], [], [], []
            for _ in range(o.runs):
                wall, s = timed(["--union", base + "_b.wkt", base + "_a.wkt"])
                merge.append(float(s["time_union_merge"]))
                join.append(float(s["time_union_join"]))
                uproc.append(wall)
                wall, s = timed([base + ".wkt"])
                total.append(float(s["time_total"]))
                oproc.append(wall)
            med = statistics.median
            rows.append("| %d | %d | %.6f | %.4f | %.3f | %.3f | %.3f | %.5f |" % (
                n, edges, med(merge), med(join), med(uproc), med(total), med(oproc), med(merge) / med(total)))
            print(rows[-1], flush=True)
    text = "\n".join(rows) + "\n"
    print(text)
    if o.out:
        with open(o.out, "w") as f:
            f.write(text)


if __name__ == "__main__":
    main()
