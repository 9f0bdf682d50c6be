#!/usr/bin/env python3
"""Multi-host system test: three hosts as network namespaces, two subnets, one host on both.

    A (10.200.1.1, veth-a) ---- (10.200.1.3, veth-ca) C (10.200.2.3, veth-cb) ---- (10.200.2.2, veth-b) B

A and B have no route to each other. Each host runs one container JVM
(dev.trade.examples.system.HostNode) with DISCOVERYRANGE=subnet on its own interfaces. The test
checks that the containers find each other by multicast within each subnet, that A and B call each
other through C's forwarding, that killing C makes the services of the other side leave on A and on
B within the detection bound, that a new C brings them back, and that a silent (frozen) C is
declared gone after FAILURETIMEOUT and rejoins when it wakes up. See docs/system-tests.md.

Needs root and `ip netns` (iproute2) and `unshare` (util-linux). Where they are unavailable the
test is skipped with the reason, unless CI=true, where that is a failure. Every packet stays inside
the namespaces this test creates; nothing runs with subnet range outside them. The test runs in a
private mount namespace of its own, so the namespaces' mounts never reach the rest of the machine
and disappear with the test even if it is killed.

Output: one PASS/FAIL line per step, then "N passed, N failed" alone on the last line.
Exit status 0 when every step passed (or the test was skipped outside CI), 1 otherwise.
"""

import ctypes
import os
import re
import shutil
import signal
import subprocess
import sys
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
CLASSPATH = os.pathsep.join([os.path.join(ROOT, "trade-core", "target", "classes"),
                             os.path.join(ROOT, "trade-examples", "target", "classes")])
MAIN_CLASS = "dev.trade.examples.system.HostNode"
IN_PRIVATE_MOUNTS = "TRADE_SYSTEM_TEST_PRIVATE_MOUNTS"

# Bounds. A killed process's sockets are closed by its kernel, so its neighbours see the loss at
# once; a silent one is declared gone after FAILURETIMEOUT (default 3000 ms), checked every
# HEARTBEATINTERVAL (default 1000 ms).
KILL_DETECTION_MS = 1000
FAILURE_TIMEOUT_MS = 3000
HEARTBEAT_MS = 1000
# A silent peer is declared gone at the first heartbeat tick after FAILURETIMEOUT without a frame
# from it. An idle link carries a ping every HEARTBEATINTERVAL (one is sent when the link has been
# idle for half an interval, checked every interval), so its last frame came up to one interval
# before it fell silent: by design it leaves 2000-3000 ms after it fell silent. The
# bounds allow one interval more below, and more above for a loaded machine, where timers run
# late (4950 ms was measured on an overloaded 2-core machine).
SILENT_DETECTION_MIN_MS = FAILURE_TIMEOUT_MS - 2 * HEARTBEAT_MS
SILENT_DETECTION_MS = FAILURE_TIMEOUT_MS + 2000
STARTUP_S = 20          # JVM start, discovery, links, tables: normally about 1 s
REJOIN_S = 15           # a frozen container rejoins at the next announcement (BROADCASTINTERVAL 3 s)
STEP_S = 10             # anything else

CI = os.environ.get("CI", "").lower() == "true"


class StepFailure(Exception):
    pass


# ---------------------------------------------------------------------------------------------
# Availability


def unavailable_reason():
    """Why namespaces cannot be used here, or None when they can."""
    if not sys.platform.startswith("linux"):
        return "not Linux"
    if os.geteuid() != 0:
        return "not running as root (network namespaces and veth pairs need root)"
    for tool in ("ip", "unshare", "mount"):
        if shutil.which(tool) is None:
            return "'%s' not found on PATH" % tool
    if java_binary() is None:
        return "no java (neither $JAVA_HOME/bin/java nor java on PATH)"
    r = run(["unshare", "--mount", "--propagation", "private", "true"], check=False)
    if r.returncode != 0:
        return "cannot create a mount namespace: `unshare --mount` failed (%d) %s" % (
            r.returncode, r.stderr.strip())
    return None


