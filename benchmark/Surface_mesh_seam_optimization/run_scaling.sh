#!/usr/bin/env bash
# The scaling mode of run_benchmark.sh (run it as `run_benchmark.sh --scaling`,
# which builds the programs and passes the arguments below).
#
# On the lucy_o_f* series (6k to 48k faces, a topological disk) and Loop
# subdivisions of lucy_o_f24136 (1 and 2 steps: 96544 and 386176 faces) and
# lucy_o_f48275 (2 steps: 772400 faces), made once into BUILD/scaling_meshes
# (not committed), in order of size, one process per run:
# - distortion only: the initial map (circle boundary + Tutte) timed alone,
#   then minimize_distortion() as a user calls it (seams fixed: none; from
#   16000 faces it starts from coarser meshes' maps), with the default
#   solver (Default_sparse_solver_traits: LDL^T by 2x2 blocks, CHOLMOD
#   supernodal from 65536 unknowns): to convergence up to CONVERGE_MAX_FACES faces, else
#   20 Newton iterations on the input mesh (the iteration count grows slowly
#   with the size, the cost of an iteration is what scales); and 20 such
#   iterations with Eigen_simplicial_ldlt_traits on every size, for comparison;
# - seam optimization: optimize_seams() at the bound, cancelled by a visitor
#   past TIME_LIMIT seconds; a size whose time, extrapolated from the sizes
#   done, exceeds 1.5 TIME_LIMIT, or larger than a size that was cancelled,
#   is not run (SKIPPED).
# Prints wall seconds and peak memory against faces, fits the exponents by
# least squares of log(y) against log(faces), and writes PREFIX.csv and
# PREFIX.md (and the same Markdown into APPEND_FILE, if given, replacing the
# section of an earlier scaling run).
set -u
[ $# -eq 14 ] || { echo "run_scaling.sh: called by run_benchmark.sh --scaling" >&2; exit 2; }
bin=$1 build_dir=$2 data_dir=$3 uvmetrics=$4 out_prefix=$5 time_limit=$6 timeout_s=$7 max_faces=$8
bound=$9 commit=${10} dirty=${11} cpu=${12} append_to=${13} converge_max_faces=${14}
capped_iterations=20

sub_bin=$(dirname "$bin")/subdivide_mesh
mesh_dir=$build_dir/scaling_meshes
mkdir -p "$mesh_dir"
series=()
for f in 6032 12067 24136 48275; do
  file=$data_dir/scalability/lucy_o_f$f.obj
  [ -f "$file" ] || { echo "missing $file" >&2; exit 2; }
  series+=("$file")
done
# (faces x4 per step: 96544, 386176, and 772400 from lucy_o_f48275)
for base_steps in 24136:1 24136:2 48275:2; do
  base=$data_dir/scalability/lucy_o_f${base_steps%:*}.obj
  steps=${base_steps#*:}
  file=$mesh_dir/lucy_o_f${base_steps%:*}_loop$steps.obj
  if [ ! -s "$file" ]; then
    tmp=${file%.obj}.part.obj # the writer picks the format from the extension
    "$sub_bin" "$base" "$tmp" "$steps" >&2 && mv "$tmp" "$file" || { echo "subdivision failed" >&2; exit 1; }
  fi
  series+=("$file")
done

work=$(mktemp -d "${TMPDIR:-/tmp}/smso_scaling.XXXXXX")
raw=$work/raw.csv
: > "$raw"
crashed=0
start_date=$(date -u '+%Y-%m-%d %H:%M UTC')
load_before=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)
seam_timeout=$(awk -v a="$timeout_s" -v b="$time_limit" 'BEGIN { t = 2 * b + 300; print (a > t ? a : t) }')
echo "scaling: ${#series[@]} meshes, seam optimization cancelled past ${time_limit}s, outputs in $work" >&2

# run MODE FILE [seam_benchmark options]: appends "MODE,<seam_benchmark line>" to raw, sets status
run() {
  local run_mode=$1 file=$2; shift 2
  local name; name=$(basename "$file" .obj)
  local out_dir=$work/$run_mode limit=$timeout_s
  [ "$run_mode" = seams ] && limit=$seam_timeout
  local t0 t1 line rc
  t0=$(date +%s.%N)
  line=$(timeout --kill-after=10 "$limit" "$bin" --no-header --bound "$bound" --out-dir "$out_dir" "$@" "$file" \
           2>"$work/$run_mode.$name.err")
  rc=$?
  t1=$(date +%s.%N)
  if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then
    line="$name,,$limit,,,,,,,,TIMEOUT,,,"
  elif [ $rc -ne 0 ] || [ -z "$line" ]; then
    line="$name,,,,,,,,,,CRASH_rc$rc,,,"
    crashed=1
  fi
  # independent check of the output (no overlap test: slow on 400k faces, and not what is measured here)
  if [ -f "$out_dir/$name.obj" ]; then
    timeout "$timeout_s" python3 "$uvmetrics" "$out_dir/$name.obj" --no-overlap --json \
      > "$work/$run_mode.$name.uvm.json" 2>/dev/null || true
    rm -f "$out_dir/$name.obj" # up to 40 MB each
  fi
  echo "$run_mode,$line" >> "$raw"
  printf '%-10s %-24s %7.1fs  %s\n' "$run_mode" "$name" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$line" >&2
  status=$(cut -d, -f11 <<<"$line")
}

# predicted seconds of optimize_seams() on $1 faces from the finished seam runs (empty below 2 runs)
predict_seams() {
  awk -F, -v F="$1" '$1 == "seams" && ($12 == "OK" || $12 ~ /^WARNING_(BOUND|MAX)/) && $4 > 0 {
      x = log($3); y = log($4); n++; sx += x; sy += y; sxx += x * x; sxy += x * y }
    END { if(n >= 2) { b = (n * sxy - sx * sy) / (n * sxx - sx * sx); a = (sy - b * sx) / n; printf "%.0f", exp(a + b * log(F)) } }' "$raw"
}

