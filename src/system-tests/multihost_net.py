"""Multi-host system test, the machine side: whether this machine can run the test, and the three
hosts as network namespaces joined by veth pairs.

    A (10.200.1.1, veth-a) ---- (10.200.1.3, veth-ca) C (10.200.2.3, veth-cb) ---- (10.200.2.2, veth-b) B

unavailable_reason, private_netns_dir and probe_netns tell why the test cannot run here (None when
it can); Topology builds the namespaces, checks that A and B have no IP route to each other, and
removes them. run() runs one command and raises StepFailure when it fails. Used by multihost.py;
see docs/system-tests.md.
"""

import os
import shutil
import subprocess
import sys
import time


class StepFailure(Exception):
    """A step of the scenario failed; the message says what was expected and what happened."""


# Where `ip netns add` keeps its namespaces (a tmpfs of the test's own: see private_netns_dir).
NETNS_DIR = "/var/run/netns"


# ---------------------------------------------------------------------------------------------
# Availability


def unavailable_reason():
    """Why namespaces cannot be used here, or None when they can."""
    if not sys.platform.startswith("linux"):
        return "not Linux"
    if os.geteuid() != 0:
        return "not running as root (network namespaces and veth pairs need root)"
    for tool in ("ip", "tc", "unshare", "nsenter", "setpriv", "mount"):
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
    path = NETNS_DIR
    try:
        os.makedirs(path, exist_ok=True)
    except OSError as e:
        return "cannot create %s: %s" % (path, e)
    r = run(["mount", "-t", "tmpfs", "-o", "size=1m,mode=755", "trade-system-test", path], check=False)
    if r.returncode != 0:
        return "cannot mount a tmpfs on %s: %s" % (path, r.stderr.strip())
    return None


def nsenter(ns):
    """The command prefix that runs a program in network namespace ns, and in nothing else new.
    Not `ip netns exec`: that also makes a mount namespace and mounts a sysfs in it for every
    program, a mount that sandboxed machines may refuse now and then, and that nothing here needs
    (the JDK reads interfaces through ioctl and /proc/net, which follow the network namespace)."""
    return ["nsenter", "--net=" + os.path.join(NETNS_DIR, ns), "--"]


def probe_netns():
    """Creates a namespace with a veth pair and removes it: does `ip netns` work here?"""
    ns = "trade-probe-%d" % os.getpid()
    steps = [["ip", "netns", "add", ns],
             ["ip", "-n", ns, "link", "add", "p0", "type", "veth", "peer", "name", "p1"],
             nsenter(ns) + ["true"]]
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
        run(nsenter(self.ns["C"]) + ["sysctl", "-qw", "net.ipv4.ip_forward=0"])
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
        return nsenter(self.ns[host])

    def check_isolation(self):
        """A and B cannot reach each other at the IP level; C forwards no IP."""
        for host, other in (("A", "B"), ("B", "A")):
            target = self.ADDRESSES[other][0]
            r = run(["ip", "-n", self.ns[host], "route", "get", target], check=False)
            if r.returncode == 0:
                raise StepFailure("%s has a route to %s (%s): %s" % (host, other, target, r.stdout.strip()))
        r = run(nsenter(self.ns["C"]) + ["sysctl", "-n", "net.ipv4.ip_forward"])
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

