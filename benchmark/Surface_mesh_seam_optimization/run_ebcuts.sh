#!/usr/bin/env bash
# The EBCuts baseline (--cut-strategy ebcuts) on every mesh of
# reference_optcuts.csv, at the bound 4.1, judged by uvmetrics.py, beside
# OptCuts' seams: ours from the first table of benchmark/results.md (default,
# bijective) and from its table without bijectivity, and the paper's code's
# (reference_optcuts.csv). EBCuts has no scaffold: its overlaps are reported,
# not prevented.
#
# Usage: run_ebcuts.sh [--build-dir DIR] [--data-dir DIR] [--out PREFIX] [--timeout S]
#                      [--max-faces N] [--work-dir DIR] [mesh ...]
# Meshes in order of size; --max-faces leaves out larger ones. --work-dir
# keeps the outputs there (a mesh already done there is not run again), so
# that an interrupted run can be resumed. Writes PREFIX.md (default
# benchmark/results_ebcuts).
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build_dir=$repo/build
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
out_prefix=$repo/benchmark/results_ebcuts
timeout_s=600
max_faces=0
work=
names=()
while (($#)); do
  case $1 in
    --build-dir) build_dir=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    --timeout) timeout_s=$2; shift ;;
    --max-faces) max_faces=$2; shift ;;
    --work-dir) work=$2; shift ;;
    *) names+=("$1") ;;
  esac
  shift
done
bin=$build_dir/cli/optimize_seams
[[ -x $bin ]] || { echo "run_ebcuts: $bin not built" >&2; exit 1; }
uvmetrics=$data_dir/../tools/uvmetrics.py
reference=$data_dir/reference_optcuts.csv
((${#names[@]})) || mapfile -t names < <(grep -v '^#' "$reference" | tail -n +2 |
  awk -F, -v m="$max_faces" '!seen[$1]++ && (m == 0 || $3 <= m) {print $3, $1}' | sort -n | cut -d' ' -f2)
if [[ -z $work ]]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi
mkdir -p "$work"

for name in "${names[@]}"; do
  mesh=$data_dir/benchmark/$name.obj
  [[ -f $mesh ]] || { echo "run_ebcuts: no $mesh" >&2; continue; }
  [[ -f $work/$name.uvm.json ]] && continue
  timeout "$timeout_s" "$bin" "$mesh" -o "$work/$name.obj" --report "$work/$name.json" --quiet \
    --cut-strategy ebcuts || echo "run_ebcuts: $name failed or timed out" >&2
  [[ -f $work/$name.obj ]] && python3 "$uvmetrics" "$work/$name.obj" --json > "$work/$name.uvm.json" 2>/dev/null
  echo "run_ebcuts: $name done" >&2
done

python3 - "$work" "$reference" "$repo/benchmark/results.md" "$out_prefix.md" "${names[@]}" <<'PY'
import json, math, os, sys
work, reference, results, out = sys.argv[1:5]
names = sys.argv[5:]
ref = {}
for line in open(reference):
    if line.startswith("#") or line.startswith("mesh,"): continue
    p = line.strip().split(",")
    if len(p) < 5: continue
    if p[1] == "1" or p[0] not in ref: ref[p[0]] = float(p[4])
# E_se of our default (bijective) table and of the table without bijectivity
ours, ours_nb = {}, {}
table, section_nb = None, False
for line in open(results):
    if line.startswith("## "):
        section_nb = line.startswith("## Without bijectivity")
        table = None
        continue
    if line.startswith("| mesh | faces | s |"):
        table = ours_nb if section_nb else (ours if not ours else None)
        continue
    if table is not None:
        if not line.startswith("|"): table = None; continue
        c = [x.strip() for x in line.strip().strip("|").split("|")]
        if c[0].startswith("---"): continue
        try: table[c[0]] = float(c[11])
        except ValueError: pass
rows, ratios, ratios_nb, ref_ratios = [], [], [], []
for n in names:
    try:
        r = json.load(open(os.path.join(work, n + ".json")))
        m = json.load(open(os.path.join(work, n + ".uvm.json")))
        if isinstance(m, list): m = m[0]
    except (OSError, ValueError):
        rows.append("| %s |" % n + " |" * 12 + " failed or timed out |"); continue
    se = m["seam_length_normalized"]
    o, onb = ours.get(n), ours_nb.get(n)
    ratio = se / o if o else float("nan")
    ratio_nb = se / onb if onb else float("nan")
    if o: ratios.append(ratio)
    if onb: ratios_nb.append(ratio_nb)
    if n in ref: ref_ratios.append(se / ref[n])
    rows.append("| %s | %d | %.4f | %.3f | %s | %s | %s | %s | %s | %d | %d | %d | %.1f | %s |" % (
        n, r["faces"], m["e_sd"], se, "%.3f" % o if o else "", "%.3f" % onb if onb else "",
        "%.3f" % ref[n] if n in ref else "", "%.2f" % ratio if o else "", "%.2f" % ratio_nb if onb else "",
        r["topology_operations"], m["flipped"], m["overlap_pairs"], r["seconds"], r["status"]))
geo = lambda v: math.exp(sum(map(math.log, v)) / len(v)) if v else float("nan")
with open(out, "w") as f:
    f.write("# EBCuts baseline (`run_ebcuts.sh`)\n\n")
    f.write("`--cut-strategy ebcuts` at the bound 4.1: cuts grown one at a time from the vertex of largest\n"
            "distortion to the nearest seam or border (shortest path), the distortion minimized with the seams\n"
            "fixed in between, until the bound is met; no scaffold (overlaps reported). E_SD, E_se, flips and\n"
            "overlaps by uvmetrics.py. *OptCuts E_se*: ours, default (bijective), from the first table of\n"
            "`results.md`; *no bij.*: ours without bijectivity (`--no-bijectivity`), like EBCuts here, from\n"
            "its table there; *ref E_se*: the paper's code's (`reference_optcuts.csv`).\n\n")
    stats = lambda v: "geometric mean %.3f, smallest %.3f, largest %.3f, above 1 on %d" % (
        geo(v), min(v) if v else float("nan"), max(v) if v else float("nan"), sum(x > 1 for x in v))
    f.write("- EBCuts E_se / OptCuts E_se (bijective) on %d meshes: %s\n" % (len(ratios), stats(ratios)))
    f.write("- EBCuts E_se / OptCuts E_se without bijectivity on %d meshes: %s\n" % (len(ratios_nb), stats(ratios_nb)))
    f.write("- EBCuts E_se / the paper's code's E_se on %d meshes: geometric mean %.3f\n\n" % (len(ref_ratios), geo(ref_ratios)))
    f.write("| mesh | faces | E_SD | EBCuts E_se | OptCuts E_se | OptCuts E_se no bij. | ref E_se | EBCuts / OptCuts "
            "| EBCuts / no bij. | cuts | flips | overlaps | s | status |\n")
    f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
    f.write("\n".join(rows) + "\n")
print("run_ebcuts: wrote", out)
PY
