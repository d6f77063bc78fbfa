#!/usr/bin/env python3
"""Writes RESULTS.md and the plots of the benchmark suite from its result files.

    make_report.py RESULTS_DIR

RESULTS_DIR holds what run_suite.sh produced:
  time.tsv          rows of bench_time (shape vertices holes method median_seconds
                    runs peak_rss_mb status note)
  accuracy.tsv      rows of bench_accuracy (shape vertices holes method branch_points
                    mean sd max topology status note)
  nv/<shape>.nv.txt one line per refinement step: "step n_v"
  accuracy/<shape>.<method>.txt  E(x) values, decreasing
  machine.txt       a description of the machine
  commands.txt      the command lines that produced the files
Plots go to benchmark/Progressive_medial_axis_2/plots/ (SVG).  RESULTS.md is
rewritten above the line MANUAL_MARKER; what follows it is kept.

Python 3 standard library only.
"""

import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT_PREFIX = os.path.normpath(os.path.join(HERE, "..", "..")) + os.sep
MANUAL_MARKER = "<!-- Runs recorded by hand below this line are kept by make_report.py -->"

METHOD_LABELS = {
    "pma_filtered": "ours, filtered traits (exact decisions)",
    "pma_epick": "ours, Epick traits (double)",
    "pma_exact": "ours, CORE::Expr traits",
    "sdg": "SDG, filtered traits",
    "sdg_hierarchy": "SDG hierarchy, filtered traits",
    "sdg_extract": "SDG filtered: interior axis extraction",
    "sdg_exact": "SDG, exact traits (CORE::Expr)",
    "boost_voronoi": "Boost.Polygon construct_voronoi",
    "floor": "floor: exact branch points rounded to double",
    "sdg_filtered": "SDG, filtered traits (double constructions)",
}
COLORS = ["#1f5fbf", "#c0392b", "#2e8b57", "#8e44ad", "#d68910", "#17a589", "#566573", "#a04000", "#1abc9c"]


