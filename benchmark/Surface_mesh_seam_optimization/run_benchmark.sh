#!/usr/bin/env bash
# Runs seam_benchmark (optimize_seams at bound 4.1) on the shared benchmark
# meshes, one process per mesh (so that peak memory is per mesh), checks each
# output with the independent evaluator uvmetrics.py, and writes a CSV and a
# Markdown table with the paper's code's figures (reference_optcuts.csv) beside
# ours.
#
# Usage: run_benchmark.sh [--quick | --profile | --scaling] [--no-bijectivity] [--starts N] [--timeout S]
#                         [--bound B] [--out PREFIX] [--data-dir DIR] [--build-dir DIR]
#                         [--jobs N] [mesh ...]
#   --quick        cat_f1500 bishop_part_f1000 pyramid_f3000 sphere_f1522 bimba_i_f10000
#   --profile      the time of each run split by phase (assembly, factorization,
#                  symbolic analysis, line search, topology queries, scaffold), on the
#                  --quick meshes or those given; every report has this table too
#   --starts N     number_of_starts(N) (default 2: the first and the one without
#                  the scaffold first, or where the charts never overlap the one
#                  from a first straight cut; 3 runs both, 4 also the one whose
#                  dual step holds the price)
#   --no-bijectivity  bijective(false): no scaffold, charts may overlap (the
#                  reference's non-bijective figures are then the yardstick)
#   (default)      every mesh of reference_optcuts.csv
#   mesh ...       explicit mesh names (in DATA/benchmark) or .obj paths; mode "custom"
#   --scaling      seconds and peak memory against faces on DATA/scalability/lucy_o_f*
#                  and Loop subdivisions of lucy_o_f24136 and lucy_o_f48275 (96544,
#                  386176 and 772400 faces, made once into BUILD/scaling_meshes), with
#                  least-squares exponents
#                  (see run_scaling.sh): minimize_distortion() on every size (to
#                  convergence up to --converge-max-faces, else 20 Newton iterations),
#                  and optimize_seams() on the sizes that fit --time-limit
#   --time-limit S (scaling) cancel optimize_seams() past S seconds (default 900); a
#                  size predicted to take over 1.5 S, or larger than one that was
#                  cancelled, is not run
#   --converge-max-faces N (scaling) default 800000
#   --max-faces N  (scaling) leave out the meshes with more than N faces
#   --append FILE  (scaling) also put the Markdown report into FILE, replacing the
#                  section of an earlier scaling run
#   --timeout S    per-mesh time limit in seconds (default 600; scaling: 3600), after
#                  which the process is killed
#   --bound B      distortion bound (default 4.1; the reference figures are at 4.1)
#   --out PREFIX   write PREFIX.csv and PREFIX.md (default benchmark/results_<mode>)
#   --data-dir DIR shared data (default: <repo>/../shared/data, or $SMSO_SHARED_DATA)
#   --build-dir D  build directory (default <repo>/build-bench)
#   --jobs N       build parallelism (default 2)
#   --keep-outputs DIR  keep the per-mesh outputs (OBJ, errors, uvmetrics JSON) in DIR;
#                  by default they are deleted with the work directory at the end
# Results are not asserted: the exit code is non-zero only if the build fails or
# the program crashes (killed by a signal or an unexpected exit code). A mesh
# that times out or is rejected gets a row with its status.
set -u

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)

mode=full
timeout_s=
time_limit=900
max_faces=0
converge_max_faces=800000
append_to=
bound=4.1
bijective=1
out_prefix=
data_dir=${SMSO_SHARED_DATA:-$repo/../shared/data}
build_dir=$repo/build-bench
jobs=2
starts=2
keep_dir=
meshes=()
while [ $# -gt 0 ]; do
  case "$1" in
    --quick) mode=quick ;;
    --scaling) mode=scaling ;;
    --profile) mode=profile ;;
    --no-bijectivity) bijective=0 ;;
    --starts) starts=$2; shift ;;
    --time-limit) time_limit=$2; shift ;;
    --max-faces) max_faces=$2; shift ;;
    --converge-max-faces) converge_max_faces=$2; shift ;;
    --append) append_to=$2; shift ;;
    --timeout) timeout_s=$2; shift ;;
    --bound) bound=$2; shift ;;
    --out) out_prefix=$2; shift ;;
    --data-dir) data_dir=$2; shift ;;
    --build-dir) build_dir=$2; shift ;;
    --jobs) jobs=$2; shift ;;
    --keep-outputs) keep_dir=$2; shift ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    -*) echo "unknown option $1" >&2; exit 2 ;;
    *) meshes+=("$1"); [ "$mode" = profile ] || mode=custom ;;
  esac
  shift
