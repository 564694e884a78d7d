#!/usr/bin/env python3
"""A real browser drives the device's web page: Debian's chromium, headless, through its
DevTools protocol (python3-websocket), against icacam-fw on the file HAL.

It opens the page (the login form shows), logs in with the device's password, presses
Measure, and sees the new reading: the μ shown is the journal's, the frame shows (decoded,
not blank) with the fitted boundaries drawn over it; Aim shows the live picture with the
found end face and a focus score, its exposure changed live and saved to the recipe with a
reason; History lists the reading; the Recipe tab saves a new version, lists the versions and
shows the audit trail intact, and the next reading names that version; one byte of the trail
changed on the card, the tab says DAMAGED and `icacam-fw --check-audit` exits 1. Screenshots of
each step go to ARTEFACT_DIR. A wrong password is refused on the page. Exit 77 without
chromium or python3-websocket.
usage: browser_test.py ICACAM_FW ARTEFACT_DIR
"""
import base64, json, os, shutil, subprocess, sys, time, urllib.request

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from netdevice import Device, Procs, fail, free_port, skip, workdir, EMULATOR  # noqa: E402

try:
    import websocket
except ImportError:
    sys.path.append("/usr/lib/python3/dist-packages")  # Debian's python3-websocket beside another Python
    try:
        import websocket
    except ImportError:
        skip("python3-websocket is not installed (Debian package python3-websocket)")

PASSWORD = "correct horse battery"


class Browser:
    def __init__(self, folder):
        exe = shutil.which("chromium") or shutil.which("chromium-browser")
        if not exe:
            skip("chromium is not installed (Debian package chromium)")
        port = free_port()
        log = open(os.path.join(folder, "chromium.log"), "ab")
        self.proc = Procs.start([exe, "--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
                                 "--remote-debugging-port=%d" % port, "--remote-allow-origins=*",
                                 "--user-data-dir=" + os.path.join(folder, "profile"), "--window-size=1200,1400",
                                 "about:blank"], stdout=log, stderr=log)
        end = time.time() + 60
        ws_url = None
        while time.time() < end and not ws_url:
            try:
                with urllib.request.urlopen("http://127.0.0.1:%d/json/list" % port, timeout=2) as r:
                    pages = [t for t in json.load(r) if t.get("type") == "page"]
                    ws_url = pages[0]["webSocketDebuggerUrl"] if pages else None
            except OSError:
                time.sleep(0.2)
        if not ws_url:
            fail("chromium's DevTools endpoint did not come up")
        self.ws = websocket.create_connection(ws_url, timeout=60, suppress_origin=True)
        self.next_id = 0

    def call(self, method, **params):
        self.next_id += 1
        self.ws.send(json.dumps({"id": self.next_id, "method": method, "params": params}))
        while True:
            msg = json.loads(self.ws.recv())
            if msg.get("id") == self.next_id:
                if "error" in msg:
                    fail("%s: %s" % (method, msg["error"]))
                return msg.get("result", {})

    def js(self, expression):
        r = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in r:
            fail("page script failed: %s" % r["exceptionDetails"])
        return r.get("result", {}).get("value")

    def wait(self, expression, timeout, what):
        end = time.time() + timeout
        guarded = "(() => { try { return !!(%s); } catch (e) { return false; } })()" % expression
        while time.time() < end:
            if self.js(guarded):  # a page still loading is not there yet
                return
            time.sleep(0.2)
        fail("the page never showed " + what + " (text: %r)" % self.js("document.body.innerText")[:600])

    def screenshot(self, path):
        data = self.call("Page.captureScreenshot", format="png")["data"]
        with open(path, "wb") as f:
            f.write(base64.b64decode(data))

    def close(self):
        self.ws.close()
        self.proc.terminate()
        self.proc.wait(20)


