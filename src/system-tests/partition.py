#!/usr/bin/env python3
"""Partition and heal, on the multi-host topology of multihost.py (docs/system-tests.md):

    A (10.200.1.1, veth-a) ---- (10.200.1.3, veth-ca) C (10.200.2.3, veth-cb) ---- (10.200.2.2, veth-b) B

The link between C and B is cut (C's veth-cb set down, which takes B's veth-b off carrier too)
while a call from A to B is in flight through C, and healed (set up again) later, twice. Each time:
the call in flight fails typed (TRADEServiceUnavailableException), not at its deadline; A sees B
leave but not C, B sees A and C leave, C sees B leave; a new call across the cut fails at once
with TRADEServiceNotFoundException. After the heal every service comes back on every side, calls
work both ways, the links are the same as before, and nothing is duplicated: the call that was in
flight ran once at B and its late answer never reaches A, and no service joins twice.

In the second round B holds a lock over actuate() of A and C across the cut: A gets the lock once B's
leases ended on its side (B seen to leave, or the leases expired), with higher fencing tokens, as the
only holder; after the heal B's calls under its old lock are refused where the services live, by
fencing token, and never run (docs/locks.md, "Under a partition").

Runs as multihost.py does (root, namespaces of its own, skipped with the reason outside CI;
docs/reliability.md): nothing leaves the namespaces it creates. The last line is "N passed, N failed".
"""

import re
import sys
import time

from multihost import main
from multihost_net import StepFailure, run
from multihost_node import FAILURE_TIMEOUT_MS, STARTUP_S
from multihost_scenario import SETTINGS, STEP_S, Scenario, call, describe_left, joined, left

# A cut cable is silence, not a closed socket: a link across it is declared gone FAILURETIMEOUT
# after its last frame, or sooner when the kernel reports the route gone. The upper bound only
# catches a loss never seen, and is generous for a busy machine.
CUT_DETECTION_MS = FAILURE_TIMEOUT_MS + 10000
REJOIN_S = 20          # after the heal: the next announcement (BROADCASTINTERVAL 3 s), a link, tables
IN_FLIGHT_MS = 6000    # the call A->B in flight at the cut; B answers after this long
ROUNDS = 2
# A's lock request after the cut: B's leases end when A and C see B leave, or at the latest
# FAILURETIMEOUT after its last renewal arrived; the rest is room for a loaded machine.
LOCK_WAIT_MS = FAILURE_TIMEOUT_MS + 20000


