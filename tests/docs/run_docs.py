#!/usr/bin/env python3
"""Runs the commands of a documentation page and checks the outputs it quotes.

Usage: run_docs.py PAGE.md --source DIR --build DIR [--update]

A page's fenced blocks mean:
  ```sh          commands, run in order with bash in a fresh folder that holds a copy of
                 datasets/ and a link build/ to the build folder (so `build/app/sdog` works and
                 nothing a command writes lands in the project's tracked files)
  ```output      what the last sh block printed (stdout and stderr): each line, in order, must
                 be a line of that output; a line "..." skips any number of lines. Numbers
                 followed by " s" or " ms", and the numbers of lines that name times
                 (ms/iteration), are not compared, since times differ from run to run.
  ```output-shape the same, with every number left out (tables of times, such as benchmarks)
  ```text, ```json and the other kinds are illustrations and are not run.
An sh block must exit with 0 unless the output quoted after it is an error ("sdog: ..." or
"sdog-studio: ..."). Commands that cannot run inside a test are left out, each named in the log:
`make` and `ctest` (the test suite itself) and the studio without --screenshot or --measure-fps
(an interactive window), which instead must start and still run after a few seconds.

--update writes the outputs of the sh blocks into the page's output blocks (every line, in place
of the quoted excerpt's lines where they differ), for regenerating a page after a change.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import struct
import tempfile
import zlib

FENCE = re.compile(r"^\s*```([\w-]*)\s*$")
PICTURE = re.compile(r"^\s*<!-- picture of (\S+) -->\s*$")
IMAGE = re.compile(r"!\[[^\]]*\]\(([^)]+\.png)\)")
TIME = re.compile(r"-?\d+(\.\d+)?(e[-+]?\d+)?(?= m?s\b)")
NUMBER = re.compile(r"-?\d+(\.\d+)?(e[-+]?\d+)?")
STUDIO_WAIT = 5


def blocks(lines):
    """(kind, first line index, last line index) of every fenced block."""
    out, i = [], 0
    while i < len(lines):
        m = FENCE.match(lines[i])
        if not m:
            i += 1
            continue
        j = i + 1
        while j < len(lines) and not lines[j].lstrip().startswith("```"):
            j += 1
        out.append((m.group(1), i + 1, j))
        i = j + 1
    return out


def logical_commands(text):
    """The block's commands: continuation lines joined, here-documents kept with their command."""
    cmds, lines, i = [], text.split("\n"), 0
    while i < len(lines):
        cmd = lines[i]
        # Continuation lines, and lines inside a double-quoted string that spans several.
        while (cmd.endswith("\\") or cmd.count('"') % 2) and i + 1 < len(lines):
            i += 1
            cmd += "\n" + lines[i]
        here = re.search(r"<<\s*'?(\w+)'?", cmd)
        if here:
            while i + 1 < len(lines):
                i += 1
                cmd += "\n" + lines[i]
                if lines[i] == here.group(1):
                    break
        cmds.append(cmd)
        i += 1
    return [c for c in cmds if c.strip() and not c.strip().startswith("#")]


def runnable(cmd, log):
    """The command as it runs in the test, or None when it is left out."""
    words = cmd.split()
    if words[0] in ("make", "ctest") or (words[:1] == ["xvfb-run"] and "ctest" in words):
        log.append("left out (the test suite itself): " + cmd.split("\n")[0])
        return None
    if "sdog-studio" in cmd and "--screenshot" not in cmd and "--measure-fps" not in cmd:
        log.append("started, must still run after %d s: %s" % (STUDIO_WAIT, cmd.split("\n")[0]))
        runner = "" if cmd.startswith("xvfb-run") else 'xvfb-run -a -s "-screen 0 1920x1080x24" '
        return "timeout %d %s%s; test $? = 124" % (STUDIO_WAIT, runner, cmd.split("#")[0].strip())
    return cmd


def masked(line, shape):
    line = NUMBER.sub("N", line) if shape else TIME.sub("T", line)
    if not shape and "ms/iteration" in line:
        line = NUMBER.sub("N", line)
    return line.strip()


def excerpt_matches(expected, actual, shape):
    """Each expected line, in order, is a line of actual; "..." skips lines."""
    got = [masked(l, shape) for l in actual]
    k = 0
    for want in expected:
        if want.strip() == "...":
            continue
        want = masked(want, shape)
        while k < len(got) and got[k] != want:
            k += 1
        if k == len(got):
            return "line not in the output (in this order): " + want
        k += 1
    return None


def png_pixels(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB or RGBA PNG without interlacing."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError(path + ": not a PNG file")
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        n = struct.unpack(">I", data[pos:pos + 4])[0]
        kind, body = data[pos + 4:pos + 8], data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                raise ValueError(path + ": not an 8-bit RGB(A) PNG without interlacing")
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line[k] for k in range(stride) if channels == 3 or k % 4 != 3))
        prev = line
    return width, height, rows


