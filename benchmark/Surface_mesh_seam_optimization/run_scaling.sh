#!/usr/bin/env bash
# The scaling mode of run_benchmark.sh (run it as `run_benchmark.sh --scaling`,
# which builds the programs and passes the arguments below).
#
# On the lucy_o_f* series (6k to 48k faces, a topological disk) and two Loop
# subdivisions of lucy_o_f24136 (96544 and 386176 faces, made once into
# BUILD/scaling_meshes, not committed), in order of size, one process per run:
# - minimize_distortion() from the initial map (circle boundary + Tutte, seams
#   fixed: none) on every size;
# - optimize_seams() at the bound with a time limit: a size that hits it is
#   reported as cancelled, and the larger sizes are not run.
# Prints wall seconds and peak memory against faces, fits the exponents by
# least squares of log(seconds) and log(MB) against log(faces), and writes
# PREFIX.csv and PREFIX.md (and the same Markdown into APPEND_FILE, if given).
set -u
[ $# -eq 13 ] || { echo "run_scaling.sh: called by run_benchmark.sh --scaling" >&2; exit 2; }
bin=$1 build_dir=$2 data_dir=$3 uvmetrics=$4 out_prefix=$5 time_limit=$6 timeout_s=$7 max_faces=$8
bound=$9 commit=${10} dirty=${11} cpu=${12} append_to=${13}

sub_bin=$(dirname "$bin")/subdivide_mesh
mesh_dir=$build_dir/scaling_meshes
mkdir -p "$mesh_dir"
series=()
for f in 6032 12067 24136 48275; do
  file=$data_dir/scalability/lucy_o_f$f.obj
  [ -f "$file" ] || { echo "missing $file" >&2; exit 2; }
  series+=("$file")
done
base=$data_dir/scalability/lucy_o_f24136.obj
for steps in 1 2; do
  file=$mesh_dir/lucy_o_f24136_loop$steps.obj
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

# run MODE FILE [seam_benchmark options]: appends "MODE,<seam_benchmark line>,<uvmetrics json file>" to raw
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
    line="$name,,$limit,,,,,,,,TIMEOUT,,"
  elif [ $rc -ne 0 ] || [ -z "$line" ]; then
    line="$name,,,,,,,,,,CRASH_rc$rc,,"
    crashed=1
  fi
  # independent check of the output (no overlap test: slow on 400k faces, and not what is measured here)
  if [ -f "$out_dir/$name.obj" ]; then
    timeout "$timeout_s" python3 "$uvmetrics" "$out_dir/$name.obj" --no-overlap --json \
      > "$work/$run_mode.$name.uvm.json" 2>/dev/null || true
    rm -f "$out_dir/$name.obj" # up to 40 MB each
  fi
  echo "$run_mode,$line" >> "$raw"
  printf '%-9s %-24s %7.1fs  %s\n' "$run_mode" "$name" "$(awk -v a="$t0" -v b="$t1" 'BEGIN{print b-a}')" "$line" >&2
  status=$(cut -d, -f11 <<<"$line")
}

skip_seams=
for file in "${series[@]}"; do
  faces=$(grep -c '^f ' "$file")
  if [ "$max_faces" -gt 0 ] && [ "$faces" -gt "$max_faces" ]; then continue; fi
  run distortion "$file" --distortion-only
  if [ -n "$skip_seams" ]; then
    echo "seams,$(basename "$file" .obj),$faces,,,,,,,,,SKIPPED,," >> "$raw"
    continue
  fi
  run seams "$file" --time-limit "$time_limit"
  case "$status" in OK|WARNING_BOUND_NOT_MET|WARNING_MAXIMUM_ITERATIONS) ;; *) skip_seams=1 ;; esac
done
load_after=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null)

python3 - "$raw" "$work" "$out_prefix" "$bound" "$commit" "$dirty" "$(nproc)" "$cpu" "$start_date" \
  "$load_before" "$load_after" "$time_limit" "$append_to" <<'EOF'
import csv, json, math, os, sys
(raw, work, prefix, bound, commit, dirty, nproc, cpu, date, load_before, load_after, time_limit,
 append_to) = sys.argv[1:]
fields = ["mode", "mesh", "faces", "seconds", "iterations", "topology_operations", "e_sd", "seam_length_normalized",
          "charts", "flipped_triangles", "peak_mb", "status", "bound_met", "lambda"]
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
    """least squares of log y = a + b log x: (b, r^2, a), or None below 2 points"""
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

done = lambda r: r["status"] in ("OK", "WARNING_BOUND_NOT_MET", "WARNING_MAXIMUM_ITERATIONS")
dist = [r for r in rows if r["mode"] == "distortion"]
seam = {r["mesh"]: r for r in rows if r["mode"] == "seams"}

