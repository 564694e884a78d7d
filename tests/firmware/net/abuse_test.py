#!/usr/bin/env python3
"""Hostile requests against the device's web server, while it measures over serial.

Malformed JSON, wrong content types, a 10 MB body (declared, and chunked), ../ paths
(plain and percent-encoded), a wrong password and a guess right after it, a slowloris
client holding connections open, and a flood of requests from the loopback: each gets a
4xx or is dropped, a client from another address is still served, and the device keeps
measuring and answering serial throughout.
usage: abuse_test.py ICACAM_FW
"""
import http.client, json, os, socket, statistics, subprocess, sys, threading, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netdevice import Device, Procs, fail, free_port, workdir, EMULATOR  # noqa: E402

PASSWORD = "another secret"


def request(port, method, path, body=None, headers=None, source="127.0.0.1"):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=20, source_address=(source, 0))
    c.request(method, path, body=body, headers=headers or {})
    r = c.getresponse()
    data = r.read()
    c.close()
    return r.status, data


def raw(port, data, source="127.0.0.1", read=True):
    s = socket.create_connection(("127.0.0.1", port), timeout=20, source_address=(source, 0))
    s.sendall(data)
    if not read:
        return s
    out = b""
    try:
        while True:
            chunk = s.recv(65536)
            if not chunk:
                break
            out += chunk
    except (ConnectionResetError, socket.timeout):
        pass
    s.close()
    return out


def expect_4xx(what, status):
    if not 400 <= status < 500:
        fail("%s: expected a 4xx, got %d" % (what, status))


