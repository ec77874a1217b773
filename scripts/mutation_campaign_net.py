"""esi-net and esi-doc in the mutation campaign (issue 27; used by mutation_campaign.py).

Inputs: a NETWORK.yaml made from the devices of a corpus ESI file and then mutated, an ESI
library of that file and a copy with mutated identities and hostile names (two files may then
describe one identity), and `ethercat slaves -v` scans made from the same devices and mutated.

What a successful run wrote is checked, not only its exit code: for `esi-net build`, network.xml
and lcec.xml well-formed and the ENI valid against the ETG.2100 schema (xmllint), igh_config.c
free of warnings under -Wall -Wextra -Werror -Wbidi-chars against the declarations of IgH's
documented interface in tests/net/data/igh_api (gcc -fsyntax-only), no raw markup in process_image.md, no CSV cell that starts a formula, no script
or event handler in process_image.html, and the same bytes with a cold cache, a warm cache and no
cache; for `esi-net init`, a network file that reads back with one slave per scanned block and
no key a name could have added; for esi-doc, pages without script, event handler or bidi
control outside an isolate.
"""

import os
import re
import subprocess

NET_TOOLS = ["esi-net-build", "esi-net-init", "esi-doc"]

# Text that has tried to become configuration or markup somewhere.
HOSTILE_TEXTS = ["<script>alert(1)</script>", "<img src=x onerror=alert(1)>", "=HYPERLINK(\"http://x\")", "+1", "-2", "@SUM(1)",
                 "\u202eevil", "a\u2028    alias: 7", "b\u2029    sdos: [{index: 0x1C12, value: 0}]", "c\u0085d", "*/ /* ??/ ??=",
                 "]]> --> <!--", "\"quoted\" 'single' \\", "tab\there", "\ufeffbom", "&amp; &lt;", "x" * 300]
