#!/bin/bash
# --svg and --png on a small shipped mesh: the SVG is well-formed XML with one
# filled polygon per face, a caption with the report's figures and a legend;
# the PNG decodes (own decoder, standard library only), has the requested
# size, and shows both checker colors, seam pixels and white background.
# Bad picture options are one-line usage errors with no output written.
set -u
BIN=$1 DATA=$2 SCRATCH=$3
mkdir -p "$SCRATCH" && cd "$SCRATCH" || exit 1
rm -f ./*
fail() { echo "FAIL: $*" >&2; exit 1; }

"$BIN" "$DATA/cat_f1500.obj" -o cat.obj --svg cat.svg --png cat.png --report r.json >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 0 ] || fail "exit code $rc (stderr: $(cat err.txt))"
[ -s cat.svg ] && [ -s cat.png ] || fail "pictures not written"
tail -n 1 err.txt | grep -q "wrote cat.obj, cat.svg, cat.png$" || fail "summary does not list the pictures: $(tail -n 1 err.txt)"

python3 - r.json cat.svg cat.png <<'PY' || fail "pictures not as expected"
import json, struct, sys, zlib
import xml.etree.ElementTree as ET
r = json.load(open(sys.argv[1]))
assert r["svg"] == "cat.svg" and r["png"] == "cat.png", (r["svg"], r["png"])

# --- SVG
ns = "{http://www.w3.org/2000/svg}"
root = ET.parse(sys.argv[2]).getroot()          # raises on malformed XML
assert root.tag == ns + "svg", root.tag
polys = [e for e in root.iter(ns + "polygon")]
assert len(polys) == r["faces"], "%d polygons for %d faces" % (len(polys), r["faces"])
for p in polys:
    pts = p.get("points").split()
    assert len(pts) == 6, p.get("points")
    [float(x) for x in pts]
# every polygon is filled (by its group) with a color of the map
for g in root.iter(ns + "g"):
    if g.find(ns + "polygon") is not None:
        assert g.get("fill", "").startswith("#") and g.get("fill") != "none", g.attrib
texts = " ".join("".join(t.itertext()) for t in root.iter(ns + "text"))
assert "E_SD %.4g" % r["e_sd"] in texts or ("E_SD " + ("%.5g" % r["e_sd"])) in texts, texts[:300]
assert ("normalized seam length %.4g" % r["seam_length_normalized"]) in texts, texts[:300]
assert "1 chart" in texts and "4 = isometric" in texts, texts[:300]
paths = [e for e in root.iter(ns + "path")]
assert any(p.get("stroke") in ("#e6142a", "#e61428", "red") or "seam" in (p.get("id") or "") for p in paths) or paths, \
    "no seam path"
assert root.find(".//" + ns + "linearGradient") is not None, "no legend gradient"

# --- PNG: chunks, zlib, the five filters
data = open(sys.argv[3], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
pos, idat, ihdr = 8, b"", None
while pos < len(data):
    n, = struct.unpack(">I", data[pos:pos + 4]); kind = data[pos + 4:pos + 8]
    body = data[pos + 8:pos + 8 + n]
    assert zlib.crc32(kind + body) & 0xffffffff == struct.unpack(">I", data[pos + 8 + n:pos + 12 + n])[0], "bad CRC"
    if kind == b"IHDR": ihdr = struct.unpack(">IIBBBBB", body)
    elif kind == b"IDAT": idat += body
    pos += 12 + n
w, h, depth, ctype, _, _, interlace = ihdr
assert (w, h) == (600, 600), (w, h)
assert depth == 8 and ctype in (2, 6) and interlace == 0, ihdr
bpp = 3 if ctype == 2 else 4
raw = zlib.decompress(idat)
stride = w * bpp
rows, prev = [], bytearray(stride)
for y in range(h):
    f = raw[y * (stride + 1)]
    line = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - bpp] if i >= bpp else 0
        b = prev[i]
        c = prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        else: assert f == 0, "filter %d" % f
    rows.append(line); prev = line
white = blue = light = seam = 0
for line in rows:
    for x in range(w):
        R, G, B = line[x * bpp:x * bpp + 3]
        if R == G == B == 255: white += 1
        elif B > R + 50 and B > G + 30: blue += 1                   # checker blue (shaded)
        elif R > 120 and abs(R - G) < 30 and abs(G - B) < 40: light += 1   # checker warm white (shaded)
        elif R > 150 and G < 90 and B < 100: seam += 1              # seams
n = w * h
assert white > 0.1 * n, "background: %d pixels" % white
assert blue > 0.05 * n and light > 0.05 * n, "checker: %d blue, %d light pixels" % (blue, light)
assert seam > 100, "seams: %d pixels" % seam
print("png: %d white, %d blue, %d light, %d seam pixels" % (white, blue, light, seam))
PY

usage_error() { # $1: word the message must contain, rest: arguments
  local word=$1; shift
  "$BIN" "$DATA/cat_f1500.obj" -o u.obj "$@" >out.txt 2>err.txt
  local rc=$?
  [ "$rc" -eq 2 ] || fail "'$*': exit code $rc, expected 2 (stderr: $(cat err.txt))"
  [ "$(wc -l <err.txt)" -eq 1 ] || fail "'$*': expected one stderr line, got: $(cat err.txt)"
  grep -q "^optimize_seams: error: " err.txt || fail "'$*': bad message: $(cat err.txt)"
  grep -q -- "$word" err.txt || fail "'$*': message does not mention '$word': $(cat err.txt)"
  [ ! -e u.obj ] || fail "'$*': an output file was written"
}
usage_error "--svg" --svg
usage_error "--png" --png
usage_error "--energy" --energy dirichlet
usage_error "--threads" --threads 0
usage_error "--threads" --threads two
usage_error "exclusive" --repair --use-input-uv

# An unwritable picture path is found before the run: a usage error (exit 2), one line.
"$BIN" "$DATA/cat_f1500.obj" -o w.obj --svg no/such/dir/x.svg --quiet >out.txt 2>err.txt
rc=$?
[ "$rc" -eq 2 ] || fail "unwritable svg: exit code $rc, expected 2 (stderr: $(cat err.txt))"
[ "$(wc -l <err.txt)" -eq 1 ] && grep -q "x.svg" err.txt || fail "unwritable svg: $(cat err.txt)"
echo "ok"
