#!/usr/bin/env python3
"""What the network costs the measurement: trigger-to-result over serial, and the device's
CPU time a press (less sensitive to a busy machine), with the network off, and with the web
page open in a browser (headless chromium on the Reading page, which
polls as a person's would) and the broker connected; the server's idle CPU and memory.

Figures are ratios and differences between runs on the same machine, printed; nothing is
asserted about the time itself. --check fails when the network adds 5 % or more.
usage: net_bench.py ICACAM_FW [--rounds N] [--check]
"""
import os, statistics, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netdevice import Broker, Device, Procs, Subscriber, fail, free_port, workdir, EMULATOR  # noqa: E402
import browser_test  # noqa: E402  (its Browser)

PASSWORD = "bench"


def cpu_seconds(pid):
    with open("/proc/%d/stat" % pid) as f:
        fields = f.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def idle(dev, seconds):
    c0 = cpu_seconds(dev.proc.pid)
    time.sleep(seconds)
    return (cpu_seconds(dev.proc.pid) - c0) / seconds, rss_kib(dev.proc.pid)


def main():
    fw = sys.argv[1]
    rounds = int(sys.argv[sys.argv.index("--rounds") + 1]) if "--rounds" in sys.argv else 2
    presses = 8
    if EMULATOR:
        print("bench: under an emulator the figures say little; run natively")
    work = workdir("bench")
    broker = Broker(work)
    broker.start()
    sub = Subscriber(broker, "bench", work)
    sub.start()
    pw = os.path.join(work, "web-password")
    out = subprocess.run(EMULATOR + [fw, "--hash-password"], input=PASSWORD + "\n", capture_output=True, text=True)
    with open(pw, "w") as f:
        f.write(out.stdout)

    plain, networked = [], []
    cpu_plain, cpu_net = [], []  # the device's CPU seconds a press (all its threads)
    idle_plain = idle_net = None
    for r in range(rounds):
        d = Device(fw, os.path.join(work, "plain-%d" % r))
        d.start()
        d.trigger("warm")
        c0 = cpu_seconds(d.proc.pid)
        plain += [d.trigger("p%d" % i)[1] for i in range(presses)]
        cpu_plain.append((cpu_seconds(d.proc.pid) - c0) / presses)
        if idle_plain is None:
            idle_plain = idle(d, 10)
        d.kill()

        port = free_port()
        d = Device(fw, os.path.join(work, "net-%d" % r),
                   "[http]\nport = %d\npassword_file = %s\n[mqtt]\nhost = 127.0.0.1\nport = %d\ntopic = bench\n"
                   % (port, pw, broker.port))
        d.start()
        d.trigger("warm")
        if idle_net is None:
            idle_net = idle(d, 10)  # the server, the broker's client, nothing asked of them
        browser = browser_test.Browser(os.path.join(work, "net-%d" % r))
        browser.call("Page.navigate", url="http://127.0.0.1:%d/" % port)
        browser.wait("!!document.getElementById('password')", 30, "the page")
        browser.js("document.getElementById('password').value = %r; document.getElementById('login-button').click()"
                   % PASSWORD)
        browser.wait("!document.getElementById('trigger').disabled", 30, "the Reading page")
        c0 = cpu_seconds(d.proc.pid)
        networked += [d.trigger("n%d" % i)[1] for i in range(presses)]
        cpu_net.append((cpu_seconds(d.proc.pid) - c0) / presses)
        browser.close()
        d.kill()
    got = len(set(sub.result_ids()))
    Procs.kill_all()
    ratio = statistics.median(networked) / statistics.median(plain)
    print("bench: trigger-to-result, page open and broker connected / network off: %.3f (median of %d each)"
          % (ratio, len(plain)))
    print("bench: icacam-fw's CPU time a press, page open and broker connected / network off: %.3f"
          " (%.1f ms / %.1f ms)" % (statistics.mean(cpu_net) / statistics.mean(cpu_plain),
                                     1000 * statistics.mean(cpu_net), 1000 * statistics.mean(cpu_plain)))
    print("bench: idle CPU of icacam-fw: network off %.2f %%, web server and MQTT client on %.2f %%"
          % (100 * idle_plain[0], 100 * idle_net[0]))
    print("bench: resident memory: network off %d KiB, on %d KiB (+%d KiB)"
          % (idle_plain[1], idle_net[1], idle_net[1] - idle_plain[1]))
    print("bench: the subscriber received %d results" % got)
    if "--check" in sys.argv and ratio >= 1.05:
        fail("the network added %.1f %% to trigger-to-result" % (100 * (ratio - 1)))


if __name__ == "__main__":
    main()
