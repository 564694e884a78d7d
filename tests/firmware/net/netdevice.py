"""icacam-fw on the file HAL with its network side, for the firmware/net tests.

A device in a temporary folder (frames from tests/data/sample, looped), its serial pty, and
a mosquitto broker on a free loopback port. ICACAM_EMULATOR (e.g. "qemu-aarch64 -L ...")
prefixes the device program.
"""
import json, os, pwd, select, shutil, signal, socket, subprocess, sys, tempfile, time

SKIP = 77
EMULATOR = os.environ.get("ICACAM_EMULATOR", "").split()
HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.abspath(os.path.join(HERE, "..", "..", ".."))


def fail(msg):
    print("FAIL:", msg, flush=True)
    Procs.kill_all()
    sys.exit(1)


def skip(msg):
    print("SKIP:", msg, flush=True)
    sys.exit(SKIP)


class Procs:
    live = []

    @classmethod
    def start(cls, argv, **kw):
        p = subprocess.Popen(argv, **kw)
        cls.live.append(p)
        return p

    @classmethod
    def kill_all(cls):
        for p in cls.live:
            if p.poll() is None:
                p.kill()
                p.wait()


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


class Broker:
    """Debian's mosquitto on a loopback port, its store in folder (kept across restarts)."""

    def __init__(self, folder):
        if not shutil.which("mosquitto"):
            skip("mosquitto is not installed (Debian package mosquitto, .ci/packages-firmware.txt)")
        self.port = free_port()
        self.folder = folder
        self.conf = os.path.join(folder, "broker.conf")
        # Started as root, mosquitto drops to the user "mosquitto", which cannot write the
        # store in a private temporary folder: the sessions would then be lost at a restart.
        with open(self.conf, "w") as f:
            f.write("listener %d 127.0.0.1\nallow_anonymous true\npersistence true\n"
                    "persistence_location %s/\nuser %s\n" % (self.port, folder, pwd.getpwuid(os.geteuid()).pw_name))
        self.proc = None

    def start(self):
        log = open(os.path.join(self.folder, "broker.log"), "a")
        self.proc = Procs.start(["mosquitto", "-c", self.conf], stdout=log, stderr=log)
        end = time.time() + 10
        while time.time() < end:
            try:
                socket.create_connection(("127.0.0.1", self.port), 0.2).close()
                return
            except OSError:
                time.sleep(0.05)
        fail("mosquitto did not start on port %d" % self.port)

    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        self.proc.wait(10)
        with open(os.path.join(self.folder, "broker.log"), errors="replace") as f:
            if "Error saving" in f.read():
                fail("the broker could not save its sessions (broker.log)")


class Subscriber:
    """mosquitto_sub with a persistent session (QoS 1): what the broker queued for it while it
    was away is delivered when it is back."""

    def __init__(self, broker, topic, folder):
        if not shutil.which("mosquitto_sub"):
            skip("mosquitto_sub is not installed (Debian package mosquitto-clients)")
        self.broker, self.topic = broker, topic
        self.path = os.path.join(folder, "sub.log")
        self.proc = None

    def start(self):
        self.out = open(self.path, "ab")
        self.proc = Procs.start(["mosquitto_sub", "-p", str(self.broker.port), "-q", "1", "-c", "-i",
                                 "icacam-test-sub", "-t", self.topic + "/#", "-v"], stdout=self.out,
                                stderr=subprocess.STDOUT)

    def stop(self):
        self.proc.terminate()
        self.proc.wait(10)

    def messages(self):
        out = []
        with open(self.path, "rb") as f:
            for raw in f.read().decode(errors="replace").splitlines():
                topic, _, payload = raw.partition(" ")
                out.append((topic, payload))
        return out

    def result_ids(self):
        ids = []
        for topic, payload in self.messages():
            if topic.endswith("/result"):
                try:
                    ids.append(json.loads(payload)["id"])
                except ValueError:
                    fail("a result payload is not JSON: %r" % payload[:200])
        return ids


class Serial:
    def __init__(self, path, timeout=20.0):
        end = time.time() + timeout
        while True:
            try:
                self.fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
                break
            except OSError:
                if time.time() > end:
                    fail("serial link %s never appeared" % path)
                time.sleep(0.05)
        self.buf = b""

    def send(self, text):
        os.write(self.fd, text.encode())

    def line(self, timeout=30.0):
        end = time.time() + timeout
        while b"\n" not in self.buf:
            left = end - time.time()
            if left <= 0:
                return None
            r, _, _ = select.select([self.fd], [], [], min(left, 0.2))
            if r:
                try:
                    chunk = os.read(self.fd, 65536)
                except OSError:
                    return None
                if not chunk:
                    return None
                self.buf += chunk
        line, self.buf = self.buf.split(b"\n", 1)
        return json.loads(line.decode())

    def until(self, pred, timeout=30.0):
        end = time.time() + timeout
        while time.time() < end:
            msg = self.line(end - time.time())
            if msg is None:
                break
            if pred(msg):
                return msg
        return None

    def close(self):
        os.close(self.fd)


class Device:
    """icacam-fw with the example config's file HAL in folder, plus the extra config lines."""

    def __init__(self, fw, folder, extra=""):
        self.fw, self.folder = fw, folder
        self.run = os.path.join(folder, "run")
        os.makedirs(self.run, exist_ok=True)
        fifo = os.path.join(self.run, "trigger.fifo")
        if not os.path.exists(fifo):
            os.mkfifo(fifo)
        with open(os.path.join(SOURCE, "firmware", "examples", "device.conf")) as f:
            conf = f.read().replace("/tmp/icacam-fw", self.run)
        conf = conf.replace("../../tests/data", os.path.join(SOURCE, "tests", "data"))
        conf += "\n[camera]\nloop = 1\n" + extra
        self.conf = os.path.join(folder, "device.conf")
        with open(self.conf, "w") as f:
            f.write(conf)
        self.journal = os.path.join(self.run, "journal")
        self.proc = None
        self.serial = None

    def start(self):
        log = open(os.path.join(self.folder, "fw.log"), "ab")
        tty = os.path.join(self.run, "tty")
        if os.path.lexists(tty):
            os.remove(tty)
        self.proc = Procs.start(EMULATOR + [self.fw, "--config", self.conf], stdout=log, stderr=log)
        self.serial = Serial(tty)
        hello = self.serial.until(lambda m: m.get("type") == "hello", 60)
        if not hello:
            fail("no hello from the device (log: %s)" % self.log())
        return hello

    def trigger(self, tag):
        """Asks for a measurement over serial; the result line and the seconds it took."""
        t0 = time.time()
        self.serial.send('{"cmd":"trigger","id":"%s"}\n' % tag)
        r = self.serial.until(lambda m: m.get("tag") == tag and m.get("type") in ("result", "error"), 60)
        if not r or r.get("type") != "result":
            fail("no result for trigger %s: %r" % (tag, r))
        return r, time.time() - t0

    def kill(self, sig=signal.SIGTERM):
        self.proc.send_signal(sig)
        self.proc.wait(30)
        if self.serial:
            self.serial.close()
            self.serial = None

    def log(self):
        with open(os.path.join(self.folder, "fw.log"), errors="replace") as f:
            return f.read()[-2000:]


def workdir(name):
    return tempfile.mkdtemp(prefix="icacam-%s-" % name)
