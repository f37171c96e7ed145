#!/usr/bin/env bash
# Side-by-side with CalculiX: one case's hexahedral mesh through bladebench and through ccx
# (exported by `bladebench export-calculix`, so the mesh, sets and constraints are identical),
# compared frequency by frequency, with the wall times of both measured in this same run.
# See bench/README.md, "Side-by-side with CalculiX".
#
# usage: bench/calculix_compare.sh [--bar NX NY NZ]... [CASE.toml ...]
#   CASE      modal case files with a 3D solid mesh. Default: cases/verification/bar_modal_hex20.toml,
#             and cases/thesis/table06_glued_modal.toml when it exists.
#   --bar     also run a copy of the bar case with NX x NY x NZ elements (written to the work folder),
#             after the CASE files or the default ones.
# environment:
#   BB       bladebench binary          (default build/solvers/bladebench)
#   CCX      CalculiX binary            (default ccx; Debian package calculix-ccx)
#   THREADS  OMP_NUM_THREADS of both programs (default 2)
#   REPEAT   runs of each program per case; the smallest wall time is kept (default 3)
#   MODES    modes asked of ccx         (default: as many as bladebench returned)
#   TOL      relative tolerance of the frequency verdict (default 1e-4)
#   WORK     scratch folder             (default: a new mktemp -d folder, kept)
# ccx is timed three times: with OMP_NUM_THREADS=THREADS alone (its SPOOLES solver then also runs
# on THREADS threads), with CCX_NPROC_EQUATION_SOLVER=1 as well (SPOOLES on one thread, the rest
# on THREADS), and on the deck without its *STEP (input phase only, subtracted for the solve ratio).
#
# Element correspondence (what "the same mesh" means for each element):
#   hex8  -> C3D8   the same element (trilinear, 2x2x2 Gauss, consistent mass): frequencies must agree
#   hex20 -> C3D20  the same element (serendipity, 3x3x3 Gauss, consistent mass): must agree
#   hex8i -> C3D8I  the same stiffness (Wilson's incompatible modes with Taylor's correction: static
#                   answers agree), NOT the same inertia: C3D8I keeps the nine incompatible-mode
#                   amplitudes as unknowns of the eigenproblem and gives them mass; hex8i condenses
#                   them out of the stiffness and gives them none (as OptiStruct's 8-node solid).
#                   The frequencies then differ by a discretization error that vanishes like h^2
#                   (several % on coarse meshes; tests/unit/hex8i_inertia_test.cpp reproduces
#                   C3D8I's numbers from that one difference). For hex8i the table is shown and
#                   marked "different element", and it does not make the verdict fail.
# Rigid-body modes (both frequencies below 1e-4 of the case's highest) are reported as such, 0 Hz,
# and agree; a mode rigid in one program and not in the other disagrees.
# Exit code: 0 every frequency of the same elements agrees within TOL, 1 some do not, 2 a run failed.
set -euo pipefail

cd "$(dirname "$0")/.."
BB=${BB:-build/solvers/bladebench}
CCX=${CCX:-ccx}
THREADS=${THREADS:-2}
REPEAT=${REPEAT:-3}
TOL=${TOL:-1e-4}
WORK=${WORK:-$(mktemp -d /tmp/calculix_compare.XXXXXX)}
BAR=cases/verification/bar_modal_hex20.toml

die() { echo "error: $*" >&2; exit 2; }
[[ -x $BB ]] || die "no bladebench binary at $BB (cmake --preset release && cmake --build build -j2)"
command -v "$CCX" > /dev/null || die "no CalculiX binary '$CCX' (apt-get install calculix-ccx)"
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)

