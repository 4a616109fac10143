#!/usr/bin/env bash
# Renders `qmckit report --quick`, opens index.html in headless Chromium and fails if the
# page or any figure is missing or blank, or a slide's section is missing.
#
# Usage: cli/tests/report/check.sh [QMCKIT_BINARY]   (default: target/release/qmckit, built
# with `cargo build --release -p qmckit-cli --bin qmckit` if missing). Needs chromium
# (Debian package `chromium`) and python3 (standard library only).
set -euo pipefail
cd "$(dirname "$0")/../../.."
bin="${1:-target/release/qmckit}"
if [ ! -x "$bin" ]; then
    cargo build --release -p qmckit-cli --bin qmckit
fi
browser="$(command -v chromium || command -v chromium-browser || true)"
if [ -z "$browser" ]; then
    echo "check.sh: chromium is not installed (apt-get install -y chromium)" >&2
    exit 1
fi
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$bin" report --quick --out "$out/report"
test -s "$out/report/index.html"
# The page, rendered by the browser; then every figure on its own (an SVG in a page, so the
# browser decodes it; a PNG too).
"$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars \
    --screenshot="$out/page.png" --window-size=1200,20000 \
    "file://$out/report/index.html" >/dev/null 2>&1
CHROMIUM="$browser" python3 - "$out" <<'PY'
import os, re, struct, subprocess, sys, zlib

out = sys.argv[1]
rep = os.path.join(out, "report")
html = open(os.path.join(rep, "index.html"), encoding="utf-8").read()

SECTIONS = """warping radical-inverse van-der-corput halton hammersley permuted-radical-inverse
owen-scrambling three-point-sets low-discrepancy-definition koksma-hlawka measured-qmc-error
elementary-intervals mse-tables-n16 quad-light motion-blur-defocus zero-two-sequences
pixel-light ambient-occlusion blue-noise-dithering power-spectrum colours-of-noise
blue-noise-sobol ld-spectra variance-spectra integration-benchmark""".split()

def png_pixels(path):
    """Decodes a non-interlaced 8-bit PNG (grey, RGB, RGBA): (width, height, rows)."""
    data = open(path, "rb").read()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise ValueError("not a PNG")
    pos, idat, w, h, ctype = 8, b"", 0, 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, inter = struct.unpack(">IIBBBBB", body)
            if depth != 8 or inter != 0:
                raise ValueError(f"unsupported PNG depth {depth} / interlace {inter}")
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    bpp = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw = zlib.decompress(idat)
    stride = w * bpp
    rows, prev, i = [], bytearray(stride), 0
    for _ in range(h):
        f = raw[i]; line = bytearray(raw[i + 1:i + 1 + stride]); i += 1 + stride
        for x in range(stride):
            a = line[x - bpp] if x >= bpp else 0
            b = prev[x]; c = prev[x - bpp] if x >= bpp else 0
            if f == 1: line[x] = (line[x] + a) & 255
            elif f == 2: line[x] = (line[x] + b) & 255
            elif f == 3: line[x] = (line[x] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(bytes(line)); prev = line
    return w, h, rows, bpp

def colours(path, step=3):
    w, h, rows, bpp = png_pixels(path)
    seen = set()
    for y in range(0, h, step):
        r = rows[y]
        for x in range(0, w, step):
            seen.add(r[x * bpp:(x + 1) * bpp])
            if len(seen) > 2:
                return w, h, len(seen)
    return w, h, len(seen)

fail = []
for sid in SECTIONS:
    if f'<section id="{sid}">' not in html:
        fail.append(f"section {sid} missing")
figs = re.findall(r'<img src="([^"]+)"', html)
if len(figs) < 20:
    fail.append(f"only {len(figs)} figures")
for f in figs:
    p = os.path.join(rep, f)
    if not os.path.isfile(p) or os.path.getsize(p) < 200:
        fail.append(f"figure {f} missing or empty"); continue
    if f.endswith(".png"):
        try:
            w, h, n = colours(p)
        except Exception as e:
            fail.append(f"figure {f} does not decode: {e}"); continue
        if n < 2:
            fail.append(f"figure {f} is a single colour")
    elif f.endswith(".svg"):
        text = open(p, encoding="utf-8").read()
        if not text.startswith("<svg") or "</svg>" not in text:
            fail.append(f"figure {f} is not a complete SVG")
        elif not re.search(r"<(circle|rect|polyline|path|line)\b", text[200:]):
            fail.append(f"figure {f} draws nothing")
    else:
        fail.append(f"figure {f}: unknown format")
# The browser's screenshot of the whole page: it exists, decodes, and is not blank.
shot = os.path.join(out, "page.png")
if not os.path.isfile(shot):
    fail.append("chromium wrote no screenshot")
else:
    w, h, n = colours(shot, step=7)
    if n < 3:
        fail.append("the page screenshot is blank")
# SVG figures as the browser draws them: a page of all of them, screenshot, not blank.
svgs = [f for f in figs if f.endswith(".svg")]
page = os.path.join(rep, "svgs.html")
with open(page, "w") as fh:
    fh.write("<html><body style='margin:0'>" + "".join(
        f"<img src='{f}' style='width:300px;height:300px'>" for f in svgs) + "</body></html>")
shot2 = os.path.join(out, "svgs.png")
subprocess.run([os.environ["CHROMIUM"], "--headless", "--no-sandbox",
                "--disable-gpu", "--hide-scrollbars", f"--screenshot={shot2}", "--window-size=1200,6000",
                "file://" + page], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
if not os.path.isfile(shot2) or colours(shot2, step=7)[2] < 3:
    fail.append("the SVG figures render blank in chromium")
if fail:
    print("check.sh: FAILED", *fail, sep="\n  ", file=sys.stderr)
    sys.exit(1)
print(f"check.sh: report OK: {len(SECTIONS)} sections, {len(figs)} figures, screenshot {w}x{h}")
PY