done
if [ -z "$timeout_s" ]; then
  if [ "$mode" = scaling ]; then timeout_s=3600; else timeout_s=600; fi
fi

if [ ! -d "$data_dir" ]; then echo "shared data not found: $data_dir (use --data-dir)" >&2; exit 2; fi
data_dir=$(cd "$data_dir" && pwd)
reference=$data_dir/reference_optcuts.csv
uvmetrics=$data_dir/../tools/uvmetrics.py
[ -f "$uvmetrics" ] || uvmetrics=$repo/../shared/tools/uvmetrics.py
[ -n "$out_prefix" ] || out_prefix=$repo/benchmark/results_$mode
mkdir -p "$(dirname "$out_prefix")"

# --- build (configure once; make is a no-op when up to date)
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
  cmake -S "$repo" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release || { echo "configure failed" >&2; exit 1; }
fi
targets=(seam_benchmark)
[ "$mode" = scaling ] && targets+=(subdivide_mesh)
cmake --build "$build_dir" --target "${targets[@]}" -j "$jobs" || { echo "build failed" >&2; exit 1; }
bin=$build_dir/benchmark/Surface_mesh_seam_optimization/seam_benchmark
[ -x "$bin" ] || { echo "no binary $bin" >&2; exit 1; }

# SMSO_BENCH_COMMIT names the commit when the tree is an export (git archive) without .git
commit=${SMSO_BENCH_COMMIT:-$(git -C "$repo" rev-parse --short HEAD 2>/dev/null || echo unknown)}
cpu=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | cut -d: -f2- | sed 's/^ *//')
dirty=$(git -C "$repo" status --porcelain -- include benchmark/Surface_mesh_seam_optimization/seam_benchmark.cpp 2>/dev/null | wc -l)

if [ "$mode" = scaling ]; then
  exec bash "$script_dir/run_scaling.sh" "$bin" "$build_dir" "$data_dir" "$uvmetrics" "$out_prefix" \
    "$time_limit" "$timeout_s" "$max_faces" "$bound" "$commit" "$dirty" "$cpu" "$append_to" "$converge_max_faces"
fi

