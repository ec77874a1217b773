#!/usr/bin/env python3
"""Loads HTML pages in headless Chromium and reports what the browser saw, as JSON.

Used by tests/doc/browser_test.cpp, which asserts on the facts. Python 3 standard library only:
Chromium is driven over the DevTools protocol (a WebSocket on 127.0.0.1), no npm, no driver.

    page_facts.py --chromium PATH --profile DIR [--screenshots DIR] PAGE.html...

For each page, at a 1280 px wide viewport:
  - layout: document scroll width against the viewport width, and the widest elements;
  - every svg.bit-layout: its box, its entries (g.entry) and how many lack a label
    (aria-label and <title>);
  - every PDO table row (tr[data-entry]) by key, and per PDO section its rows and picture entries;
  - the numbers: cells marked hex that hold no hex number, enumeration texts shown, DC times
    whose factor is spelled out (and any left as "0 ns × 1"), the title and first heading;
  - console messages and uncaught exceptions, and every request other than the page itself
    (requests are intercepted and failed, so nothing leaves the machine);
  - a screenshot from the first picture with entries (else the top of the page): its size, how
    many colours it has, and whether the pictures' tints appear in it (painted, not only laid out).
"""

import argparse
import base64
import json
import os
import socket
import struct
import subprocess
import sys
import time
import urllib.parse
import zlib

VIEWPORT = (1280, 900)
# Fills the bit-layout pictures use for entries (esi/doc/bit_layout.hpp); one of them must be
# painted in a screenshot of a page whose first viewport shows a picture.
PICTURE_TINTS = {(0xDB, 0xEA, 0xFE), (0xDC, 0xFC, 0xE7), (0xFE, 0xF3, 0xC7), (0xF3, 0xE8, 0xFF), (0xFF, 0xE4, 0xE6),
                 (0xE0, 0xF2, 0xFE), (0xBB, 0xF7, 0xD0), (0xFE, 0xCA, 0xCA), (0xBF, 0xDB, 0xFE), (0xFD, 0xE6, 0x8A)}

FACTS_SCRIPT = r"""
(() => {
  const root = document.documentElement;
  const viewport = root.clientWidth;
  const wide = [];
  // Elements reaching past the viewport, and boxes whose content overflows them (text that does
  // not wrap spills out of its box without widening it).
  for (const el of document.querySelectorAll('body *')) {
    if (wide.length >= 5) break;
    const r = el.getBoundingClientRect();
    const spills = el.scrollWidth > el.clientWidth + 1 && el.clientWidth > 0 && getComputedStyle(el).overflowX === 'visible';
    if (r.right > viewport + 0.5 || spills)
      wide.push(el.tagName.toLowerCase() + (el.id ? '#' + el.id : '') + ' right=' + Math.round(r.right) + ' scroll=' + el.scrollWidth + ' client=' + el.clientWidth);
  }
  const label = g => {
    const t = g.querySelector(':scope > title');
    return (g.getAttribute('aria-label') || '').trim() !== '' && t !== null && t.textContent.trim() !== '';
  };
  const svgs = [...document.querySelectorAll('svg.bit-layout')].map(s => {
    const r = s.getBoundingClientRect();
    const entries = [...s.querySelectorAll('g.entry')];
    const title = s.querySelector(':scope > title');
    return {id: s.id, width: r.width, height: r.height, entries: entries.length,
            unlabelled: entries.filter(g => !label(g)).length,
            title: title ? title.textContent : ''};
  });
  const keys = {};
  for (const tr of document.querySelectorAll('tr[data-entry]')) keys[tr.dataset.entry] = (keys[tr.dataset.entry] || 0) + 1;
  const pdos = [...document.querySelectorAll('section.pdo')].map(s => ({
    id: s.id, rows: s.querySelectorAll('tr[data-entry]').length,
    entries: [...s.querySelectorAll('svg.bit-layout g.entry')].length}));
  const firstSvg = [...document.querySelectorAll('svg.bit-layout')].find(s => s.querySelector('g.entry'));
  // Numbers as an EtherCAT engineer reads them: every cell the page marks as hex (indices,
  // identities, PDO indices, masks) holds a hex number; enumerations show their texts; DC times
  // spell their factors out.
  const hexCells = [...document.querySelectorAll('td.hex')].map(td => td.textContent.trim()).filter(t => t !== '');
  const notHex = hexCells.filter(t => !/^0x[0-9A-F]+(:[0-9A-F]+)?$/.test(t)).slice(0, 5);
  const dcCells = [...document.querySelectorAll('section#dc td')].map(td => td.textContent.trim());
  const h1 = document.querySelector('h1');
  return JSON.stringify({title: document.title, h1: h1 ? h1.textContent.trim() : '',
                         hex_cells: hexCells.length, not_hex: notHex,
                         enum_texts: document.querySelectorAll('small.enum').length,
                         dc_factor_cells: dcCells.filter(t => t.includes(' × ')).length,
                         dc_bare_factors: dcCells.filter(t => / ns × /.test(t)).slice(0, 5),
                         lang: root.lang, scroll_width: root.scrollWidth, client_width: viewport,
                         wide_elements: wide, svgs, entry_keys: keys, pdo_sections: pdos,
                         first_svg_top: firstSvg ? firstSvg.getBoundingClientRect().top + window.scrollY : null,
                         scripts: document.scripts.length});
})()
"""


