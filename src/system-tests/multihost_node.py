"""Multi-host system test, the container processes: one HostNode JVM per host, started in its
host's network namespace, fed commands on its standard input, its standard output read line by
line so that a step can wait for the line it expects (Node.expect) and, at the end, list the
lines no step expected (Node.unconsumed). Used by multihost_scenario.py; see docs/system-tests.md.
"""

import os
import re
import signal
import subprocess
import threading
import time

from multihost_net import StepFailure, java_binary

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
# Links coming and going are DEBUG lines; the .log files keep them for the steps that read them.
LOGGING = os.path.join(ROOT, "config", "logging.properties")
CLASSPATH = os.pathsep.join([os.path.join(ROOT, "trade-core", "target", "classes"),
                             os.path.join(ROOT, "trade-examples", "target", "classes")])
MAIN_CLASS = "dev.trade.examples.system.HostNode"

# Every node runs with these failure detection settings, set explicitly because the scenario's
# bounds depend on them: a silent peer is declared gone after FAILURETIMEOUT (default 3000 ms),
# checked every HEARTBEATINTERVAL (default 1000 ms).
FAILURE_TIMEOUT_MS = 3000
HEARTBEAT_MS = 1000
STARTUP_S = 20          # JVM start, discovery, links, tables: normally about 1 s

# Every node's access file (PRINCIPALSFILE, docs/security.md): an administrator and an operator, who
# may not use the middleware services (the reserved group needs the role admin). The secrets are
# the test's own. Every node may have a Lamp started in it by class name (PROVIDERCLASSES).
ADMIN = "ops:ops-secret-multihost"
OPERATOR = "guest:guest-secret-multihost"
PRINCIPALS = "principal ops admin ops-secret-multihost\nprincipal guest operator guest-secret-multihost\n"
LAMP = "dev.trade.examples.system.HostNode$Lamp"


# A node is killed when this test dies, even by SIGKILL (a node also exits at the end of its input,
# but a node stopped by SIGSTOP reads nothing): setpriv sets the parent-death signal and execs the
# rest, which keeps it. Not a preexec_fn: code between fork and exec is unsafe in a process with
# threads, as this one has (a reader per node).
DIE_WITH_PARENT = ["setpriv", "--pdeathsig", "KILL", "--"]


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
        self.listening = None

    def start(self, settings):
        """Starts a new incarnation with these TRADE settings (KEY=VALUE strings); see wait_ready."""
        if self.proc is not None:
            self.past.append((self.incarnation, self.lines, self.quit_at))
        self.incarnation += 1
        self.lines = []
        self.eof = False
        self.quit_at = None
        self.id = None
        principals = os.path.join(self.log_dir, "principals")
        if not os.path.exists(principals):
            with open(principals, "w") as f:
                f.write(PRINCIPALS)
        cmd = DIE_WITH_PARENT + self.topology.exec_prefix(self.host) + [
            java_binary(), "-XX:TieredStopAtLevel=1", "-cp", CLASSPATH,
            "-Djava.util.logging.config.file=" + LOGGING, MAIN_CLASS,
            self.host,
            "DISCOVERYRANGE=subnet",
            "CREDENTIALS=multihost-secret",
            "FAILURETIMEOUT=%d" % FAILURE_TIMEOUT_MS,
            "HEARTBEATINTERVAL=%d" % HEARTBEAT_MS,
            "PRINCIPALSFILE=" + principals,
            "PROVIDERCLASSES=" + LAMP,
        ] + list(settings)
        self.settings = " ".join(settings) or "(defaults)"
        base = os.path.join(self.log_dir, "%s-%d" % (self.host, self.incarnation))
        self.err_path = base + ".log"
        self.out_path = base + ".out"
        err = open(self.err_path, "w")
        self.started = time.time()
        self.proc = subprocess.Popen(cmd, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=err,
                                     text=True, bufsize=1, start_new_session=True)
        err.close()
        proc, lines, out_path = self.proc, self.lines, self.out_path
        threading.Thread(target=self._read, args=(proc, lines, out_path), daemon=True).start()

    def wait_ready(self):
        ready = self.expect(r"^READY ", STARTUP_S)
        m = re.search(r" id=(\S+) pid=(\d+) listening=\[([^\]]*)\]", ready.text)
        self.id = m.group(1)
        self.listening = m.group(3).split(", ")
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
        context = "; its last lines: %s; log: %s" % (recent, self.err_path)
        if self.proc.poll() is not None:
            # It exited: why is in its log (an exception, or a JVM or nsenter that did not start),
            # and CI shows only what the test prints.
            context += "; the log ends: %s" % self._log_tail()
        return context

    def _log_tail(self, count=8):
        """The log's last lines but stack frames: an exception's message and its causes."""
        try:
            with open(self.err_path, errors="replace") as f:
                lines = [l.rstrip("\n") for l in f if not re.match(r"\s+(at |\.\.\. )", l)]
            return lines[-count:]
        except OSError as e:
            return ["(cannot read it: %s)" % e]

    def log_contains(self, text, timeout):
        """Waits until this process's TRADE log (standard error) holds text; returns that line."""
        deadline = time.time() + timeout
        while True:
            with open(self.err_path, errors="replace") as f:
                for l in f:
                    if text in l:
                        return l.rstrip("\n")
            if time.time() > deadline:
                raise StepFailure("%s's log did not show '%s' within %.1f s; log: %s" % (
                    self.host, text, timeout, self.err_path))
            time.sleep(0.1)

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

