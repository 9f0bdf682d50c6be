#!/usr/bin/env python3
"""Where a scale JVM's CPU went in a round: interpreted, C1 or C2 code, or outside Java.

Usage: frame_types.py ROUND.collapsed [ROUND.collapsed ...]

Reads the profiles that scale JVMs write with -Dbench.scaleProfiler (RoundProfile: async-profiler's
collapsed stacks, each Java frame marked _[0] interpreted, _[1] C1, _[j] C2, _[i] inlined) and
counts each sample by the Java frame nearest its top (an inlined one counts as the code it was
inlined into; system calls made from Java count as the Java frame that made them), or as the
JIT's, the collector's or other native work when it has no Java frame. Then the activities whose
code ran in the interpreter most (the outermost two frames of dev.trade's) and the methods most
often on top there. Several files are counted together.
"""
import collections
import re
import sys

TIER = {"0": "interpreted", "1": "C1 code", "j": "C2 code"}
MARK = re.compile(r"_\[([01ij])\]$")
LAMBDA = re.compile(r"\$\$Lambda\$\d+(\.0x[0-9a-f]+)?")


def tier(frames):
    """The tier of the Java frame nearest the top, or None when there is none."""
    for frame in reversed(frames):
        m = MARK.search(frame)
        if m and m.group(1) != "i":
            return TIER[m.group(1)]
    return None


def outside_java(stack):
    if "CompileBroker" in stack:
        return "the JIT's threads"
    if "G1" in stack or "GC" in stack:
        return "the collector"
    return "other native code"


def short(frame):
    return LAMBDA.sub("$$Lambda", MARK.sub("", frame)).split("/")[-1]


def main(paths):
    if not paths:
        sys.exit(__doc__.strip().splitlines()[2])
    total = 0
    kinds = collections.Counter()
    activities = collections.Counter()
    methods = collections.Counter()
    for path in paths:
        with open(path, encoding="utf-8") as f:
            for line in f:
                stack, _, count = line.rstrip("\n").rpartition(" ")
                n = int(count)
                frames = stack.split(";")
                total += n
                kind = tier(frames)
                if kind is None:
                    kinds[outside_java(stack)] += n
                    continue
                kinds[kind] += n
                if kind == "interpreted":
                    own = [short(x) for x in frames if x.startswith("dev/trade/")]
                    activities[" > ".join(own[:2]) or "(the JDK's code alone)"] += n
                    top = [x for x in frames if MARK.search(x)][-1]
                    methods[MARK.sub("", top)] += n
    if total == 0:
        sys.exit("frame_types.py: no samples")
    print(f"{total} samples in {len(paths)} profile(s)")
    for kind, n in kinds.most_common():
        print(f"  {100 * n / total:5.1f} %  {kind}")
    print("interpreted, by activity:")
    for name, n in activities.most_common(8):
        print(f"  {100 * n / total:5.1f} %  {name}")
    print("interpreted, by method on top:")
    for name, n in methods.most_common(8):
        print(f"  {100 * n / total:5.1f} %  {name}")


if __name__ == "__main__":
    main(sys.argv[1:])
