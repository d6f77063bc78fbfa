#!/usr/bin/env python3
"""Fetches and generates the benchmark shapes of Progressive_medial_axis_2.

    python3 benchmark/Progressive_medial_axis_2/fetch_data.py [--quick] [--build DIR]

Real outlines: `npm pack @geo-maps/countries-coastline-1m` (OpenStreetMap data, (c) OpenStreetMap
contributors, ODbL 1.0; packaged by Simone Primarosa, https://github.com/simonepri/geo-maps).
The chosen polygons are written as WKT POLYGONs with their coordinates copied
character for character from the GeoJSON text (the JSON numbers are never
converted to binary floating point), rings and vertex order as published.

Synthetic shapes come from make_synthetic (built in DIR, default `build`).

Everything goes to benchmark/Progressive_medial_axis_2/data/ (git-ignored; the
npm tarballs are cached in data/cache/).  Each shape is then validated by the
tool (`progressive_medial_axis --step 0`, which runs the library's input
checks), and the list is written to data/shapes.tsv with the columns

    name file kind vertices holes sets source status

`sets` is "quick,full" or "full": run_suite.sh --quick uses the shapes whose
sets contain "quick".  `status` is "ok" or the tool's error message; shapes
that do not validate are listed but not benchmarked.  --quick only prepares
the quick set.
"""
import argparse
import json
import os
import subprocess
import sys
import tarfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DATA = os.path.join(HERE, "data")
CACHE = os.path.join(DATA, "cache")

PACKAGE = "@geo-maps/countries-coastline-1m@0.6.0"
TARBALL = "geo-maps-countries-coastline-1m-0.6.0.tgz"

# (ISO A3 code of the country, polygon index in its MultiPolygon (the name's
# suffix), sets).  The largest valid single polygons of the package are CHN_0
# (128,262 vertices) and USA_3 (83,083 vertices, 105 holes); the largest
# shapes of the suite are synthetic.
REAL = [
    ("CYP", 0, "quick,full"),
    ("QAT", 0, "quick,full"),
    ("DNK", 0, "quick,full"),
    ("ISL", 184, "quick,full"),
    ("GBR", 0, "quick,full"),
    ("ZAF", 0, "full"),
    ("ITA", 0, "full"),
    ("MMR", 0, "quick,full"),
    ("DEU", 0, "full"),
    ("USA", 3, "full"),
    ("BRA", 0, "full"),
    ("CAN", 0, "full"),
    ("CHN", 0, "full"),
]

# (name, make_synthetic arguments, sets)
SYNTHETIC = [
    ("syn_star2k", ["star", "2000", "1"], "quick,full"),
    ("syn_maze60", ["maze", "60", "1"], "quick,full"),
    ("syn_plate1k", ["holes-grid", "1000", "8", "1"], "quick,full"),
    ("syn_star100k", ["star", "100000", "2"], "full"),
    ("syn_maze120", ["maze", "120", "2"], "full"),
    ("syn_plate100k", ["holes-grid", "100000", "6", "1"], "full"),
    ("syn_plate170k", ["holes-grid", "170000", "6", "2"], "full"),
]


def fetch():
    os.makedirs(CACHE, exist_ok=True)
    path = os.path.join(CACHE, TARBALL)
    if not os.path.exists(path):
        print("npm pack %s" % PACKAGE, file=sys.stderr)
        subprocess.run(["npm", "pack", PACKAGE], cwd=CACHE, check=True, stdout=subprocess.DEVNULL)
    with tarfile.open(path) as t:
        member = t.getmember("package/map.geo.json")
        # parse_float=str: coordinates stay the published decimal text
        return json.load(t.extractfile(member), parse_float=str, parse_int=str)


def polygons_of(geometry):
    if geometry["type"] == "Polygon":
        return [geometry["coordinates"]]
    if geometry["type"] == "MultiPolygon":
        return geometry["coordinates"]
    raise ValueError("unexpected geometry " + geometry["type"])


def write_wkt(polygon, path):
    with open(path, "w") as out:
        out.write("POLYGON (")
        out.write(", ".join("(" + ", ".join("%s %s" % (p[0], p[1]) for p in ring) + ")" for ring in polygon))
        out.write(")\n")


def ring_vertices(ring):
    return len(ring) - 1 if len(ring) > 1 and ring[0] == ring[-1] else len(ring)


def read_wkt_rings(path):
    """The rings of a WKT POLYGON as lists of coordinate strings (only to count them)."""
    with open(path) as f:
        text = f.read()
    body = text[text.index("(") + 1:text.rindex(")")]
    return [[p.split() for p in ring.strip(" ()\n").split(",")] for ring in body.split("),")]


def validate(tool, path):
    r = subprocess.run([tool, "--step", "0", path], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
    if r.returncode == 0:
        return "ok"
    msg = " ".join(r.stderr.split()) or "exit status %d" % r.returncode
    return "invalid: " + msg.replace("\t", " ")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="only the shapes of the quick set")
    ap.add_argument("--build", default=os.path.join(ROOT, "build"), help="CMake build directory")
    args = ap.parse_args()
    tool = os.path.join(args.build, "tool", "Progressive_medial_axis_2", "progressive_medial_axis")
    synth = os.path.join(args.build, "benchmark", "Progressive_medial_axis_2", "make_synthetic")
    for exe in (tool, synth):
        if not os.access(exe, os.X_OK):
            sys.exit("missing %s: build the project first" % exe)
    os.makedirs(DATA, exist_ok=True)
    wanted = lambda sets: (not args.quick) or "quick" in sets.split(",")
    rows = []

    doc = fetch() if any(wanted(sets) for _, _, sets in REAL) else None
    for key, index, sets in REAL:
        if not wanted(sets):
            continue
        geometry = next(f["geometry"] for f in doc["features"] if f["properties"].get("A3") == key)
        name = "c1m_%s_%d" % (key, index)
        origin = "countries-coastline-1m, %s, polygon %d" % (key, index)
        polygon = polygons_of(geometry)[index]
        path = os.path.join(DATA, name + ".wkt")
        write_wkt(polygon, path)
        rows.append((name, path, "real", sum(ring_vertices(r) for r in polygon), len(polygon) - 1, sets, origin))

    for name, argv, sets in SYNTHETIC:
        if not wanted(sets):
            continue
        path = os.path.join(DATA, name + ".wkt")
        with open(path, "w") as out:
            subprocess.run([synth] + argv, stdout=out, check=True)
        polygon = read_wkt_rings(path)
        rows.append((name, path, "synthetic", sum(ring_vertices(r) for r in polygon), len(polygon) - 1, sets,
                     "make_synthetic " + " ".join(argv)))

    with open(os.path.join(DATA, "shapes.tsv"), "w") as out:
        out.write("name\tfile\tkind\tvertices\tholes\tsets\tsource\tstatus\n")
        for name, path, kind, n, holes, sets, origin in rows:
            status = validate(tool, path)
            print("%-16s %9d vertices %7d holes  %s" % (name, n, holes, status), file=sys.stderr)
            out.write("%s\t%s\t%s\t%d\t%d\t%s\t%s\t%s\n" %
                      (name, os.path.relpath(path, ROOT), kind, n, holes, sets, origin, status))


if __name__ == "__main__":
    main()
