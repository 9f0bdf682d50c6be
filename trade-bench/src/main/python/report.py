#!/usr/bin/env python3
"""Turns trade-bench/results/*.json into docs/benchmarks.md and two SVG charts (stdlib only).

usage: report.py RESULTS_DIR DOCS_DIR COMMAND
The hand-written findings in trade-bench/report-notes.md are appended verbatim.
"""
import json
import os
import statistics
import sys

SYSTEMS = ["raw-tcp", "rmi", "grpc", "jgroups", "trade"]
LABELS = {"raw-tcp": "raw TCP", "rmi": "JDK RMI", "grpc": "gRPC-java", "jgroups": "JGroups", "trade": "TRADE"}
COLORS = {"raw-tcp": "#888888", "rmi": "#4e79a7", "grpc": "#f28e2b", "jgroups": "#59a14f", "trade": "#e15759",
          "first round": "#e15759", "warm round": "#f1a7a8"}


def load(d, name):
    p = os.path.join(d, name)
    if not os.path.exists(p):
        return None
    with open(p) as f:
        return json.load(f)


def span(values):
    """'lo–hi' of a list of microsecond values, as the tables print them."""
    return f"{fmt(min(values))}–{fmt(max(values))}"


def fmt(v, digits=1):
    if v is None:
        return "–"
    if abs(v) >= 100:
        return f"{v:,.0f}"
    return f"{v:.{digits}f}"


def ratio(a, b):
    return None if a is None or not b else a / b


def rfmt(r):
    return "–" if r is None else f"{r:.2f}×"