class PartitionScenario(Scenario):
    def run(self):
        A, B, C = self.nodes["A"], self.nodes["B"], self.nodes["C"]

        def discovery():
            for n in (A, B, C):
                n.start(SETTINGS["C again"] if n is C else SETTINGS[n.host])
            for n in (A, B, C):
                n.wait_ready()
            for n in (A, B, C):
                for other in "ABC".replace(n.host, ""):
                    n.expect(joined(other), STARTUP_S)
            return "each host sees the other two"

        def calls_both_ways():
            ab = call(A, "host-B", "B on [10.200.2.2]")
            ba = call(B, "host-A", "A on [10.200.1.1]")
            return "A->B %s ms, B->A %s ms" % (ab, ba)

        def veth_cb(state):
            run(self.topology.exec_prefix("C") + ["ip", "link", "set", "veth-cb", state])

        state = {}

        def cut():
            A.send("call host-B %d" % IN_FLIGHT_MS)
            B.expect(r"^SERVING whereAmIAfter\(%d\) " % IN_FLIGHT_MS, STEP_S)
            t = time.time()
            veth_cb("down")
            state["cut"] = t
            delays = {}
            for n, others in ((A, "B"), (B, "AC"), (C, "B")):
                for other in others:
                    delays[(n.host, other)] = (n.expect(left(other), CUT_DETECTION_MS / 1000.0).stamp - t) * 1000
            text = describe_left(delays)
            if any(v > CUT_DETECTION_MS for v in delays.values()):
                raise StepFailure("left later than %d ms after the cut: %s" % (CUT_DETECTION_MS, text))
            line = A.expect(r"^CALL(ED|-FAILED) host-B ", STEP_S)
            in_flight = (line.stamp - t) * 1000
            if not line.text.startswith("CALL-FAILED host-B TRADEServiceUnavailableException"):
                raise StepFailure("A's call in flight across the cut: " + line.text)
            if in_flight > CUT_DETECTION_MS:
                raise StepFailure("A's call in flight failed only %.0f ms after the cut" % in_flight)
            reason = line_reason(line)
            for n, group in ((A, "host-B"), (B, "host-A"), (B, "host-C")):
                n.send("call " + group)
                line = n.expect(r"^CALL(ED|-FAILED) " + group + " ", STEP_S)
                if not line.text.startswith("CALL-FAILED %s TRADEServiceNotFoundException" % group):
                    raise StepFailure("%s could still call %s across the cut: %s" % (n.host, group, line.text))
            for n, other in ((A, "C"), (C, "A")):
                if n.pending(left(other)):
                    raise StepFailure("%s saw %s leave, on the side of the cut they share" % (n.host, other))
            call(A, "host-C", "C on [10.200.1.3, 10.200.2.3]")
            return ("%s; A's call in flight failed (service unavailable) after %.0f ms (%s); new calls"
                    " across the cut fail at once (not found); A still calls C" % (
                        text, in_flight, reason))

        def heal():
            t = time.time()
            veth_cb("up")
            self.topology.wait_carrier()
            times = []
            for n, others in ((A, "B"), (B, "AC"), (C, "B")):
                for other in others:
                    times.append(n.expect(joined(other), REJOIN_S).stamp - t)
            detail = calls_both_ways()
            self.check_links()
            # The call that was in flight ran once at B; B's late answer (IN_FLIGHT_MS after it
            # began) must not reach A. Watched for a quiet window after B answered.
            quiet_until = state["cut"] + IN_FLIGHT_MS / 1000.0 + 2
            while time.time() < quiet_until:
                time.sleep(0.1)
            if B.pending(r"^SERVING whereAmIAfter"):
                raise StepFailure("B ran the call in flight twice")
            for n in (A, B, C):
                for other in "ABC".replace(n.host, ""):
                    if n.pending(joined(other)) or n.pending(left(other)):
                        raise StepFailure("%s saw %s join or leave once more after the heal" % (n.host, other))
            if A.pending(r"^CALL"):
                raise StepFailure("A got a second answer: " + A.expect(r"^CALL", 0).text)
            return ("every service back within %.2f s; %s; links as before; the call in flight ran once"
                    " and its late answer never reached A" % (max(times), detail))

        def lock(node, groups, wait_ms):
            """node locks actuate() of groups; returns (lock id, {container: token}) or fails."""
            node.send("lock %s %d" % (",".join(groups), wait_ms))
            line = node.expect(r"^LOCK(ED|-FAILED) ", wait_ms / 1000.0 + STEP_S)
            m = re.match(r"^LOCKED (\S+) (\S+) t=", line.text)
            if not m:
                raise StepFailure("%s could not lock %s: %s" % (node.host, ",".join(groups), line.text))
            tokens = dict((k, int(v)) for k, v in (p.split("=") for p in m.group(2).split(",")))
            return m.group(1), tokens

        def under(node, group):
            """node calls actuate() in group under its lock; the line it printed."""
            node.send("under " + group)
            return node.expect(r"^UNDER-LOCK(-FAILED)? %s " % group, STEP_S)

        def release(node):
            node.send("release")
            line = node.expect(r"^RELEASE(D|-FAILED)", STEP_S)
            if not line.text.startswith("RELEASED "):
                raise StepFailure("%s: %s" % (node.host, line.text))

        def holders(node):
            """{service@container: (holder's container, lock id, token)} as node lists them."""
            node.send("locks")
            line = node.expect(r"^LOCKS(-FAILED)? ", STEP_S)
            if line.text.startswith("LOCKS-FAILED"):
                raise StepFailure("%s: %s" % (node.host, line.text))
            rows = {}
            for row in [r for r in line.text.split(" ")[1:-1] if r]:
                service, holder = row.split("=", 1)
                if service in rows:
                    raise StepFailure("%s lists two holders of %s: %s" % (node.host, service, line.text))
                container, lock_id, token = holder.split(":")
                rows[service] = (container, lock_id, int(token))
            return rows

        def lock_held():
            state["B lock"], state["B tokens"] = lock(B, ("host-A", "host-C"), 0)
            line = under(B, "host-A")
            if not line.text.startswith("UNDER-LOCK host-A -> A "):
                raise StepFailure("B's call under its lock: " + line.text)
            A.expect(r"^ACTUATED by B ", STEP_S)
            line = under(A, "host-C")     # A holds no lock: an ordinary call, to a locked service
            if not re.match(r"^UNDER-LOCK-FAILED host-C TRADELockedException: .*of container B ", line.text):
                raise StepFailure("A's call without the lock was not refused: " + line.text)
            if C.pending(r"^ACTUATED by A "):
                raise StepFailure("C ran A's call although B holds the lock")
            return "B holds actuate() of A and C (tokens %s) under lock %s; its call ran at A; A's" \
                " call without the lock was refused at C, naming B" % (state["B tokens"], state["B lock"])

        def lock_moved():
            # B is cut off, and A and C saw it leave (the step before): its leases end there then,
            # or at the latest when they expire (FAILURETIMEOUT after its last renewal); A's request
            # may wait that long and more, for a loaded machine.
            t = time.time()
            state["A lock"], state["A tokens"] = lock(A, ("host-A", "host-C"), LOCK_WAIT_MS)
            after_cut = (time.time() - state["cut"]) * 1000
            waited = (time.time() - t) * 1000
            for host, token in state["B tokens"].items():
                if state["A tokens"].get(host, 0) <= token:
                    raise StepFailure("A's fencing token at %s, %s, is not above B's, %d" % (
                        host, state["A tokens"].get(host), token))
            rows = holders(C)
            expected = {("actuate(java.lang.String)@" + h): ("A", state["A lock"]) for h in "AC"}
            seen = {k: v[:2] for k, v in rows.items()}
            if seen != expected:
                raise StepFailure("C lists holders %s, not only A's lock %s" % (rows, state["A lock"]))
            line = under(A, "host-C")
            if not line.text.startswith("UNDER-LOCK host-C -> C "):
                raise StepFailure("A's call under its lock: " + line.text)
            C.expect(r"^ACTUATED by A ", STEP_S)
            return ("A got the lock %.0f ms after the cut (its request waited %.0f ms), tokens %s"
                    " above B's %s; C lists A's lock as the only holder; A's call under it ran at C"
                    % (after_cut, waited, state["A tokens"], state["B tokens"]))

        def stale_fenced():
            refusals = []
            for group, host in (("host-A", "A"), ("host-C", "C")):
                line = under(B, group)
                fence = "fencing token %d is older than the service's latest grant, %d" % (
                    state["B tokens"][host], state["A tokens"][host])
                if not line.text.startswith("UNDER-LOCK-FAILED %s TRADELockedException: " % group) \
                        or fence not in line.text:
                    raise StepFailure("B's call under its old lock to %s was not refused by fencing"
                                      " ('%s'): %s" % (host, fence, line.text))
                refusals.append(host + ": " + fence)
            for n in (A, C):
                if n.pending(r"^ACTUATED by B "):
                    raise StepFailure("%s ran B's call under its old lock" % n.host)
            rows = holders(B)
            if any(v[1] != state["A lock"] for v in rows.values()) or len(rows) != 2:
                raise StepFailure("B, healed, lists holders %s, not only A's lock" % rows)
            release(A)
            release(B)                      # its old lock: forgotten here, held nowhere
            again, tokens = lock(B, ("host-A", "host-C"), 0)
            line = under(B, "host-A")
            if not line.text.startswith("UNDER-LOCK host-A -> A "):
                raise StepFailure("B's call under its new lock: " + line.text)
            A.expect(r"^ACTUATED by B ", STEP_S)
            release(B)
            return ("B's calls under its old lock refused where the services live (%s), never run;"
                    " B sees A's lock as the only holder; after A released, B locked again (tokens %s)"
                    " and its call ran" % ("; ".join(refusals), tokens))

        def shutdown():
            self.shut_down_in_turn()
            return "A, B and C quit in turn, each seen leaving by the others; all exited with status 0"

        def nothing_else():
            extra = ["%s-%d: %s" % (n.host, i, l.text) for n in (A, B, C)
                     for i, l in n.unconsumed(r"^(JOINED|LEFT|UNKNOWN|CALL|SERVING|ACTUATED|LOCK|UNDER|RELEASE)")]
            if extra:
                raise StepFailure("unexpected events: " + "; ".join(extra))
            return "no event but the expected ones"

        self.step("topology: two subnets, C on both, no IP route between A and B", self.build_topology)
        self.step("discovery by multicast within each subnet", discovery)
        self.step("calls A->B and B->A through C", calls_both_ways)
        for r in range(1, ROUNDS + 1):
            if r == ROUNDS:
                self.step("lock: B locks services of A and C, calls under it; A is refused", lock_held)
            self.step("cut %d: C-B down with a call A->B in flight: it fails typed, left where due" % r, cut)
            if r == ROUNDS:
                self.step("lock: B's leases end on the far side; A gets the lock, the only holder",
                          lock_moved)
            self.step("heal %d: C-B up: services back, calls work, nothing duplicated" % r, heal)
            if r == ROUNDS:
                self.step("lock: B's calls under its old lock are refused by fencing, never run",
                          stale_fenced)
        self.step("clean shutdown", shutdown)
        self.step("no spurious joined/left events or answers", nothing_else)


def line_reason(line):
    m = re.search(r"TRADEServiceUnavailableException: (.*?) t=\d+$", line.text)
    return m.group(1) if m else line.text


if __name__ == "__main__":
    sys.exit(main(PartitionScenario, "partition"))
