#!/usr/bin/env python3
"""Mutation campaign over the real corpus (issue 16; not part of CI, see docs/reliability.md).

Mutates real ESI files, SII images and YAML device sources (byte flips, truncation, duplicated
and deleted element ranges, swapped attribute values, huge and negative numbers, lying encoding
declarations, deep nesting, XML 1.0 faults, splices of other files) and runs every tool on them,
each run with a wall-time limit, an address-space limit and no core dumps:

  esi-lint, esi-diff, esi-gen, esi-gen --import, esi-sii build, esi-sii dump, esi-sii check,
  esi-net build, esi-net init, esi-doc (scripts/mutation_campaign_net.py: hostile networks, scans
  and ESI libraries, and checks on what a successful run wrote)

Each run is classified: exit code, crash (a signal such as SIGSEGV or SIGABRT), out of memory
(std::bad_alloc under the limit), timeout; and checked for what must hold whatever the input:
exit codes 0, 1 or 2 only, JSON output that parses, nothing written by a run that failed and no
temporary or lock file left by one that succeeded. Peak memory is the child's ru_maxrss (wait4).

Reproducers of every crash, timeout, out-of-memory or violation are kept in OUT/findings/.
The campaign is deterministic for a seed: run i of a tool uses random.Random(f"{seed}/{tool}/{i}").

  nice -n 10 scripts/mutation_campaign.py --build build-release --runs 10000 --jobs 2
  scripts/mutation_campaign.py --replay esi-diff:4711     # the inputs and command of one run

Only the Python standard library is used; prlimit (util-linux) applies the limits and GNU time
(/usr/bin/time, Debian package time) measures each tool's peak memory.
"""

import argparse
import collections
import concurrent.futures
import json
import os
import random
import re
import shutil
import signal
import statistics
import subprocess
import sys
import threading
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import mutation_campaign_net as net  # noqa: E402
TIME = "/usr/bin/time"  # GNU time, for the tool's own peak RSS (see execute)
CRASH_SIGNALS = {signal.SIGSEGV, signal.SIGABRT, signal.SIGBUS, signal.SIGFPE, signal.SIGILL, signal.SIGSYS, signal.SIGTRAP}
TOOLS = ["esi-lint", "esi-diff", "esi-gen", "esi-gen-import", "esi-sii-build", "esi-sii-dump", "esi-sii-check"] + net.NET_TOOLS


# ---- inputs ---------------------------------------------------------------------------------

