#!/usr/bin/env python3
"""Writes the Red Sea as a WKT POLYGON, for the centerline picture of the manual.

    /usr/bin/python3 make_red_sea.py OUT.wkt

Source: `npm pack @geo-maps/earth-seas-10m` (OpenStreetMap data, (c) OpenStreetMap
contributors, ODbL 1.0; packaged by Simone Primarosa), cached in
data/cache/.  The sea polygon that meets the box 32..43.6 E, 12.6..30 N is
cut by that box (the cut closes the sea at the strait of Bab-el-Mandeb and
in the north), its largest part kept, and its islands dropped (the picture
shows one centerline, not the channels around 392 islands).  Coordinates are
degrees, written with 6 decimals.  Needs npm and python3-shapely.
"""
import json
import os
import subprocess
import sys
import tarfile

from shapely.geometry import Polygon, box, shape
from shapely.geometry.polygon import orient

HERE = os.path.dirname(os.path.abspath(__file__))
CACHE = os.path.join(HERE, "data", "cache")


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    os.makedirs(CACHE, exist_ok=True)
    tgz = os.path.join(CACHE, "geo-maps-earth-seas-10m-0.6.0.tgz")
    if not os.path.exists(tgz):
        subprocess.run(["npm", "pack", "@geo-maps/earth-seas-10m@0.6.0"], cwd=CACHE, check=True,
                       stdout=subprocess.DEVNULL)
    with tarfile.open(tgz) as t:
        data = json.load(t.extractfile("package/map.geo.json"))
    seas = shape(data["geometries"][0])
    window = box(32.0, 12.6, 43.6, 30.0)
    best = None
    for p in seas.geoms:
        if not p.intersects(window):
            continue
        cut = p.intersection(window)
        for part in (cut.geoms if hasattr(cut, "geoms") else [cut]):
            if part.geom_type == "Polygon" and (best is None or part.area > best.area):
                best = part
    sea = orient(Polygon(best.exterior.coords), 1.0)
    with open(sys.argv[1], "w") as f:
        f.write("POLYGON ((" + ", ".join("%.6f %.6f" % c for c in sea.exterior.coords) + "))\n")


if __name__ == "__main__":
    main()
