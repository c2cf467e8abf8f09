#!/usr/bin/env bash
# "General inputs": the command-line program with its defaults (bound 4.1,
# bijective) on every mesh a user may have: the shared high_genus/,
# multi_component/, edge_cases/ and invalid/ meshes (the invalid ones with
# --repair) and CGAL's own sample meshes (Debian's libcgal-demo, data/meshes
# of its data.tar.gz: fetched with `apt-get download` into the build directory
# when --cgal-dir is not given). Each output is judged by uvmetrics.py; the
# input's topology (genus, boundary loops, components) is computed here.
#
# Usage: run_general.sh [--build-dir DIR] [--data-dir DIR] [--cgal-dir DIR]
#                       [--timeout S] [--out PREFIX] [--quick] [--all-cgal] [mesh path ...]
#   --quick     only the meshes under 5000 faces
#   --all-cgal  every mesh of CGAL's data/meshes (OFF, OBJ, PLY, STL; ~140,
#               of which ~90 under 5000 faces), not only the list below
# Writes PREFIX.md (default benchmark/results_general). Results are not
# asserted: the exit code is non-zero only if the program is missing.
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build_dir=$repo/build
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
cgal_dir=
timeout_s=900
out_prefix=$repo/benchmark/results_general
quick=0
all_cgal=0
explicit=()
while (($#)); do
  case $1 in
    --build-dir) build_dir=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --cgal-dir) cgal_dir=$2; shift ;;
    --timeout) timeout_s=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    --quick) quick=1 ;;
    --all-cgal) all_cgal=1 ;;
    *) explicit+=("$1") ;;
  esac
  shift
done
bin=$build_dir/cli/optimize_seams
[[ -x $bin ]] || { echo "run_general: $bin not built" >&2; exit 1; }
uvmetrics=$data_dir/../tools/uvmetrics.py

# CGAL's sample meshes of genus >= 1, several boundary loops or several
# components (and a few disks), small to large.
cgal_meshes=(rotor pinion pipe mpi_triang 3torus P double-torus-example double-torus-3-holes eight joint
             helmet knot1 knot2 elk couplingdown anchor femur cheese turbine
             holes pig head horizons mask_cone blobby_3cc bones ALSTOM_TEST4 boeing b9_mesh
             mech-holes-shark lion ChineseDragon-10kv blade elephant-with-holes
             cube open_cube cylinder mushroom nefertiti three_peaks)
