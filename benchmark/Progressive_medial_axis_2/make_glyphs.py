#!/usr/bin/env python3
"""Writes glyph outlines of fonts as WKT POLYGONs, one file per connected glyph part.

    /usr/bin/python3 make_glyphs.py OUTDIR [--fonts DejaVuSans,LiberationSerif-Regular,FreeMono]
                                           [--chars CHARS] [--segments 8] [--decimals 0]

Glyph outlines are the polygons of CAM and engraving work: flattened curves, so long
runs of short edges, many vertices nearly (or exactly) cocircular, exact repeated
coordinates where the font's points are on a grid.  Each curve (quadratic as in TrueType,
or cubic as in CFF) is replaced by a polyline of a fixed number of segments (--segments),
evaluated at t = i / segments; coordinates are in font units, rounded to integers
(--decimals 0, the default) or to a few decimal places, as a CAM tool writes them.
Consecutive equal points and spikes (two edges folding back onto each other) that the
rounding creates are removed.

A glyph's contours are grouped into parts: a contour inside an even number of others
is the outer ring of a part, a contour inside an odd number is a hole of the part whose
outer ring is the smallest one containing it, and its orientation must be the opposite
of that outer ring's (fonts draw holes the other way round; a contour with the wrong
orientation is an overlap, not a hole, and its part is skipped).  'i' has two parts,
'o' one part with a hole, 'B' one part with two holes.

Every part is checked before it is written, strictly (what
Progressive_medial_axis_2 accepts today): each ring has at least 3 vertices, no vertex
repeats anywhere in the polygon, no spike, every ring is simple, no two rings touch
(not even at one point), the holes are inside the outer ring (shapely's is_valid, plus
the checks shapely does not make).  Parts failing a check are skipped and listed on
stderr.  Written: OUTDIR/<font>_<glyphname>_<k>.wkt, k = 0, 1, ... in the order of the
parts' lowest-leftmost points; outer ring counter-clockwise, holes clockwise, rings
closed as WKT wants.

Fonts are looked up as <name>.ttf or <name>.otf under /usr/share/fonts (Debian:
fonts-dejavu-core, fonts-liberation, fonts-freefont-ttf).  Needs python3-fonttools and
python3-shapely.  Mind the fonts' licences before shipping outlines (see
test/Progressive_medial_axis_2/data/glyphs/LICENSE.txt).
"""
import argparse
import os
import re
import sys
from fractions import Fraction

from fontTools.pens.basePen import BasePen
from fontTools.ttLib import TTFont
from shapely.geometry import LinearRing, Point, Polygon

FONT_ROOT = "/usr/share/fonts"
DEFAULT_FONTS = "DejaVuSans,LiberationSerif-Regular,FreeMono"
DEFAULT_CHARS = ("abcdefghijklmnopqrstuvwxyz"
                 "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                 "0123456789&@%$#?!")


def find_font(name):
    for base, _, files in sorted(os.walk(FONT_ROOT)):
        for ext in (".ttf", ".otf"):
            if name + ext in files:
                return os.path.join(base, name + ext)
    raise SystemExit("make_glyphs.py: font %s not found under %s" % (name, FONT_ROOT))


class FlatteningPen(BasePen):
    """Collects the closed contours of a glyph as lists of (x, y) floats, every curve
    replaced by `segments` chords.  BasePen splits TrueType's implied on-curve points
    into single quadratic segments, and decomposes components through the glyph set."""

    def __init__(self, glyph_set, segments):
        BasePen.__init__(self, glyph_set)
        self.segments = segments
        self.contours = []
        self.current = None

    def _moveTo(self, p):
        self.current = [p]

    def _lineTo(self, p):
        self.current.append(p)

    def _qCurveToOne(self, p1, p2):
        (x0, y0) = self._getCurrentPoint()
        n = self.segments
        for i in range(1, n + 1):
            t = i / n
            u = 1 - t
            self.current.append((u * u * x0 + 2 * u * t * p1[0] + t * t * p2[0],
                                 u * u * y0 + 2 * u * t * p1[1] + t * t * p2[1]))

    def _curveToOne(self, p1, p2, p3):
        (x0, y0) = self._getCurrentPoint()
        n = self.segments
        for i in range(1, n + 1):
            t = i / n
            u = 1 - t
            a, b, c, d = u * u * u, 3 * u * u * t, 3 * u * t * t, t * t * t
            self.current.append((a * x0 + b * p1[0] + c * p2[0] + d * p3[0],
                                 a * y0 + b * p1[1] + c * p2[1] + d * p3[1]))

    def _closePath(self):
        if self.current is not None:
            self.contours.append(self.current)
        self.current = None

    def _endPath(self):
        # an open contour bounds nothing: dropped
        self.current = None


def round_point(p, decimals):
    if decimals <= 0:
        return (int(round(p[0])), int(round(p[1])))
    return (round(p[0], decimals), round(p[1], decimals))


def exact(p):
    return (Fraction(p[0]), Fraction(p[1]))


def cross(o, a, b):
    """Exact orientation of (o, a, b), > 0 for a left turn (coordinates as Fractions)."""
    return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])


