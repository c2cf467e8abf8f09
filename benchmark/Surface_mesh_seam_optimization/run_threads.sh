#!/usr/bin/env bash
# Threads: optimize_seams() (bijective default, the CLI) on each mesh with
# TBB capped at 1 thread and then at 2 (--threads), one run each: wall
# seconds (the report's `seconds`), the speed-up, and whether the two OBJ
# files are byte-identical (results must not depend on the thread count).
# What runs in parallel: the two starts (one per thread), the scoring of
# topology candidates, and from 8192 triangles the element loops of the
# Newton iterations (energies, gradients, Hessians, flip-free bounds; added
# in element order, so the same bits); the factorizations are sequential.
# Then distortion only (--keep-seams, one Newton descent: the element loops
# are all that runs in parallel) on larger meshes, among them lucy_o_f24136
# after one Loop step (96544 faces, made with subdivide_mesh if built).
#
# Usage: run_threads.sh [--build-dir DIR] [--data-dir DIR] [--out PREFIX] [mesh name ...]
# Writes PREFIX.md (default benchmark/results_threads).
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build_dir=$repo/build
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
out_prefix=$repo/benchmark/results_threads
names=()
while (($#)); do
  case $1 in
    --build-dir) build_dir=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    *) names+=("$1") ;;
  esac
  shift
done
((${#names[@]})) || names=(face_f10000 bone_noInputUV tooth max_planck_i_f8000 bunny vase_i_f10000 statue_1_i_f8000
                           camel_vova_f10000)
bin=$build_dir/cli/optimize_seams
[ -x "$bin" ] || { echo "run_threads.sh: $bin not built" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

rows=()
for name in "${names[@]}"; do
  mesh=$data_dir/benchmark/$name.obj
  [ -f "$mesh" ] || { echo "run_threads.sh: no $mesh" >&2; exit 2; }
  line="$name"
  for threads in 1 2; do
    "$bin" "$mesh" --threads "$threads" --quiet -o "$work/$name.$threads.obj" --report "$work/$name.$threads.json" \
      || { echo "run_threads.sh: $name with $threads thread(s) failed" >&2; exit 1; }
    s=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["seconds"])' "$work/$name.$threads.json")
    line="$line,$s"
    echo "$name: $threads thread(s) ${s} s" >&2
  done
  if cmp -s "$work/$name.1.obj" "$work/$name.2.obj"; then line="$line,yes"; else line="$line,no"; fi
  rows+=("$line")
done

# distortion only: one descent, 1 thread against 2, each run twice (alternately)
dense_names=(male_2_f20000 kingkong_f20000 circular_box_o_f20000)
dense_files=()
for name in "${dense_names[@]}"; do dense_files+=("$data_dir/benchmark/$name.obj"); done
loop1=$build_dir/scaling_meshes/lucy_o_f24136_loop1.obj
sub_bin=$build_dir/benchmark/Surface_mesh_seam_optimization/subdivide_mesh
if [ ! -s "$loop1" ] && [ -x "$sub_bin" ] && [ -f "$data_dir/scalability/lucy_o_f24136.obj" ]; then
  mkdir -p "$(dirname "$loop1")"
  "$sub_bin" "$data_dir/scalability/lucy_o_f24136.obj" "${loop1%.obj}.part.obj" 1 >&2 && mv "${loop1%.obj}.part.obj" "$loop1"
fi
[ -s "$loop1" ] && dense_files+=("$loop1")
drows=()
for mesh in "${dense_files[@]}"; do
  name=$(basename "$mesh" .obj)
  declare -A best=()
  for round in 1 2; do
    for threads in 1 2; do
      "$bin" "$mesh" --keep-seams --threads "$threads" --quiet -o "$work/$name.d$threads.obj" --report "$work/$name.d$threads.json" \
        || { echo "run_threads.sh: $name --keep-seams with $threads thread(s) failed" >&2; exit 1; }
      s=$(python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["seconds"])' "$work/$name.d$threads.json")
      echo "$name --keep-seams: $threads thread(s) ${s} s" >&2
      best[$threads]="${best[$threads]:+${best[$threads]} }$s"
    done
  done
  faces=$(grep -c '^f ' "$mesh")
  same=no; cmp -s "$work/$name.d1.obj" "$work/$name.d2.obj" && same=yes
  drows+=("$name,$faces,${best[1]// /;},${best[2]// /;},$same")
  unset best
done
printf '%s\n' "${drows[@]}" > "$work/dense.csv"

printf '%s\n' "${rows[@]}" > "$work/rows.csv"
python3 - "$work/rows.csv" "$out_prefix" "$work/dense.csv" "$(git -C "$repo" rev-parse --short HEAD)" "$(nproc)" <<'EOF'
import statistics, sys, time
rows_file, prefix, dense_file, commit, nproc = sys.argv[1:]
rows = [l.strip().split(",") for l in open(rows_file) if l.strip()]
L = ["# optimize_seams(): 1 thread against 2", "",
     f"Made by `benchmark/Surface_mesh_seam_optimization/run_threads.sh`; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}, "
     f"git {commit}, {nproc} cores; bijective default (two starts), the CLI with `--threads 1` then `--threads 2`, "
     "one run each (the machine is shared: wall times are noisy).", "",
     "| mesh | 1 thread s | 2 threads s | speed-up | same OBJ |", "|---|---|---|---|---|"]
ups = []
for name, s1, s2, same in rows:
    up = float(s1) / float(s2)
    ups.append(up)
    L.append(f"| {name} | {float(s1):.2f} | {float(s2):.2f} | {up:.2f}x | {same} |")
L += ["", f"Median speed-up {statistics.median(ups):.2f}x (worst {min(ups):.2f}x, best {max(ups):.2f}x); "
      f"{sum(r[3] == 'yes' for r in rows)} of {len(rows)} outputs byte-identical.", "",
      "What runs in parallel: the two starts, one per thread (the call waits for both, so the speed-up "
      "is lower where one start takes much longer than the other), the scoring of topology "
      "candidates (topology queries are 1-6% of a run, `results.md`, time by phase), and from 8192 "
      "triangles (charts and scaffold) the element loops of every Newton iteration: energies, "
      "gradients and Hessians, the line search's energies and the flip-free bounds, computed in "
      "parallel by blocks of 4096 elements and added in element order, so that the sums have the "
      "serial loop's bits. With two starts on two cores these only gain where one start runs alone.", ""]
dense = [l.strip().split(",") for l in open(dense_file) if l.strip()]
if dense:
    L += ["## Distortion only (`--keep-seams`): one descent", "",
          "`minimize_distortion()` through the CLI, 1 thread then 2, twice alternately; the median of the "
          "two (seconds of the report). One Newton descent: only the element loops run in parallel; "
          "the factorizations and solves (the LDL^T by blocks, CHOLMOD from 65536 unknowns with a "
          "serial OpenBLAS) do not.", "",
          "| mesh | faces | 1 thread s | 2 threads s | speed-up | same OBJ |", "|---|---|---|---|---|---|"]
    for name, faces, s1, s2, same in dense:
        a = statistics.median(float(x) for x in s1.split(";"))
        b = statistics.median(float(x) for x in s2.split(";"))
        L.append(f"| {name} | {faces} | {a:.2f} | {b:.2f} | {a / b:.2f}x | {same} |")
    L.append("")
open(prefix + ".md", "w").write("\n".join(L))
print("\n".join(L))
EOF