if [[ -z $cgal_dir && ${#explicit[@]} -eq 0 ]]; then
  cgal_dir=$build_dir/cgal_sample_meshes
  if [[ ! -d $cgal_dir/data/meshes ]]; then
    mkdir -p "$cgal_dir" && (
      cd "$cgal_dir" && apt-get download libcgal-demo >/dev/null 2>&1 && ar x libcgal-demo_*.deb &&
      tar xf data.tar.* && tar xzf usr/share/doc/libcgal-dev/data.tar.gz) ||
      echo "run_general: libcgal-demo not available: CGAL's sample meshes left out" >&2
  fi
  cgal_dir=$cgal_dir/data/meshes
fi

inputs=()
if ((${#explicit[@]})); then
  inputs=("${explicit[@]}")
else
  for d in high_genus multi_component edge_cases invalid; do
    for f in "$data_dir"/$d/*.obj; do [[ -e $f ]] && inputs+=("$f"); done
  done
  if ((all_cgal)); then
    for f in "$cgal_dir"/*.{off,obj,ply,stl}; do [[ -e $f ]] && inputs+=("$f"); done
  else
    for n in "${cgal_meshes[@]}"; do [[ -e $cgal_dir/$n.off ]] && inputs+=("$cgal_dir/$n.off"); done
  fi
fi

work=$(mktemp -d /tmp/smso_general.XXXXXX)
trap 'rm -rf "$work"' EXIT

topology() { # faces genus loops components triangles? of an OBJ/OFF (polygons as given)
  python3 - "$1" <<'PY'
import sys, collections
p = sys.argv[1]
V, F = 0, []
if p.endswith('.off'):
    toks = [l.split('#')[0].split() for l in open(p, errors='replace')]
    toks = [t for t in toks if t]
    h = toks[0]; i = 1
    nums = h[1:] if len(h) > 1 else toks[1]
    if len(h) == 1: i = 2
    V, nf = int(nums[0]), int(nums[1])
    for t in toks[i + V:i + V + nf]: F.append([int(x) for x in t[1:1 + int(t[0])]])
elif p.endswith('.ply'):   # ASCII only (a binary one gives no face)
    lines = open(p, errors='replace').read().split('\n')
    counts, k = {}, 0
    while k < len(lines) and lines[k].strip() != 'end_header':
        t = lines[k].split()
        if t[:1] == ['element']: counts[t[1]] = int(t[2])
        if t[:1] == ['format'] and t[1] != 'ascii': counts = {}; break
        k += 1
    V = counts.get('vertex', 0)
    for l in lines[k + 1 + V:k + 1 + V + counts.get('face', 0)]:
        t = l.split(); F.append([int(x) for x in t[1:1 + int(t[0])]])
elif p.endswith('.stl'):   # equal points merged, as the program does
    import struct
    data = open(p, 'rb').read()
    pts = []
    if len(data) >= 84 and 84 + 50 * struct.unpack('<I', data[80:84])[0] == len(data):
        for f in range(struct.unpack('<I', data[80:84])[0]):
            for k in range(3): pts.append(struct.unpack('<3f', data[84 + 50 * f + 12 + 12 * k:96 + 50 * f + 12 * k + 12]))
    else:
        t = data.decode(errors='replace').split()
        pts = [tuple(float(x) for x in t[i + 1:i + 4]) for i in range(len(t)) if t[i] == 'vertex']
    ids = {}
    for q in pts: ids.setdefault(q, len(ids))
    V = len(ids)
    F = [[ids[q] for q in pts[i:i + 3]] for i in range(0, len(pts) - 2, 3)]
else:
    for l in open(p, errors='replace'):
        t = l.split()
        if not t: continue
        if t[0] == 'v': V += 1
        elif t[0] == 'f': F.append([int(x.split('/')[0]) - 1 for x in t[1:]])
E = collections.Counter()
for f in F:
    for a, b in zip(f, f[1:] + f[:1]): E[(min(a, b), max(a, b))] += 1
par = list(range(V))
def find(x):
    while par[x] != x: par[x] = par[par[x]]; x = par[x]
    return x
used = set()
for f in F:
    used.update(f)
    for a in f[1:]: par[find(a)] = find(f[0])
comps = len({find(v) for v in used})
bpar = list(range(V))
def bfind(x):
    while bpar[x] != x: bpar[x] = bpar[bpar[x]]; x = bpar[x]
    return x
bv = set()
for (a, b), c in E.items():
    if c == 1: bv.update((a, b)); bpar[bfind(a)] = bfind(b)
loops = len({bfind(v) for v in bv})
chi = len(used) - len(E) + len(F)
genus = (2 * comps - loops - chi) // 2
nonmanifold = sum(1 for c in E.values() if c > 2)
print(len(F), genus if nonmanifold == 0 else '?', loops, comps)
PY
}

md=$out_prefix.md
{
  echo "# General inputs"
  echo
  echo "\`optimize_seams\` with its defaults (bound 4.1, bijective), one process per mesh, at $(git -C "$repo" rev-parse --short HEAD 2>/dev/null);"
  echo "E_SD, E_se (normalized seam length), charts, flips and overlapping pairs by uvmetrics.py on the written OBJ."
  echo "Genus, boundary loops and components of the input as read (before any triangulation or repair)."
  echo
  echo "| mesh | genus | loops | parts | faces | status | s | E_SD | E_se | charts | bound met | flips | overlaps |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} >"$md"

index=0
for f in "${inputs[@]}"; do
  name=$(basename "$f"); name=${name%.*}
  [[ $f == *.obj || $f == *.off ]] || name=$(basename "$f")   # (sphere.off, sphere.ply and sphere.stl apart)
  index=$((index + 1))
  read -r faces genus loops comps < <(topology "$f")
  if ((quick)) && ((faces > 5000)); then continue; fi
  extra=()
  [[ $f == */invalid/* ]] && extra+=(--repair)
  start=$(date +%s.%N)
  w=$work/$index
  timeout "$timeout_s" "$bin" "$f" -o "$w.obj" --report "$w.json" --quiet "${extra[@]}" >"$w.out" 2>"$w.err"
  rc=$?
  secs=$(python3 -c "import time; print('%.1f' % (time.time() - $start))")
  status=$(python3 -c "import json; print(json.load(open('$w.json'))['status'])" 2>/dev/null)
  [[ $rc -eq 124 ]] && status="timeout ${timeout_s} s"
  [[ -z $status ]] && status="exit $rc: $(head -c 80 "$w.err" | tr '\n|' '  ')"
  if [[ -s $w.obj ]]; then
    row=$(python3 "$uvmetrics" "$w.obj" --json --bound 4.1 2>/dev/null | python3 -c "
import json, sys
r = json.load(sys.stdin)
print('%.4f | %.3f | %d | %s | %d | %d' % (r['e_sd'], r['seam_length_normalized'], r['charts'],
      'yes' if r['e_sd'] <= 4.1 else 'no', r['flipped'] + r['degenerate'], r['overlap_pairs']))")
  else
    row="- | - | - | - | - | -"
  fi
  echo "| $name | $genus | $loops | $comps | $faces | $status | $secs | $row |" | tee -a "$md"
done
echo
echo "written $md"