def read_tsv(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return [row for row in csv.DictReader(f, delimiter="\t")]


def fnum(x):
    try:
        return float(x)
    except (TypeError, ValueError):
        return None


def fmt_time(x):
    if x is None or x < 0:
        return "-"
    if x >= 100:
        return "%.0f" % x
    if x >= 10:
        return "%.1f" % x
    if x >= 1:
        return "%.2f" % x
    return "%.3f" % x


def fmt_sci(x):
    if x is None:
        return "-"
    if x == 0:
        return "0"
    return "%.2e" % x


# ---------------------------------------------------------------- SVG plots

class Axes:
    def __init__(self, width=720, height=420, left=70, right=270, top=30, bottom=55):
        self.W, self.H = width, height
        self.l, self.r, self.t, self.b = left, right, top, bottom
        self.items = []

    def frame(self, xmin, xmax, ymin, ymax, xlog, ylog, xlabel, ylabel, title):
        self.xmin, self.xmax, self.ymin, self.ymax = xmin, xmax, ymin, ymax
        self.xlog, self.ylog = xlog, ylog
        self.xlabel, self.ylabel, self.title = xlabel, ylabel, title

    def _tx(self, v, lo, hi, log):
        if log:
            v, lo, hi = math.log10(v), math.log10(lo), math.log10(hi)
        return 0.0 if hi == lo else (v - lo) / (hi - lo)

    def X(self, x):
        return self.l + self._tx(x, self.xmin, self.xmax, self.xlog) * (self.W - self.l - self.r)

    def Y(self, y):
        return self.H - self.b - self._tx(y, self.ymin, self.ymax, self.ylog) * (self.H - self.t - self.b)

    def ticks(self, lo, hi, log):
        if log:
            a, b = int(math.floor(math.log10(lo))), int(math.ceil(math.log10(hi)))
            step = max(1, (b - a) // 8)
            return [10.0 ** e for e in range(a, b + 1, step) if lo <= 10.0 ** e <= hi]
        span = hi - lo
        if span <= 0:
            return [lo]
        raw = span / 6
        mag = 10 ** math.floor(math.log10(raw))
        step = min([m * mag for m in (1, 2, 5, 10) if m * mag >= raw])
        t = math.ceil(lo / step) * step
        out = []
        while t <= hi + 1e-9 * span:
            out.append(t)
            t += step
        return out

    def label(self, v, log):
        if log:
            e = int(round(math.log10(v)))
            return "1e%d" % e
        return ("%g" % v)

    def svg(self, series):
        out = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d" '
               'font-family="sans-serif" font-size="12">' % (self.W, self.H, self.W, self.H),
               '<rect width="100%" height="100%" fill="white"/>']
        x0, x1 = self.l, self.W - self.r
        y0, y1 = self.t, self.H - self.b
        out.append('<rect x="%g" y="%g" width="%g" height="%g" fill="none" stroke="#333"/>' % (x0, y0, x1 - x0, y1 - y0))
        for tv in self.ticks(self.xmin, self.xmax, self.xlog):
            x = self.X(tv)
            out.append('<line x1="%.1f" y1="%g" x2="%.1f" y2="%g" stroke="#ddd"/>' % (x, y0, x, y1))
            out.append('<text x="%.1f" y="%g" text-anchor="middle">%s</text>' % (x, y1 + 16, self.label(tv, self.xlog)))
        for tv in self.ticks(self.ymin, self.ymax, self.ylog):
            y = self.Y(tv)
            out.append('<line x1="%g" y1="%.1f" x2="%g" y2="%.1f" stroke="#ddd"/>' % (x0, y, x1, y))
            out.append('<text x="%g" y="%.1f" text-anchor="end" dominant-baseline="middle">%s</text>' % (x0 - 6, y, self.label(tv, self.ylog)))
        out.append('<text x="%g" y="%g" text-anchor="middle">%s</text>' % ((x0 + x1) / 2, self.H - 12, esc(self.xlabel)))
        out.append('<text x="14" y="%g" text-anchor="middle" transform="rotate(-90 14 %g)">%s</text>' % ((y0 + y1) / 2, (y0 + y1) / 2, esc(self.ylabel)))
        out.append('<text x="%g" y="18" text-anchor="middle" font-size="14">%s</text>' % ((x0 + x1) / 2, esc(self.title)))
        for i, (name, pts, style) in enumerate(series):
            color = COLORS[i % len(COLORS)]
            pts = [(x, y) for x, y in pts if self.inside(x, y)]
            if not pts:
                continue
            if style == "points":
                for x, y in pts:
                    out.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (self.X(x), self.Y(y), color))
            else:
                d = " ".join(("M" if k == 0 else "L") + "%.1f %.1f" % (self.X(x), self.Y(y)) for k, (x, y) in enumerate(pts))
                out.append('<path d="%s" fill="none" stroke="%s" stroke-width="1.5"/>' % (d, color))
                if style == "linepoints":
                    for x, y in pts:
                        out.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (self.X(x), self.Y(y), color))
            ly = y0 + 14 + 16 * i
            out.append('<line x1="%g" y1="%g" x2="%g" y2="%g" stroke="%s" stroke-width="2"/>' % (x1 + 10, ly, x1 + 28, ly, color))
            out.append('<text x="%g" y="%g" dominant-baseline="middle">%s</text>' % (x1 + 32, ly, esc(name)))
        out.append("</svg>")
        return "\n".join(out) + "\n"

    def inside(self, x, y):
        if x is None or y is None:
            return False
        if self.xlog and x <= 0 or self.ylog and y <= 0:
            return False
        return True


def esc(s):
    return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def plot_time(rows, plots_dir):
    """Time against vertex count, log-log, one series per method."""
    by_method = {}
    for r in rows:
        t = fnum(r["median_seconds"])
        if r["status"] != "ok" or t is None or t <= 0:
            continue
        by_method.setdefault(r["method"], []).append((float(r["vertices"]), t))
    if not by_method:
        return None
    xs = [p[0] for v in by_method.values() for p in v]
    ys = [p[1] for v in by_method.values() for p in v]
    ax = Axes(width=760, right=290)
    ax.frame(10 ** math.floor(math.log10(min(xs))), 10 ** math.ceil(math.log10(max(xs))),
             10 ** math.floor(math.log10(min(ys))), 10 ** math.ceil(math.log10(max(ys))),
             True, True, "vertices", "seconds (median)", "Running time against input size")
    series = [(METHOD_LABELS.get(m, m), sorted(p), "linepoints") for m, p in sorted(by_method.items())]
    name = "time_vs_vertices.svg"
    write(os.path.join(plots_dir, name), ax.svg(series))
    return name