class Corpus:
    """The unmutated inputs: ESI files (with their devices), YAML sources, SII images, ESI+image pairs."""

    def __init__(self, tools, work, shared):
        self.esi = []      # (name, bytes, [product codes])
        self.yaml = []     # (name, bytes)
        self.sii = []      # (name, bytes)
        self.pairs = []    # (esi name, esi bytes, image bytes, product code)
        esi_dirs = [os.path.join(shared, "corpus", "esi"), os.path.join(ROOT, "samples", "esi")]
        for d in esi_dirs:
            if not os.path.isdir(d):
                continue
            for name in sorted(os.listdir(d)):
                if name.endswith(".xml"):
                    data = open(os.path.join(d, name), "rb").read()
                    self.esi.append((name, data, product_codes(data)))
        for d in [os.path.join(ROOT, "samples")]:
            for name in sorted(os.listdir(d)):
                if name.endswith(".yaml"):
                    self.yaml.append((name, open(os.path.join(d, name), "rb").read()))
        sii_dir = os.path.join(shared, "corpus", "sii")
        if os.path.isdir(sii_dir):
            for name in sorted(os.listdir(sii_dir)):
                if name.endswith(".bin"):
                    self.sii.append((name, open(os.path.join(sii_dir, name), "rb").read()))
        if not self.esi:
            sys.exit("mutation_campaign: no ESI files (is ../shared/corpus there?)")
        # Real-data YAML sources and images, made from the corpus with the tools themselves.
        made = os.path.join(work, "corpus-made")
        os.makedirs(made, exist_ok=True)
        for name, data, codes in self.esi:
            if len(data) > 400_000 or not codes:
                continue
            source = os.path.join(made, name)
            with open(source, "wb") as f:
                f.write(data)
            device = ["--device", codes[0]]
            yaml_path = os.path.join(made, name[:-4] + ".yaml")
            if subprocess.run([tools["esi-gen"], "--import", source, "-o", yaml_path] + device,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
                self.yaml.append((os.path.basename(yaml_path), open(yaml_path, "rb").read()))
            image_path = os.path.join(made, name[:-4] + ".bin")
            if subprocess.run([tools["esi-sii"], "build", source, "-o", image_path] + device,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0:
                image = open(image_path, "rb").read()
                self.sii.append((os.path.basename(image_path), image))
                self.pairs.append((name, data, image, codes[0]))

    def pick_esi(self, rng):
        # Small files are picked more often (a run on a 4 MB catalogue takes seconds), large ones
        # still regularly: weight 1/sqrt(size).
        weights = [1.0 / max(len(d), 1000) ** 0.5 for _, d, _ in self.esi]
        return rng.choices(self.esi, weights=weights)[0]


def product_codes(data):
    codes = []
    for m in re.finditer(rb'<Type[^>]*ProductCode="([^"]+)"', data):
        code = m.group(1).decode("latin-1").strip()
        if code not in codes:
            codes.append(code)
    return codes


# ---- mutations ------------------------------------------------------------------------------

HUGE_NUMBERS = [b"9" * 20, b"9" * 400, b"#x" + b"F" * 40, b"-1", b"-2147483649", b"-9223372036854775809", b"0",
                b"4294967296", b"65536", b"65535", b"256", b"#x", b"1e9", b"", b"-0", b"+7", b"#x-1", b"0x10"]
ENCODINGS = [b"UTF-16", b"UTF-16LE", b"UTF-8", b"ISO-8859-1", b"windows-1252", b"US-ASCII", b"Shift_JIS", b"EBCDIC-US",
             b"bogus", b"", b"utf8", b"UTF-32", b"ISO-8859-15"]


def flip(rng, data):
    if not data:
        return data
    b = bytearray(data)
    for _ in range(rng.randint(1, 8)):
        i = rng.randrange(len(b))
        b[i] ^= 1 << rng.randrange(8)
    return bytes(b)


def truncate(rng, data):
    return data[: rng.randrange(len(data) + 1)] if data else data


def random_start_tag(rng, data):
    starts = [m.start() for m in re.finditer(rb"<[A-Za-z]", data[: 2_000_000])]
    return rng.choice(starts) if starts else None


def element_range(data, start):
    m = re.match(rb"<([A-Za-z_:][\w:.-]*)", data[start:])
    if not m:
        return None
    name = m.group(1)
    close = data.find(b">", start)
    if close < 0:
        return None
    if data[close - 1: close] == b"/":
        return start, close + 1
    end = data.find(b"</" + name + b">", close)
    if end < 0:
        return None
    return start, end + len(name) + 3


def duplicate_element(rng, data):
    start = random_start_tag(rng, data)
    span = element_range(data, start) if start is not None else None
    if not span:
        return flip(rng, data)
    chunk = data[span[0]: span[1]]
    copies = rng.choice([1, 1, 2, 10, 200])
    return data[: span[1]] + chunk * copies + data[span[1]:]


def delete_element(rng, data):
    start = random_start_tag(rng, data)
    span = element_range(data, start) if start is not None else None
    if not span:
        return truncate(rng, data)
    return data[: span[0]] + data[span[1]:]


def swap_attribute_values(rng, data):
    attrs = list(re.finditer(rb'\s[\w:]+="([^"<]*)"', data[: 2_000_000]))
    if len(attrs) < 2:
        return flip(rng, data)
    a, b = sorted(rng.sample(attrs, 2), key=lambda m: m.start(1))
    va, vb = a.group(1), b.group(1)
    return data[: a.start(1)] + vb + data[a.end(1): b.start(1)] + va + data[b.end(1):]


def numbers(rng, data):
    found = list(re.finditer(rb"#x[0-9A-Fa-f]+|(?<![\w#.])\d+(?![\w.])", data[: 2_000_000]))
    if not found:
        return flip(rng, data)
    out = data
    for m in sorted(rng.sample(found, min(len(found), rng.randint(1, 5))), key=lambda m: -m.start()):
        out = out[: m.start()] + rng.choice(HUGE_NUMBERS) + out[m.end():]
    return out


def lying_encoding(rng, data):
    choice = rng.randrange(5)
    declared = re.search(rb'encoding="[^"]*"', data[:200])
    if choice == 0 and declared:  # another name in the declaration
        return data[: declared.start()] + b'encoding="' + rng.choice(ENCODINGS) + b'"' + data[declared.end():]
    if choice == 1:  # a byte-order mark that does not match the bytes
        return rng.choice([b"\xef\xbb\xbf", b"\xff\xfe", b"\xfe\xff", b"\x00\x00\xfe\xff"]) + data
    if choice == 2:  # the text really in UTF-16, declared as something else (or not at all)
        text = data.decode("utf-8", errors="replace")
        return text.encode(rng.choice(["utf-16", "utf-16-le", "utf-16-be"]))
    if choice == 3:  # 8-bit bytes declared as UTF-8
        text = data.decode("utf-8", errors="replace").replace("<Name", "<Name>Größe µ°</Name><Name", 1)
        return text.encode("latin-1", errors="replace")
    return re.sub(rb"^<\?xml[^>]*\?>", b'<?xml version="1.0" encoding="' + rng.choice(ENCODINGS) + b'"?>', data, count=1)


def deep_nesting(rng, data):
    start = random_start_tag(rng, data)
    if start is None:
        return data
    close = data.find(b">", start)
    if close < 0:
        return data
    depth = rng.choice([300, 1000, 10_000, 100_000])
    opening, closing = rng.choice([(b"<a>", b"</a>"), (b"<SubItem><Info>", b"</Info></SubItem>"), (b"<Info>", b"</Info>")])
    return data[: close + 1] + opening * depth + closing * depth + data[close + 1:]


XML_FAULTS = [b"&undefined;", b"&#0;", b"&#x1;", b"\x01", b"\x0c", b"]]>", b"<!-- a -- b -->", b"<?xml version='1.0'?>",
              b"<![CDATA[ <&> ]]>", b"<?pi data?>", b"&amp", b"& ", b"<xi:include xmlns:xi='http://www.w3.org/2001/XInclude' href='x'/>",
              b"\xef\xbf\xbe", b"<!DOCTYPE x>", b"&#xD800;"]


def xml_faults(rng, data):
    choice = rng.randrange(6)
    start = random_start_tag(rng, data)
    if start is None:
        return flip(rng, data)
    close = data.find(b">", start)
    if close < 0:
        return data
    if choice == 0:  # a repeated attribute
        m = re.match(rb"<[\w:.-]+(\s+[\w:.-]+=\"[^\"]*\")", data[start:close + 1])
        attribute = m.group(1) if m else b' A="1"'
        return data[:close] + attribute + attribute + data[close:]
    if choice == 1:  # '<' inside an attribute value
        return data[:close] + b' Bad="a<b"' + data[close:]
    if choice == 2:  # a huge value
        return data[: close + 1] + b"9" * rng.choice([100_000, 1_000_000, 8_000_000]) + data[close + 1:]
    if choice == 3:  # many attributes in one tag
        return data[:close] + b"".join(b' a%d="%d"' % (i, i) for i in range(rng.choice([20, 1000, 20_000]))) + data[close:]
    if choice == 4:  # an entity bomb
        bomb = b'<!DOCTYPE EtherCATInfo [<!ENTITY l0 "lol">' + b"".join(
            b'<!ENTITY l%d "%s">' % (i, b"&l%d;" % (i - 1) * 10) for i in range(1, 10)) + b"]>"
        declaration_end = data.find(b"?>")
        at = declaration_end + 2 if 0 <= declaration_end < 200 else 0
        return data[:at] + bomb + data[at: close + 1] + b"&l9;" + data[close + 1:]
    return data[: close + 1] + rng.choice(XML_FAULTS) + data[close + 1:]


def splice(rng, data, donor):
    if not donor:
        return data
    a = rng.randrange(len(donor))
    chunk = donor[a: a + rng.randint(1, 4096)]
    at = rng.randrange(len(data) + 1)
    return data[:at] + chunk + data[at:]


XML_MUTATIONS = [flip, truncate, duplicate_element, delete_element, swap_attribute_values, numbers, lying_encoding,
                 deep_nesting, xml_faults]


def mutate_xml(rng, data, corpus):
    out = data
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        if rng.random() < 0.08:
            out = splice(rng, out, corpus.pick_esi(rng)[1])
        else:
            out = rng.choice(XML_MUTATIONS)(rng, out)
    return out


def mutate_yaml(rng, data):
    out = data
    for _ in range(rng.choice([1, 1, 2, 3])):
        choice = rng.randrange(10)
        lines = out.split(b"\n")
        if choice == 0:
            out = flip(rng, out)
        elif choice == 1:
            out = truncate(rng, out)
        elif choice == 2:  # a line repeated (duplicate keys) or removed
            i = rng.randrange(len(lines))
            if rng.random() < 0.6:
                lines[i:i] = [lines[i]] * rng.choice([1, 1, 50])
            else:
                del lines[i]
            out = b"\n".join(lines)
        elif choice == 3:
            out = numbers(rng, out)
        elif choice == 4:  # deep flow nesting as a value
            depth = rng.choice([70, 1000, 100_000])
            out = out.replace(b": ", b": " + b"[" * depth + b"1" + b"]" * depth + b" #", 1)
        elif choice == 5:  # an alias bomb
            bomb = b"x0: &a0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n" + b"".join(
                b"x%d: &a%d [*a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d, *a%d]\n" % ((i, i) + (i - 1,) * 10) for i in range(1, 9))
            out = bomb + out
        elif choice == 6:  # tabs, control characters, a lone quote
            out = out.replace(b"  ", rng.choice([b"\t", b"\x01 ", b"'"]), rng.randint(1, 3))
        elif choice == 7:  # a huge scalar
            out = out.replace(b": ", b": " + b"9" * rng.choice([10_000, 2_000_000]) + b" #", 1)
        elif choice == 8:  # swapped values
            out = swap_yaml_values(rng, out)
        else:
            out = rng.choice([b"\xff\xfe", b"\xef\xbb\xbf", b"%YAML 1.1\n---\n", b"--- !!binary\n"]) + out
    return out


def swap_yaml_values(rng, data):
    values = list(re.finditer(rb":[ ]+([^\n#{}\[\],]+)", data))
    if len(values) < 2:
        return flip(rng, data)
    a, b = sorted(rng.sample(values, 2), key=lambda m: m.start(1))
    return data[: a.start(1)] + b.group(1) + data[a.end(1): b.start(1)] + a.group(1) + data[b.end(1):]


def mutate_sii(rng, data):
    b = bytearray(data)
    for _ in range(rng.choice([1, 1, 2, 3])):
        choice = rng.randrange(7)
        if choice == 0 or len(b) < 0x84:
            b = bytearray(flip(rng, bytes(b)))
        elif choice == 1:
            b = b[: rng.randrange(len(b) + 1)]
        elif choice == 2:  # a header word (checksum, sizes, mailbox) set to an extreme
            at = rng.choice([0x0E, 0x10, 0x14, 0x18, 0x30, 0x32, 0x7C, 0x7E]) if len(b) > 0x80 else 0
            b[at: at + 2] = rng.choice([b"\xff\xff", b"\x00\x00", b"\x01\x80"])
        elif choice == 3:  # a category length word set to an extreme (walk the chain to a random category)
            at, steps = 0x80, rng.randrange(8)
            while steps and at + 4 <= len(b):
                at += 4 + 2 * int.from_bytes(b[at + 2: at + 4], "little")
                steps -= 1
            if at + 4 <= len(b):
                b[at + 2: at + 4] = rng.choice([b"\xff\xff", b"\x00\x80", b"\x00\x00", b"\x01\x00"])
        elif choice == 4:  # a range duplicated
            i = rng.randrange(len(b))
            chunk = b[i: i + rng.randint(2, 512)]
            b[i:i] = chunk * rng.choice([1, 3, 100])
        elif choice == 5:  # an endless chain of empty categories
            b += b"\x01\x00\x00\x00" * rng.choice([10, 2000, 200_000])
        else:  # random category type
            at = 0x80
            if at + 2 <= len(b):
                b[at: at + 2] = rng.randrange(65536).to_bytes(2, "little")
    return bytes(b)


# ---- runs -----------------------------------------------------------------------------------

class Run:
    """One tool invocation: its argv, the files it reads, what to check afterwards."""

    def __init__(self, tool, argv, inputs, json_output=False, output=None, output_is_dir=False):
        self.tool, self.argv, self.inputs = tool, argv, inputs
        self.json_output, self.output, self.output_is_dir = json_output, output, output_is_dir


def write(path, data):
    with open(path, "wb") as f:
        f.write(data)
    return path


def mutated_source(rng, corpus, esi, device, workdir, yaml_share):
    """A mutated device source for esi-gen or esi-sii build: YAML (a share of the runs) or ESI; with
    the --device selection that goes with it (none for YAML: one device per source)."""
    if rng.random() < yaml_share and corpus.yaml:
        return write(os.path.join(workdir, "device.yaml"), mutate_yaml(rng, rng.choice(corpus.yaml)[1])), []
    return write(os.path.join(workdir, "device.xml"), mutate_xml(rng, esi, corpus)), device


def plan_run(tool, rng, corpus, tools, workdir):
    """Builds the inputs of run (tool, rng) in workdir and returns the Run."""
    if tool in net.NET_TOOLS:
        return net.plan(tool, rng, corpus, tools, workdir, write, mutate_yaml, Run, None)
    name, esi, codes = corpus.pick_esi(rng)
    device = ["--device", rng.choice(codes)] if codes and rng.random() < 0.8 else []
    if tool == "esi-lint":
        path = write(os.path.join(workdir, "device.xml"), mutate_xml(rng, esi, corpus))
        fmt = rng.choice(["text", "json", "sarif", "github"])
        return Run(tool, [tools["esi-lint"], "--format", fmt, "-j", "1", path], [path], json_output=fmt in ("json", "sarif"))
    if tool == "esi-diff":
        old = write(os.path.join(workdir, "old.xml"), esi)
        new = write(os.path.join(workdir, "new.xml"), mutate_xml(rng, esi, corpus))
        pair = [old, new] if rng.random() < 0.5 else [new, old]
        fmt = rng.choice(["text", "json", "markdown"])
        return Run(tool, [tools["esi-diff"], "--format", fmt] + pair + (device if rng.random() < 0.3 else []), pair,
                   json_output=fmt == "json")
    if tool == "esi-gen":
        source, selection = mutated_source(rng, corpus, esi, device, workdir, yaml_share=0.5)
        out = os.path.join(workdir, "out")
        only = ["--only", ",".join(rng.sample(["esi", "cpp", "c", "soes", "structs", "sii"], rng.randint(1, 3)))] if rng.random() < 0.5 else []
        return Run(tool, [tools["esi-gen"], source, "-o", out] + selection + only, [source], output=out, output_is_dir=True)
    if tool == "esi-gen-import":
        source = write(os.path.join(workdir, "device.xml"), mutate_xml(rng, esi, corpus))
        out = os.path.join(workdir, "device.yaml")
        return Run(tool, [tools["esi-gen"], "--import", source, "-o", out] + device, [source], output=out)
    if tool == "esi-sii-build":
        source, selection = mutated_source(rng, corpus, esi, device, workdir, yaml_share=0.3)
        out = os.path.join(workdir, "image." + rng.choice(["bin", "hex", "c"]))
        fmt = os.path.splitext(out)[1][1:]
        return Run(tool, [tools["esi-sii"], "build", source, "-o", out, "--format", fmt] + selection, [source], output=out)
    if tool == "esi-sii-dump":
        image = write(os.path.join(workdir, "image.bin"), mutate_sii(rng, rng.choice(corpus.sii)[1]))
        fmt = rng.choice(["text", "json"])
        return Run(tool, [tools["esi-sii"], "dump", image, "--format", fmt], [image], json_output=fmt == "json")
    if tool == "esi-sii-check":
        pair_name, pair_esi, image, code = rng.choice(corpus.pairs)
        what = rng.randrange(3)
        esi_path = write(os.path.join(workdir, "device.xml"), mutate_xml(rng, pair_esi, corpus) if what != 1 else pair_esi)
        image_path = write(os.path.join(workdir, "image.bin"), mutate_sii(rng, image) if what != 0 else image)
        return Run(tool, [tools["esi-sii"], "check", esi_path, image_path] + (["--device", code] if rng.random() < 0.5 else []),
                   [esi_path, image_path])
    raise ValueError(tool)


def execute(run, workdir, timeout, memory_mb):
    """Runs under prlimit and GNU time; returns a result dict.

    GNU time forks the tool and reports its peak RSS: a child forked from this (large) Python
    process would count the parent's pages in its own ru_maxrss, one forked from time does not.
    """
    stdout_path, stderr_path = os.path.join(workdir, "stdout"), os.path.join(workdir, "stderr")
    usage_path = os.path.join(workdir, "usage")
    argv = (["prlimit", f"--as={memory_mb << 20}", "--core=0", f"--cpu={timeout}", "--", TIME, "-f", "%M %x", "-o", usage_path, "--"] +
            run.argv)
    with open(stdout_path, "wb") as out, open(stderr_path, "wb") as err:
        started = time.monotonic()
        process = subprocess.Popen(argv, stdin=subprocess.DEVNULL, stdout=out, stderr=err, cwd=workdir, start_new_session=True)
        timed_out = threading.Event()

        def kill():
            timed_out.set()
            try:
                os.killpg(process.pid, signal.SIGKILL)
            except ProcessLookupError:
                pass

        timer = threading.Timer(timeout, kill)
        timer.start()
        process.wait()
        timer.cancel()
        elapsed = time.monotonic() - started
    usage = open(usage_path).read().split("\n") if os.path.exists(usage_path) else []
    terminated = [int(m.group(1)) for line in usage for m in [re.match(r"Command terminated by signal (\d+)", line)] if m]
    figures = [line.split() for line in usage if re.fullmatch(r"\d+ \d+", line.strip())]
    stdout = open(stdout_path, "rb").read()
    stderr = open(stderr_path, "rb").read()
    result = {"exit": None, "signal": None, "seconds": elapsed, "max_rss_kb": int(figures[-1][0]) if figures else 0,
              "input_bytes": max(os.path.getsize(p) for p in run.inputs), "problems": []}
    if terminated:
        result["signal"] = terminated[0]
    elif figures:
        result["exit"] = int(figures[-1][1])
    if timed_out.is_set() or result["signal"] == signal.SIGXCPU or not figures:
        result["class"] = "timeout"
    elif b"bad_alloc" in stderr or b"cannot allocate" in stderr.lower():
        result["class"] = "out-of-memory"
    elif result["signal"] in CRASH_SIGNALS:
        result["class"] = "crash"
    elif result["signal"] is not None:
        result["class"] = "signal"
    else:
        result["class"] = "exit"
        if result["exit"] not in (0, 1, 2):
            result["problems"].append(f"exit code {result['exit']}")
        if run.json_output and result["exit"] in (0, 1):
            try:
                json.loads(stdout)
            except ValueError as e:
                result["problems"].append(f"invalid JSON: {e}")
        if run.output:
            exists = os.path.exists(run.output)
            if result["exit"] != 0 and exists:
                result["problems"].append("a failed run wrote its output")
            if result["exit"] == 0 and not exists:
                result["problems"].append("a successful run wrote nothing")
            if result["exit"] == 0 and run.output_is_dir:
                for base, _, files in os.walk(run.output):
                    for f in files:
                        if ".tmp" in f or f.startswith(".esi-output.lock"):
                            result["problems"].append(f"left {os.path.join(base, f)}")
    result["stderr_tail"] = stderr[-400:].decode("utf-8", "replace")
    return result


def keep_finding(run, result, workdir, findings, index):
    folder = os.path.join(findings, run.tool, f"{index:06d}-{result['class']}")
    os.makedirs(folder, exist_ok=True)
    for p in run.inputs:
        shutil.copy(p, folder)
    with open(os.path.join(folder, "run.json"), "w") as f:
        json.dump({"argv": run.argv, "result": result}, f, indent=2)


# ---- campaign -------------------------------------------------------------------------------

def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build-release"), help="build tree with cli/ (a Release build)")
    parser.add_argument("--shared", default=os.path.join(ROOT, "..", "shared"), help="directory holding corpus/")
    parser.add_argument("--runs", type=int, default=10000, help="runs per tool")
    parser.add_argument("--tools", default=",".join(TOOLS), help="comma-separated subset of " + ",".join(TOOLS))
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=int, default=60, help="seconds of wall time (and CPU time) per run")
    parser.add_argument("--memory-mb", type=int, default=2048, help="address-space limit per run")
    parser.add_argument("--seed", default="16")
    parser.add_argument("--out", default=os.path.join(ROOT, "build-mutation"), help="work directory; findings in OUT/findings")
    parser.add_argument("--replay", metavar="TOOL:INDEX", help="only write the inputs of that run to OUT/replay and print its command")
    args = parser.parse_args()

    try:
        os.nice(10)  # a guest on a shared machine; children inherit it
    except OSError:
        pass
    tools = {name: os.path.join(args.build, "cli", name) for name in ("esi-lint", "esi-diff", "esi-gen", "esi-sii", "esi-net", "esi-doc")}
    for path in tools.values():
        if not os.access(path, os.X_OK):
            sys.exit(f"mutation_campaign: {path} is missing; build the tools first")
    if shutil.which("prlimit") is None or not os.access(TIME, os.X_OK):
        sys.exit("mutation_campaign: prlimit (util-linux) and GNU time (/usr/bin/time) are needed")
    if args.replay:
        tool, index = args.replay.split(":")
        replay = os.path.join(args.out, "replay")
        shutil.rmtree(replay, ignore_errors=True)
        os.makedirs(replay)
        corpus = Corpus(tools, replay, os.path.abspath(args.shared))
        run = plan_run(tool, random.Random(f"{args.seed}/{tool}/{index}"), corpus, tools, replay)
        print(" ".join(run.argv))
        return 0
    shutil.rmtree(args.out, ignore_errors=True)
    findings = os.path.join(args.out, "findings")
    os.makedirs(findings)
    corpus = Corpus(tools, args.out, os.path.abspath(args.shared))
    selected = [t for t in args.tools.split(",") if t]
    print(f"corpus: {len(corpus.esi)} ESI files, {len(corpus.yaml)} YAML sources, {len(corpus.sii)} SII images, "
          f"{len(corpus.pairs)} ESI+image pairs; {args.runs} runs per tool, {args.jobs} jobs, limits {args.timeout} s and "
          f"{args.memory_mb} MB per run", flush=True)

    stats = {t: {"runs": 0, "exit": collections.Counter(), "class": collections.Counter(), "problems": 0, "seconds": [],
                 "rss_kb": [], "rss_per_mb": [], "extremes": {}} for t in selected}
    lock = threading.Lock()
    slots = list(range(args.jobs))
    started = time.monotonic()

    def one(tool, index):
        with lock:
            slot = slots.pop()
        workdir = os.path.join(args.out, f"job{slot}")
        try:
            shutil.rmtree(workdir, ignore_errors=True)
            os.makedirs(workdir)
            rng = random.Random(f"{args.seed}/{tool}/{index}")
            run = plan_run(tool, rng, corpus, tools, workdir)
            result = execute(run, workdir, args.timeout, args.memory_mb)
            result["problems"] += net.check_outputs(run, result, workdir, os.path.abspath(args.shared), tools)
            bad = result["class"] != "exit" or result["problems"]
            if bad:
                keep_finding(run, result, workdir, findings, index)
            with lock:
                s = stats[tool]
                s["runs"] += 1
                s["class"][result["class"]] += 1
                if result["exit"] is not None:
                    s["exit"][result["exit"]] += 1
                s["problems"] += len(result["problems"])
                s["seconds"].append(result["seconds"])
                s["rss_kb"].append(result["max_rss_kb"])
                per_mb = None
                if result["input_bytes"] >= 256 * 1024:
                    per_mb = result["max_rss_kb"] / 1024 / (result["input_bytes"] / 1048576)
                    s["rss_per_mb"].append(per_mb)
                # The run behind each maximum, to replay it (--replay TOOL:INDEX).
                for key, value in (("slowest", result["seconds"]), ("largest_rss", result["max_rss_kb"]), ("largest_rss_per_mb", per_mb)):
                    if value is not None and value > s["extremes"].get(key, {}).get("value", -1):
                        s["extremes"][key] = {"value": round(value, 2), "index": index, "input_bytes": result["input_bytes"]}
                if bad:
                    print(f"  {tool} run {index}: {result['class']} exit={result['exit']} signal={result['signal']} "
                          f"{result['problems']} {result['stderr_tail'][-160:]!r}", flush=True)
        finally:
            with lock:
                slots.append(slot)

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    signal.signal(signal.SIGTERM, interrupt)  # a campaign cut short by its time budget still reports
    work = [(t, i) for i in range(args.runs) for t in selected]
    done = 0
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = [pool.submit(one, t, i) for t, i in work]
        try:
            for future in concurrent.futures.as_completed(futures):
                future.result()
                done += 1
                if done % 1000 == 0:
                    print(f"{done}/{len(work)} runs, {time.monotonic() - started:.0f} s", flush=True)
        except KeyboardInterrupt:  # SIGINT or SIGTERM: stop and summarise the runs done so far
            for future in futures:
                future.cancel()
            print(f"interrupted after {done}/{len(work)} runs", flush=True)

    summary = {"seed": args.seed, "runs_per_tool": args.runs, "jobs": args.jobs, "timeout_s": args.timeout,
               "memory_mb": args.memory_mb, "wall_s": round(time.monotonic() - started), "tools": {}}
    print("\n| Tool | Runs | Exit 0 / 1 / 2 | Crashes | Timeouts | Out of memory | Other problems | Slowest run | Peak RSS | Peak RSS per input MB (inputs ≥ 256 KiB: median / max) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for tool in selected:
        s = stats[tool]
        per_mb = s["rss_per_mb"]
        row = {"runs": s["runs"], "exit": dict(s["exit"]), "class": dict(s["class"]), "problems": s["problems"],
               "slowest_s": round(max(s["seconds"], default=0), 2), "peak_rss_mb": round(max(s["rss_kb"], default=0) / 1024, 1),
               "rss_per_input_mb_median": round(statistics.median(per_mb), 1) if per_mb else None,
               "rss_per_input_mb_max": round(max(per_mb), 1) if per_mb else None, "extremes": s["extremes"]}
        summary["tools"][tool] = row
        print(f"| {tool} | {s['runs']:,} | {s['exit'][0]:,} / {s['exit'][1]:,} / {s['exit'][2]:,} | {s['class']['crash']} | "
              f"{s['class']['timeout']} | {s['class']['out-of-memory']} | {s['problems'] + s['class']['signal']} | "
              f"{row['slowest_s']} s | {row['peak_rss_mb']} MB | {row['rss_per_input_mb_median']} / {row['rss_per_input_mb_max']} |")
    with open(os.path.join(args.out, "summary.json"), "w") as f:
        json.dump(summary, f, indent=2)
    print(f"\n{sum(s['runs'] for s in stats.values()):,} runs in {summary['wall_s']} s; summary in "
          f"{os.path.join(args.out, 'summary.json')}, reproducers in {findings}")
    bad = sum(s["class"]["crash"] + s["class"]["timeout"] + s["class"]["out-of-memory"] + s["class"]["signal"] + s["problems"]
              for s in stats.values())
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