def is_spike(a, b, c):
    """b is a spike: a, b, c collinear and the path a -> b -> c turns back at b."""
    ea, eb, ec = exact(a), exact(b), exact(c)
    if cross(ea, eb, ec) != 0:
        return False
    return (eb[0] - ea[0]) * (ec[0] - eb[0]) + (eb[1] - ea[1]) * (ec[1] - eb[1]) < 0


def clean_ring(ring):
    """Drops the closing point, consecutive duplicates and spikes (repeatedly: removing
    one can make another)."""
    ring = list(ring)
    changed = True
    while changed and len(ring) >= 3:
        changed = False
        out = []
        for p in ring:
            if not out or out[-1] != p:
                out.append(p)
        while len(out) > 1 and out[0] == out[-1]:
            out.pop()
        ring = out
        for i in range(len(ring)):
            if len(ring) < 3:
                break
            a, b, c = ring[i - 2], ring[i - 1], ring[i]
            if is_spike(a, b, c):
                del ring[i - 1]
                changed = True
                break
    return ring


def signed_area2(ring):
    """Twice the exact signed area (> 0: counter-clockwise)."""
    s = Fraction(0)
    for i in range(len(ring)):
        a, b = exact(ring[i - 1]), exact(ring[i])
        s += a[0] * b[1] - a[1] * b[0]
    return s


def group_parts(rings):
    """[(outer, [holes])] by nesting depth and orientation, plus a list of problems for
    the contours that could not be placed."""
    polys = [Polygon(r) for r in rings]
    areas = [signed_area2(r) for r in rings]
    n = len(rings)

    def inside(i, j):
        # is contour i inside contour j? (any vertex strictly inside: a contour touching
        # another at a point is still placed, and then fails the validity check)
        return i != j and any(polys[j].contains(Point(p)) for p in rings[i])

    containers = [[j for j in range(n) if inside(i, j)] for i in range(n)]
    depth = [len(c) for c in containers]
    parts = {}
    problems = []
    for i in range(n):
        if depth[i] % 2 == 0:
            parts[i] = []
    for i in range(n):
        if depth[i] % 2 == 1:
            outers = [j for j in containers[i] if depth[j] == depth[i] - 1]
            if not outers:
                problems.append("contour %d: no enclosing outer contour" % i)
                continue
            parent = min(outers, key=lambda j: abs(areas[j]))
            if (areas[i] > 0) == (areas[parent] > 0):
                problems.append("contour %d: inside contour %d with the same orientation "
                                "(overlapping contours)" % (i, parent))
                parts[parent].append(None)  # marks the part as broken
                continue
            parts[parent].append(i)
    return parts, problems


def polygon_problem(outer, holes):
    """The first reason why (outer, holes) is not a valid polygon in the strict sense, or
    None."""
    rings = [outer] + holes
    for k, r in enumerate(rings):
        if len(r) < 3:
            return "ring %d has fewer than 3 vertices" % k
        if signed_area2(r) == 0:
            return "ring %d has no area" % k
        for i in range(len(r)):
            if is_spike(r[i - 2], r[i - 1], r[i]):
                return "ring %d has a spike" % k
    points = [p for r in rings for p in r]
    if len(set(points)) != len(points):
        return "a vertex repeats"
    lines = [LinearRing(r) for r in rings]
    for k, line in enumerate(lines):
        if not line.is_simple:
            return "ring %d is not simple" % k
    for a in range(len(lines)):
        for b in range(a + 1, len(lines)):
            if lines[a].intersects(lines[b]):
                return "rings %d and %d touch or cross" % (a, b)
    poly = Polygon(outer, holes)
    if not poly.is_valid:
        return "shapely: invalid polygon"
    shell = Polygon(outer)
    for k, h in enumerate(holes):
        if not shell.contains(Polygon(h)):
            return "hole %d is not inside the outer ring" % (k + 1)
    return None