with open(prefix + ".csv", "w", newline="") as f:
    cols = fields + ["uvm_e_sd", "uvm_flips", "uvm_valid"]
    w = csv.DictWriter(f, fieldnames=cols)
    w.writeheader()
    for r in rows: w.writerow({k: ("" if r.get(k) is None else r.get(k)) for k in cols})

fits = []
def add_fit(label, rs, key):
    pts = [(num(r["faces"]), key(r)) for r in rs if done(r)]
    fr = fit(pts)
    fits.append((label, fr))
    return fr
add_fit("minimize_distortion(): seconds", dist, lambda r: num(r["seconds"]))
add_fit("minimize_distortion(): seconds per Newton iteration", dist,
        lambda r: num(r["seconds"]) / num(r["iterations"]) if num(r["iterations"]) else None)
add_fit("minimize_distortion(): peak MB", dist, lambda r: num(r["peak_mb"]))
seam_fit = add_fit("optimize_seams(): seconds", list(seam.values()), lambda r: num(r["seconds"]))
add_fit("optimize_seams(): peak MB", list(seam.values()), lambda r: num(r["peak_mb"]))

L = ["<!-- scaling:begin -->", "## Scaling (lucy series and Loop subdivisions)", ""]
L.append(f"- date: {date}; git commit: {commit}" +
         (f" (working tree had {dirty} uncommitted change(s) in include/ or the benchmark source)" if dirty != "0" else ""))
L.append(f"- machine: {nproc} cores (nproc), {cpu}; load average at start {load_before}, at end {load_after} "
         "(the machine is shared: wall times are noisy, one run per size)")
L.append("- meshes: lucy_o_f6032 to lucy_o_f48275 (shared data, one topological disk each), and "
         "lucy_o_f24136 after 1 and 2 steps of Loop subdivision (CGAL::Subdivision_method_3, made by subdivide_mesh)")
L.append("- distortion only: `minimize_distortion()` from the initial map (circle boundary + Tutte, no seam), "
         "to convergence; s = wall seconds of the call (initial map included)")
L.append(f"- seams: `optimize_seams()` at the bound {bound}, not bijective, cancelled by a visitor past {time_limit} s "
         "(status WARNING_CANCELLED; the larger sizes are then not run: SKIPPED)")
L.append("- MB: peak resident memory (ru_maxrss) of the process, one process per run (reading the mesh included); "
         "E_SD checked by uvmetrics.py on the written OBJ (no overlap test)")
L.append("")
hdr = ["mesh", "faces", "dist. s", "dist. Newton it", "dist. s/it", "dist. E_SD", "dist. MB",
       "seams s", "seams Newton it", "topo ops", "seams E_SD", "E_se", "seams MB", "seams status"]
L.append("| " + " | ".join(hdr) + " |")
L.append("|" + "---|" * len(hdr))
for d in dist:
    s = seam.get(d["mesh"], {})
    it = num(d["iterations"])
    cells = [d["mesh"], d["faces"], fmt(num(d["seconds"])), d["iterations"] or "-",
             fmt(num(d["seconds"]) / it, 4) if it and num(d["seconds"]) else "-",
             fmt(num(d["uvm_e_sd"]) if d["uvm_e_sd"] is not None else num(d["e_sd"]), 4),
             fmt(num(d["peak_mb"]), 0),
             fmt(num(s.get("seconds"))), s.get("iterations") or "-", s.get("topology_operations") or "-",
             fmt(num(s.get("uvm_e_sd")) if s.get("uvm_e_sd") is not None else num(s.get("e_sd")), 4),
             fmt(num(s.get("seam_length_normalized")), 3), fmt(num(s.get("peak_mb")), 0),
             s.get("status", "-") or "-"]
    L.append("| " + " | ".join(str(c) for c in cells) + " |")
L.append("")
L.append("Fitted exponents (least squares of log y against log faces; only the runs that finished):")
L.append("")
L.append("| quantity | exponent | r^2 | sizes |")
L.append("|---|---|---|---|")
for label, fr in fits:
    L.append(f"| {label} | " + (f"{fr[0]:.2f} | {fr[1]:.3f} | {fr[3]}" if fr else "- | - | fewer than 2") + " |")
if seam_fit:
    b, _, a, _ = seam_fit
    big = max(num(r["faces"]) for r in dist)
    L.append("")
    L.append(f"Extrapolated from the fit, `optimize_seams()` on {int(big)} faces would take about "
             f"{math.exp(a + b * math.log(big)) / 3600:.1f} h.")
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
