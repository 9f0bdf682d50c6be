#!/usr/bin/env python3
"""Multi-host system test: three hosts as network namespaces, two subnets, one host on both.

    A (10.200.1.1, veth-a) ---- (10.200.1.3, veth-ca) C (10.200.2.3, veth-cb) ---- (10.200.2.2, veth-b) B

A and B have no route to each other. Each host runs one container JVM
(dev.trade.examples.system.HostNode) with DISCOVERYRANGE=subnet on its own interfaces. The test
checks that the containers find each other by multicast within each subnet, that A and B call each
other through C's forwarding, that killing C makes the services of the other side leave on A and on
B within the detection bound, that a new C brings them back, that a slow link which keeps carrying
bytes is not taken for dead, and that a silent (frozen) C is declared gone after FAILURETIMEOUT and
rejoins when it wakes up. See docs/system-tests.md.

Needs root, `ip netns` and `tc` (iproute2), and `unshare`, `nsenter` and `setpriv` (util-linux).
Where they are unavailable the test is skipped with the reason, unless CI=true, where that is a
failure.
Every packet stays inside the namespaces this test creates; nothing runs with subnet range outside
them. The test runs in a private mount namespace of its own, so the namespaces' mounts never reach
the rest of the machine and disappear with the test even if it is killed.

The test is split into sibling modules, imported from this script's directory: multihost_net
(availability, the namespaces and veth pairs), multihost_node (the container JVMs) and
multihost_scenario (the steps). This file is the entry point: it checks that the test can run,
runs it again in a private mount namespace, and prints the summary.

Output: one PASS/FAIL line per step, then "N passed, N failed" alone on the last line.
Exit status 0 when every step passed (or the test was skipped outside CI), 1 otherwise.
"""

import os
import shutil
import signal
import subprocess
import sys
import time

from multihost_net import private_netns_dir, probe_netns, unavailable_reason
from multihost_node import CLASSPATH, ROOT
from multihost_scenario import Scenario

IN_PRIVATE_MOUNTS = "TRADE_SYSTEM_TEST_PRIVATE_MOUNTS"

CI = os.environ.get("CI", "").lower() == "true"


def summary(passed, failed):
    print("%d passed, %d failed" % (passed, failed), flush=True)


def main(scenario_class=Scenario, name="multi-host"):
    """Runs scenario_class's steps on hosts A, B and C (also the entry point of partition.py)."""
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
                                  sys.executable, os.path.abspath(sys.argv[0])] + sys.argv[1:], env=env)
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

    log_dir = os.path.join(ROOT, "target", "system-tests", "%s-%d-%d" % (name.replace("-", ""), int(time.time()), os.getpid()))
    os.makedirs(log_dir)
    print("%s system test: hosts A, B, C in network namespaces trade-%d-{A,B,C}; logs in %s"
          % (name, os.getpid(), log_dir), flush=True)

    def terminate(signum, frame):
        # Once: a second signal must not interrupt the cleanup.
        for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
            signal.signal(sig, signal.SIG_IGN)
        raise KeyboardInterrupt("signal %d" % signum)
    for sig in (signal.SIGINT, signal.SIGTERM, signal.SIGHUP):
        signal.signal(sig, terminate)

    scenario = scenario_class(log_dir)
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
    print("%s system test took %.1f s" % (name, time.time() - t0), flush=True)
    if failed == 0 and os.environ.get("TRADE_SYSTEM_TEST_KEEP_LOGS") != "1":
        shutil.rmtree(log_dir, ignore_errors=True)
    else:
        print("logs of every container kept in %s (<host>-<n>.out: its events, <host>-<n>.log: its"
              " TRADE log)" % log_dir, flush=True)
    summary(passed, failed)
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