def private_netns_dir():
    """Puts a tmpfs of our own on `ip netns`' directory, in our private mount namespace: the
    namespace names and their mounts then live only as long as this test, even if it is killed,
    and parallel runs do not see each other's. Returns why that failed, or None."""
    path = "/var/run/netns"
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        return "cannot create %s: %s" % (path, e)
    r = run(["mount", "-t", "tmpfs", "-o", "size=1m,mode=755", "trade-system-test", path], check=False)
    if r.returncode != 0:
        return "cannot mount a tmpfs on %s: %s" % (path, r.stderr.strip())
    return None


def probe_netns():
    """Creates a namespace with a veth pair and removes it: does `ip netns` work here?"""
    ns = "trade-probe-%d" % os.getpid()
    steps = [["ip", "netns", "add", ns],
             ["ip", "-n", ns, "link", "add", "p0", "type", "veth", "peer", "name", "p1"],
             ["ip", "netns", "exec", ns, "true"]]
    try:
        for cmd in steps:
            r = run(cmd, check=False)
            if r.returncode != 0:
                return "`%s` failed: %s" % (" ".join(cmd), r.stderr.strip())
        return None
    finally:
        run(["ip", "netns", "del", ns], check=False)


def java_binary():
    home = os.environ.get("JAVA_HOME")
    if home and os.access(os.path.join(home, "bin", "java"), os.X_OK):
        return os.path.join(home, "bin", "java")
    return shutil.which("java")


def run(cmd, check=True):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if check and r.returncode != 0:
        raise StepFailure("`%s` failed (%d): %s" % (" ".join(cmd), r.returncode,
                                                     (r.stderr or r.stdout).strip()))
    return r


# ---------------------------------------------------------------------------------------------
# Topology


class Topology:
    """Three namespaces: A and B on their own subnets, C on both. Names carry our pid."""

    SUBNETS = [  # (host, interface, address, peer host, peer interface, peer address)
        ("A", "veth-a", "10.200.1.1/24", "C", "veth-ca", "10.200.1.3/24"),
        ("B", "veth-b", "10.200.2.2/24", "C", "veth-cb", "10.200.2.3/24"),
    ]
    INTERFACES = {"A": "veth-a", "B": "veth-b", "C": "veth-ca,veth-cb"}
    ADDRESSES = {"A": ["10.200.1.1"], "B": ["10.200.2.2"], "C": ["10.200.1.3", "10.200.2.3"]}

    def __init__(self):
        self.ns = {h: "trade-%d-%s" % (os.getpid(), h) for h in "ABC"}
        self.created = []

    def build(self):
        for host in "ABC":
            run(["ip", "netns", "add", self.ns[host]])
            self.created.append(self.ns[host])
            run(["ip", "-n", self.ns[host], "link", "set", "lo", "up"])
        for host, nif, addr, peer, peer_nif, peer_addr in self.SUBNETS:
            run(["ip", "-n", self.ns[host], "link", "add", nif, "type", "veth",
                 "peer", "name", peer_nif, "netns", self.ns[peer]])
            run(["ip", "-n", self.ns[host], "addr", "add", addr, "dev", nif])
            run(["ip", "-n", self.ns[peer], "addr", "add", peer_addr, "dev", peer_nif])
            run(["ip", "-n", self.ns[host], "link", "set", nif, "up", "multicast", "on"])
            run(["ip", "-n", self.ns[peer], "link", "set", peer_nif, "up", "multicast", "on"])
        # C is a host on two networks, not a router: only TRADE's forwarding may connect A and B.
        run(["ip", "netns", "exec", self.ns["C"], "sysctl", "-qw", "net.ipv4.ip_forward=0"])
        self.wait_carrier()

    def wait_carrier(self, timeout=5.0):
        """Waits until every veth is operationally up. The kernel reports carrier asynchronously
        (up to a second after `link set up`), and until then Java's NetworkInterface.isUp() is
        false, so a container with that interface in DISCOVERYINTERFACES would refuse to start."""
        deadline = time.time() + timeout
        while True:
            down = []
            for host in "ABC":
                for nif in self.INTERFACES[host].split(","):
                    r = run(["ip", "-n", self.ns[host], "-o", "link", "show", nif])
                    if "LOWER_UP" not in r.stdout or " state UP " not in r.stdout:
                        down.append("%s %s" % (host, nif))
            if not down:
                return
            if time.time() > deadline:
                raise StepFailure("interfaces not up after %.0f s: %s" % (timeout, ", ".join(down)))
            time.sleep(0.05)

    def exec_prefix(self, host):
        return ["ip", "netns", "exec", self.ns[host]]

    def check_isolation(self):
        """A and B cannot reach each other at the IP level; C forwards no IP."""
        for host, other in (("A", "B"), ("B", "A")):
            target = self.ADDRESSES[other][0]
            r = run(["ip", "-n", self.ns[host], "route", "get", target], check=False)
            if r.returncode == 0:
                raise StepFailure("%s has a route to %s (%s): %s" % (host, other, target, r.stdout.strip()))
        r = run(["ip", "netns", "exec", self.ns["C"], "sysctl", "-n", "net.ipv4.ip_forward"])
        if r.stdout.strip() != "0":
            raise StepFailure("C forwards IP (net.ipv4.ip_forward=%s)" % r.stdout.strip())
        for host in "ABC":
            for nif in self.INTERFACES[host].split(","):
                r = run(["ip", "-n", self.ns[host], "link", "show", nif])
                if "MULTICAST" not in r.stdout or ",UP" not in r.stdout:
                    raise StepFailure("%s's %s is not up with multicast: %s" % (host, nif, r.stdout.strip()))

    def destroy(self):
        for ns in reversed(self.created):
            run(["ip", "netns", "del", ns], check=False)
        self.created = []


