#!/usr/bin/env bash
# Hidden seams: benchmark meshes run with the defaults (bound 4.1, bijective)
# and with --hide-seams; both measure visible_seam_share (the share of the
# seam length on the most visible quarter of the edges, by the library's
# edge_visibility()). Judged by uvmetrics.py (E_SD, seam length, flips,
# overlaps). Targets: the visible share halved or better, the seam length
# at most 1.3x the default's, the bound met. With --png DIR, a rendering of
# each run (seams in red) goes to DIR.
#
# Usage: run_hidden.sh [--build-dir DIR] [--data-dir DIR] [--out PREFIX] [--png DIR] [mesh name ...]
# Writes PREFIX.md (default benchmark/results_hidden).
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build_dir=$repo/build
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
out_prefix=$repo/benchmark/results_hidden
png_dir=
names=()
while (($#)); do
  case $1 in
    --build-dir) build_dir=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    --png) png_dir=$2; shift ;;
    *) names+=("$1") ;;
  esac
  shift
done
((${#names[@]})) || names=(cat_f1500 bimba_i_f10000 bunny_i_f10000 hand_1_i_f5000 horse_f10000 camel_vova_f10000)
bin=$build_dir/cli/optimize_seams
[[ -x $bin ]] || { echo "run_hidden: $bin not built" >&2; exit 1; }
uvmetrics=$data_dir/../tools/uvmetrics.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
[[ -n $png_dir ]] && mkdir -p "$png_dir"

rows=()
status=0
for name in "${names[@]}"; do
  mesh=$data_dir/benchmark/$name.obj
  [[ -f $mesh ]] || { echo "run_hidden: no $mesh" >&2; continue; }
  for run in default hidden; do
    extra=(--measure-visibility)
    [[ $run == hidden ]] && extra=(--hide-seams)
    [[ -n $png_dir ]] && extra+=(--png "$png_dir/$name.$run.png")
    "$bin" "$mesh" -o "$work/$name.$run.obj" --report "$work/$name.$run.json" --quiet "${extra[@]}" ||
      echo "run_hidden: $name $run failed" >&2
  done
  row=$(python3 - "$work/$name" "$uvmetrics" "$name" <<'PY'
import json, subprocess, sys
stem, uvmetrics, name = sys.argv[1:4]
fig = {}
for run in ("default", "hidden"):
    rep = json.load(open(stem + "." + run + ".json"))
    m = json.loads(subprocess.run([sys.executable, uvmetrics, stem + "." + run + ".obj", "--json"],
                                  capture_output=True, text=True).stdout)
    if isinstance(m, list): m = m[0]
    fig[run] = (rep, m)
(dr, dm), (hr, hm) = fig["default"], fig["hidden"]
share_ratio = hr["visible_seam_share"] / dr["visible_seam_share"] if dr["visible_seam_share"] else float("nan")
length_ratio = hm["seam_length_normalized"] / dm["seam_length_normalized"]
ok = (hm["e_sd"] <= 4.1 and hm["flipped"] == 0 and hm["overlap_pairs"] == 0 and share_ratio <= 0.5 and
      length_ratio <= 1.3)
print("| %s | %d | %.4f | %.4f | %.3f | %.3f | %.2f | %.3f | %.3f | %.2f | %d / %d | %.1f / %.1f | %s |" % (
    name, dr["faces"], dm["e_sd"], hm["e_sd"], dm["seam_length_normalized"], hm["seam_length_normalized"],
    length_ratio, dr["visible_seam_share"], hr["visible_seam_share"], share_ratio,
    dm["flipped"] + dm["overlap_pairs"], hm["flipped"] + hm["overlap_pairs"], dr["seconds"], hr["seconds"],
    "yes" if ok else "no"))
PY
)
  echo "$row"
  rows+=("$row")
done

{
  echo "# Hidden seams (\`run_hidden.sh\`)"
  echo
  echo "Defaults (bound 4.1, bijective) against \`--hide-seams\` (seam cost 1 to 4 by the rank of each edge's"
  echo "visibility: ambient occlusion over 64 ray directions and concave creases). *Visible share*: the share"
  echo "of the seam length on the most visible quarter of the edges (same visibility measure for both runs)."
  echo "E_SD, E_se, flips and overlaps by uvmetrics.py. Targets: visible share halved or better (ratio <= 0.5),"
  echo "E_se at most 1.3x the default's, bound met, no flip or overlap."
  echo
  echo "| mesh | faces | E_SD default | E_SD hidden | E_se default | E_se hidden | E_se ratio | visible share default | visible share hidden | share ratio | flips+overlaps default / hidden | seconds default / hidden | targets met |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} > "$out_prefix.md"
echo "run_hidden: wrote $out_prefix.md"
exit $status
