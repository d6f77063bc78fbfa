#!/usr/bin/env python3
"""Writes polygons of a WKT MULTIPOLYGON file as files of their own, for
sweeps against the oracle (scripts/check_oracle.sh) on real data.

    python3 benchmark/Progressive_medial_axis_2/split_polygons.py FILE.wkt OUTDIR
        [--largest N] [--most-holes N]
        [--sample N --min-vertices A --max-vertices B --min-holes H --seed S]

FILE.wkt is a MULTIPOLYGON, as the tool's `--repair --repaired-out` writes a
whole-world GeoJSON file after repair.  Each polygon chosen is written to
OUTDIR/PREFIX_K.wkt as a POLYGON, its text copied character for character
(K is its 0-based index in FILE.wkt, which is the k of the tool's `p<k>:`
ids).  --largest takes the N polygons of most vertices, --most-holes the N
of most holes, --sample N polygons drawn (Python's random with --seed) from
those with A to B vertices and at least H holes.  Prints one line per file:
name, index, vertices, holes.
"""
import argparse
import os
import random


def polygons(text):
    """The polygon texts "((...), (...))" of a MULTIPOLYGON, in order."""
    body = text[text.index("(") + 1:text.rindex(")")]
    out, depth, start = [], 0, 0
    for i, c in enumerate(body):
        if c == "(":
            if depth == 0:
                start = i
            depth += 1
        elif c == ")":
            depth -= 1
            if depth == 0:
                out.append(body[start:i + 1])
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("file")
    ap.add_argument("outdir")
    ap.add_argument("--prefix", default="polygon")
    ap.add_argument("--largest", type=int, default=0)
    ap.add_argument("--most-holes", type=int, default=0)
    ap.add_argument("--sample", type=int, default=0)
    ap.add_argument("--min-vertices", type=int, default=0)
    ap.add_argument("--max-vertices", type=int, default=10**9)
    ap.add_argument("--min-holes", type=int, default=0)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    with open(a.file) as f:
        text = f.read()
    if not text.lstrip().upper().startswith("MULTIPOLYGON"):
        raise SystemExit("split_polygons.py: %s: not a MULTIPOLYGON" % a.file)
    polys = polygons(text)
    # (a ring of n vertices is written with n + 1 points, n commas; the R
    # rings are separated by R - 1 more: vertices = commas - R + 1)
    holes = [p.count("(") - 2 for p in polys]
    vertices = [p.count(",") - h for p, h in zip(polys, holes)]
    chosen = []
    by_size = sorted(range(len(polys)), key=lambda k: -vertices[k])
    chosen += by_size[:a.largest]
    by_holes = sorted(range(len(polys)), key=lambda k: -holes[k])
    chosen += by_holes[:a.most_holes]
    if a.sample:
        pool = [k for k in range(len(polys))
                if a.min_vertices <= vertices[k] <= a.max_vertices and holes[k] >= a.min_holes]
        random.seed(a.seed)
        chosen += random.sample(pool, min(a.sample, len(pool)))
    os.makedirs(a.outdir, exist_ok=True)
    seen = set()
    for k in chosen:
        if k in seen:
            continue
        seen.add(k)
        name = "%s_%d.wkt" % (a.prefix, k)
        with open(os.path.join(a.outdir, name), "w") as f:
            f.write("POLYGON " + polys[k] + "\n")
        print("%s\t%d\t%d\t%d" % (name, k, vertices[k], holes[k]))


if __name__ == "__main__":
    main()