XML_HOSTILE = [t.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;") for t in HOSTILE_TEXTS] + \
              ["&#x202E;rlo", "&#35;x1003", "&#x1;", "a&#xD;b"]
IDENTITY_VALUES = ["#x1002G", "-1", "4294967295", "4294967296", "#x", "&#35;x00001003", "0x10", "#xFFFFFFFF", "", "1e3", "#x7FFFFFFF"]
BITLEN_VALUES = ["-1", "0", "256", "4294967295", "65536", "1", "255"]


def devices_of(data):
    """(vendor text, [(product text, revision text, type text)]) of an ESI file, by regular expression."""
    vendor = re.search(rb"<Vendor[^>]*>\s*<Id>([^<]*)</Id>", data)
    out = []
    for m in re.finditer(rb'<Type([^>]*)>([^<]*)</Type>', data):
        attrs = m.group(1)
        p = re.search(rb'ProductCode="([^"]*)"', attrs)
        r = re.search(rb'RevisionNo="([^"]*)"', attrs)
        if p:
            out.append((p.group(1).decode("latin-1"), r.group(1).decode("latin-1") if r else None, m.group(2).decode("utf-8", "replace")))
    return (vendor.group(1).decode("latin-1").strip() if vendor else "0"), out


def esi_number(text):
    text = (text or "").strip()
    try:
        return int(text[2:], 16) if text[:2] in ("#x", "0x") else int(text)
    except ValueError:
        return None


def mutate_identities(rng, data):
    """Identities, bit lengths and names of an ESI file made hostile (the text stays XML)."""
    out = data
    for _ in range(rng.randint(1, 4)):
        choice = rng.randrange(5)
        if choice == 0:
            attrs = list(re.finditer(rb'(ProductCode|RevisionNo)="([^"]*)"', out))
            if attrs:
                m = rng.choice(attrs)
                out = out[: m.start(2)] + rng.choice(IDENTITY_VALUES).encode() + out[m.end(2):]
        elif choice == 1:
            m = re.search(rb"<Vendor[^>]*>\s*<Id>([^<]*)</Id>", out)
            if m:
                out = out[: m.start(1)] + rng.choice(IDENTITY_VALUES).encode() + out[m.end(1):]
        elif choice == 2:
            lens = list(re.finditer(rb"<BitLen>([^<]*)</BitLen>", out))
            if lens:
                m = rng.choice(lens)
                out = out[: m.start(1)] + rng.choice(BITLEN_VALUES).encode() + out[m.end(1):]
        else:
            names = list(re.finditer(rb"<(Name|Type)([^>]*)>([^<]*)</(Name|Type)>", out))
            if names:
                m = rng.choice(names)
                out = out[: m.start(3)] + rng.choice(XML_HOSTILE).encode() + out[m.end(3):]
    return out


def yaml_quoted(text):
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"').replace("\n", "\\n") + '"'


def network_yaml(rng, devices, esi_names):
    lines = ["esi: [" + ", ".join(esi_names) + "]", f"master: {{ name: {yaml_quoted(rng.choice(HOSTILE_TEXTS + ['Line']))}, "
             f"cycle_time_us: {rng.choice([1000, 250, 4000])} }}", "slaves:"]
    for i in range(rng.randint(1, 6)):
        product, revision, type_text = rng.choice(devices)
        name = rng.choice(HOSTILE_TEXTS + [f"S{i}"] * 6) + f" {i}"
        if rng.random() < 0.5 and esi_number(product) is not None:
            ident = f"product_code: {esi_number(product):#x}" + (f", revision: {esi_number(revision):#x}" if esi_number(revision) is not None else "")
        else:
            ident = f"device: {yaml_quoted(type_text)}"
        extra = ""
        if rng.random() < 0.2:
            extra = f", sdos: [{{ index: 0x{rng.choice([0x1C12, 0x6060, 0x2000, 0x8000]):04X}, " + rng.choice(
                ["type: UDINT, value: 1", "type: UDINT, value: 4294967295", "data: 0102", "data: 0102", "value: 1",
                 "type: USINT, value: 1, transition: [PS, SO]", "data: \"\"", "value: 1, transition: []"]) + f", comment: {yaml_quoted(rng.choice(HOSTILE_TEXTS))} }}]"
        if rng.random() < 0.05:
            extra += f", alias: {rng.choice([1, 65535, 65536, -1])}"
        if rng.random() < 0.05:
            extra += f", pdo_entries: {{ 0x1600: [0x7000:1:{rng.choice([8, 255, 256, 0])}] }}"
        lines.append(f"  - {{ name: {yaml_quoted(name)}, {ident}{extra} }}")
    return ("\n".join(lines) + "\n").encode()


def scan_text(rng, vendor, devices):
    out = []
    for position in range(rng.randint(1, 5)):
        product, revision, type_text = rng.choice(devices)
        out.append(f"=== Master 0, Slave {position} ===\nDevice: Main\nState: PREOP\nFlag: +\nAlias: {rng.choice([0] * 30 + [7, 65535, 70000])}\n"
                   f"Identity:\n  Vendor Id:       {vendor_hex(vendor)}\n  Product code:    {hex_or(product)}\n"
                   f"  Revision number: {hex_or(revision)}\n  Serial number:   0x00000000\nGeneral:\n  Group: G\n"
                   f"  Order number: {rng.choice(HOSTILE_TEXTS)}\n  Device name: {rng.choice(HOSTILE_TEXTS + [type_text])}\n")
    return "".join(out).encode()


def vendor_hex(text):
    v = esi_number(text)
    return f"0x{v:08x}" if v is not None and 0 <= v <= 0xFFFFFFFF else "0x00000002"


def hex_or(text):
    v = esi_number(text)
    return f"0x{v:08x}" if v is not None and 0 <= v <= 0xFFFFFFFF else "0x00000001"


def mutate_scan(rng, data, mutate_yaml):
    choice = rng.randrange(6)
    if choice >= 3:
        return data
    if choice == 1:  # a block repeated: the same position twice
        blocks = data.split(b"=== Master")
        if len(blocks) > 1:
            blocks.insert(rng.randrange(1, len(blocks)), blocks[rng.randrange(1, len(blocks))])
        return b"=== Master".join(blocks)
    if choice == 2:  # cut short
        return data[: rng.randrange(len(data) + 1)]
    return mutate_yaml(rng, data)  # byte flips, numbers, repeated lines (the scan is line-based text)


def plan(tool, rng, corpus, tools, workdir, write, mutate_yaml, run_class, cache_dir):
    """The Run of an esi-net or esi-doc tool."""
    # Files up to 300 KB (most of the corpus by count): a network names a few devices, and the
    # output checks run esi-net three times, xmllint and gcc on every successful build.
    small = [e for e in corpus.esi if len(e[1]) <= 300_000] or corpus.esi
    name, esi, codes = rng.choice(small)
    vendor, devices = devices_of(esi)
    if not devices:
        devices = [("#x1", "#x1", "X")]
    if tool == "esi-doc":
        data = mutate_identities(rng, esi) if rng.random() < 0.7 else esi
        source = write(os.path.join(workdir, "device.xml"), data)
        out = os.path.join(workdir, "doc")
        return run_class(tool, [tools["esi-doc"], source, "-o", out], [source], output=out, output_is_dir=True)
    lib = os.path.join(workdir, "lib")
    os.makedirs(lib, exist_ok=True)
    first = write(os.path.join(lib, "a-original.xml"), esi)
    files = [first]
    if rng.random() < 0.8:
        files.append(write(os.path.join(lib, "b-mutated.xml"), mutate_identities(rng, esi)))
    esi_names = ["lib/" + os.path.basename(f) for f in (files if rng.random() < 0.5 else list(reversed(files)))]
    if tool == "esi-net-init":
        scan = write(os.path.join(workdir, "scan.txt"), mutate_scan(rng, scan_text(rng, vendor, devices), mutate_yaml))
        out = os.path.join(workdir, "net", "network.yaml")
        os.makedirs(os.path.dirname(out), exist_ok=True)
        argv = [tools["esi-net"], "--no-cache", "init", "--from-igh", scan, "-o", out] + sum((["--esi", f] for f in files), [])
        return run_class(tool, argv, [scan] + files, output=out)
    network = network_yaml(rng, devices, esi_names)
    if rng.random() < 0.25:
        network = mutate_yaml(rng, network)
    path = write(os.path.join(workdir, "network.yaml"), network)
    out = os.path.join(workdir, "out")
    return run_class(tool, [tools["esi-net"], "--no-cache", "build", path, "-o", out], [path] + files, output=out, output_is_dir=True)


# ---- output checks --------------------------------------------------------------------------

BIDI = re.compile("[\u202a-\u202e\u2066-\u2069]")
TAG = re.compile(r"<([A-Za-z][A-Za-z0-9-]*)((?:\s+[^\s=>]+(?:\s*=\s*(?:\"[^\"]*\"|'[^']*'|[^\s>]+))?)*)\s*/?>")
ATTRIBUTE = re.compile(r"\s+([^\s=>]+)(?:\s*=\s*(\"[^\"]*\"|'[^']*'|[^\s>]+))?")


def active_markup(html):
    """The first tag that runs code or fetches something (script, image, frame, an on… handler,
    a javascript: URL), else None: text that merely reads like one is escaped and not a tag."""
    for m in TAG.finditer(html):
        name, attributes = m.group(1).lower(), m.group(2)
        if name in ("script", "img", "iframe", "object", "embed"):
            return m.group(0)[:80]
        for a in ATTRIBUTE.finditer(attributes):
            value = (a.group(2) or "").strip("\"'").strip().lower()
            if a.group(1).lower().startswith("on") or value.startswith("javascript:"):
                return m.group(0)[:80]
    return None


def run_quiet(argv, env=None, cwd=None, timeout=120):
    try:
        r = subprocess.run(argv, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=cwd, timeout=timeout)
        return r.returncode, r.stderr.decode("utf-8", "replace")
    except subprocess.TimeoutExpired:
        return -1, "timeout"


def read_all(folder):
    out = {}
    for base, _, files in os.walk(folder):
        for f in files:
            with open(os.path.join(base, f), "rb") as h:
                out[os.path.relpath(os.path.join(base, f), folder)] = h.read()
    return out


def check_build_outputs(run, workdir, shared, tools):
    problems = []
    out = run.output
    files = read_all(out)
    xsd = os.path.join(shared, "corpus", "schema", "eni-v1.6", "EtherCATConfig.xsd")
    for name in ("network.xml", "lcec.xml"):
        if name in files:
            code, err = run_quiet(["xmllint", "--noout", os.path.join(out, name)])
            if code != 0:
                problems.append(f"{name} not well-formed: {err[-200:]}")
    if "network.xml" in files and os.path.exists(xsd):
        code, err = run_quiet(["xmllint", "--noout", "--schema", xsd, os.path.join(out, "network.xml")])
        if code != 0:
            problems.append(f"network.xml not schema-valid: {err[-300:]}")
    ecrt = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "net", "data", "igh_api")
    if "igh_config.c" in files and os.path.exists(os.path.join(ecrt, "ecrt.h")):
        code, err = run_quiet(["gcc", "-std=c99", "-trigraphs", "-fsyntax-only", "-Wall", "-Wextra", "-Werror", "-Wbidi-chars=any",
                               "-I" + ecrt, os.path.join(out, "igh_config.c")])
        if code != 0:
            problems.append(f"igh_config.c does not compile with -Werror: {err[-300:]}")
    md = files.get("process_image.md", b"").decode("utf-8", "replace")
    if "<" in md:
        problems.append("raw markup in process_image.md")
    csv = files.get("process_image.csv", b"").decode("utf-8", "replace")
    if re.search(r'(^|,)"?[=+\-@\t\r]', csv, re.M):
        problems.append("a process_image.csv cell starts a formula")
    active = active_markup(files.get("process_image.html", b"").decode("utf-8", "replace"))
    if active:
        problems.append(f"script, image or event handler in process_image.html: {active!r}")
    # The same result without the cache and with it, cold and warm.
    env = dict(os.environ, XDG_CACHE_HOME=os.path.join(workdir, "cache"))
    argv = [a for a in run.argv if a != "--no-cache"]
    for label in ("cold cache", "warm cache"):
        again = os.path.join(workdir, "again")
        code, err = run_quiet(argv[:argv.index("-o") + 1] + [again], env=env, cwd=workdir)
        if code != 0:
            problems.append(f"{label}: exit {code} where --no-cache gave 0: {err[-200:]}")
        elif read_all(again) != files:
            problems.append(f"{label}: the outputs differ from --no-cache")
        subprocess.run(["rm", "-rf", again])
    return problems


