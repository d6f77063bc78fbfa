#!/usr/bin/env python3
# Alternating timing of whole tool processes (RESULTS.md, forty-first session on):
#   ab_time.py ROUNDS [--args "..."] FILE name:TOOL ...
# runs each TOOL with the args and FILE, ROUNDS times, alternating the order each
# round; prints median and minimum wall time (ms), median peak RSS (MiB) and the
# ratio of medians against the first tool.  A TOOL can be a wrapper script that
# adds options (for example --traits epick).
import sys, os, time, statistics, resource, subprocess, shlex
a = sys.argv[1:]; rounds = int(a.pop(0)); extra = []
if a[0] == "--args": a.pop(0); extra = shlex.split(a.pop(0))
f = a.pop(0); tools = [x.split(":", 1) for x in a]
res = {n: [] for n, _ in tools}; mem = {n: [] for n, _ in tools}
for r in range(rounds):
    for n, t in (tools if r % 2 == 0 else tools[::-1]):
        t0 = time.perf_counter(); pid = os.fork()
        if pid == 0:
            fd = os.open(os.devnull, os.O_WRONLY); os.dup2(fd, 1); os.execv(t, [t] + extra + [f])
        _, st, ru = os.wait4(pid, 0); dt = time.perf_counter() - t0
        assert st == 0, (n, st)
        res[n].append(dt * 1000); mem[n].append(ru.ru_maxrss / 1024)
base = statistics.median(res[tools[0][0]])
for n, _ in tools:
    m = statistics.median(res[n])
    print("%-8s median %.1f ms  min %.1f ms  rss %.1f MiB  ratio %.3f" % (n, m, min(res[n]), statistics.median(mem[n]), m / base))
