#!/usr/bin/env bash
# Regional seam preferences: every mesh of the shared regional/ folder with
# its painted region (NAME_selected.txt: vertices where seams are unwanted),
# run with the defaults (bound 4.1, bijective), once plain and once with
# --seam-weights NAME_selected.txt (cost 100 on the region, as in the paper).
# Judged from the output OBJs: E_SD, flips and overlaps by uvmetrics.py, the
# seam length inside the region (edges with both ends selected) by
# region_seams.py. The target: inside the region at most half the plain run's,
# the bound met.
#
# Usage: run_regional.sh [--build-dir DIR] [--data-dir DIR] [--out PREFIX] [--cost W]
# Writes PREFIX.md (default benchmark/results_regional). Exit code non-zero
# when the program is missing or a target is missed.
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build_dir=$repo/build
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
out_prefix=$repo/benchmark/results_regional
cost=
while (($#)); do
  case $1 in
    --build-dir) build_dir=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    --cost) cost=":$2"; shift ;;
    *) echo "run_regional: unknown argument '$1'" >&2; exit 2 ;;
  esac
  shift
done
bin=$build_dir/cli/optimize_seams
[[ -x $bin ]] || { echo "run_regional: $bin not built" >&2; exit 1; }
uvmetrics=$data_dir/../tools/uvmetrics.py
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rows=()
status=0
for selected in "$data_dir"/regional/*_selected.txt; do
  name=$(basename "$selected" _selected.txt)
  mesh=$data_dir/regional/$name.obj
  [[ -f $mesh ]] || continue
  for run in plain weighted; do
    extra=()
    [[ $run == weighted ]] && extra=(--seam-weights "$selected$cost")
    "$bin" "$mesh" -o "$work/$name.$run.obj" --report "$work/$name.$run.json" --quiet "${extra[@]}" ||
      echo "run_regional: $name $run failed" >&2
  done
  row=$(python3 - "$mesh" "$selected" "$work/$name" "$uvmetrics" "$script_dir/region_seams.py" <<'PY'
import json, subprocess, sys
mesh, selected, stem, uvmetrics, region = sys.argv[1:6]
fig = {}
for run in ("plain", "weighted"):
    rep = json.load(open(stem + "." + run + ".json"))
    m = json.loads(subprocess.run([sys.executable, uvmetrics, stem + "." + run + ".obj", "--json"],
                                  capture_output=True, text=True).stdout)
    if isinstance(m, list): m = m[0]
    s = json.loads(subprocess.run([sys.executable, region, mesh, stem + "." + run + ".obj", selected, "--json"],
                                  capture_output=True, text=True).stdout)
    fig[run] = (rep, m, s)
(pr, pm, ps), (wr, wm, ws) = fig["plain"], fig["weighted"]
ok = (wm["e_sd"] <= 4.1 and wm["flipped"] == 0 and wm["overlap_pairs"] == 0 and
      ws["region_seam_length"] <= 0.5 * ps["region_seam_length"])
print("| %s | %d | %.4f | %.4f | %.3f | %.3f | %.4f | %.4f | %.2f | %.4f | %d / %d | %.1f / %.1f | %s |" % (
    mesh.split("/")[-1][:-4], pr["faces"], pm["e_sd"], wm["e_sd"],
    ps["seam_length_normalized"], ws["seam_length_normalized"],
    ps["region_seam_length_normalized"], ws["region_seam_length_normalized"],
    ws["region_seam_length"] / ps["region_seam_length"] if ps["region_seam_length"] > 0 else float("nan"),
    wr["weighted_seam_length_normalized"], pm["flipped"] + pm["overlap_pairs"], wm["flipped"] + wm["overlap_pairs"],
    pr["seconds"], wr["seconds"], "yes" if ok else "**no**"))
PY
)
  echo "$row"
  rows+=("$row")
  [[ $row == *"| yes |" ]] || status=1
done

{
  echo "# Regional seam preferences (\`run_regional.sh\`)"
  echo
  echo "Defaults (bound 4.1, bijective); *weighted*: \`--seam-weights NAME_selected.txt${cost}\` (the region's"
  echo "vertices cost ${cost:+${cost#:}}${cost:-100}, smoothed over the one-ring). E_SD, flips and overlaps by uvmetrics.py;"
  echo "E_se and the region's seams (edges with both ends selected) by region_seams.py, both normalized by"
  echo "sqrt(area / pi); *weighted E_se* is the library's weighted seam term. Target: region seams at most"
  echo "half the plain run's, bound met, no flip or overlap."
  echo
  echo "| mesh | faces | E_SD plain | E_SD weighted | E_se plain | E_se weighted | region seams plain | region seams weighted | ratio | weighted E_se (costs) | flips+overlaps plain / weighted | seconds plain / weighted | target met |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
  printf '%s\n' "${rows[@]}"
} > "$out_prefix.md"
echo "run_regional: wrote $out_prefix.md"
exit $status