skip_seams=
for file in "${series[@]}"; do
  name=$(basename "$file" .obj)
  faces=$(grep -c '^f ' "$file")
  if [ "$max_faces" -gt 0 ] && [ "$faces" -gt "$max_faces" ]; then continue; fi
  if [ "$faces" -le "$converge_max_faces" ]; then
    run distortion "$file" --distortion-only
  else
    run distortion "$file" --distortion-only --max-iterations "$capped_iterations"
  fi
  run ldlt "$file" --distortion-only --solver ldlt --max-iterations "$capped_iterations"
  predicted=$(predict_seams "$faces")
  if [ -z "$skip_seams" ] && [ -n "$predicted" ] && [ "$predicted" -gt $((time_limit * 3 / 2)) ]; then
    skip_seams="predicted"
  fi
  if [ -n "$skip_seams" ]; then
    echo "seams,$name,$faces,$predicted,,,,,,,,SKIPPED,,," >> "$raw" # seconds: extrapolated
    echo "seams      $name: skipped (extrapolated ${predicted:-?} s)" >&2
    continue
  fi
  run seams "$file" --time-limit "$time_limit" --no-bijectivity
  case "$status" in OK|WARNING_BOUND_NOT_MET|WARNING_MAXIMUM_ITERATIONS) ;; *) skip_seams="cancelled" ;; esac
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)

python3 - "$raw" "$work" "$out_prefix" "$bound" "$commit" "$dirty" "$(nproc)" "$cpu" "$start_date" \
  "$load_before" "$load_after" "$time_limit" "$append_to" "$converge_max_faces" "$capped_iterations" <<'EOF'
import csv, json, math, os, sys
(raw, work, prefix, bound, commit, dirty, nproc, cpu, date, load_before, load_after, time_limit,
 append_to, converge_max_faces, capped) = sys.argv[1:]
fields = ["mode", "mesh", "faces", "seconds", "iterations", "topology_operations", "e_sd", "seam_length_normalized",
          "charts", "flipped_triangles", "peak_mb", "status", "bound_met", "lambda", "initial_map_seconds",
          "overlapping_pairs", "scaffold_rebuilds", "t_assembly", "t_factorization", "t_symbolic", "t_line_search",
          "t_topology", "t_scaffold"]
rows = [dict(zip(fields, l)) for l in csv.reader(open(raw)) if l]
for r in rows:
    p = os.path.join(work, f"{r['mode']}.{r['mesh']}.uvm.json")
    u = {}
    if os.path.exists(p):
        try: u = json.load(open(p))
        except ValueError: pass
    r["uvm_e_sd"], r["uvm_flips"], r["uvm_valid"] = u.get("e_sd"), u.get("flipped"), u.get("valid")

def num(x):
    try: return float(x)
    except (TypeError, ValueError): return None

def fit(points):
    """least squares of log y = a + b log x: (b, r^2, a, n), or None below 2 points"""
    pts = [(math.log(x), math.log(y)) for x, y in points if x and y and x > 0 and y > 0]
    if len(pts) < 2: return None
    n = len(pts)
    mx = sum(p[0] for p in pts) / n; my = sum(p[1] for p in pts) / n
    sxx = sum((p[0] - mx) ** 2 for p in pts); sxy = sum((p[0] - mx) * (p[1] - my) for p in pts)
    syy = sum((p[1] - my) ** 2 for p in pts)
    b = sxy / sxx
    return b, (sxy * sxy / (sxx * syy) if syy > 0 else 1.0), my - b * mx, n