def main():
    fw = sys.argv[1]
    work = workdir("abuse")
    pw = os.path.join(work, "web-password")
    out = subprocess.run(EMULATOR + [fw, "--hash-password"], input=PASSWORD + "\n", capture_output=True, text=True)
    with open(pw, "w") as f:
        f.write(out.stdout)
    port = free_port()
    dev = Device(fw, work, "[http]\nport = %d\npassword_file = %s\n" % (port, pw))
    dev.start()
    quiet = [dev.trigger("quiet-%d" % i)[1] for i in range(3)]
    json_h = {"Content-Type": "application/json"}

    # Log in for the requests that need it.
    status, _ = request(port, "POST", "/api/login", '{"password":"nope"}', json_h)
    expect_4xx("a wrong password", status)
    status, body = request(port, "POST", "/api/login", json.dumps({"password": PASSWORD}), json_h)
    if status != 429:
        fail("a guess right after a wrong password was not held off (%d %r)" % (status, body))
    time.sleep(1.1)
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=20)
    c.request("POST", "/api/login", json.dumps({"password": PASSWORD}), json_h)
    r = c.getresponse()
    r.read()
    cookie = (r.getheader("Set-Cookie") or "").split(";")[0]
    if r.status != 200 or not cookie.startswith("icacam_session="):
        fail("the right password did not log in (%d)" % r.status)
    auth = dict(json_h, Cookie=cookie)

    cases = [
        ("malformed login JSON", "POST", "/api/login", '{"password": ', json_h),
        ("login as a form", "POST", "/api/login", "password=x", {"Content-Type": "application/x-www-form-urlencoded"}),
        ("malformed command JSON", "POST", "/api/command", '{"cmd":"trigger"', auth),
        ("nested JSON", "POST", "/api/command", '{"cmd":{"a":1}}', auth),
        ("an unknown command", "POST", "/api/command", '{"cmd":"format_disk"}', auth),
        ("a command as a form", "POST", "/api/command", "cmd=trigger", dict(auth, **{"Content-Type": "text/plain"})),
        ("trigger without a login", "POST", "/api/command", '{"cmd":"trigger"}', json_h),
        ("results without a login", "GET", "/api/results", None, {}),
        ("a bad id", "GET", "/api/result?id=1e9999", None, auth),
        ("a negative step", "GET", "/api/image?id=1&step=-3", None, auth),
        ("a missing record", "GET", "/api/result?id=999999", None, auth),
        ("an unknown page", "GET", "/etc/passwd", None, auth),
        ("PUT", "PUT", "/api/command", "{}", auth),
    ]
    for what, method, path, body, headers in cases:
        expect_4xx(what, request(port, method, path, body, headers)[0])

    for path in (b"/../../etc/passwd", b"/api/../../etc/passwd", b"/%2e%2e/%2e%2e/etc/passwd", b"/api/image/..%2f..%2fx"):
        reply = raw(port, b"GET " + path + b" HTTP/1.1\r\nHost: x\r\nCookie: " + cookie.encode() + b"\r\n\r\n")
        code = int(reply.split(b" ", 2)[1]) if reply.startswith(b"HTTP/1.") else 0
        if code and not 400 <= code < 500:
            fail("%s answered %d" % (path, code))

    # 10 MB: refused on its declared length before it is read, and when it comes chunked.
    ten = 10 * 1024 * 1024
    s = raw(port, b"POST /api/command HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\nContent-Length: %d\r\n\r\n" % ten,
            read=False)
    head = s.recv(4096)
    s.close()
    if b" 413 " not in head.split(b"\r\n")[0]:
        fail("a declared 10 MB body was not refused with 413: %r" % head[:100])
    s = raw(port, b"POST /api/command HTTP/1.1\r\nHost: x\r\nContent-Type: application/json\r\n"
            b"Transfer-Encoding: chunked\r\n\r\n", read=False)
    chunk = b"%x\r\n%s\r\n" % (65536, b"x" * 65536)
    reply = b""
    try:
        for _ in range(ten // 65536):
            s.sendall(chunk)
    except (BrokenPipeError, ConnectionResetError):
        pass
    try:
        reply = s.recv(4096)
    except (ConnectionResetError, socket.timeout):
        pass
    s.close()
    if reply and b" 413 " not in reply.split(b"\r\n")[0]:
        fail("a chunked 10 MB body was not refused: %r" % reply[:100])
    print("abuse: 10 MB bodies refused (declared: 413; chunked: %s)" % ("413" if reply else "dropped"))

    # Slowloris: 30 connections from 127.0.0.1 trickling a header; the per-address limit
    # refuses most, the rest hold only their own slots; 127.0.0.2 is served meanwhile, and
    # the device measures.
    slow = []
    for _ in range(30):
        try:
            slow.append(raw(port, b"GET / HTTP/1.1\r\nHost: x\r\n", read=False))
        except OSError:
            pass
    during = []
    for i in range(3):
        for s in slow:
            try:
                s.sendall(b"X-a: b\r\n")
            except OSError:
                pass
        during.append(dev.trigger("slowloris-%d" % i)[1])
        status, _ = request(port, "GET", "/api/session", source="127.0.0.2")
        if status != 200:
            fail("another address was not served while a slowloris client held connections (%d)" % status)
    held = 0
    for s in slow:
        try:
            s.setblocking(False)
            held += 1 if s.recv(1) is None else 0
        except BlockingIOError:
            held += 1  # still open, nothing said
        except OSError:
            pass
    print("abuse: slowloris held %d of 30 connections" % held)
    if held > 16:
        fail("one address held %d connections (the limit is 16)" % held)
    # Gone silent, they are closed by the server's idle time-out.
    end = time.time() + 40
    for s in slow:
        s.setblocking(True)
        s.settimeout(max(0.1, end - time.time()))
        try:
            while s.recv(4096):
                pass
        except socket.timeout:
            fail("a silent slowloris connection was still open after 40 s")
        except OSError:
            pass
        s.close()

    # A flood: as many requests as 8 threads can send for 3 s; most refused with 429.
    counts = {}
    lock = threading.Lock()
    stop = time.time() + 3

    def flood():
        c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
        while time.time() < stop:
            try:
                c.request("GET", "/api/session")
                r = c.getresponse()
                r.read()
                code = r.status
            except (OSError, http.client.HTTPException):
                code = 0
                c.close()
                c = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            with lock:
                counts[code] = counts.get(code, 0) + 1

    threads = [threading.Thread(target=flood) for _ in range(8)]
    for t in threads:
        t.start()
    flooded = [dev.trigger("flood-%d" % i)[1] for i in range(3)]
    for t in threads:
        t.join()
    total = sum(counts.values())
    print("abuse: flood of %d requests in 3 s (%.0f/s): %s" % (total, total / 3, counts))
    if counts.get(200, 0) > 50 * 3 + 100 + 10:
        fail("the rate limit let %d requests through in 3 s" % counts.get(200, 0))
    if counts.get(429, 0) == 0:
        fail("a flood was never refused with 429")

    dev.serial.send('{"cmd":"status","id":"alive"}\n')
    if not dev.serial.until(lambda m: m.get("tag") == "alive" and m.get("type") == "status", 30):
        fail("the device stopped answering serial")
    status, _ = request(port, "GET", "/api/session")
    print("abuse: trigger-to-result during slowloris / quiet %.2f, during the flood / quiet %.2f" %
          (statistics.median(during) / statistics.median(quiet), statistics.median(flooded) / statistics.median(quiet)))
    dev.kill()
    Procs.kill_all()
    print("abuse: ok")


if __name__ == "__main__":
    main()