def plot_nv(results, shape, plots_dir, kind=""):
    """kind: "" (region growing) or ".boundary" (boundary evolution)"""
    path = os.path.join(results, "nv", shape + kind + ".nv.txt")
    if not os.path.exists(path):
        return None
    pts = []
    with open(path) as f:
        for line in f:
            p = line.split()
            if len(p) >= 2:
                pts.append((float(p[0]), float(p[1])))
    if not pts:
        return None
    title = "n_v per step: " + shape + (" (boundary evolution)" if kind else "")
    label = "n_v"
    if len(pts) > 3000:
        # many steps: the largest n_v of each run of w consecutive steps
        w = (len(pts) + 1499) // 1500
        pts = [(pts[k][0], max(y for _, y in pts[k:k + w])) for k in range(0, len(pts), w)]
        title += " (max over every %d steps)" % w
        label = "max n_v of %d steps" % w
    ax = Axes(right=170)
    ax.frame(0, max(1.0, pts[-1][0]), 0, max(1.0, max(y for _, y in pts)) * 1.1, False, False,
             "refinement step", "n_v (largest priority queue of the merge)", title)
    ax_series = [(label, pts, "points")]
    svg = ax.svg(ax_series).replace('r="2.5"', 'r="1"')
    name = "nv%s_%s.svg" % (kind.replace(".", "_"), shape)
    write(os.path.join(plots_dir, name), svg)
    return name


def plot_accuracy(results, shape, methods, plots_dir):
    series = []
    ymin, ymax = None, None
    for m in methods:
        path = os.path.join(results, "accuracy", "%s.%s.txt" % (shape, m))
        if not os.path.exists(path):
            continue
        vals = [float(v) for v in open(path).read().split()]
        if not vals:
            continue
        n = len(vals)
        # long curves: about 2000 points spread evenly on the log-scaled x axis
        keep = sorted({min(n - 1, int(n * 10 ** (-4 + 4 * k / 2000.0))) for k in range(2001)} | set(range(min(n, 50))))
        pts = [((i + 1) / n, vals[i]) for i in keep if vals[i] > 0]
        if pts:
            ymin = min(ymin or pts[-1][1], min(y for _, y in pts))
            ymax = max(ymax or 0, max(y for _, y in pts))
        series.append((METHOD_LABELS.get(m, m), pts, "line"))
    if not series or ymin is None:
        return None
    xmin = min(x for _, pts, _ in series for x, _ in pts[:1]) if series else 1e-4
    ax = Axes(width=840, right=360)
    ax.frame(10 ** math.floor(math.log10(min(xmin, 1e-4))), 1, 10 ** math.floor(math.log10(ymin)), 10 ** math.ceil(math.log10(ymax)),
             True, True, "fraction of branch points (sorted by E(x), decreasing)", "E(x)",
             "Sorted E(x): " + shape)
    name = "accuracy_%s.svg" % shape
    write(os.path.join(plots_dir, name), ax.svg(series))
    return name


# ---------------------------------------------------------------- RESULTS.md

