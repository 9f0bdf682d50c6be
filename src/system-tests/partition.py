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

        def shutdown():
            self.shut_down_in_turn()
            return "A, B and C quit in turn, each seen leaving by the others; all exited with status 0"

        def nothing_else():
            extra = ["%s-%d: %s" % (n.host, i, l.text) for n in (A, B, C)
                     for i, l in n.unconsumed(r"^(JOINED|LEFT|UNKNOWN|CALL|SERVING)")]
            if extra:
                raise StepFailure("unexpected events: " + "; ".join(extra))
            return "no event but the expected ones"

        self.step("topology: two subnets, C on both, no IP route between A and B", self.build_topology)
        self.step("discovery by multicast within each subnet", discovery)
        self.step("calls A->B and B->A through C", calls_both_ways)
        for r in range(1, ROUNDS + 1):
            self.step("cut %d: C-B down with a call A->B in flight: it fails typed, left where due" % r, cut)
            self.step("heal %d: C-B up: services back, calls work, nothing duplicated" % r, heal)
        self.step("clean shutdown", shutdown)
        self.step("no spurious joined/left events or answers", nothing_else)


def line_reason(line):
    m = re.search(r"TRADEServiceUnavailableException: (.*?) t=\d+$", line.text)
    return m.group(1) if m else line.text


if __name__ == "__main__":
    sys.exit(main(PartitionScenario, "partition"))