# --- mesh list
if [ "$mode" = quick ] || { [ "$mode" = profile ] && [ ${#meshes[@]} -eq 0 ]; }; then
  meshes=(cat_f1500 bishop_part_f1000 pyramid_f3000 sphere_f1522 bimba_i_f10000)
elif [ "$mode" = full ]; then
  [ -f "$reference" ] || { echo "no $reference" >&2; exit 2; }
  mapfile -t meshes < <(grep -v '^#' "$reference" | tail -n +2 | cut -d, -f1 | awk 'NF && !seen[$0]++')
fi

work=$(mktemp -d "${TMPDIR:-/tmp}/smso_bench.XXXXXX")
# (a run of 19 meshes leaves about 20 MB of OBJ files)
trap 'rm -rf "$work"' EXIT
out_dir=$work/out
mkdir -p "$out_dir"
raw=$work/raw.csv
: > "$raw"
crashed=0
start_date=$(date -u '+%Y-%m-%d %H:%M UTC')
load_before=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
echo "mode $mode: ${#meshes[@]} meshes, bound $bound, timeout ${timeout_s}s, work directory $work" >&2

for m in "${meshes[@]}"; do
  case "$m" in
    */*|*.obj|*.off) file=$m ;;
    *) file=$data_dir/benchmark/$m.obj ;;
  esac
  name=$(basename "$file"); name=${name%.*}
  t0=$(date +%s.%N)
  bij_flag=(); [ "$bijective" = 1 ] || bij_flag=(--no-bijectivity)
  line=$(timeout --kill-after=10 "$timeout_s" "$bin" --no-header --bound "$bound" --starts "$starts" "${bij_flag[@]}" --out-dir "$out_dir" "$file" 2>"$work/$name.err")
  rc=$?
  t1=$(date +%s.%N)
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    line="$name,,$timeout_s,,,,,,,,TIMEOUT,,"
  elif [ $rc -ne 0 ] || [ -z "$line" ]; then
    line="$name,,,,,,,,,,CRASH_rc$rc,,"
    crashed=1
  fi
  # uvmetrics on the output (independent figures)
  if [ -f "$out_dir/$name.obj" ]; then
    timeout "$timeout_s" python3 "$uvmetrics" "$out_dir/$name.obj" --json > "$work/$name.uvm.json" 2>"$work/$name.uvm.err" || true
  fi
  echo "$line" >> "$raw"
  printf '%-24s %6.1fs  %s\n' "$name" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$line" >&2
done


python3 - "$raw" "$work" "$reference" "$out_prefix" "$mode" "$bound" "$commit" "$dirty" "$(nproc)" "$cpu" \
  "$start_date" "$load_before" "$timeout_s" "$bijective" "$starts" <<'EOF'
import csv, json, os, statistics, sys
raw, work, reference, prefix, mode, bound, commit, dirty, nproc, cpu, date, load, timeout_s, bijective, starts = sys.argv[1:]
fields = ["mesh", "faces", "seconds", "iterations", "topology_operations", "e_sd", "seam_length_normalized",
          "charts", "flipped_triangles", "peak_mb", "status", "bound_met", "lambda", "initial_map_seconds",
          "overlapping_pairs", "scaffold_rebuilds", "t_assembly", "t_factorization", "t_symbolic",
          "t_line_search", "t_topology", "t_scaffold", "start"]
rows = [dict(zip(fields, l)) for l in csv.reader(open(raw)) if l]

ref = {}  # mesh -> {bijective flag -> row}
if os.path.exists(reference):
    lines = [l for l in open(reference) if not l.startswith("#")]
    for r in csv.DictReader(lines):
        ref.setdefault(r["mesh"], {})[r["bijective"]] = r

def num(x):
    try: return float(x)
    except (TypeError, ValueError): return None

def fmt(x, d=2):
    return "-" if x is None else f"{x:.{d}f}"

out = []
for r in rows:
    u = {}
    p = os.path.join(work, r["mesh"] + ".uvm.json")
    if os.path.exists(p):
        try: u = json.load(open(p))
        except ValueError: u = {}
    rr = ref.get(r["mesh"], {})
    rb = (rr.get("1") or rr.get("0")) if bijective == "1" else (rr.get("0") or rr.get("1"))
    o = dict(r)
    o["uvm_e_sd"] = u.get("e_sd")
    o["uvm_seam_length_normalized"] = u.get("seam_length_normalized")
    o["uvm_charts"] = u.get("charts")
    o["uvm_flips"] = u.get("flipped")
    o["uvm_overlap_pairs"] = u.get("overlap_pairs")
    o["uvm_valid"] = u.get("valid")
    o["ref_bijective"] = rb["bijective"] if rb else None
    for k in ("e_sd", "seam_norm", "wall_s", "newton_iterations", "peak_mb"):
        o["ref_" + k] = num(rb[k]) if rb else None
    has = r["status"] == "OK" or r["status"].startswith("WARNING")
    se = None if not has else num(o["uvm_seam_length_normalized"]) if o["uvm_seam_length_normalized"] is not None else num(r["seam_length_normalized"])
    o["seam_ratio"] = se / o["ref_seam_norm"] if se is not None and o["ref_seam_norm"] else None
    s = num(r["seconds"])
    o["speedup"] = o["ref_wall_s"] / s if has and s and o["ref_wall_s"] else None
    out.append(o)

cols = list(out[0].keys()) if out else fields
with open(prefix + ".csv", "w", newline="") as f:
    w = csv.DictWriter(f, fieldnames=cols)
    w.writeheader()
    for o in out:
        w.writerow({k: ("" if v is None else v) for k, v in o.items()})

ok = [o for o in out if num(o["seconds"]) is not None and o["status"] not in ("TIMEOUT",) and not o["status"].startswith(("ERROR", "CRASH"))]
ours_med = statistics.median([num(o["seconds"]) for o in ok]) if ok else None
both = [o for o in ok if o["ref_wall_s"]]
ref_med = statistics.median([o["ref_wall_s"] for o in both]) if both else None
ours_med_both = statistics.median([num(o["seconds"]) for o in both]) if both else None

L = []
L.append(f"# optimize_seams benchmark ({mode})\n")
L.append(f"- date: {date}; git commit: {commit}" + (f" (working tree had {dirty} uncommitted change(s) in include/ or the benchmark source)" if dirty != "0" else "") + "")
L.append(f"- machine: {nproc} cores (nproc), {cpu}; load average at start: {load}")
if bijective == "1":
    L.append(f"- settings: distortion bound {bound}, default settings (bijective: scaffold on)" + ("" if starts == "2" else f" but number_of_starts({starts})") + f", one process per mesh, time limit {timeout_s} s per mesh")
    L.append(f"- reference: the paper's code on this kind of machine (reference_optcuts.csv), its bijective run (ref bij = 1) where there is one, else its non-bijective one (ref bij = 0)")
else:
    L.append(f"- settings: distortion bound {bound}, bijective(false) (no scaffold: charts may overlap)" + ("" if starts == "2" else f", number_of_starts({starts})") + f", one process per mesh, time limit {timeout_s} s per mesh")
    L.append(f"- reference: the paper's code on this kind of machine (reference_optcuts.csv); the non-bijective row where there is one (ref bij = 0), else the bijective one (ref bij = 1)")
L.append(f"- s: wall seconds of the optimize_seams() call; E_SD, E_se (normalized seam length), flips and overlapping pairs by uvmetrics.py on the written OBJ; E_SD lib / E_se lib: the library's own figures; MB: peak resident memory (ru_maxrss) of the process")
L.append(f"- ratios: E_se / ref E_se (< 1: shorter seams), ref s / s (> 1: faster)")
if ours_med is not None:
    line = f"- median wall time: {ours_med:.2f} s over {len(ok)} meshes"
    if ref_med is not None:
        line += f"; on the {len(both)} meshes with a reference: ours {ours_med_both:.2f} s, reference {ref_med:.2f} s (ratio {ref_med / ours_med_both:.2f}x)"
    L.append(line)
# seams against the reference: the figures issue 19 judges by
rated = [o for o in out if o["seam_ratio"] is not None]
if rated:
    import math
    gm = math.exp(sum(math.log(o["seam_ratio"]) for o in rated) / len(rated))
    worst = max(rated, key=lambda o: o["seam_ratio"])
    above = lambda t: sum(1 for o in rated if o["seam_ratio"] > t)
    L.append(f"- seams (E_se / ref E_se) on {len(rated)} meshes: geometric mean {gm:.3f}, worst {worst['seam_ratio']:.3f} ({worst['mesh']}), "
             f"{above(1.05)} above 1.05, {above(1.1)} above 1.1")
    unmet = [o["mesh"] for o in out if o["uvm_e_sd"] in (None, "") or num(o["uvm_e_sd"]) is None or num(o["uvm_e_sd"]) > float(bound) + 1e-9]
    bad = [o["mesh"] for o in out if str(o["uvm_flips"]) not in ("0", "None") or str(o["uvm_overlap_pairs"]) not in ("0", "None")]
    L.append(f"- bound met on {len(out) - len(unmet)} of {len(out)} meshes" + (f" (not: {', '.join(unmet)})" if unmet else "")
             + f"; flips or overlaps on {len(bad)}" + (f" ({', '.join(bad)})" if bad else ""))
L.append("")
hdr = ["mesh", "faces", "s", "ref s", "ref s / s", "Newton it", "ref it", "topo ops", "E_SD", "E_SD lib", "ref E_SD",
       "E_se", "E_se lib", "ref E_se", "ref bij", "E_se / ref", "charts", "flips", "overlaps", "MB", "ref MB", "status"]
L.append("| " + " | ".join(hdr) + " |")
L.append("|" + "---|" * len(hdr))
for o in out:
    cells = [o["mesh"], o["faces"] or "-", fmt(num(o["seconds"])), fmt(o["ref_wall_s"]), fmt(o["speedup"]),
             o["iterations"] or "-", fmt(o["ref_newton_iterations"], 0), o["topology_operations"] or "-",
             fmt(num(o["uvm_e_sd"]), 4), fmt(num(o["e_sd"]), 4), fmt(o["ref_e_sd"], 4),
             fmt(num(o["uvm_seam_length_normalized"]), 3), fmt(num(o["seam_length_normalized"]), 3),
             fmt(o["ref_seam_norm"], 3), o["ref_bijective"] or "-", fmt(o["seam_ratio"]),
             str(o["uvm_charts"]) if o["uvm_charts"] is not None else (o["charts"] or "-"),
             str(o["uvm_flips"]) if o["uvm_flips"] is not None else (o["flipped_triangles"] or "-"),
             str(o["uvm_overlap_pairs"]) if o["uvm_overlap_pairs"] is not None else "-",
             fmt(num(o["peak_mb"]), 0), fmt(o["ref_peak_mb"], 0), o["status"]]
    L.append("| " + " | ".join(str(c) for c in cells) + " |")
# where the time goes (Optimization_result::timings)
phases = [("t_assembly", "assembly"), ("t_factorization", "factorization"), ("t_symbolic", "symbolic analysis"),
          ("t_line_search", "line search"), ("t_topology", "topology queries"), ("t_scaffold", "scaffold")]
timed = [o for o in out if num(o.get("t_assembly")) is not None and num(o["seconds"])]
if timed:
    L.append("")
    L.append("## Time by phase\n")
    L.append("Seconds (and share of the wall time) of each phase of the kept start (all of its path: the relaxed start's run without the scaffold, the first-cut start's distortion minimization); other: setup, measures, copies, and the time the call waited for the starts not kept, which ran beside it. Scaffold rebuilds: times the scaffold was meshed.\n")
    hdr = ["mesh", "s"] + [p[1] for p in phases] + ["other", "scaffold rebuilds"]
    L.append("| " + " | ".join(hdr) + " |")
    L.append("|" + "---|" * len(hdr))
    sums = [0.0] * (len(phases) + 2)
    for o in timed:
        s = num(o["seconds"])
        ts = [num(o[p[0]]) or 0.0 for p in phases]
        other = max(0.0, s - sum(ts))
        for i, t in enumerate(ts + [other]): sums[i] += t
        sums[-1] += s
        L.append("| " + " | ".join([o["mesh"], fmt(s)] + [f"{t:.2f} ({100 * t / s:.0f}%)" for t in ts + [other]]
                                   + [o.get("scaffold_rebuilds") or "-"]) + " |")
    tot = sums[-1]
    L.append("| " + " | ".join(["all", fmt(tot)] + [f"{t:.2f} ({100 * t / tot:.0f}%)" for t in sums[:-1]] + ["-"]) + " |")
open(prefix + ".md", "w").write("\n".join(L) + "\n")
print("\n".join(L))
print(f"\nwrote {prefix}.csv and {prefix}.md", file=sys.stderr)
EOF
py=$?
[ $py -eq 0 ] || { echo "report generation failed" >&2; exit 1; }
if [ -n "$keep_dir" ]; then
  mkdir -p "$keep_dir" && cp "$work"/*.err "$work"/*.json "$out_dir"/* "$keep_dir"/ 2>/dev/null
  echo "per-mesh outputs: $keep_dir" >&2
fi
exit $crashed