def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    results = sys.argv[1]
    plots_dir = os.path.join(HERE, "plots")
    os.makedirs(plots_dir, exist_ok=True)
    time_rows = read_tsv(os.path.join(results, "time.tsv"))
    acc_rows = read_tsv(os.path.join(results, "accuracy.tsv"))
    shapes = read_tsv(os.path.join(HERE, "data", "shapes.tsv"))
    machine = open(os.path.join(results, "machine.txt")).read().strip() if os.path.exists(os.path.join(results, "machine.txt")) else "(not recorded)"
    commands = open(os.path.join(results, "commands.txt")).read().strip() if os.path.exists(os.path.join(results, "commands.txt")) else "(not recorded)"

    rel = os.path.relpath(plots_dir, HERE)
    lines = ["# Benchmark results", "",
             "Written by `make_report.py` from the result files of `run_suite.sh` "
             "(do not edit above the marker line; hand-recorded runs go below it).", "",
             "## Machine", "", "```", machine, "```", "",
             "## Commands", "", "```", commands, "```", ""]

    # shapes
    order = []
    info = {}
    for r in time_rows + acc_rows:
        if r["shape"] not in info:
            order.append(r["shape"])
            info[r["shape"]] = (int(r["vertices"]), int(r["holes"]))
    order.sort(key=lambda s: info[s][0])
    source = {r["name"]: r for r in shapes}
    lines += ["## Shapes", "", "| shape | vertices | holes | kind | source |", "|---|---:|---:|---|---|"]
    for s in order:
        src = source.get(s, {})
        lines.append("| %s | %d | %d | %s | %s |" % (s, info[s][0], info[s][1], src.get("kind", ""), src.get("source", "")))
    lines.append("")
    rejected = [r for r in shapes if r.get("status", "ok") != "ok"]
    if rejected:
        lines += ["Fetched but not benchmarked, because the library rejects them as invalid input "
                  "(the coordinates are kept as published, never repaired):", ""]
        for r in rejected:
            lines.append("- %s (%s vertices, %s holes, %s): %s" % (r["name"], r["vertices"], r["holes"], r["source"],
                                                                  esc(r["status"].replace(ROOT_PREFIX, ""))))
        lines.append("")

    # time table
    methods = ["pma_filtered", "pma_epick", "pma_exact", "sdg", "sdg_hierarchy", "sdg_extract", "sdg_exact", "boost_voronoi"]
    present = [m for m in methods if any(r["method"] == m for r in time_rows)]
    if time_rows:
        lines += ["## Time", "",
                  "Median seconds over the runs (each in its own process), and in parentheses the ratio "
                  "method / ours (filtered) within the same run: a ratio above 1 means slower than ours. "
                  "Ours: the full progressive sequence (triangulation and every merge; every intermediate "
                  "axis is available along the way), then the coordinates of every vertex of the final axis. "
                  "SDG: the construction of the diagram; `sdg_extract` is the extraction of the interior "
                  "axis from it, counted separately. Peak memory (MB) of ours and of SDG in the last columns.", ""]
        head = "| shape | vertices | holes | " + " | ".join(METHOD_LABELS.get(m, m) for m in present) + " | peak MB ours | peak MB SDG |"
        lines += [head, "|---|---:|---:|" + "---:|" * (len(present) + 2)]
        for s in order:
            rows = {r["method"]: r for r in time_rows if r["shape"] == s}
            if not rows:
                continue
            ref = fnum(rows.get("pma_filtered", {}).get("median_seconds"))
            cells = []
            for m in present:
                r = rows.get(m)
                if r is None:
                    cells.append("-")
                    continue
                if r["status"] != "ok":
                    cells.append(esc(r["status"]))
                    continue
                t = fnum(r["median_seconds"])
                if m == "pma_filtered" or ref is None or not ref > 0:
                    cells.append(fmt_time(t))
                else:
                    cells.append("%s (%.2f)" % (fmt_time(t), t / ref))
            mem = lambda m: rows[m]["peak_rss_mb"] if m in rows and rows[m]["status"] == "ok" else "-"
            lines.append("| %s | %d | %d | %s | %s | %s |" % (s, info[s][0], info[s][1], " | ".join(cells),
                                                             mem("pma_filtered"), mem("sdg")))
        lines.append("")
        name = plot_time(time_rows, plots_dir)
        if name:
            lines += ["![time against vertices](%s/%s)" % (rel, name), ""]

    # accuracy
    if acc_rows:
        amethods = ["pma_filtered", "pma_epick", "pma_exact", "floor", "sdg_filtered", "sdg_exact"]
        apresent = [m for m in amethods if any(r["method"] == m for r in acc_rows)]
        lines += ["## Accuracy", "",
                  "E(x) = 1 - r_min / r_max over the branch points (paper, Table 3), with the true "
                  "distances to each point's generators. Per method: mean / standard deviation / max. "
                  "The floor is the exact branch point correctly rounded to double. `topology`: whether "
                  "the medial curves match the oracle (CGAL's segment Delaunay graph with exact "
                  "predicates) within the degenerate tolerance: \"same\" when every model that ran "
                  "(ours with each traits model, SDG's interior extraction) matches, else the models "
                  "that differ, with the number of curves that differ.", ""]
        lines += ["| shape | branch points | " + " | ".join(METHOD_LABELS.get(m, m) for m in apresent) + " | topology |",
                  "|---|---:|" + "---|" * (len(apresent) + 1)]
        for s in order:
            rows = {r["method"]: r for r in acc_rows if r["shape"] == s}
            if not rows:
                continue
            cells = []
            for m in apresent:
                r = rows.get(m)
                if r is None:
                    cells.append("-")
                elif r["status"] != "ok":
                    cells.append(esc(r["status"]))
                else:
                    cells.append("%s / %s / %s" % (fmt_sci(fnum(r["mean"])), fmt_sci(fnum(r["sd"])), fmt_sci(fnum(r["max"]))))
            bp = rows.get("pma_filtered", rows.get("floor", {})).get("branch_points", "-")
            checked = [(m, r["topology"]) for m, r in rows.items() if r["status"] == "ok" and r["topology"] not in ("-", "")]
            differ = ["%s %s" % (m, t.replace("differs ", "")) for m, t in checked if t != "same"]
            topo = ("differs: " + ", ".join(differ)) if differ else ("same" if checked else "-")
            lines.append("| %s | %s | %s | %s |" % (s, bp, " | ".join(cells), topo))
        lines.append("")
        for s in order:
            name = plot_accuracy(results, s, apresent, plots_dir)
            if name:
                lines.append("![sorted E(x), %s](%s/%s)" % (s, rel, name))
        lines.append("")

    # n_v
    nv_lines = []
    for s, kind in [(s, k) for s in order for k in ("", ".boundary")]:
        path = os.path.join(results, "nv", s + kind + ".nv.txt")
        if not os.path.exists(path):
            continue
        vals = [int(l.split()[1]) for l in open(path) if len(l.split()) >= 2]
        if not vals:
            continue
        vals_sorted = sorted(vals)
        def pct(q):
            return vals_sorted[min(len(vals_sorted) - 1, int(q * len(vals_sorted)))]
        hist = {}
        for v in vals:
            hist[v] = hist.get(v, 0) + 1
        nv_lines.append("| %s | %s | %d | %d | %d | %d | %d | %s |" % (
            s, "boundary" if kind else "region", len(vals), vals_sorted[-1], pct(0.5), pct(0.99), pct(0.999),
            ", ".join("%d:%d" % (k, hist[k]) for k in sorted(hist))))
        plot_nv(results, s, plots_dir, kind)
    if nv_lines:
        lines += ["## n_v", "",
                  "n_v is the largest number of live vanishing candidates in the priority queue of a merge "
                  "(paper, Theorem 1 and Figs. 17 and 20), per refinement step of the progressive runs "
                  "(filtered traits): region growing, and boundary evolution (a cut or a split counts 0).", "",
                  "| shape | driver | steps | max | median | 99% | 99.9% | distribution (n_v:steps) |",
                  "|---|---|---:|---:|---:|---:|---:|---|"] + nv_lines + [""]
        for s in order:
            for kind in ("", "_boundary"):
                if os.path.exists(os.path.join(plots_dir, "nv%s_%s.svg" % (kind, s))):
                    lines.append("![n_v per step%s, %s](%s/nv%s_%s.svg)" % (kind.replace("_", ", "), s, rel, kind, s))
        lines.append("")

    out = os.path.join(HERE, "RESULTS.md")
    manual = ""
    if os.path.exists(out):
        text = open(out).read()
        if MANUAL_MARKER in text:
            manual = text.split(MANUAL_MARKER, 1)[1]
    write(out, "\n".join(lines) + "\n" + MANUAL_MARKER + manual)
    print("wrote", out, "and plots in", plots_dir)
    return 0


if __name__ == "__main__":
    sys.exit(main())