cases=() bars=()
while (($#)); do
  case $1 in
    --bar)
      (($# >= 4)) || die "--bar needs NX NY NZ"
      copy="$WORK/bar_modal_hex20_${2}x${3}x${4}.toml"
      # Same bar, finer divisions; the reference path made absolute so the copy's check still resolves.
      sed -e "s/^nx = .*/nx = $2/" -e "s/^ny = .*/ny = $3/" -e "s/^nz = .*/nz = $4/" \
          -e "s/^name = \"bar_modal_hex20\"/name = \"bar_modal_hex20_${2}x${3}x${4}\"/" \
          -e "s#^reference = \"../../#reference = \"$PWD/#" "$BAR" > "$copy"
      bars+=("$copy")
      shift 4 ;;
    -h|--help) sed -n '2,37p' "$0"; exit 0 ;;
    *) cases+=("$1"); shift ;;
  esac
done
if ((${#cases[@]} == 0)); then
  cases=("$BAR")
  [[ -f cases/thesis/table06_glued_modal.toml ]] && cases+=(cases/thesis/table06_glued_modal.toml)
fi
cases+=(${bars[@]+"${bars[@]}"})

now() { date +%s.%N; }
elapsed() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
min() { awk -v a="$1" -v b="$2" 'BEGIN { print (a == "" || b + 0 < a + 0) ? b : a }'; }

# Frequencies [Hz] of ccx's .dat: column CYCLES/TIME of the first E I G E N V A L U E table.
ccx_frequencies() {
  awk '/E I G E N V A L U E   O U T P U T/ { on = 1; next }
       on && /P A R T I C I P A T I O N|E I G E N V A L U E/ { exit }
       on && NF == 5 && $1 ~ /^[0-9]+$/ { printf "%.10g\n", $4 }' "$1"
}

# bladebench's frequencies.csv: the column named frequency_hz.
bb_frequencies() {
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "frequency_hz") c = i; next } { print $c }' "$1"
}

# measure DIR LOG CMD...: runs CMD in DIR REPEAT times; best = smallest wall time [s], rss = peak
# resident memory of the last run [MiB] (from /usr/bin/time, "-" without it), last_rc = its exit
# code. $ON_BEST, when set, is run after each run that set a new best (to keep that run's details).
measure() {
  local run_dir=$1 log=$2 r t0 t1 this
  shift 2
  best="" rss="-" last_rc=0
  for ((r = 1; r <= REPEAT; ++r)); do
    t0=$(now)
    if [[ -x /usr/bin/time ]]; then
      (cd "$run_dir" && /usr/bin/time -f %M -o "$log.rss" "$@" > "$log" 2>&1) && last_rc=0 || last_rc=$?
      rss=$(awk '{ v = $1 } END { printf "%.0f", v / 1024 }' "$log.rss")
    else
      (cd "$run_dir" && "$@" > "$log" 2>&1) && last_rc=0 || last_rc=$?
    fi
    t1=$(now)
    this=$(elapsed "$t0" "$t1")
    best=$(min "$best" "$this")
    if [[ $best == "$this" && -n ${ON_BEST:-} ]]; then $ON_BEST; fi
  done
}

fact() { sed -n "s/^ *\"$1\": \"\(.*\)\",\{0,1\}$/\1/p" "$2"; }

overall=0
for case_file in "${cases[@]}"; do
  [[ -f $case_file ]] || die "no case file $case_file"
  name=$(basename "$case_file" .toml)
  dir="$WORK/$name"
  rm -rf "$dir" && mkdir -p "$dir/ccx" "$dir/ccx1" "$dir/ccx0"

  # (a) bladebench, whole process.
  # The assembly / eigensolve split is that of the fastest run.
  keep_split() { split=$(fact "assembly \/ eigensolve \[s\]" "$dir/bb/summary.json"); }
  ON_BEST=keep_split measure "$PWD" "$dir/bb.log" env OMP_NUM_THREADS="$THREADS" "$BB" run "$case_file" --no-plots --out "$dir/bb"
  bb_wall=$best bb_rss=$rss
  ((last_rc <= 1)) || { cat "$dir/bb.log" >&2; die "bladebench run $case_file exited with $last_rc"; }
  bb_f=$(bb_frequencies "$dir/bb/frequencies.csv")
  n_bb=$(wc -l <<< "$bb_f")
  dofs=$(fact "free DOFs" "$dir/bb/summary.json")
  elements=$(fact "elements" "$dir/bb/summary.json")
  nodes=$(fact "nodes" "$dir/bb/summary.json")

  # (b) the same model as a CalculiX deck, solved by ccx in two thread settings, and read
  # without its *STEP to time ccx's input phase alone.
  modes=${MODES:-$n_bb}
  "$BB" export-calculix "$case_file" --out "$dir/ccx/$name.inp" --modes "$modes" 2> "$dir/export.log" \
    || { cat "$dir/export.log" >&2; die "export-calculix $case_file failed"; }
  cp "$dir/ccx/$name.inp" "$dir/ccx1/$name.inp"
  sed '/^\*STEP/,/^\*END STEP/d' "$dir/ccx/$name.inp" > "$dir/ccx0/$name.inp"
  measure "$dir/ccx" "$dir/ccx/ccx.log" env OMP_NUM_THREADS="$THREADS" "$CCX" -i "$name"
  ccx_wall=$best ccx_rss=$rss
  measure "$dir/ccx1" "$dir/ccx1/ccx.log" env OMP_NUM_THREADS="$THREADS" CCX_NPROC_EQUATION_SOLVER=1 "$CCX" -i "$name"
  ccx1_wall=$best ccx1_rss=$rss
  measure "$dir/ccx0" "$dir/ccx0/ccx.log" env OMP_NUM_THREADS="$THREADS" "$CCX" -i "$name"
  ccx0_wall=$best
  for variant in ccx ccx1 ccx0; do
    grep -q "Job finished" "$dir/$variant/ccx.log" || { tail -20 "$dir/$variant/ccx.log" >&2; die "ccx failed on $dir/$variant/$name.inp"; }
  done
  ccx_f=$(ccx_frequencies "$dir/ccx/$name.dat")
  ccx1_f=$(ccx_frequencies "$dir/ccx1/$name.dat")
  [[ -n $ccx_f ]] || die "no eigenvalue table in $dir/ccx/$name.dat"
  [[ $ccx_f == "$ccx1_f" ]] || echo "note: the two ccx thread settings printed different frequencies" >&2

  # (c) frequency by frequency. When ccx returned more modes (MODES), align on the best offset.
  echo
  echo "### $name"
  echo
  echo "\`$case_file\`: $elements, $nodes nodes, $dofs free DOFs; $modes modes asked of ccx."
  echo
  # The element types of the deck: hex8i (C3D8I) is not the same element in a frequency analysis.
  types=$(grep -o 'TYPE=C3D[0-9A-Z]*' "$dir/ccx/$name.inp" | sed 's/TYPE=//' | sort -u | tr '\n' ' ')
  same=1
  case " $types " in *" C3D8I "*) same=0 ;; esac
  if ((same)); then
    echo "Elements: $types- the same formulation in both programs; the frequencies must agree within $TOL."
  else
    echo "Elements: $types- hex8i and C3D8I share their stiffness but not their inertia (C3D8I gives the"
    echo "incompatible modes mass and keeps them in the eigenproblem): the differences below are that"
    echo "difference of formulation, not of the solvers, and do not count in the verdict."
  fi
  echo
  status=0
  awk -v tol="$TOL" -v nb="$n_bb" -v same="$same" -v bb="$(echo "$bb_f" | tr '\n' ' ')" -v cx="$(echo "$ccx_f" | tr '\n' ' ')" '
    function abs(x) { return x < 0 ? -x : x }
    BEGIN {
      split(bb, b, " "); nc = split(cx, c, " ")
      if (nc < nb) { printf "ccx returned %d modes, bladebench %d\n", nc, nb; exit 2 }
      top = 0
      for (i = 1; i <= nb; ++i) if (b[i] > top) top = b[i]
      rigid = 1e-4 * top   # the modal solver calls a mode rigid below 1e-8 of the largest eigenvalue
      best = -1
      for (o = 0; o + nb <= nc; ++o) {
        s = 0; for (i = 1; i <= nb; ++i) s += abs(c[i + o] - b[i]) / (b[i] > rigid ? b[i] : top)
        if (best < 0 || s < best) { best = s; off = o }
      }
      if (off > 0) printf "bladebench mode 1 aligned with ccx mode %d.\n\n", off + 1
      print "| mode | bladebench [Hz] | CalculiX [Hz] | rel. difference |"
      print "|---:|---:|---:|---:|"
      worst = 0; rigid_modes = 0; mismatch = 0
      for (i = 1; i <= nb; ++i) {
        if (b[i] <= rigid && c[i + off] <= rigid) {
          ++rigid_modes
          printf "| %d | 0 (rigid-body mode) | 0 (rigid-body mode) | - |\n", i
          continue
        }
        if (b[i] <= rigid || c[i + off] <= rigid) {
          ++mismatch
          printf "| %d | %.10g | %.7g | rigid in one program only |\n", i, b[i], c[i + off]
          continue
        }
        d = (b[i] - c[i + off]) / c[i + off]
        if (abs(d) > worst) worst = abs(d)
        printf "| %d | %.10g | %.7g | %+.2e |\n", i, b[i], c[i + off], d
      }
      if (rigid_modes > 0) printf "\n%d rigid-body mode(s) (0 Hz) in both programs.\n", rigid_modes
      ok = worst <= tol && mismatch == 0
      if (same) {
        printf "\nmax |rel. difference| = %.2e, tolerance %g: %s\n", worst, tol, ok ? "AGREE" : "DISAGREE"
        exit ok ? 0 : 1
      }
      printf "\nmax |rel. difference| = %.2e: DIFFERENT ELEMENT (hex8i vs C3D8I inertia), not a verdict%s\n", worst,
             mismatch ? "; but a rigid-body mode in one program only: DISAGREE" : ""
      exit mismatch ? 1 : 0
    }' || status=$?
  ((status == 2)) && die "mode counts do not match"
  ((status > overall)) && overall=$status

  echo
  echo "| program (best of $REPEAT) | wall [s] | peak RSS [MiB] | what the wall time includes |"
  echo "|---|---:|---:|---|"
  echo "| bladebench run --no-plots | $bb_wall | $bb_rss | parse, model, assembly / eigensolve $split s, checks, CSV + report |"
  echo "| ccx | $ccx_wall | $ccx_rss | deck input, assembly, SPOOLES on $THREADS threads + ARPACK, .dat + .frd |"
  echo "| ccx, CCX_NPROC_EQUATION_SOLVER=1 | $ccx1_wall | $ccx1_rss | the same, SPOOLES on 1 thread |"
  echo "| ccx, deck without *STEP | $ccx0_wall | | deck input and checks only |"
  echo
  awk -v b="$bb_wall" -v c="$ccx_wall" -v c1="$ccx1_wall" -v c0="$ccx0_wall" -v t="$THREADS" -v s="$split" 'BEGIN {
    printf "wall-time ratio bladebench / CalculiX, whole process: %.3f (ccx, SPOOLES on %s threads), %.3f (ccx, SPOOLES on 1 thread)\n", b / c, t, b / c1
    split(s, p, " / ")
    printf "beyond input, bladebench (assembly + eigensolve) / (ccx - ccx deck without *STEP): %.3f (%s threads), %.3f (1 thread)\n",
           (p[1] + p[2]) / (c - c0), t, (p[1] + p[2]) / (c1 - c0)
  }'
done
echo
echo "work folder: $WORK; ccx: $("$CCX" -v 2>&1 | sed -n 's/.*\(Version [0-9.]*\).*/\1/p' | head -1); load average:$(cut -d' ' -f1-3 /proc/loadavg | sed 's/^/ /')"
exit "$overall"
