#!/usr/bin/env python3
"""Draws a shape with its centerline, and the centerline's width profile.

    /usr/bin/python3 plot_centerline.py SHAPE.wkt CENTERLINE.wkt WIDTH.csv OUT_PREFIX [--title T]

Inputs are what the tool writes (`progressive_medial_axis --centerline
CENTERLINE.wkt --width WIDTH.csv SHAPE.wkt`).  Writes OUT_PREFIX_map.svg
(the shape filled, its centerline) and OUT_PREFIX_width.svg (width against
arc length).  Needs python3-matplotlib and python3-shapely (Debian).
"""
import argparse
import csv

import matplotlib
matplotlib.use("svg")
import matplotlib.pyplot as plt
from shapely import wkt


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("shape")
    ap.add_argument("centerline")
    ap.add_argument("width")
    ap.add_argument("out_prefix")
    ap.add_argument("--title", default="")
    args = ap.parse_args()
    shape = wkt.loads(open(args.shape).read())
    line = wkt.loads(open(args.centerline).read())

    fig, ax = plt.subplots(figsize=(5, 7))
    polygons = shape.geoms if hasattr(shape, "geoms") else [shape]
    for p in polygons:
        x, y = p.exterior.xy
        ax.fill(x, y, color="#e8eef7", edgecolor="#203040", linewidth=0.5)
        for ring in p.interiors:
            x, y = ring.xy
            ax.fill(x, y, color="white", edgecolor="#203040", linewidth=0.5)
    lines = line.geoms if hasattr(line, "geoms") else [line]
    for l in lines:
        x, y = l.xy
        ax.plot(x, y, color="#c0392b", linewidth=1.2)
    ax.set_aspect("equal")
    ax.set_axis_off()
    if args.title:
        ax.set_title(args.title)
    fig.savefig(args.out_prefix + "_map.svg", bbox_inches="tight")

    s, w = [], []
    with open(args.width) as f:
        for row in csv.DictReader(f):
            s.append(float(row["s"]))
            w.append(float(row["width"]))
    fig, ax = plt.subplots(figsize=(7, 2.5))
    ax.plot(s, w, color="#1f5fbf", linewidth=1)
    ax.set_xlabel("arc length along the centerline")
    ax.set_ylabel("width (2R)")
    if args.title:
        ax.set_title(args.title + ": width profile")
    fig.savefig(args.out_prefix + "_width.svg", bbox_inches="tight")


if __name__ == "__main__":
    main()