def main():
    fw, artefacts = sys.argv[1], sys.argv[2]
    os.makedirs(artefacts, exist_ok=True)
    work = workdir("browser")
    pw = os.path.join(work, "web-password")
    with open(pw, "w") as f:
        out = subprocess.run(EMULATOR + [fw, "--hash-password"], input=PASSWORD + "\n", capture_output=True, text=True)
        if out.returncode != 0 or not out.stdout.startswith("$argon2id$"):
            fail("icacam-fw --hash-password: %r %r" % (out.stdout, out.stderr))
        f.write(out.stdout)
    port = free_port()
    dev = Device(fw, work, "[http]\nport = %d\npassword_file = %s\n" % (port, pw))
    dev.start()
    browser = Browser(work)
    browser.call("Page.enable")
    browser.call("Page.navigate", url="http://127.0.0.1:%d/" % port)
    visible = "(id) => getComputedStyle(document.getElementById(id)).display !== 'none'"
    browser.wait("(%s)('login')" % visible, 30, "the login form")
    browser.screenshot(os.path.join(artefacts, "1-login.png"))

    # A wrong password: refused, still the login form.
    browser.js("document.getElementById('password').value = 'not it';"
               "document.getElementById('login-button').click()")
    browser.wait("document.getElementById('login-message').textContent.includes('wrong password')", 30,
                 "the wrong password refused")
    time.sleep(1.1)  # a wrong password holds logins off for a second
    browser.js("document.getElementById('user').value = 'alice';"
               "document.getElementById('password').value = %s;"
               "document.getElementById('login-button').click()" % json.dumps(PASSWORD))
    browser.wait("(%s)('reading') && !document.getElementById('trigger').disabled" % visible, 30,
                 "the Reading page with Measure enabled after logging in")

    browser.js("document.getElementById('trigger').click()")
    browser.wait("document.getElementById('last-id').textContent === '#1' && "
                 "document.getElementById('image').dataset.loaded === 'yes'", 60, "result #1 and its frame")
    with open(os.path.join(dev.journal, "journal.jsonl")) as f:
        record = json.loads(f.readline())
    if record.get("trigger") != "web":
        fail("a measurement asked for on the page is journaled as trigger %r, not 'web'" % record.get("trigger"))
    shown = browser.js("document.getElementById('mu').textContent")
    want = "μ = %.4f ± %.4f" % (record["mu"], 2 * record["mu_sigma"])
    if shown != want:
        fail("the page shows %r, the journal has %r" % (shown, want))
    if browser.js("document.getElementById('status').textContent") != record["status"]:
        fail("the page's status is not the record's")
    # The frame shows: decoded, the journal frame's size (every second pixel), not one flat grey.
    spread = browser.js("""(() => {
        const img = document.getElementById('image'), c = document.createElement('canvas');
        c.width = img.naturalWidth; c.height = img.naturalHeight;
        const g = c.getContext('2d'); g.drawImage(img, 0, 0);
        const d = g.getImageData(0, 0, c.width, c.height).data;
        let lo = 255, hi = 0;
        for (let i = 0; i < d.length; i += 4 * 97) { lo = Math.min(lo, d[i]); hi = Math.max(hi, d[i]); }
        return [c.width, c.height, hi - lo, document.querySelectorAll('#overlay circle').length];
    })()""")
    with open(os.path.join(dev.journal, record["image"]), "rb") as f:
        header = f.read(32).split()
    full_w, full_h = int(header[1]), int(header[2])
    if spread[0] != (full_w + 1) // 2 or spread[1] != (full_h + 1) // 2:
        fail("the frame shown is %dx%d, not half of the journal's %dx%d" % (spread[0], spread[1], full_w, full_h))
    if spread[2] < 40:
        fail("the frame shown is nearly flat (grey levels spread %d)" % spread[2])
    if spread[3] != 2:
        fail("the fitted boundaries are not drawn over the frame (%d circles)" % spread[3])
    browser.screenshot(os.path.join(artefacts, "2-reading.png"))

    # Aim: the live picture (four a second) with the found end face and the focus score.
    browser.js("location.hash = '#aim'; document.getElementById('aim-start').click()")
    browser.wait("document.getElementById('aim-image').naturalWidth > 0 && "
                 "document.querySelectorAll('#aim-overlay circle').length === 2 && "
                 "/^[0-9.]+$/.test(document.getElementById('aim-focus').textContent)", 30,
                 "an aim picture with the end face found and a focus score")
    browser.screenshot(os.path.join(artefacts, "3-aim.png"))
    # The exposure live, then saved to the recipe with a reason: version 2, made by alice.
    browser.js("location.hash = '#recipe'")
    browser.wait("document.querySelectorAll('#recipe-keys input').length >= 20", 20, "the recipe form")
    browser.js("location.hash = '#aim'; document.getElementById('live-exposure').value = '7000';"
               "document.getElementById('live-apply').click()")
    browser.wait("document.getElementById('live-message').textContent.includes('camera.exposure_us')", 20,
                 "the live exposure applied")
    browser.js("document.getElementById('live-reason').value = 'darker specimens';"
               "document.getElementById('live-save').click()")
    browser.wait("document.getElementById('live-message').textContent === 'saved: default version 2'", 20,
                 "the live controls saved as version 2")
    browser.js("document.getElementById('aim-stop').click()")
    browser.wait("document.getElementById('aim-left').textContent === 'stopped'", 20, "aiming stopped")

    browser.js("location.hash = '#history'")
    browser.wait("document.querySelectorAll('#table tbody tr').length === 1 && "
                 "document.querySelectorAll('#plot circle').length === 1", 20, "History with result #1")
    browser.screenshot(os.path.join(artefacts, "4-history.png"))

    # The Recipe tab: a new material saved with a reason is version 3; the next reading names it.
    browser.js("location.hash = '#recipe'")
    browser.wait("document.getElementById('recipe-name').textContent === 'default version 2'", 20,
                 "version 2 in effect")
    browser.js("""(() => {
        document.querySelector('#recipe-keys input[name="specimen.material"]').value = 'S355';
        document.getElementById('recipe-reason').value = 'new batch of S355';
        document.getElementById('recipe-save').click();
    })()""")
    browser.wait("document.getElementById('recipe-message').textContent === 'saved: default version 3' && "
                 "document.querySelectorAll('#versions tbody tr').length === 3 && "
                 "document.getElementById('audit-state').textContent === 'intact (3 entries)'", 30,
                 "version 3 saved, three versions, the trail intact")
    who = browser.js("document.querySelector('#audit tbody tr').cells[2].textContent")
    if who != "alice (web)":
        fail("the newest audit entry's who is %r, not the name logged in with" % who)
    browser.screenshot(os.path.join(artefacts, "5-recipe.png"))
    browser.js("location.hash = '#reading'; document.getElementById('trigger').click()")
    browser.wait("document.getElementById('last-id').textContent === '#2'", 60, "result #2")
    with open(os.path.join(dev.journal, "journal.jsonl")) as f:
        second = [json.loads(line) for line in f if line.strip()][-1]
    if (second.get("recipe_version"), second.get("material"), second.get("exposure_us")) != (3, "S355", 7000):
        fail("result #2 has recipe version %r, material %r, exposure %r, not 3, S355, 7000" %
             (second.get("recipe_version"), second.get("material"), second.get("exposure_us")))
    if second["recipe_hash"] not in browser.js("document.getElementById('last-recipe').textContent"):
        fail("the Reading page does not name the record's recipe hash")

    # One byte of the trail changed on the card: the page and the check both say so.
    trail = os.path.join(dev.journal, "audit.jsonl")
    with open(trail, "rb") as f:
        data = bytearray(f.read())
    data[data.index(b"new batch of S355")] = ord("N")
    with open(trail, "wb") as f:
        f.write(data)
    browser.js("location.hash = '#recipe'")  # the tab reads the trail again when opened
    browser.wait("document.getElementById('audit-state').textContent === 'DAMAGED' && "
                 "document.getElementById('audit-problems').textContent.includes('altered')", 20,
                 "the damaged trail reported")
    browser.screenshot(os.path.join(artefacts, "6-audit-damaged.png"))
    check = subprocess.run(EMULATOR + [fw, "--check-audit", dev.journal], capture_output=True, text=True)
    if check.returncode != 1 or "entry 3): altered" not in check.stdout:
        fail("icacam-fw --check-audit on a changed trail: exit %d, %r" % (check.returncode, check.stdout))
    browser.close()
    dev.kill()
    Procs.kill_all()
    print("browser: ok; screenshots in", artefacts)


if __name__ == "__main__":
    main()
