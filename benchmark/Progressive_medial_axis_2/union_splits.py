#!/usr/bin/env python3
"""Splits a polygon into two along random chains of edges, for sweeps of the
tool's --union against a one-shot of the union (union_sweep.sh).

    python3 benchmark/Progressive_medial_axis_2/union_splits.py FILE.wkt PREFIX COUNT SEED

FILE.wkt holds one polygon (holes allowed; of a MULTIPOLYGON the polygon of
the longest outer ring).  Each split is one chain of 1 to 100 edges between
two vertices of the outer ring (at most 400 apart along it), or, in about
40% of the tries on a polygon with holes, two chains from the outer ring to
a hole, so that the union encloses that hole (the two parts share the
chains, and the hole's boundary is split between them).  The chains' inner
points are random offsets of the straight line between their ends; a split
is kept where both parts are valid, with Shapely, and their areas add up to
the polygon's.  The other holes go to the part that contains them.  Writes
PREFIX<K>_a.wkt and PREFIX<K>_b.wkt for K = 0 .. COUNT-1 (coordinates in
full precision, so the shared chains are the same points in both files) and
prints one line per split.  Needs Shapely and NumPy (python3-shapely).
"""
import random
import sys

import numpy
from shapely import wkt as W
from shapely.geometry import LineString, MultiPoint, Polygon


def fmt(rings):
    return "POLYGON (" + ", ".join("(" + ", ".join("%r %r" % (x, y) for x, y in r + [r[0]]) + ")"
                                   for r in rings) + ")\n"


def main():
    src, prefix, count, seed = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    g = W.loads(open(src).read())
    if g.geom_type == 'MultiPolygon':
        g = max(g.geoms, key=lambda p: len(p.exterior.coords))
    outer = list(g.exterior.coords)[:-1]
    holes = [list(h.coords)[:-1] for h in g.interiors]
    rng = random.Random(seed)
    xy = numpy.array(outer)
    whole = Polygon(outer, holes)
    n = len(outer)

    def chain(p, q, k):   # k edges from p to q
        dx, dy = q[0] - p[0], q[1] - p[1]
        pts = [p]
        for t in range(1, k):
            s, o = t / k, rng.uniform(-0.15, 0.15)
            pts.append((p[0] + s * dx - o * dy, p[1] + s * dy + o * dx))
        return pts + [q]

    def inside(c):   # simple, inside, touching the boundary at its ends only
        line = LineString(c)
        return line.is_simple and whole.contains(line) and \
            line.intersection(whole.boundary).equals(MultiPoint([c[0], c[-1]]))

    def parts_ok(a, b):
        try:
            pa, pb = Polygon(a[0], a[1:]), Polygon(b[0], b[1:])
        except Exception:
            return False
        return pa.is_valid and pb.is_valid and abs(pa.area + pb.area - whole.area) <= 1e-9 * whole.area and \
            pa.intersection(pb).area <= 1e-12 * whole.area

    def nearest(q):
        return int(((xy[:, 0] - q[0]) ** 2 + (xy[:, 1] - q[1]) ** 2).argmin())

    def run(s, e, ring):   # ring[s .. e], cyclically
        m = len(ring)
        return [ring[(s + t) % m] for t in range((e - s) % m + 1)]

    made = tries = 0
    while made < count and tries < 200 * count:
        tries += 1
        k = rng.choice([1, 1, 2, 3, 5, 10, 30, 100])
        if holes and rng.random() < 0.4:
            h = rng.randrange(len(holes))
            H = holes[h]
            a, b = rng.randrange(len(H)), rng.randrange(len(H))
            i, j = nearest(H[a]), nearest(H[b])
            if i == j or a == b:
                continue
            c1, c2 = chain(outer[i], H[a], k), chain(H[b], outer[j], k)
            if not (inside(c1) and inside(c2)) or LineString(c1).intersects(LineString(c2)):
                continue
            others = [holes[t] for t in range(len(holes)) if t != h]
            found = None
            for forward in (True, False):
                A0 = run(i, j, outer) + c2[::-1][1:-1] + (run(b, a, H) if forward else run(a, b, H)[::-1]) + c1[::-1][1:-1]
                B0 = run(j, i, outer) + c1[1:-1] + (run(a, b, H) if forward else run(b, a, H)[::-1]) + c2[1:-1]
                pa, pb = Polygon(A0), Polygon(B0)
                if not (pa.is_valid and pb.is_valid):
                    continue
                A, B = [A0], [B0]
                for r in others:
                    (A if pa.contains(Polygon(r)) else B).append(r)
                if parts_ok(A, B):
                    found = (A, B)
                    break
            if found is None:
                continue
            A, B = found
        else:
            i = rng.randrange(n)
            j = (i + rng.randrange(2, max(3, min(n - 1, 400)))) % n
            i, j = min(i, j), max(i, j)
            if j - i < 2 or n - (j - i) < 2:
                continue
            c = chain(outer[i], outer[j], k)
            if not inside(c):
                continue
            A0 = outer[i:j + 1] + c[::-1][1:-1]
            B0 = outer[j:] + outer[:i + 1] + c[1:-1]
            pa = Polygon(A0)
            if not pa.is_valid:
                continue
            A, B = [A0], [B0]
            for r in holes:
                (A if pa.contains(Polygon(r)) else B).append(r)
            if not parts_ok(A, B):
                continue
        open("%s%d_a.wkt" % (prefix, made), "w").write(fmt(A))
        open("%s%d_b.wkt" % (prefix, made), "w").write(fmt(B))
        print("%s%d chain edges %d, rings %d + %d" % (prefix, made, k, len(A), len(B)))
        made += 1


if __name__ == "__main__":
    main()
