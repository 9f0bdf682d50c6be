"""Multi-host system test, the scenario: its thirteen steps in order, each printed as a PASS or FAIL
line with what it measured; a step after a failed one fails as "not run". Scenario.run runs them,
Scenario.cleanup stops the nodes and removes the namespaces. Used by multihost.py; see
docs/system-tests.md for what each step proves.
"""

import re
import signal
import time

from multihost_net import StepFailure, Topology, run
from multihost_node import ADMIN, FAILURE_TIMEOUT_MS, HEARTBEAT_MS, LAMP, OPERATOR, STARTUP_S, Node

# Bounds. A killed process's sockets are closed by its kernel, so its neighbours see the loss at
# once (typically 10-60 ms); a silent one is declared gone after FAILURETIMEOUT, checked every
# HEARTBEATINTERVAL (the settings every node runs with, FAILURE_TIMEOUT_MS and HEARTBEAT_MS: see
# multihost_node). What tells the two apart is the reason the call in flight fails with, not the
# time: the upper bounds only catch a loss never seen, and are generous for a busy machine.
KILL_DETECTION_MS = 10000
# A silent peer is declared gone FAILURETIMEOUT after its last frame (checked at every heartbeat
# tick, and exactly when the timeout falls between two ticks). An idle link carries a ping every HEARTBEATINTERVAL (one is sent when the link has been
# idle for half an interval, checked every interval), so its last frame came up to one interval
# before it fell silent: by design it leaves 2000-3000 ms after it fell silent. The
# bounds allow one interval more below, and far more above for a loaded machine, where timers run
# late (4950 ms was measured on an overloaded 2-core machine).
SILENT_DETECTION_MIN_MS = FAILURE_TIMEOUT_MS - 2 * HEARTBEAT_MS
SILENT_DETECTION_MS = FAILURE_TIMEOUT_MS + 10000
REJOIN_S = 15           # a frozen container rejoins at the next announcement (BROADCASTINTERVAL 3 s)
STEP_S = 10             # anything else
SLOW_CALLS = 12         # of 1 MiB each, over a 16 Mbit/s link (step 9)
SLOW_S = 40


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


def admin(node, credentials, target, operation, argument=None):
    """Has node call target's middleware service operation as credentials ('-': anonymously);
    returns the ADMIN or ADMIN-FAILED line's text after the operation's name."""
    node.send(" ".join(["admin", credentials, target.host, operation] + ([argument] if argument else [])))
    what = re.escape("%s@%s" % (operation, target.host))
    line = node.expect(r"^ADMIN(-FAILED)? " + what + " ", STEP_S)
    return re.sub(r" t=\d+$", "", line.text)


def refused(node, credentials, target, operation, argument, missing):
    """node's call of target's operation is refused with TRADENotAuthorizedException naming what
    was missing."""
    text = admin(node, credentials, target, operation, argument)
    if "ADMIN-FAILED" not in text or "TRADENotAuthorizedException" not in text or missing not in text:
        raise StepFailure("%s as %s: expected a refusal (TRADENotAuthorizedException: ...%s), got: %s"
                          % (node.host, credentials.split(":")[0], missing, text))
    if credentials != "-" and credentials.split(":")[1] in text:
        raise StepFailure("a refusal shows the secret: " + text)


def succeeded(node, target, operation, argument=None, answer=None):
    """node's call of target's operation as the administrator answers (answer, when given)."""
    text = admin(node, ADMIN, target, operation, argument)
    prefix = "ADMIN %s@%s -> " % (operation, target.host)
    if not text.startswith(prefix) or answer is not None and text[len(prefix):] != answer:
        raise StepFailure("%s as the administrator: expected %s%s, got: %s" % (
            node.host, prefix, answer if answer is not None else "...", text))
    return text[len(prefix):]


def call(node, group, expect_answer):
    """Has node call group; returns the call's ms, or raises unless it answered expect_answer."""
    node.send("call " + group)
    line = node.expect(r"^CALL(ED|-FAILED) " + group + " ", STEP_S)
    if not re.search(r"^CALLED " + group + " -> " + re.escape(expect_answer) + r" in \d+ ms", line.text):
        raise StepFailure("%s: %s" % (node.host, line.text))
    return re.search(r"in (\d+) ms", line.text).group(1)