def fmt(x, d=2):
    return "-" if x is None else f"{x:.{d}f}"

finished = lambda r: r["status"] in ("OK", "WARNING_BOUND_NOT_MET", "WARNING_MAXIMUM_ITERATIONS")
converged = lambda r: r["status"] == "OK"
by_mode = {}
for r in rows: by_mode.setdefault(r["mode"], {})[r["mesh"]] = r
dist, chol, seam = by_mode.get("distortion", {}), by_mode.get("ldlt", {}), by_mode.get("seams", {})
# the input mesh's Newton iterations alone (the call's seconds include the initial map and coarser levels)
newton_s = lambda r: sum(num(r.get(k)) or 0 for k in ("t_assembly", "t_factorization", "t_symbolic", "t_line_search"))
per_it = lambda r: newton_s(r) / num(r["iterations"]) if num(r["iterations"]) and newton_s(r) else None
# a capped descent whose map still has a tiny triangle returns no map, but its iterations were timed
timed = lambda r: finished(r) or (r["status"] == "ERROR_DEGENERATE_UV_RESULT" and num(r["iterations"]) is not None)

with open(prefix + ".csv", "w", newline="") as f:
    cols = fields + ["uvm_e_sd", "uvm_flips", "uvm_valid"]
    w = csv.DictWriter(f, fieldnames=cols)
    w.writeheader()
    for r in rows: w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in cols})

fits = []
def add_fit(label, rs, keep, key):
    fr = fit([(num(r["faces"]), key(r)) for r in rs.values() if keep(r)])
    fits.append((label, fr))
    return fr
add_fit("initial map (circle + Tutte): seconds", dist, lambda r: num(r["initial_map_seconds"]) is not None,
        lambda r: num(r["initial_map_seconds"]))
add_fit("minimize_distortion(), default solver: seconds per Newton iteration", dist, timed, per_it)
add_fit("minimize_distortion(), default solver: seconds to convergence", dist, converged, lambda r: num(r["seconds"]))
add_fit("minimize_distortion(): Newton iterations to convergence", dist, converged,
        lambda r: num(r["iterations"]))
add_fit("minimize_distortion(), default solver: peak MB", dist, timed, lambda r: num(r["peak_mb"]))
if chol:
    add_fit("minimize_distortion(), SimplicialLDLT: seconds per Newton iteration", chol, timed, per_it)
    add_fit("minimize_distortion(), SimplicialLDLT: peak MB", chol, timed, lambda r: num(r["peak_mb"]))
seam_fit = add_fit("optimize_seams(): seconds", seam, finished, lambda r: num(r["seconds"]))
add_fit("optimize_seams(): Newton iterations", seam, finished, lambda r: num(r["iterations"]))
add_fit("optimize_seams(): peak MB", seam, finished, lambda r: num(r["peak_mb"]))

L = ["<!-- scaling:begin -->", "## Scaling (lucy series and Loop subdivisions)", ""]
L.append(f"Made by `run_benchmark.sh --scaling`.")
L.append("")
L.append(f"- date: {date}; git commit: {commit}" +
         (f" (working tree had {dirty} uncommitted change(s) in include/ or the benchmark source)" if dirty != "0" else ""))
L.append(f"- machine: {nproc} cores (nproc), {cpu}; load average at start {load_before}, at end {load_after} "
         "(the machine is shared with other jobs: wall times are noisy, one run per size)")
L.append("- meshes: lucy_o_f6032 to lucy_o_f48275 (shared data; each a topological disk), lucy_o_f24136 "
         "after 1 and 2 steps of Loop subdivision and lucy_o_f48275 after 2 (CGAL::Subdivision_method_3, made by "
         "`subdivide_mesh`)")
L.append(f"- distortion only: the initial map alone (circle boundary + Tutte through Surface_mesh_parameterization; "
         f"\"init s\"), then `minimize_distortion()` as a user calls it (\"dist. s\": the whole call, its own initial "
         f"map included, and from 16000 faces its start from coarser meshes), seams fixed (none), default solver "
         f"(`Default_sparse_solver_traits`: LDL^T by 2x2 blocks, CHOLMOD supernodal from 65536 unknowns): to convergence up to {converge_max_faces} faces, else {capped} Newton iterations "
         f"on the input mesh (\"capped\"; E_SD is then not the minimum); \"s/it\": the input mesh's Newton iterations alone "
         f"(assembly, factorization, line search)"
         + (f"; SimplicialLDLT: the same with `Eigen_simplicial_ldlt_traits`, {capped} iterations on every size" if chol else ""))
