#!/usr/bin/env python3
"""Results to a real MQTT broker (Debian's mosquitto on a loopback port), none lost.

The device publishes every result; the broker is stopped for a burst of presses and
restarted; the subscriber (a persistent QoS 1 session), back only once the device has
delivered its backlog, then has every result, each id once after de-duplication; the device
answered every press meanwhile. The retained state is
"online" while the device is connected and its last will makes it "offline" when it dies;
a restarted device sends nothing acknowledged before. Exit 77 without mosquitto.
usage: mqtt_test.py ICACAM_FW
"""
import os, signal, statistics, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netdevice import Broker, Device, Procs, Subscriber, fail, workdir  # noqa: E402

TOPIC = "lab/icacam-test"


def wait_for(pred, timeout, what):
    end = time.time() + timeout
    while time.time() < end:
        if pred():
            return
        time.sleep(0.1)
    fail("timed out waiting for " + what)


def retained_state(broker):
    out = subprocess.run(["mosquitto_sub", "-p", str(broker.port), "-t", TOPIC + "/state", "-C", "1", "-W", "5"],
                         capture_output=True, text=True)
    return out.stdout.strip()


def main():
    fw = sys.argv[1]
    work = workdir("mqtt")
    broker = Broker(work)
    broker.start()
    sub = Subscriber(broker, TOPIC, work)
    sub.start()
    time.sleep(0.3)  # the subscription is in place before anything is published
    dev = Device(fw, work, "[mqtt]\nhost = 127.0.0.1\nport = %d\ntopic = %s\nkeepalive_s = 5\n" % (broker.port, TOPIC))
    dev.start()

    up = [dev.trigger("up-%d" % i)[1] for i in range(3)]
    wait_for(lambda: len(set(sub.result_ids())) == 3, 20, "the first 3 results at the subscriber")
    wait_for(lambda: retained_state(broker) == "online", 10, "the retained state 'online'")
    # The payload is the journal's line: the record with its CRC seal.
    with open(os.path.join(dev.journal, "journal.jsonl")) as f:
        first = f.readline().rstrip("\n")
    if first not in [p for _, p in sub.messages()]:
        fail("the published payload is not the journal's line")

    broker.stop()
    sub.stop()
    down = []
    for i in range(5):
        down.append(dev.trigger("down-%d" % i)[1])
    broker.start()
    # The consumer comes back only after the device has delivered its backlog: what it gets
    # was queued for its persistent session by the broker, whatever order they reconnect in.
    wait_for(lambda: open(os.path.join(dev.journal, "mqtt.acked")).read().strip() == "8", 60,
             "mqtt.acked to reach 8")
    sub.start()
    expected = list(range(1, 9))
    wait_for(lambda: sorted(set(sub.result_ids())) == expected, 60,
             "results 1-8 after the broker came back (have %s)" % sorted(set(sub.result_ids())))
    ids = sub.result_ids()
    dupes = len(ids) - len(set(ids))
    # Every press was answered while the broker was away (trigger() fails otherwise); the
    # times are reported, not judged: they depend on the machine's load.
    print("mqtt: %d results, %d sent twice; median trigger-to-result with the broker away %.2f s, "
          "connected %.2f s" % (len(set(ids)), dupes, statistics.median(down), statistics.median(up)))

    # Killed: the broker's last will says offline (within 1.5 keepalives).
    dev.kill(signal.SIGKILL)
    wait_for(lambda: retained_state(broker) == "offline", 20, "the last will's 'offline'")
    before = len(sub.result_ids())
    dev.start()
    wait_for(lambda: retained_state(broker) == "online", 20, "'online' after the restart")
    dev.trigger("after-restart")
    wait_for(lambda: 9 in sub.result_ids(), 20, "result 9 after the restart")
    again = [i for i in sub.result_ids()[before:] if i != 9]
    if again:
        fail("acknowledged results sent again after a restart: %s" % again)
    dev.kill()
    Procs.kill_all()
    print("mqtt: ok")


if __name__ == "__main__":
    main()