def check_init_output(run, workdir):
    problems = []
    text = open(run.output, "rb").read().decode("utf-8", "replace")
    scan = open(run.inputs[0], "rb").read()
    # As the tool reads the header (sscanf "=== Master %u, Slave %u ===": blanks and a sign allowed).
    masters = [int(m.group(1)) for m in re.finditer(rb"^=== Master \s*\+?(\d+), Slave \s*[+-]?\d+ ===", scan, re.M)]
    blocks = masters.count(masters[0]) if masters else 0  # the network takes the first master's slaves
    body = [line for line in re.split("\r\n|\r|\n|\u0085|\u2028|\u2029", text) if line.strip() and not line.lstrip().startswith("#")]
    keys = [re.match(r"\s*-?\s*([A-Za-z_]+):", line) for line in body]
    allowed = {"esi", "master", "slaves", "name", "vendor_id", "product_code", "revision", "alias"}
    for line, m in zip(body, keys):
        if not m and not line.strip().startswith("- \""):
            problems.append(f"unexpected line in the network file: {line[:80]!r}")
        elif m and m.group(1) not in allowed:
            problems.append(f"key {m.group(1)!r} in the network file: text from the scan became configuration")
    names = sum(1 for m in keys if m and m.group(1) == "name")
    if names != blocks:
        problems.append(f"{names} slaves written for {blocks} scanned blocks")
    for line in text.split("\n"):
        if "#" in line and re.search("[\u0085\u2028\u2029\x00-\x08\x0b-\x1f]", line.split("#", 1)[1]):
            problems.append("a comment holds a line break or control character")
    return problems


def check_doc_outputs(run):
    problems = []
    for name, data in read_all(run.output).items():
        if not name.endswith(".html"):
            continue
        html = data.decode("utf-8", "replace")
        active = active_markup(html)
        if active:
            problems.append(f"script, image or event handler in {name}: {active!r}")
        if name == "index.html":
            # In the title (no elements allowed) the isolates are FSI … PDI characters.
            html = re.sub("<title>.*?</title>", "", html, flags=re.S)
            for m in BIDI.finditer(html):
                if html.rfind("<bdi>", 0, m.start()) <= html.rfind("</bdi>", 0, m.start()):
                    problems.append("a bidi control outside <bdi> in index.html")
                    break
    return problems


def check_outputs(run, result, workdir, shared, tools):
    """Problems with what a successful esi-net or esi-doc run wrote."""
    if result.get("exit") != 0 or not run.output or not os.path.exists(run.output):
        return []
    if run.tool == "esi-net-build":
        return check_build_outputs(run, workdir, shared, tools)
    if run.tool == "esi-net-init":
        return check_init_output(run, workdir)
    if run.tool == "esi-doc":
        return check_doc_outputs(run)
    return []
