#!/usr/bin/env python3
"""How long methods waited for the JIT in a JVM: its compile queue, tier by tier.

Usage: compile_waits.py COMPILATION.log

Reads the log a JVM writes with -XX:+UnlockDiagnosticVMOptions -XX:+LogCompilation
-XX:LogFile=COMPILATION.log (for one scale JVM: pass those in -Dbench.nodeOptions) and prints, for
each tier, how many methods were compiled and how long they waited between being queued and their
compilation's start: the median, the 90th percentile and the longest. Tiers 1-3 are C1's (2: with
little profiling, chosen while C2's queue is long), 4 is C2's.
"""
import re
import statistics
import sys

ATTRS = re.compile(r"(\w+)='([^']*)'")


def tasks(text, tag):
    """compile_id -> (level, stamp) of every <tag ...> element; C2's name no level."""
    found = {}
    for m in re.finditer(r"<" + tag + r" ([^>]*)>", text):
        a = dict(ATTRS.findall(m.group(1)))
        if "compile_id" in a and "stamp" in a:
            found[a["compile_id"]] = (a.get("level", "4"), float(a["stamp"]))
    return found


def main(args):
    if len(args) != 1:
        sys.exit(__doc__.strip().splitlines()[2])
    with open(args[0], encoding="utf-8", errors="replace") as f:
        text = f.read()
    queued = tasks(text, "task_queued")
    waits = {}
    for cid, (level, started) in tasks(text, "task").items():
        if cid in queued:
            # The level it was compiled at: the policy may lower a queued tier 3 to tier 2.
            waits.setdefault(level, []).append(started - queued[cid][1])
    if not waits:
        sys.exit("compile_waits.py: no queued compilations in " + args[0])
    print("tier  methods  median wait  90th percentile  longest")
    for level in sorted(waits):
        w = sorted(waits[level])
        print(f"{level:>4}  {len(w):7d}  {statistics.median(w):9.2f} s  "
              f"{w[int(0.9 * (len(w) - 1))]:13.2f} s  {w[-1]:6.2f} s")


if __name__ == "__main__":
    main(sys.argv[1:])