def svg_bars(groups, series, values, title, unit, path, log=False):
    """Grouped horizontal bars: groups (rows) × series (bars per row); values[(g, s)]."""
    import math
    width, left, bar, gap = 760, 170, 14, 10
    rows = len(groups) * (len(series) * bar + gap)
    height = 60 + rows + 30
    vmax = max([v for v in values.values() if v] or [1])
    scale = lambda v: (math.log10(max(v, 1)) / math.log10(max(vmax, 10)) if log else v / vmax) * (width - left - 160)
    out = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
           f'font-family="sans-serif" font-size="12">',
           f'<rect width="100%" height="100%" fill="white"/>',
           f'<text x="10" y="20" font-size="14" font-weight="bold">{title}</text>']
    y = 40
    for g in groups:
        out.append(f'<text x="10" y="{y + len(series) * bar / 2 + 4}">{g}</text>')
        for s in series:
            v = values.get((g, s))
            w = scale(v) if v else 0
            out.append(f'<rect x="{left}" y="{y}" width="{w:.1f}" height="{bar - 2}" fill="{COLORS.get(s, "#999")}"/>')
            out.append(f'<text x="{left + w + 4:.1f}" y="{y + bar - 4}" font-size="10">'
                       f'{LABELS.get(s, s)} {fmt(v)}{unit}</text>')
            y += bar
        y += gap
    out.append(f'<text x="{left}" y="{height - 10}" font-size="10" fill="#555">'
               f'{"log scale; " if log else ""}shorter is {"better" if unit.strip() in ("µs", "ms", "s") else "worse"}</text>')
    out.append("</svg>")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    res, docs, command = sys.argv[1], sys.argv[2], sys.argv[3]
    machine = load(res, "machine.json") or {}
    remote = load(res, "remote.json") or {}
    jmh = load(res, "jmh.json") or []
    life = load(res, "lifecycle.json") or {}
    scale = load(res, "scale.json") or {}
    cpu = (load(res, "localcpu.json") or {}).get("cpu_ns_per_call", {})
    wall = open(os.path.join(res, "wall_s.txt")).read().strip() if os.path.exists(os.path.join(res, "wall_s.txt")) else "?"
    lat = remote.get("latency", {})
    thr = remote.get("throughput", {})
    systems = [s for s in SYSTEMS if s in lat.get("small", {})]

    def p(scn, s, q="p50_us"):
        return lat.get(scn, {}).get(s, {}).get(q)

    def tp(n, s):
        return thr.get(f"{n}_callers", {}).get(s, {}).get("calls_per_s")

    local = {b["benchmark"].rsplit(".", 1)[1]: b["primaryMetric"]["score"] for b in jmh}
    local_err = {b["benchmark"].rsplit(".", 1)[1]: b["primaryMetric"]["scoreError"] for b in jmh}
    its = life.get("iterations", [])
    med = lambda key: statistics.median([i[key] for i in its]) if its else None
    mx = lambda key: max([i[key] for i in its]) if its else None
    sizes = {}  # containers -> the runs of that size, in order
    for s in scale.get("sizes", []):
        sizes.setdefault(s["containers"], []).append(s)
    converged_ms = lambda s: s["convergence_ms"] if s.get("converged") else float("inf")
    s100 = sizes.get(100, [])
    warm100 = [s for s in s100 if "warm_converged" in s]
    warm_ms = lambda s: s["warm_convergence_ms"] if s.get("warm_converged") else float("inf")

    goals = [
        ("small-call p50 ≤ 1.0× RMI", ratio(p("small", "trade"), p("small", "rmi")), lambda r: r <= 1.0, rfmt),
        ("small-call p50 ≤ 1.25× raw TCP", ratio(p("small", "trade"), p("small", "raw-tcp")), lambda r: r <= 1.25, rfmt),
        ("64-caller throughput ≥ 2× RMI", ratio(tp(64, "trade"), tp(64, "rmi")), lambda r: r >= 2.0, rfmt),
        ("64-caller throughput ≥ gRPC-java", ratio(tp(64, "trade"), tp(64, "grpc")), lambda r: r >= 1.0, rfmt),
        ("1 MB call p50 ≤ 5 ms", None if p("1MB", "trade") is None else p("1MB", "trade") / 1000, lambda v: v <= 5, lambda v: f"{v:.2f} ms"),
        ("local non-strict ≤ 50 ns over a MethodHandle (CPU time)",
         None if "tradeNonStrict" not in cpu else cpu["tradeNonStrict"] - cpu["methodHandle"], lambda v: v <= 50, lambda v: f"+{v:.0f} ns"),
        ("the same by JMH wall-clock average",
         None if "tradeNonStrict" not in local else local["tradeNonStrict"] - local["methodHandle"], lambda v: v <= 50, lambda v: f"+{v:.0f} ns"),
        ("start → callable ≤ 300 ms (median)", med("start_to_callable_ms"), lambda v: v <= 300, lambda v: f"{v:.0f} ms"),
        ("the same with an AppCDS archive (median)",
         statistics.median([i["start_to_callable_ms"] for i in life.get("iterations_appcds", [])])
         if life.get("iterations_appcds") else None, lambda v: v <= 300, lambda v: f"{v:.0f} ms"),
        ("kill -9 → left ≤ 1 s (worst)", mx("kill_to_left_ms"), lambda v: v <= 1000, lambda v: f"{v:.0f} ms"),
        (f"100 containers converge ≤ 10 s (median of {len(s100)} run{'s' if len(s100) != 1 else ''})",
         statistics.median([converged_ms(s) for s in s100]) if s100 else None,
         lambda v: v <= 10_000, lambda v: "not within 60 s" if v == float("inf") else f"{v / 1000:.1f} s"),
        (f"the same in warm JVMs: a second round in the same JVMs (median of {len(warm100)})",
         statistics.median([warm_ms(s) for s in warm100]) if warm100 else None,
         lambda v: v <= 10_000, lambda v: "not within 60 s" if v == float("inf") else f"{v / 1000:.1f} s"),
        ("≤ 16 MB heap per container (100 containers, largest)",
         max((s["heap_per_container_mb"] for s in s100 if s.get("heap_per_container_mb") is not None), default=None),
         lambda v: v <= 16, lambda v: f"{v:.1f} MB"),
    ]

    L = []
    w = L.append
    w("# Benchmarks: TRADE beside raw TCP, JDK RMI, gRPC-java and JGroups\n")
    w("<!-- Generated by trade-bench/src/main/python/report.py from trade-bench/results/*.json; "
      "edit trade-bench/report-notes.md for the findings, not this file. -->\n")
    w(f"Reproduce: **`{command}`** (from the repository root; builds with `-Pbench`, runs every part, "
      f"rewrites `trade-bench/results/*.json` and this page). Raw results: "
      f"[`trade-bench/results/`](../trade-bench/results/).\n")
    w("## Machine and run\n")
    w(f"- {machine.get('cores', '?')} cores ({machine.get('cpu', '?')}), {machine.get('memory_gb', '?')} GB, "
      f"{machine.get('os', '?')}; {machine.get('jdk', '?')}.")
    # When the run ended (src/run-benchmarks writes ended.txt), not when this page was generated.
    ended = os.path.join(res, "ended.txt")
    when = open(ended).read().strip() if os.path.exists(ended) else "?"
    w(f"- Run: {when}, wall time {wall} s"
      f"{' (quick smoke run: numbers mean little)' if remote.get('quick') else ''}.")
    loads = [(n, d.get("load_average_before"), d.get("load_average_after"))
             for n, d in (("remote", remote), ("lifecycle", life), ("scale", scale)) if d]
    w("- 1-minute load average before/after each part: " + ", ".join(f"{n} {b}/{a}" for n, b, a in loads)
      + ". The load after a part counts the part's own threads (64 callers, 100 containers' "
      "threads, and the 1-minute average decays slowly into the next part); a load above the 2 "
      "cores before a part means other processes competed for the CPU: absolute µs are then noisy "
      "and inflated, most for the systems that hand each call between several threads. The CPU of "
      "this shared virtual machine is also not equally fast at all hours: compare **ratios from "
      "the same run**; rounds are interleaved so that noise spreads over all systems alike.")
    speeds = [(n, d.get("cpu_index_ms")) for n, d in
              (("remote", remote), ("lifecycle", life), ("scale", scale)) if d and d.get("cpu_index_ms")]
    if speeds:
        w("- CPU speed index before each part (`Calibration`: one fixed single-threaded Java workload, "
          "median of 7 runs after 5 to warm up; lower is faster): " + ", ".join(f"{n} {v:.0f} ms" for n, v in speeds)
          + ". It tells how fast the machine was when a goal stated in absolute time (start → callable, "
          "convergence) was measured, so that runs of different hours can be compared.")
    w("")
    w("## Goals\n")
    w("| goal | measured | |")
    w("|---|---|---|")
    for name, v, ok, f in goals:
        w(f"| {name} | {'–' if v is None else f(v)} | {'–' if v is None else ('met' if ok(v) else '**missed**')} |")
    w("")
    w("Why a goal is missed, in short, and what was measured and tried: "
      "[What the goals came to](#what-the-goals-came-to-and-why-some-are-missed).\n")
    w("## Latency of one call (one caller, µs)\n")
    w("Each server in its own JVM, one client JVM for all; loopback; every system answers "
      "`small(int) → boolean` and `consume(byte[]) → int` (the argument's length). "
      "Ratios are p50 over the p50 of raw TCP and of RMI in the same run.\n")
    w("![latency](benchmarks-latency.svg)\n")
    for scn in ("small", "1KB", "1MB", "small_every_1ms"):
        if scn not in lat:
            continue
        n = lat[scn].get(systems[0], {}).get("count", 0) if systems else 0
        if scn == "small_every_1ms":
            w(f"**small, one call every millisecond** ({n} calls per system): a control loop's calls, "
              "started on a fixed schedule, every thread of both sides idle between them, so that "
              "each call also pays for waking the threads that carry it. Not a goal of its own; "
              "the back-to-back figures above do not show this cost.\n")
        else:
            w(f"**{scn}** ({n} calls per system)\n")
        w("| system | p50 | p90 | p99 | p99.9 | p50 / raw TCP | p50 / RMI |")
        w("|---|---|---|---|---|---|---|")
        for s in systems:
            w(f"| {LABELS[s]} | {fmt(p(scn, s))} | {fmt(p(scn, s, 'p90_us'))} | {fmt(p(scn, s, 'p99_us'))} | "
              f"{fmt(p(scn, s, 'p999_us'))} | {rfmt(ratio(p(scn, s), p(scn, 'raw-tcp')))} | "
              f"{rfmt(ratio(p(scn, s), p(scn, 'rmi')))} |")
        w("")
        rounds = lat[scn].get("round_p50_us", {})
        if rounds.get("trade") and rounds.get("raw-tcp"):
            # Adjacent rounds share the machine's mood; the spread shows how much a run's ratio owes to it.
            per = [t / r for t, r in zip(rounds["trade"], rounds["raw-tcp"]) if r]
            w(f"Per round ({len(per)} rounds, every system in turn): raw TCP's p50 {span(rounds['raw-tcp'])} µs, "
              f"TRADE's {span(rounds['trade'])} µs; TRADE / raw TCP by round {min(per):.2f}–{max(per):.2f}×.\n")
    if thr:
        w("## Throughput (small calls per second, median of rounds)\n")
        w("1, 16 and 64 threads in the client JVM call `small` as fast as they can for 2 s after 0.5 s "
          "of warm-up. Raw TCP gets a socket per thread; RMI pools connections itself; gRPC shares one "
          "channel, JGroups one dispatcher, TRADE one container pair (one link).\n")
        w("![throughput](benchmarks-throughput.svg)\n")
        w("| system | 1 caller | 16 callers | 64 callers | 64 / RMI | 64 / gRPC |")
        w("|---|---|---|---|---|---|")
        for s in systems:
            w(f"| {LABELS[s]} | {fmt(tp(1, s))} | {fmt(tp(16, s))} | {fmt(tp(64, s))} | "
              f"{rfmt(ratio(tp(64, s), tp(64, 'rmi')))} | {rfmt(ratio(tp(64, s), tp(64, 'grpc')))} |")
        w("")
    if local or cpu:
        w("## Local calls (ns per call)\n")
        w("JMH (`LocalCallBench`, average wall-clock time, one fork) and the same calls timed by the "
          "calling thread's CPU time (`LocalCpu`: median of 7 × 2 million calls). On a machine whose load "
          "exceeds its cores, wall time also counts the time the thread waited for a core, so the CPU-time "
          "column is the one to read; the goal is judged on it. `methodHandle` is a handle held in a "
          "field (not a constant), which is what a dispatcher uses.\n")
        w("| benchmark | JMH ns/op | ± (99.9 %) | CPU ns/call | CPU over MethodHandle |")
        w("|---|---|---|---|---|")
        for b in ("direct", "methodHandle", "tradeNonStrict", "tradeStrict", "tradeNonStrict1KB", "tradeStrict1KB"):
            j = f"{local[b]:.1f} | {local_err[b]:.1f}" if b in local else "– | –"
            c = f"{cpu[b]:.1f} | {cpu[b] - cpu['methodHandle']:+.1f}" if b in cpu else "– | –"
            w(f"| {b} | {j} | {c} |")
        w("")
    if its:
        w("## Start and death (multicast discovery on loopback)\n")
        w(f"{len(its)} iterations, each with a provider in a fresh JVM; the peer is a container in the "
          "benchmark JVM. *start → callable*: from just before the provider's `build()` to the end of "
          "the peer's first successful call, made in its `joined` callback. *spawn → callable* adds "
          "the JVM's own start. *kill → left*: from `kill -9` of the provider's JVM to the peer's "
          "`left` callback. The provider's JVM has a TRADE application's class path, trade-core and the "
          "benchmark's own classes, not the peers' jars the benchmark module also carries (21 MB, whose "
          "every jar the JDK's service lookups at start would open and index).\n")
        w("| measure | median | min | max | with AppCDS: median | min | max |")
        w("|---|---|---|---|---|---|---|")
        cds = life.get("iterations_appcds", [])
        for key, name in (("start_to_callable_ms", "start → callable"), ("build_ms", "of which build() + register"),
                          ("spawn_to_callable_ms", "spawn JVM → callable"), ("kill_to_left_ms", "kill -9 → left")):
            vals = [i[key] for i in its]
            row = f"| {name} | {statistics.median(vals):.1f} ms | {min(vals):.1f} ms | {max(vals):.1f} ms |"
            if cds:
                c = [i[key] for i in cds]
                row += f" {statistics.median(c):.1f} ms | {min(c):.1f} ms | {max(c):.1f} ms |"
            else:
                row += " – | – | – |"
            w(row)
        w("")
        w("*With AppCDS*: the provider JVM maps a class-data archive that one training run of the same "
          "program wrote at exit (`-XX:ArchiveClassesAtExit=…`, then `-XX:SharedArchiveFile=…`; JDK 13+), "
          "instead of loading and linking TRADE's and the JDK's classes and spinning lambda classes again. "
          "A deployment choice, not a code change; the goal is judged on the plain figures.\n")
    if sizes:
        w("## Many containers on one host\n")
        w("Containers run 25 to a JVM plus one JVM holding a single container under `-Xmx16m` "
          "(starting 100 JVMs on 2 cores would measure JVM start-up, not TRADE), each on a TRADE application's class path. All find each other "
          "by multicast on loopback. A JVM starts its containers one after the other. *All built*: from the moment every JVM is told to build "
          "its containers until the last one has registered its service. *Converged*: from that same "
          "moment until every container lists every container's service. *Heap per container*: "
          "heap in use after full GCs with the containers running, minus the same JVM's heap before "
          "building them, divided by their number. *CPU*: the CPU time all JVMs used from that same "
          "moment until the last one converged (all threads, JIT compilers and collectors "
          "included): the work converging took, which a busy machine stretches less than it "
          "stretches the wall-clock time.\n")
        w("Each size runs several times, each time a new system of new JVMs; the goal is judged on the "
          "median. *Warm round*: each run then closes its containers and builds them again, as a new "
          "system, in the same JVMs, whose JIT has by then compiled what converging runs; the same "
          "figures for that round (the goal's JVMs are those of the first round, started for it).\n")
        w("![convergence](benchmarks-scale.svg)\n")
        w("| containers | run | JVMs | all built after | converged after | heap per container | the -Xmx16m JVM: its container / whole heap | CPU (all JVMs) | threads (all JVMs) | links per container: mean / most | warm round: all built / converged / CPU |")
        w("|---|---|---|---|---|---|---|---|---|---|---|")
        def warm(s):
            if "warm_converged" not in s:
                return "–"
            if not s["warm_converged"]:
                return "**not within 60 s**"
            b = "–" if s.get("warm_all_built_ms") is None else f"{s['warm_all_built_ms'] / 1000:.2f} s"
            return f"{b} / {s['warm_convergence_ms'] / 1000:.2f} s / {s['warm_cpu_seconds']:.1f} s"

        for n, run, s in ((n, k + 1, s) for n in sorted(sizes) for k, s in enumerate(sizes[n])):
            conv = f"{s['convergence_ms'] / 1000:.2f} s" if s.get("converged") else "**not within 60 s**"
            mb = lambda v: "–" if v is None else f"{v:.2f}"
            built = "–" if s.get("all_built_ms") is None else f"{s['all_built_ms'] / 1000:.2f} s"
            cpu = "–" if s.get("cpu_seconds") is None else f"{s['cpu_seconds']:.1f} s"
            w(f"| {n} | {run} | {s['jvms']} | {built} | {conv} | {mb(s['heap_per_container_mb'])} MB | "
              f"{mb(s['single_container_jvm_xmx16m_heap_mb'])} / {mb(s['single_container_jvm_total_heap_mb'])} MB | {cpu} | {s['threads_total']} | "
              f"{s.get('links_per_container', '–')} / {s.get('most_links', '–')} | {warm(s)} |")
        w("")
    failed = [s for runs in sizes.values() for s in runs if s.get("problems") or s.get("warm_problems")]
    if failed:
        w("What the JVMs that did not converge reported (`TIMEOUT` lists how many services each of "
          "their containers saw):\n")
        for s in failed:
            if s.get("problems"):
                w(f"- {s['containers']} containers: `{s['problems'][:600]}`")
            if s.get("warm_problems"):
                w(f"- {s['containers']} containers, warm round: `{s['warm_problems'][:600]}`")
        w("")
    notes = os.path.join(os.path.dirname(__file__), "..", "..", "..", "report-notes.md")
    if os.path.exists(notes):
        with open(notes) as f:
            w(f.read().rstrip() + "\n")
    with open(os.path.join(docs, "benchmarks.md"), "w") as f:
        f.write("\n".join(L))

    vals = {}
    for scn in ("small", "1KB"):
        for s in systems:
            vals[(f"{scn} p50", s)] = p(scn, s)
            vals[(f"{scn} p99", s)] = p(scn, s, "p99_us")
    rows = ["small p50", "small p99", "1KB p50", "1KB p99"]
    if "small_every_1ms" in lat:
        rows.append("every 1 ms p50")
        for s in systems:
            vals[("every 1 ms p50", s)] = p("small_every_1ms", s)
    svg_bars(rows, systems, vals,
             "Latency of one remote call (µs, log scale)", " µs", os.path.join(docs, "benchmarks-latency.svg"), log=True)
    tv = {(f"{n} caller{'s' if n > 1 else ''}", s): tp(n, s) for n in (1, 16, 64) for s in systems}
    svg_bars([f"{n} caller{'s' if n > 1 else ''}" for n in (1, 16, 64)], systems, tv,
             "Throughput of small calls (calls/s)", "/s", os.path.join(docs, "benchmarks-throughput.svg"))
    if sizes:
        conv = {}
        seconds = lambda ms: None if ms == float("inf") else ms / 1000  # a median that did not converge
        for n, runs in sizes.items():
            conv[(f"{n} containers", "first round")] = seconds(statistics.median(converged_ms(r) for r in runs))
            warm = [r for r in runs if "warm_converged" in r]
            if warm:
                conv[(f"{n} containers", "warm round")] = seconds(statistics.median(warm_ms(r) for r in warm))
        svg_bars([f"{n} containers" for n in sorted(sizes)], ["first round", "warm round"], conv,
                 "Time until every container sees every service (s, median; goal at 100: 10 s)", " s",
                 os.path.join(docs, "benchmarks-scale.svg"))


if __name__ == "__main__":
    main()