def pictures_differ(a, b):
    """Why the pictures differ: another size, or more than 0.5% of the pixels off by more than 24."""
    wa, ha, ra = png_pixels(a)
    wb, hb, rb = png_pixels(b)
    if (wa, ha) != (wb, hb):
        return "%dx%d instead of %dx%d" % (wb, hb, wa, ha)
    off = sum(1 for y in range(ha) for x in range(0, 3 * wa, 3)
              if max(abs(ra[y][x + k] - rb[y][x + k]) for k in range(3)) > 24)
    return "%d of %d pixels differ" % (off, wa * ha) if off > 0.005 * wa * ha else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("page")
    ap.add_argument("--source", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--update", action="store_true")
    a = ap.parse_args()
    lines = open(a.page).read().split("\n")
    work = tempfile.mkdtemp(prefix="sdog_docs_")
    shutil.copytree(os.path.join(a.source, "datasets"), os.path.join(work, "datasets"))
    os.symlink(os.path.abspath(a.build), os.path.join(work, "build"))
    failures, log, last_output, ran = [], [], None, 0
    replacements = []
    page_blocks = blocks(lines)
    for n, (kind, first, last) in enumerate(page_blocks):
        where = "%s:%d" % (os.path.basename(a.page), first)
        if kind in ("sh", "bash"):
            script = []
            indent = len(lines[first - 1]) - len(lines[first - 1].lstrip())
            for cmd in logical_commands("\n".join(l[indent:] for l in lines[first:last])):
                r = runnable(cmd, log)
                if r is not None:
                    script.append(r)
            if not script:
                last_output = None
                continue
            # Every command's exit code counts: the block fails with the last non-zero one.
            checked = "__codes=\n" + "".join(
                c + "\n__rc=$?; [ $__rc = 0 ] || __codes=\"$__codes $__rc\"\n" for c in script)
            checked += 'test -z "$__codes" || exit ${__codes##* }\n'
            p = subprocess.run(["bash", "-c", checked], cwd=work, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, text=True)
            ran += len(script)
            last_output = p.stdout.rstrip("\n").split("\n")
            print("ran %s: exit %d, %d output lines" % (where, p.returncode, len(last_output)))
            # An error exit is fine only when the next block quotes the error.
            following = page_blocks[n + 1] if n + 1 < len(page_blocks) else None
            quotes_error = following and following[0].startswith("output") and any(
                l.strip().startswith(("sdog: ", "sdog-studio: ")) for l in lines[following[1]:following[2]])
            if p.returncode != 0 and not quotes_error:
                failures.append("%s: exit %d:\n  %s" % (where, p.returncode, "\n  ".join(last_output[-15:])))
        elif kind in ("output", "output-shape"):
            if last_output is None:
                failures.append(where + ": an output block without an sh block before it")
                continue
            expected = [l.strip() for l in lines[first:last]]
            why = excerpt_matches(expected, last_output, kind == "output-shape")
            if why:
                failures.append("%s: %s\n  output was:\n  %s" % (where, why, "\n  ".join(last_output[:60])))
                replacements.append((first, last, [l for l in last_output if l.strip()]))
    # Pictures: "<!-- picture of OUT.png -->" before an image says the command above drew it.
    for i, line in enumerate(lines[:-1]):
        m, img = PICTURE.match(line), IMAGE.search(lines[i + 1])
        if not m:
            continue
        where = "%s:%d" % (os.path.basename(a.page), i + 1)
        if not img:
            failures.append(where + ": a picture marker without an image on the next line")
            continue
        drawn = os.path.join(work, m.group(1))
        shown = os.path.join(os.path.dirname(a.page), img.group(1))
        if not os.path.exists(drawn):
            failures.append("%s: %s was not drawn" % (where, m.group(1)))
            continue
        why = pictures_differ(shown, drawn)
        print("picture %s: %s" % (img.group(1), why or "as drawn"))
        if why and a.update:
            shutil.copyfile(drawn, shown)
            print("updated " + shown)
        elif why:
            failures.append("%s: %s is not what %s draws now: %s" % (where, img.group(1), m.group(1), why))
    shutil.rmtree(work, ignore_errors=True)
    for line in log:
        print(line)
    if a.update and replacements:
        for first, last, new in sorted(replacements, reverse=True):
            lines[first:last] = new
        open(a.page, "w").write("\n".join(lines))
        print("updated %d output block(s) of %s" % (len(replacements), a.page))
    if ran == 0:
        failures.append("no command ran")
    for f in failures:
        print("FAIL " + f)
    print("%s: %d commands, %d failure(s)" % (a.page, ran, len(failures)))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