def format_number(v, decimals):
    if decimals <= 0:
        return "%d" % v
    return "%.*f" % (decimals, v)


def to_wkt(outer, holes, decimals):
    parts = []
    for r in [outer] + holes:
        closed = r + [r[0]]
        parts.append("(" + ", ".join("%s %s" % (format_number(x, decimals), format_number(y, decimals))
                                     for (x, y) in closed) + ")")
    return "POLYGON (" + ", ".join(parts) + ")"


def glyph_polygons(glyph_set, glyph_name, segments, decimals):
    """The valid parts of a glyph as [(outer, holes)] (outer counter-clockwise, holes
    clockwise), and the problems of the skipped ones."""
    pen = FlatteningPen(glyph_set, segments)
    glyph_set[glyph_name].draw(pen)
    rings = []
    problems = []
    for c in pen.contours:
        r = clean_ring([round_point(p, decimals) for p in c])
        if len(r) < 3 or signed_area2(r) == 0:
            problems.append("a degenerate contour (no area once rounded) dropped")
            continue
        rings.append(r)
    if not rings:
        return [], problems
    groups, group_problems = group_parts(rings)
    problems += group_problems
    parts = []
    for o, hs in sorted(groups.items()):
        if None in hs:
            problems.append("part of contour %d skipped (overlapping contours)" % o)
            continue
        outer = rings[o] if signed_area2(rings[o]) > 0 else rings[o][::-1]
        holes = [rings[h] if signed_area2(rings[h]) < 0 else rings[h][::-1] for h in hs]
        problem = polygon_problem(outer, holes)
        if problem is not None:
            problems.append("part of contour %d skipped: %s" % (o, problem))
            continue
        parts.append((outer, holes))
    parts.sort(key=lambda part: min((p[1], p[0]) for p in part[0]))
    return parts, problems


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("outdir")
    ap.add_argument("--fonts", default=DEFAULT_FONTS,
                    help="comma-separated font file names without extension (default %(default)s)")
    ap.add_argument("--chars", default=DEFAULT_CHARS, help="characters (default: letters, digits, &@%%$#?!)")
    ap.add_argument("--segments", type=int, default=8, help="segments per curve (default 8)")
    ap.add_argument("--decimals", type=int, default=0,
                    help="decimal places of the coordinates, 0: integers (default 0)")
    args = ap.parse_args()
    if args.segments < 1:
        ap.error("--segments must be at least 1")
    os.makedirs(args.outdir, exist_ok=True)
    chars = list(dict.fromkeys(args.chars))
    written = skipped = 0
    for font_name in [f for f in args.fonts.split(",") if f]:
        font = TTFont(find_font(font_name))
        cmap = font.getBestCmap()
        glyph_set = font.getGlyphSet()
        for ch in chars:
            glyph_name = cmap.get(ord(ch))
            if glyph_name is None:
                print("%s: no glyph for %r" % (font_name, ch), file=sys.stderr)
                continue
            parts, problems = glyph_polygons(glyph_set, glyph_name, args.segments, args.decimals)
            for p in problems:
                print("%s %s: %s" % (font_name, glyph_name, p), file=sys.stderr)
                skipped += 1
            safe = re.sub(r"[^A-Za-z0-9._-]", "_", glyph_name)
            for k, (outer, holes) in enumerate(parts):
                path = os.path.join(args.outdir, "%s_%s_%d.wkt" % (font_name, safe, k))
                with open(path, "w") as f:
                    f.write(to_wkt(outer, holes, args.decimals) + "\n")
                written += 1
                print("%s %d vertices %d holes" % (os.path.basename(path),
                                                    len(outer) + sum(len(h) for h in holes), len(holes)))
    print("%d polygons written, %d problems (dropped contours, skipped parts)" % (written, skipped),
          file=sys.stderr)


if __name__ == "__main__":
    main()