class Scenario:
    def __init__(self, log_dir):
        self.topology = Topology()
        self.log_dir = log_dir
        self.nodes = {h: Node(self.topology, h, log_dir) for h in "ABC"}
        self.results = []
        self.catching_up = None     # (from, to): while a woken C caught up (step 11)

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
            return self.build_topology()

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
            self.check_links()
            return "A-C and C-B only: A and B have no direct link"

        def forwarding():
            ab = call(A, "host-B", "B on [10.200.2.2]")
            ba = call(B, "host-A", "A on [10.200.1.1]")
            return "A->B answered by B on 10.200.2.2 (%s ms), B->A by A on 10.200.1.1 (%s ms)" % (ab, ba)

        def c_stops(sig, wait_s):
            """Sends C `sig` while a call from A is in flight at B (it answers after 10 s); returns
            when, and how many ms after it A and B each saw the other two leave."""
            A.send("call host-B 10000")
            B.expect(r"^SERVING whereAmIAfter\(10000\) ", STEP_S)
            t = C.kill(sig)
            delays = {}
            for n, others in ((A, "BC"), (B, "AC")):
                for other in others:
                    delays[(n.host, other)] = (n.expect(left(other), wait_s).stamp - t) * 1000
            return t, delays

        def killed():
            t_kill, delays = c_stops(signal.SIGKILL, STEP_S)
            C.wait_exit(STEP_S)
            slow = {k: v for k, v in delays.items() if v > KILL_DETECTION_MS}
            text = describe_left(delays)
            if slow:
                raise StepFailure("left later than %d ms after kill -9: %s" % (KILL_DETECTION_MS, text))
            line = A.expect(r"^CALL(ED|-FAILED) host-B ", STEP_S)
            in_flight = (line.stamp - t_kill) * 1000
            if not line.text.startswith("CALL-FAILED host-B TRADEServiceUnavailableException"):
                raise StepFailure("A's call in flight through C: " + line.text)
            if "FAILURETIMEOUT" in line.text:
                raise StepFailure("A took the killed C for a silent one, not seeing its sockets end: "
                                  + line.text)
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

        def administered():
            # Refused: anonymous, a wrong secret, a principal without the role admin; from B, whose
            # calls reach A through C. The providing container audits each refusal.
            refused(B, "-", A, "shutdown", None, "the call proves no principal")
            refused(B, ADMIN.split(":")[0] + ":not-the-secret", A, "shutdown", None,
                    "is not valid (unknown principal or wrong secret)")
            refused(B, OPERATOR, C, "disconnect", B.id, "principal 'guest' has the roles operator")
            A.log_contains("refused: shutdown() of container A", STEP_S)
            # Done by the administrator, from A: B's description (through C), with its link's
            # round-trip time, measured from the heartbeat over the veth pair.
            deadline = time.time() + STEP_S
            while True:
                described = succeeded(A, B, "describeContainer")
                rtt = re.search(r"roundTripMicros=\{%s=([0-9.E]+)\}" % re.escape(C.id), described)
                if rtt or time.time() > deadline:
                    break
            if not rtt or "name=B," not in described or "links=[%s]" % C.id not in described:
                raise StepFailure("B's description lacks its name, its one link to C or that link's"
                                  " round-trip time: " + described)
            succeeded(A, B, "startProvider", LAMP, "[light()]")
            succeeded(A, B, "stopProvider", LAMP, "1")
            # C's link to B, closed and dialled again by the administrator on A: B's services leave
            # A and C, A's and C's leave B, and all come back.
            t0 = time.time()
            succeeded(A, C, "disconnect", B.id, "true")
            for n, others in ((A, "B"), (B, "AC"), (C, "B")):
                for other in others:
                    n.expect(left(other), STEP_S)
            port = B.listening[0].split("@")[1]
            succeeded(A, C, "connect", "10.200.2.2@" + port, "null")
            times = []
            for n, others in ((A, "B"), (B, "AC"), (C, "B")):
                for other in others:
                    times.append(n.expect(joined(other), REJOIN_S).stamp - t0)
            self.check_links()
            return ("refused (anonymous, wrong secret, operator; audited); B described from A, its"
                    " link to C %s us; a Lamp started and stopped on B; C's link to B disconnected"
                    " and connected again, every service back within %.2f s") % (
                        rtt.group(1), max(times))

        def slow_link():
            # A's link to C at 16 Mbit/s (2 MB/s): 12 MiB of calls take about six seconds to leave
            # A, twice FAILURETIMEOUT, while C reads all along. No link may be taken for dead.
            def shape(verb, *args):
                run(self.topology.exec_prefix("A") + ["tc", "qdisc", verb, "dev", "veth-a", "root"]
                    + list(args))
            shape("add", "tbf", "rate", "16mbit", "burst", "32kb", "latency", "5s")
            try:
                A.send("bulk host-B %d 1024" % SLOW_CALLS)
                line = A.expect(r"^BULK(-FAILED)? host-B ", SLOW_S)
            finally:
                shape("del")
            m = re.search(r"^BULK host-B %d answered in (\d+) ms" % SLOW_CALLS, line.text)
            if not m:
                raise StepFailure("A: " + line.text)
            if int(m.group(1)) < FAILURE_TIMEOUT_MS:
                raise StepFailure("the link was not slow: " + line.text)
            for n in (A, B, C):
                for other in "ABC".replace(n.host, ""):
                    if n.pending(left(other)):
                        raise StepFailure("%s saw %s leave during the slow transfer" % (n.host, other))
            return ("%d calls of 1 MiB A->B over a 16 Mbit/s A-C link answered in %s ms (FAILURETIMEOUT=%d);"
                    " no link taken for dead" % (SLOW_CALLS, m.group(1), FAILURE_TIMEOUT_MS))

        def frozen():
            t_stop, delays = c_stops(signal.SIGSTOP, SILENT_DETECTION_MS / 1000.0 + STEP_S)
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
            delays = self.shut_down_in_turn()
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
                    # by step 11 (they are printed on the notification thread).
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
        self.step("middleware operations across hosts: done with credentials, refused without",
                  administered)
        self.step("slow link: calls that take longer than FAILURETIMEOUT to leave", slow_link)
        self.step("C frozen (SIGSTOP): left on A and B after FAILURETIMEOUT (%d..%d ms)"
                  % (SILENT_DETECTION_MIN_MS, SILENT_DETECTION_MS), frozen)
        self.step("C wakes up (SIGCONT): services rejoin, calls work", woken)
        self.step("clean shutdown", shutdown)
        self.step("no spurious joined/left events", nothing_else)

    def build_topology(self):
        self.topology.build()
        self.topology.check_isolation()
        return "A 10.200.1.1 | C 10.200.1.3 + 10.200.2.3 | B 10.200.2.2; no route A<->B"

    def check_links(self):
        """A's and B's only direct link is to C, and C's are to A and B, once each."""
        A, B, C = self.nodes["A"], self.nodes["B"], self.nodes["C"]
        expected = {"A": {C.id}, "B": {C.id}, "C": {A.id, B.id}}
        for n in (A, B, C):
            n.send("neighbours")
            line = n.expect(r"^NEIGHBOURS ", STEP_S)
            got = list(filter(None, line.text.split(" ")[1].split(",")))
            if len(got) != len(set(got)) or set(got) != expected[n.host]:
                raise StepFailure("%s's direct links are %s, expected %s" % (
                    n.host, self.names(got), self.names(expected[n.host])))

    def shut_down_in_turn(self):
        """A, B and C quit one after the other; each one's goodbye makes the others print LEFT
        for it at once. Returns those delays (s)."""
        A, B, C = self.nodes["A"], self.nodes["B"], self.nodes["C"]
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
        return delays

    def names(self, ids):
        by_id = {n.id: n.host for n in self.nodes.values()}
        return sorted(by_id.get(i, i) for i in ids)

    def cleanup(self):
        for n in self.nodes.values():
            n.stop()
        self.topology.destroy()