class WebSocket:
    """A minimal RFC 6455 client: text frames out (masked), text/continuation frames in."""

    def __init__(self, url, timeout):
        parts = urllib.parse.urlparse(url)
        self.sock = socket.create_connection((parts.hostname, parts.port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (f"GET {parts.path} HTTP/1.1\r\nHost: {parts.hostname}:{parts.port}\r\nUpgrade: websocket\r\n"
                   f"Connection: Upgrade\r\nSec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.sock.sendall(request.encode())
        response = b""
        while b"\r\n\r\n" not in response:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise ConnectionError("DevTools closed the connection during the handshake")
            response += chunk
        head, self.buffer = response.split(b"\r\n\r\n", 1)
        if b" 101 " not in head.split(b"\r\n", 1)[0]:
            raise ConnectionError("DevTools refused the WebSocket: " + head.decode(errors="replace"))

    def send(self, text):
        payload = text.encode()
        header = bytes([0x81])
        n = len(payload)
        if n < 126:
            header += bytes([0x80 | n])
        elif n < 1 << 16:
            header += bytes([0x80 | 126]) + struct.pack(">H", n)
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", n)
        mask = os.urandom(4)
        masked = bytes(b ^ mask[i % 4] for i, b in enumerate(payload))
        self.sock.sendall(header + mask + masked)

    def _read(self, n):
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise ConnectionError("DevTools closed the connection")
            self.buffer += chunk
        out, self.buffer = self.buffer[:n], self.buffer[n:]
        return out

    def receive(self):
        message = b""
        while True:
            b0, b1 = self._read(2)
            n = b1 & 0x7F
            if n == 126:
                n = struct.unpack(">H", self._read(2))[0]
            elif n == 127:
                n = struct.unpack(">Q", self._read(8))[0]
            if b1 & 0x80:
                self._read(4)  # servers do not mask; skip a mask if one is sent
            payload = self._read(n)
            opcode = b0 & 0x0F
            if opcode == 0x8:
                raise ConnectionError("DevTools closed the WebSocket")
            if opcode in (0x9, 0xA):  # ping/pong: not used by DevTools
                continue
            message += payload
            if b0 & 0x80:
                return message.decode()


class Browser:
    def __init__(self, chromium, profile, timeout=60):
        self.timeout = timeout
        os.makedirs(profile, exist_ok=True)
        port_file = os.path.join(profile, "DevToolsActivePort")
        if os.path.exists(port_file):
            os.remove(port_file)
        flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--disable-extensions", "--disable-default-apps", "--mute-audio", "--hide-scrollbars",
                 "--remote-debugging-port=0", "--remote-allow-origins=*", f"--user-data-dir={profile}",
                 f"--window-size={VIEWPORT[0]},{VIEWPORT[1]}", "about:blank"]
        self.process = subprocess.Popen([chromium] + flags, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        deadline = time.time() + timeout
        while not os.path.exists(port_file) or len(open(port_file).read().split("\n")) < 2:
            if self.process.poll() is not None:
                raise RuntimeError(f"chromium exited with {self.process.returncode} before DevTools started")
            if time.time() > deadline:
                raise TimeoutError("chromium did not start DevTools")
            time.sleep(0.05)
        port, path = open(port_file).read().split("\n")[:2]
        self.ws = WebSocket(f"ws://127.0.0.1:{port}{path}", timeout)
        self.next_id = 0
        self.events = []
        self.current_url = None
        target = self.call("Target.createTarget", {"url": "about:blank"})["targetId"]
        self.session = self.call("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]

    def call(self, method, params=None, session=None):
        self.next_id += 1
        message = {"id": self.next_id, "method": method, "params": params or {}}
        if session:
            message["sessionId"] = session
        self.ws.send(json.dumps(message))
        deadline = time.time() + self.timeout
        while time.time() < deadline:
            reply = json.loads(self.ws.receive())
            if reply.get("id") == self.next_id:
                if "error" in reply:
                    raise RuntimeError(f"{method}: {reply['error']}")
                return reply.get("result", {})
            if "method" in reply:
                self.on_event(reply)
        raise TimeoutError(method)

    def page(self, method, params=None):
        return self.call(method, params, self.session)

    def on_event(self, event):
        if event["method"] == "Fetch.requestPaused":
            # Only the page itself may load; everything else is recorded and refused.
            params = event["params"]
            if params["request"]["url"] == self.current_url:
                self.ws.send(json.dumps({"id": 0, "sessionId": self.session, "method": "Fetch.continueRequest",
                                         "params": {"requestId": params["requestId"]}}))
            else:
                self.events.append(event)
                self.ws.send(json.dumps({"id": 0, "sessionId": self.session, "method": "Fetch.failRequest",
                                         "params": {"requestId": params["requestId"], "errorReason": "BlockedByClient"}}))
            return
        self.events.append(event)

    def wait_for(self, method):
        deadline = time.time() + self.timeout
        while time.time() < deadline:
            for i, e in enumerate(self.events):
                if e["method"] == method:
                    del self.events[i]
                    return e
            reply = json.loads(self.ws.receive())
            if "method" in reply:
                self.on_event(reply)
        raise TimeoutError(method)

    def close(self):
        try:
            self.call("Browser.close")
        except Exception:  # the browser may already be gone
            pass
        try:
            self.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self.process.kill()


def png_pixels(data):
    """Width, height and the set of RGB colours of an 8-bit RGB or RGBA PNG (what Chromium writes)."""
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, width, height, colour = 8, b"", 0, 0, 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            if depth != 8 or colour not in (2, 6):
                raise ValueError(f"unsupported PNG (depth {depth}, colour type {colour})")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    channels = 4 if colour == 6 else 3
    raw = zlib.decompress(idat)
    stride = width * channels
    previous = bytearray(stride)
    colours = set()
    for y in range(height):
        line = raw[y * (stride + 1):(y + 1) * (stride + 1)]
        kind, row = line[0], bytearray(line[1:])
        for x in range(stride):
            a = row[x - channels] if x >= channels else 0
            b = previous[x]
            c = previous[x - channels] if x >= channels else 0
            if kind == 1:
                row[x] = (row[x] + a) & 0xFF
            elif kind == 2:
                row[x] = (row[x] + b) & 0xFF
            elif kind == 3:
                row[x] = (row[x] + ((a + b) >> 1)) & 0xFF
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                row[x] = (row[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 0xFF
        if y % 2 == 0:  # every other row is plenty to see which colours are painted
            for x in range(0, stride, channels * 2):
                colours.add((row[x], row[x + 1], row[x + 2]))
        previous = row
    return width, height, colours


def page_facts(browser, path, screenshot_path):
    url = "file://" + os.path.abspath(path)
    browser.current_url = url
    browser.events.clear()
    browser.page("Page.navigate", {"url": url})
    browser.wait_for("Page.loadEventFired")
    facts = json.loads(browser.page("Runtime.evaluate", {"expression": FACTS_SCRIPT, "returnByValue": True})["result"]["value"])
    facts["page"] = path
    # The screenshot shows the first picture with entries when there is one (else the top of the page), at a
    # quarter scale: the boxes are large enough that their inner pixels keep their exact tint.
    top = facts["first_svg_top"] or 0
    clip = {"x": 0, "y": max(0, top - 40), "width": VIEWPORT[0], "height": VIEWPORT[1], "scale": 0.25}
    shot = base64.b64decode(browser.page("Page.captureScreenshot", {"format": "png", "clip": clip, "captureBeyondViewport": True})["data"])
    if screenshot_path:
        with open(screenshot_path, "wb") as f:
            f.write(shot)
    width, height, colours = png_pixels(shot)
    facts["screenshot"] = {"width": width, "height": height, "colours": len(colours),
                           "picture_tints": len(colours & PICTURE_TINTS), "path": screenshot_path}
    console, requests = [], []
    for e in browser.events:
        p = e["params"]
        if e["method"] == "Runtime.consoleAPICalled" and p["type"] in ("error", "warning", "assert"):
            console.append(p["type"] + ": " + " ".join(str(a.get("value", a.get("description", ""))) for a in p["args"]))
        elif e["method"] == "Runtime.exceptionThrown":
            console.append("exception: " + p["exceptionDetails"].get("text", ""))
        elif e["method"] == "Log.entryAdded" and p["entry"]["level"] in ("error", "warning"):
            console.append(p["entry"]["level"] + ": " + p["entry"]["text"])
        elif e["method"] == "Fetch.requestPaused":
            requests.append(p["request"]["url"])
        elif e["method"] == "Network.requestWillBeSent" and p["request"]["url"] != url:
            requests.append(p["request"]["url"])
    facts["console"] = console
    facts["requests"] = sorted(set(requests))
    return facts


def capture(browser, path, element, png):
    url = "file://" + os.path.abspath(path)
    browser.current_url = url
    browser.page("Page.navigate", {"url": url})
    browser.wait_for("Page.loadEventFired")
    top = browser.page("Runtime.evaluate", {"expression": f"document.getElementById({json.dumps(element)}).getBoundingClientRect().top + window.scrollY",
                                            "returnByValue": True})["result"]["value"]
    clip = {"x": 0, "y": max(0, top - 16), "width": VIEWPORT[0], "height": 760, "scale": 0.5}
    with open(png, "wb") as f:
        f.write(base64.b64decode(browser.page("Page.captureScreenshot", {"format": "png", "clip": clip, "captureBeyondViewport": True})["data"]))
    browser.events.clear()


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--chromium", required=True)
    parser.add_argument("--profile", required=True, help="a fresh directory for Chromium's user data")
    parser.add_argument("--screenshots", help="directory to keep the screenshots in")
    parser.add_argument("--capture", nargs=3, action="append", default=[], metavar=("PAGE", "ELEMENT_ID", "PNG"),
                        help="also write a half-scale screenshot of PAGE scrolled to ELEMENT_ID (for docs/)")
    parser.add_argument("pages", nargs="*")
    args = parser.parse_args()
    browser = Browser(args.chromium, args.profile)
    try:
        browser.page("Page.enable")
        browser.page("Runtime.enable")
        browser.page("Log.enable")
        browser.page("Network.enable")
        browser.page("Fetch.enable", {"patterns": [{"urlPattern": "*"}]})
        browser.page("Emulation.setDeviceMetricsOverride",
                     {"width": VIEWPORT[0], "height": VIEWPORT[1], "deviceScaleFactor": 1, "mobile": False})
        results = []
        for i, page in enumerate(args.pages):
            shot = os.path.join(args.screenshots, f"page{i}.png") if args.screenshots else None
            results.append(page_facts(browser, page, shot))
        for page, element, png in args.capture:
            capture(browser, page, element, png)
    finally:
        browser.close()
    json.dump(results, sys.stdout, indent=1)
    sys.stdout.write("\n")


if __name__ == "__main__":
    main()