L.append(f"- seams: `optimize_seams()` at the bound {bound}, not bijective, cancelled by a visitor past {time_limit} s "
         f"(WARNING_CANCELLED); a size whose time extrapolated from the finished sizes exceeds 1.5 x {time_limit} s, "
         "or larger than a cancelled one, is not run (SKIPPED, with the extrapolated seconds)")
L.append("- MB: peak resident memory (ru_maxrss) of the process, one process per run (mesh reading included); "
         "E_SD checked by uvmetrics.py on the written OBJ (no overlap test)")
L.append("")
hdr = ["mesh", "faces", "init s", "dist. s", "dist. Newton it", "dist. s/it", "dist. E_SD", "dist. MB"]
if chol: hdr += ["SimplicialLDLT s/it", "SimplicialLDLT MB"]
hdr += ["seams s", "seams Newton it", "topo ops", "seams E_SD", "E_se", "seams MB", "seams status"]
L.append("| " + " | ".join(hdr) + " |")
L.append("|" + "---|" * len(hdr))
for name, d in dist.items():
    s = seam.get(name, {})
    it = d["iterations"] or "-"
    capped = d["status"] in ("WARNING_MAXIMUM_ITERATIONS", "ERROR_DEGENERATE_UV_RESULT")
    if capped: it += " (capped)"
    cells = [name, d["faces"], fmt(num(d["initial_map_seconds"])), fmt(num(d["seconds"])), it,
             fmt(per_it(d), 4) if timed(d) else "-",
             "-" if capped else fmt(num(d["uvm_e_sd"]) if d["uvm_e_sd"] is not None else num(d["e_sd"]), 4),
             fmt(num(d["peak_mb"]), 0)]
    if chol:
        c = chol.get(name)
        cells += [fmt(per_it(c), 4) if c and timed(c) else (c["status"] if c else "-"),
                  fmt(num(c["peak_mb"]), 0) if c else "-"]
    st = s.get("status", "-") or "-"
    skipped = st == "SKIPPED"
    if skipped and num(s.get("seconds")):
        st += f" (extrapolated {num(s['seconds']) / 60:.0f} min)"
    cells += ["-" if skipped else fmt(num(s.get("seconds"))), s.get("iterations") or "-", s.get("topology_operations") or "-",
              fmt(num(s.get("uvm_e_sd")) if s.get("uvm_e_sd") is not None else num(s.get("e_sd")), 4),
              fmt(num(s.get("seam_length_normalized")), 3), fmt(num(s.get("peak_mb")), 0), st]
    L.append("| " + " | ".join(str(c) for c in cells) + " |")
L.append("")
L.append("Fitted exponents b of y ~ faces^b (least squares of log y against log faces, over the runs that "
         "finished; \"to convergence\" only over the converged ones):")
L.append("")
L.append("| quantity | exponent b | r^2 | sizes |")
L.append("|---|---|---|---|")
for label, fr in fits:
    L.append(f"| {label} | " + (f"{fr[0]:.2f} | {fr[1]:.3f} | {fr[3]}" if fr else "- | - | fewer than 2") + " |")
if seam_fit:
    b, _, a, _ = seam_fit
    big = max(num(r["faces"]) for r in dist.values())
    L.append("")
    L.append(f"Extrapolated from the fit, `optimize_seams()` on {int(big)} faces would take about "
             f"{math.exp(a + b * math.log(big)) / 3600:.1f} h on this machine.")
L.append("<!-- scaling:end -->")
text = "\n".join(L) + "\n"
open(prefix + ".md", "w").write(text)
print(text)
if append_to:
    old = open(append_to).read() if os.path.exists(append_to) else ""
    i, j = old.find("<!-- scaling:begin -->"), old.find("<!-- scaling:end -->")
    if i >= 0 and j > i:
        new = old[:i] + text.rstrip("\n") + old[j + len("<!-- scaling:end -->"):]
    else:
        new = old.rstrip("\n") + "\n\n" + text
    open(append_to, "w").write(new)
    print(f"scaling section written into {append_to}", file=sys.stderr)
print(f"wrote {prefix}.csv and {prefix}.md", file=sys.stderr)
EOF
[ $? -eq 0 ] || { echo "report generation failed" >&2; exit 1; }
echo "per-run logs: $work" >&2
exit $crashed
