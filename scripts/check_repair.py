#!/usr/bin/python3
# Random invalid polygons (holes that cross each other and the outer ring,
# holes outside it, on an integer grid or not) through the tool's --repair,
# against GEOS's MakeValid (structure method) on the whole polygon: the area
# after repair must be GEOS's.  Also counts outputs that are valid for the
# tool but not by OGC (a hole touching the outer ring at two points).
# Needs Debian's python3-shapely (the outputs' areas) and gcc with libgeos-dev
# (a small C program that calls GEOS).  Usage:
#   scripts/check_repair.py [--tool T] [--cases N] [--seed S] [--outside P]
# (P: the share of holes placed anywhere, not inside the outer ring).
# Slow for large polygons (GEOS on a whole polygon): small ones only.
import argparse, math, os, random, subprocess, tempfile
from shapely import wkt as W
from shapely.geometry import Polygon

GEOS_C = r'''
#include <geos_c.h>
#include <stdio.h>
#include <stdlib.h>
int main(int argc, char** argv) {
  GEOSContextHandle_t c = GEOS_init_r();
  FILE* f = fopen(argv[1], "r"); fseek(f, 0, SEEK_END); long n = ftell(f); rewind(f);
  char* s = malloc(n + 1); if(fread(s, 1, n, f) != (size_t)n) return 1; s[n] = 0;
  GEOSWKTReader* r = GEOSWKTReader_create_r(c);
  GEOSGeometry* g = GEOSWKTReader_read_r(c, r, s);
  GEOSMakeValidParams* p = GEOSMakeValidParams_create_r(c);
  GEOSMakeValidParams_setMethod_r(c, p, GEOS_MAKE_VALID_STRUCTURE);
  GEOSMakeValidParams_setKeepCollapsed_r(c, p, 0);
  GEOSGeometry* v = GEOSMakeValidWithParams_r(c, g, p);
  double a = 0; GEOSArea_r(c, v, &a);
  printf("%.17g\n", a);
  return 0;
}
'''

ap = argparse.ArgumentParser()
ap.add_argument('--tool', default='build/tool/Progressive_medial_axis_2/progressive_medial_axis')
ap.add_argument('--cases', type=int, default=400)
ap.add_argument('--seed', type=int, default=1)
ap.add_argument('--outside', type=float, default=0.3)
a = ap.parse_args()
tmp = tempfile.mkdtemp(prefix='check_repair_')
open(tmp + '/geos.c', 'w').write(GEOS_C)
subprocess.run(['gcc', '-O2', tmp + '/geos.c', '-o', tmp + '/geos', '-lgeos_c'], check=True)
rng = random.Random(a.seed)

def star(cx, cy, r, k, grid):
    pts = []
    for t in sorted(rng.uniform(0, 2 * math.pi) for _ in range(k)):
        rr = r * rng.uniform(0.4, 1.0)
        x, y = cx + rr * math.cos(t), cy + rr * math.sin(t)
        pts.append((round(x), round(y)) if grid else (x, y))
    out = []
    for p in pts:
        if not out or out[-1] != p: out.append(p)
    if len(out) > 1 and out[0] == out[-1]: out.pop()
    return out

def rect(cx, cy, w, h, grid):
    x0, y0, x1, y1 = cx - w, cy - h, cx + w, cy + h
    if grid: x0, y0, x1, y1 = round(x0), round(y0), round(x1), round(y1)
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]

def ring_wkt(r): return '(' + ', '.join('%r %r' % p for p in r + [r[0]]) + ')'

R = 100
bad = ogc_invalid = cases = 0
for case in range(a.cases):
    grid = rng.random() < 0.5
    outer = star(0, 0, R, rng.randint(6, 40), grid) if rng.random() < 0.6 else rect(0, 0, R, R * rng.uniform(0.3, 1), grid)
    po = Polygon(outer)
    if not po.is_valid or po.area <= 0: continue
    holes = []
    for _ in range(rng.randint(1, 25)):
        anywhere = rng.random() < a.outside
        while True:
            cx, cy = rng.uniform(-1.4 * R, 1.4 * R), rng.uniform(-1.4 * R, 1.4 * R)
            if anywhere or po.contains(Polygon([(cx - 0.01, cy - 0.01), (cx + 0.01, cy - 0.01), (cx + 0.01, cy + 0.01)])): break
        s = rng.uniform(3, 30)
        h = rect(cx, cy, s, s * rng.uniform(0.2, 1), grid) if rng.random() < 0.5 else star(cx, cy, s, rng.randint(3, 12), grid)
        if len(set(h)) < 3 or not Polygon(h).is_valid or Polygon(h).area <= 0: continue
        holes.append(h)
    if not holes: continue
    cases += 1
    text = 'POLYGON (' + ', '.join(ring_wkt(r) for r in [outer] + holes) + ')\n'
    open(tmp + '/in.wkt', 'w').write(text)
    expected = float(subprocess.run([tmp + '/geos', tmp + '/in.wkt'], capture_output=True, text=True, check=True).stdout)
    p = subprocess.run([a.tool, '--repair', '--repaired-out', tmp + '/out.wkt', tmp + '/in.wkt'], capture_output=True, text=True)
    if p.returncode != 0:
        if 'no polygon of positive area' in p.stderr and expected < 1e-9: continue
        bad += 1
        print('case %d: exit status %d: %s' % (case, p.returncode, p.stderr.strip()))
        open(tmp + '/bad_%d.wkt' % case, 'w').write(text)
        continue
    g = W.loads(open(tmp + '/out.wkt').read())
    polygons = list(g.geoms) if g.geom_type == 'MultiPolygon' else [g]
    area = sum(q.area for q in polygons)
    if not all(q.is_valid for q in polygons): ogc_invalid += 1
    if abs(area - expected) > 1e-9 * max(1.0, expected):
        bad += 1
        print('case %d: area %.17g, GEOS %.17g' % (case, area, expected))
        open(tmp + '/bad_%d.wkt' % case, 'w').write(text)
print('cases %d, area differs from GEOS in %d, not valid by OGC (valid for the tool) %d; inputs kept in %s'
      % (cases, bad, ogc_invalid, tmp))