# ---------------------------------------------------------------------------------------------
# Container processes


_prctl = ctypes.CDLL(None).prctl if sys.platform.startswith("linux") else None


def die_with_parent():
    """In a node's process before exec: SIGKILL it when this test dies, even by SIGKILL. (A node
    also exits at the end of its input, but a node stopped by SIGSTOP reads nothing.) Only a
    prepared foreign call happens here, between fork and exec."""
    PR_SET_PDEATHSIG = 1
    _prctl(PR_SET_PDEATHSIG, int(signal.SIGKILL), 0, 0, 0)


class Line:
    def __init__(self, text, received):
        self.text = text
        self.received = received        # time.time() when the harness read it
        m = re.search(r" t=(\d+)$", text)
        self.stamp = int(m.group(1)) / 1000.0 if m else received   # when the node printed it
        self.consumed = False

    def __str__(self):
        return self.text


class Node:
    """One HostNode JVM in a host's namespace, fed commands on stdin; stdout read line by line."""

    def __init__(self, topology, host, log_dir):
        self.topology = topology
        self.host = host
        self.log_dir = log_dir
        self.incarnation = 0
        self.proc = None
        self.lines = []
        self.cond = threading.Condition()
        self.past = []          # (incarnation, lines, quit_at) of earlier processes
        self.quit_at = None
        self.eof = False
        self.id = None

    def start(self, settings):
        """Starts a new incarnation with these TRADE settings (KEY=VALUE strings); see wait_ready."""
        if self.proc is not None:
            self.past.append((self.incarnation, self.lines, self.quit_at))
        self.incarnation += 1
        self.lines = []
        self.eof = False
        self.quit_at = None
        self.id = None
        cmd = self.topology.exec_prefix(self.host) + [
            java_binary(), "-XX:TieredStopAtLevel=1", "-cp", CLASSPATH, MAIN_CLASS,
            self.host,
            "DISCOVERYRANGE=subnet",
            "FAILURETIMEOUT=%d" % FAILURE_TIMEOUT_MS,
            "HEARTBEATINTERVAL=%d" % HEARTBEAT_MS,
        ] + list(settings)
        self.settings = " ".join(settings) or "(defaults)"
        base = os.path.join(self.log_dir, "%s-%d" % (self.host, self.incarnation))
        self.err_path = base + ".log"
        self.out_path = base + ".out"
        err = open(self.err_path, "w")
        self.started = time.time()
        self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err,
                                     text=True, bufsize=1, start_new_session=True,
                                     preexec_fn=die_with_parent)
        err.close()
        proc, lines, out_path = self.proc, self.lines, self.out_path
        threading.Thread(target=self._read, args=(proc, lines, out_path), daemon=True).start()

    def wait_ready(self):
        ready = self.expect(r"^READY ", STARTUP_S)
        m = re.search(r" id=(\S+) pid=(\d+)", ready.text)
        self.id = m.group(1)
        if int(m.group(2)) != self.proc.pid:
            raise StepFailure("%s's JVM has pid %s, not the started process %d" %
                              (self.host, m.group(2), self.proc.pid))
        return ready

    def _read(self, proc, lines, out_path):
        with open(out_path, "w") as out:
            for text in proc.stdout:
                text = text.rstrip("\n")
                out.write(text + "\n")
                out.flush()
                with self.cond:
                    lines.append(Line(text, time.time()))
                    self.cond.notify_all()
        with self.cond:
            if lines is self.lines:
                self.eof = True
            self.cond.notify_all()

    def send(self, command):
        if command == "quit":
            with self.cond:
                self.quit_at = len(self.lines)
        try:
            self.proc.stdin.write(command + "\n")
            self.proc.stdin.flush()
        except (BrokenPipeError, OSError) as e:
            raise StepFailure("cannot send '%s' to %s: %s" % (command, self.host, e))

    def expect(self, pattern, timeout):
        """The first unconsumed line matching pattern, waiting until the deadline."""
        regex = re.compile(pattern)
        deadline = time.time() + timeout
        with self.cond:
            while True:
                for line in self.lines:
                    if not line.consumed and regex.search(line.text):
                        line.consumed = True
                        return line
                if self.eof:
                    raise StepFailure("%s exited (status %s) without printing /%s/%s" %
                                      (self.host, self.proc.poll(), pattern, self._context()))
                left = deadline - time.time()
                if left <= 0:
                    raise StepFailure("%s did not print /%s/ within %.1f s%s" %
                                      (self.host, pattern, timeout, self._context()))
                self.cond.wait(min(left, 0.2))

    def pending(self, pattern):
        """Whether the current process printed a line matching pattern that no expectation took."""
        regex = re.compile(pattern)
        with self.cond:
            return any(not l.consumed and regex.search(l.text) for l in self.lines)

    def unconsumed(self, pattern):
        """(incarnation, line) of every process's lines matching pattern that no expectation
        took, up to its quit command (a container that closes sees every other one leave)."""
        regex = re.compile(pattern)
        result = []
        with self.cond:
            for incarnation, lines, quit_at in self.past + [(self.incarnation, self.lines, self.quit_at)]:
                for l in lines if quit_at is None else lines[:quit_at]:
                    if not l.consumed and regex.search(l.text):
                        result.append((incarnation, l))
        return result

    def _context(self):
        recent = [l.text for l in self.lines[-8:]]
        return "; its last lines: %s; log: %s" % (recent, self.err_path)

    def kill(self, sig=signal.SIGKILL):
        before = time.time()
        os.kill(self.proc.pid, sig)
        return before

    def wait_exit(self, timeout):
        try:
            return self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            raise StepFailure("%s did not exit within %d s%s" % (self.host, timeout, self._context()))

    def stop(self):
        """Ends the process whatever its state (cleanup)."""
        if self.proc and self.proc.poll() is None:
            try:
                os.kill(self.proc.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass
            try:
                self.proc.wait(5)
            except subprocess.TimeoutExpired:
                pass


# ---------------------------------------------------------------------------------------------
# The scenario


# Per host: the TRADE settings besides DISCOVERYRANGE=subnet. Between them they cover named and
# automatically chosen discovery interfaces, and listening on the wildcard address (announced as
# each interface's own address) as well as on explicit per-interface addresses.
SETTINGS = {
    "A": ["DISCOVERYINTERFACES=veth-a"],
    "B": [],                                                    # every up multicast interface
    "C": ["DISCOVERYINTERFACES=veth-ca,veth-cb"],               # wildcard listen
    "C again": ["SERVERIPS=10.200.1.3@0,10.200.2.3@0"],         # every interface, explicit listen
}

SERVICE = r"whereAmI\(\)@"


def joined(host):
    return r"^JOINED " + SERVICE + host + " "


def left(host):
    return r"^LEFT " + SERVICE + host + " "


def describe_left(delays):
    """{(observer, gone): ms} as 'on A: B left after 12 ms, C after 13 ms; on B: ...'."""
    parts = []
    for observer in sorted({o for o, _ in delays}):
        gone = sorted(g for o, g in delays if o == observer)
        parts.append("on %s: " % observer + ", ".join(
            "%s left after %.0f ms" % (g, delays[(observer, g)]) for g in gone))
    return "; ".join(parts)


class Scenario:
    def __init__(self, log_dir):
        self.topology = Topology()
        self.log_dir = log_dir
        self.nodes = {h: Node(self.topology, h, log_dir) for h in "ABC"}
        self.results = []
        self.catching_up = None     # (from, to): while a woken C caught up (step 9)

    def step(self, title, fn):
        if any(not ok for _, ok, _ in self.results):
            self.results.append((title, False, "not run: an earlier step failed"))
            print("FAIL %d %s (not run: an earlier step failed)" % (len(self.results), title), flush=True)
            return
        t0 = time.time()
        try:
            detail = fn()
            self.results.append((title, True, detail))
            print("PASS %d %s%s (%.1f s)" % (len(self.results), title,
                                              ": " + detail if detail else "", time.time() - t0), flush=True)
        except StepFailure as e:
            self.results.append((title, False, str(e)))
            print("FAIL %d %s: %s" % (len(self.results), title, e), flush=True)

    def run(self):
        A, B, C = self.nodes["A"], self.nodes["B"], self.nodes["C"]

        def topology():
            self.topology.build()
            self.topology.check_isolation()
            return "A 10.200.1.1 | C 10.200.1.3 + 10.200.2.3 | B 10.200.2.2; no route A<->B"

        def discovery():
            t0 = time.time()
            for n in (A, B, C):
                n.start(SETTINGS[n.host])
            for n in (A, B, C):
                n.wait_ready()
            times = {}
            for n in (A, B, C):
                for other in "ABC".replace(n.host, ""):
                    line = n.expect(joined(other), STARTUP_S)
                    times[n.host] = max(times.get(n.host, 0), line.stamp - t0)
            return "each host sees the other two (%s s after start)" % ", ".join(
                "%s %.2f" % (h, times[h]) for h in "ABC")

        def links():
            expected = {"A": {C.id}, "B": {C.id}, "C": {A.id, B.id}}
            for n in (A, B, C):
                n.send("neighbours")
                line = n.expect(r"^NEIGHBOURS ", STEP_S)
                got = set(filter(None, line.text.split(" ")[1].split(",")))
                if got != expected[n.host]:
                    raise StepFailure("%s's direct links are %s, expected %s" % (
                        n.host, self.names(got), self.names(expected[n.host])))
            return "A-C and C-B only: A and B have no direct link"

        def call(node, group, expect_answer):
            node.send("call " + group)
            line = node.expect(r"^CALL(ED|-FAILED) " + group + " ", STEP_S)
            if not re.search(r"^CALLED " + group + " -> " + re.escape(expect_answer) + r" in \d+ ms", line.text):
                raise StepFailure("%s: %s" % (node.host, line.text))
            return re.search(r"in (\d+) ms", line.text).group(1)

        def forwarding():
            ab = call(A, "host-B", "B on [10.200.2.2]")
            ba = call(B, "host-A", "A on [10.200.1.1]")
            return "A->B answered by B on 10.200.2.2 (%s ms), B->A by A on 10.200.1.1 (%s ms)" % (ab, ba)

        def killed():
            # A call from A is in flight at B (it answers after 10 s) when C dies.
            A.send("call host-B 10000")
            B.expect(r"^SERVING whereAmIAfter\(10000\) ", STEP_S)
            t_kill = C.kill(signal.SIGKILL)
            delays = {}
            for n, others in ((A, "BC"), (B, "AC")):
                for other in others:
                    line = n.expect(left(other), STEP_S)
                    delays[(n.host, other)] = (line.stamp - t_kill) * 1000
            C.wait_exit(STEP_S)
            slow = {k: v for k, v in delays.items() if v > KILL_DETECTION_MS}
            text = describe_left(delays)
            if slow:
                raise StepFailure("left later than %d ms after kill -9: %s" % (KILL_DETECTION_MS, text))
            line = A.expect(r"^CALL(ED|-FAILED) host-B ", STEP_S)
            in_flight = (line.stamp - t_kill) * 1000
            if not line.text.startswith("CALL-FAILED host-B TRADEServiceUnavailableException"):
                raise StepFailure("A's call in flight through C: " + line.text)
            if in_flight > KILL_DETECTION_MS:
                raise StepFailure("A's call in flight failed only %.0f ms after kill -9" % in_flight)
            A.send("call host-B")
            line = A.expect(r"^CALL(ED|-FAILED) host-B ", STEP_S)
            if not line.text.startswith("CALL-FAILED host-B TRADEServiceNotFoundException"):
                raise StepFailure("A could still call B without C: " + line.text)
            return ("after kill -9 C: " + text + "; A's call in flight failed (service unavailable)"
                    " after %.0f ms, and a new lookup of B fails at once" % in_flight)

        def restarted():
            t0 = time.time()
            C.start(SETTINGS["C again"])
            C.wait_ready()
            times = []
            for n, others in ((A, "BC"), (B, "AC"), (C, "AB")):
                for other in others:
                    times.append(n.expect(joined(other), STARTUP_S).stamp - t0)
            return "new C (%s): every service joined on A, B and C within %.2f s of its start" % (
                C.settings, max(times))

        def forwarding_again():
            ab = call(A, "host-B", "B on [10.200.2.2]")
            ba = call(B, "host-A", "A on [10.200.1.1]")
            return "A->B %s ms, B->A %s ms through the new C" % (ab, ba)

        def frozen():
            A.send("call host-B 10000")
            B.expect(r"^SERVING whereAmIAfter\(10000\) ", STEP_S)
            t_stop = C.kill(signal.SIGSTOP)
            delays = {}
            for n, others in ((A, "BC"), (B, "AC")):
                for other in others:
                    line = n.expect(left(other), SILENT_DETECTION_MS / 1000.0 + STEP_S)
                    delays[(n.host, other)] = (line.stamp - t_stop) * 1000
            text = describe_left(delays)
            if any(v > SILENT_DETECTION_MS or v < SILENT_DETECTION_MIN_MS for v in delays.values()):
                raise StepFailure("left outside %d..%d ms after SIGSTOP (FAILURETIMEOUT=%d): %s" % (
                    SILENT_DETECTION_MIN_MS, SILENT_DETECTION_MS, FAILURE_TIMEOUT_MS, text))
            # The call in flight fails with the same detection, and says why.
            line = A.expect(r"^CALL(ED|-FAILED) host-B ", STEP_S)
            in_flight = (line.stamp - t_stop) * 1000
            if not re.search(r"^CALL-FAILED host-B TRADEServiceUnavailableException: .*"
                             r"silent for \d+ ms \(FAILURETIMEOUT=%d\)" % FAILURE_TIMEOUT_MS, line.text):
                raise StepFailure("A's call in flight through the silent C: " + line.text)
            if in_flight > SILENT_DETECTION_MS or in_flight < SILENT_DETECTION_MIN_MS:
                raise StepFailure("A's call in flight failed %.0f ms after SIGSTOP, outside %d..%d ms" % (
                    in_flight, SILENT_DETECTION_MIN_MS, SILENT_DETECTION_MS))
            return "C silent (SIGSTOP): %s; A's call in flight failed after %.0f ms naming FAILURETIMEOUT" % (
                text, in_flight)

        def woken():
            t0 = C.kill(signal.SIGCONT)
            times = []
            for n, others in ((A, "BC"), (B, "AC")):
                for other in others:
                    times.append(n.expect(joined(other), REJOIN_S).stamp - t0)
            calls = []
            for n, group, answer in ((A, "host-B", "B on [10.200.2.2]"), (B, "host-A", "A on [10.200.1.1]"),
                                     (C, "host-A", "A on [10.200.1.1]"), (C, "host-B", "B on [10.200.2.2]")):
                calls.append("%s->%s %s ms" % (n.host, group[-1], call(n, group, answer)))
            # C slept through FAILURETIMEOUT and wakes with a stale view: until it has read the
            # end of the links its neighbours closed, it still lists them, may pass that on to the
            # first neighbour that links again, and then takes it back. So a host may see a service
            # leave and join again while C catches up (and C itself may see nothing leave, when a
            # new link replaces an old one before C has read its end). Accepted: a LEFT followed
            # by a JOINED. Not accepted: a service that stays away (the calls above) or flaps later.
            transients = []
            for n in (A, B, C):
                for other in "ABC".replace(n.host, ""):
                    while n.pending(left(other)):
                        n.expect(left(other), 0)
                        n.expect(joined(other), REJOIN_S)
                        transients.append("%s saw %s leave and rejoin" % (n.host, other))
            self.catching_up = (t0, time.time())
            return "C resumed (SIGCONT): A and B saw it rejoin within %.2f s; %s; calls %s" % (
                max(times), ", ".join(transients) if transients else "no transient left/joined",
                ", ".join(calls))

        def shutdown():
            # One after the other; each one's goodbye makes the others print LEFT for it at once.
            delays = []
            for n, rest in ((A, (B, C)), (B, (C,)), (C, ())):
                t0 = time.time()
                n.send("quit")
                n.expect(r"^BYE ", STEP_S)
                status = n.wait_exit(STEP_S)
                if status != 0:
                    raise StepFailure("%s exited with status %d" % (n.host, status))
                for other in rest:
                    delays.append(other.expect(left(n.host), STEP_S).stamp - t0)
            return "A, B and C quit in turn; the others saw each leave within %.0f ms; all exited with status 0" % (
                max(delays) * 1000)

        def nothing_else():
            extra, late = [], []
            for n in (A, B, C):
                lines = n.unconsumed(r"^(JOINED|LEFT|UNKNOWN|CALL)")
                for i, (incarnation, l) in enumerate(lines):
                    if l.consumed:
                        continue
                    # A LEFT printed while C caught up after waking, and its JOINED, seen too late
                    # by step 9 (they are printed on the notification thread).
                    m = re.match(r"^LEFT (\S+) ", l.text)
                    if m and self.catching_up and self.catching_up[0] <= l.stamp <= self.catching_up[1]:
                        rejoin = [x for _, x in lines[i + 1:] if x.text.startswith("JOINED %s " % m.group(1))
                                  and not x.consumed]
                        if rejoin:
                            l.consumed = rejoin[0].consumed = True
                            late.append("%s saw %s leave and rejoin" % (n.host, m.group(1)))
                            continue
                    extra.append("%s-%d: %s" % (n.host, incarnation, l.text))
            if extra:
                raise StepFailure("unexpected events: " + "; ".join(extra))
            return "no event but the expected ones" + (
                " (while C caught up after waking: %s)" % ", ".join(late) if late else "")

        self.step("topology: two subnets, C on both, no IP route between A and B", topology)
        self.step("discovery by multicast within each subnet (DISCOVERYRANGE=subnet)", discovery)
        self.step("links follow the subnets", links)
        self.step("calls A->B and B->A through C's forwarding", forwarding)
        self.step("kill -9 C: left on A and B within %d ms, a call in flight fails" % KILL_DETECTION_MS,
                  killed)
        self.step("C restarted: services rejoin on both sides", restarted)
        self.step("calls A->B and B->A work again", forwarding_again)
        self.step("C frozen (SIGSTOP): left on A and B after FAILURETIMEOUT (%d..%d ms)"
                  % (SILENT_DETECTION_MIN_MS, SILENT_DETECTION_MS), frozen)
        self.step("C wakes up (SIGCONT): services rejoin, calls work", woken)
        self.step("clean shutdown", shutdown)
        self.step("no spurious joined/left events", nothing_else)

    def names(self, ids):
        by_id = {n.id: n.host for n in self.nodes.values()}
        return sorted(by_id.get(i, i) for i in ids)

    def cleanup(self):
        for n in self.nodes.values():
            n.stop()
        self.topology.destroy()


# ---------------------------------------------------------------------------------------------


def summary(passed, failed):
    print("%d passed, %d failed" % (passed, failed), flush=True)


def main():
    if os.environ.get(IN_PRIVATE_MOUNTS) != "1":
        reason = unavailable_reason()
        if reason:
            if CI:
                print("FAIL multi-host system tests cannot run in CI: " + reason, flush=True)
                summary(0, 1)
                return 1
            print("SKIPPED multi-host system tests: " + reason +
                  " (they need root, iproute2 and util-linux; with CI=true this is a failure)", flush=True)
            summary(0, 0)
            return 0
        # Again, in a private mount namespace: `ip netns add` mounts stay in it and go with it.
        # Signals are passed on, so that the test cleans up after itself.
        env = dict(os.environ, **{IN_PRIVATE_MOUNTS: "1"})
        child = subprocess.Popen(["unshare", "--mount", "--propagation", "private",
                                  sys.executable, os.path.abspath(__file__)] + sys.argv[1:], env=env)
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, lambda signum, frame: child.send_signal(signum))
        return child.wait()

    reason = private_netns_dir() or probe_netns()
    if reason:
        if CI:
            print("FAIL multi-host system tests cannot run in CI: network namespaces unavailable: "
                  + reason, flush=True)
            summary(0, 1)
            return 1
        print("SKIPPED multi-host system tests: network namespaces unavailable: " + reason +
              " (with CI=true this is a failure)", flush=True)
        summary(0, 0)
        return 0
    for path in CLASSPATH.split(os.pathsep):
        if not os.path.isdir(path):
            print("FAIL multi-host system tests: %s is missing; build first (mvn install -DskipTests)"
                  % path, flush=True)
            summary(0, 1)
            return 1

    log_dir = os.path.join(ROOT, "target", "system-tests", "multihost-%d-%d" % (int(time.time()), os.getpid()))
    os.makedirs(log_dir)
    print("multi-host system test: hosts A, B, C in network namespaces trade-%d-{A,B,C}; logs in %s"
          % (os.getpid(), log_dir), flush=True)

    def terminate(signum, frame):
        # Once: a second signal must not interrupt the cleanup.
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, signal.SIG_IGN)
        raise KeyboardInterrupt("signal %d" % signum)
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, terminate)

    scenario = Scenario(log_dir)
    t0 = time.time()
    try:
        scenario.run()
    except KeyboardInterrupt as e:
        print("FAIL interrupted (%s)" % e, flush=True)
        scenario.results.append(("interrupted", False, str(e)))
    finally:
        scenario.cleanup()
    passed = sum(1 for _, ok, _ in scenario.results if ok)
    failed = len(scenario.results) - passed
    print("multi-host system test took %.1f s" % (time.time() - t0), flush=True)
    if failed == 0 and os.environ.get("TRADE_SYSTEM_TEST_KEEP_LOGS") != "1":
        shutil.rmtree(log_dir, ignore_errors=True)
    else:
        print("logs of every container kept in %s (<host>-<n>.out: its events, <host>-<n>.log: its"
              " TRADE log)" % log_dir, flush=True)
    summary(passed, failed)
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
