#!/usr/bin/env bash
# One grid point of a contact_modal case through bladebench and through CalculiX on the identical
# mesh (bladebench export-calculix writes the contact pairs as ccx face-to-face penalty contact, one
# interaction per face size, a *CLEARANCE for the interference, a *STATIC step and a PERTURBATION
# *FREQUENCY step). Frequencies side by side and the wall time of each program, taken in this run.
# See bench/README.md, "Root contact against CalculiX".
#
# usage: bench/calculix_contact_compare.sh [CASE.toml]
#   CASE  a contact_modal case with the linear law (roughness_m = 0). Default: a one-point copy of
#         cases/thesis/sec32_root_contact_linear.toml at 1e-4 m, FKN = 1, without stress stiffening
#         (ccx's *STATIC without NLGEOM gives its perturbation step no stress stiffness).
# environment: BB (default build/solvers/bladebench), CCX (default ccx), THREADS (default 2),
#   TOL (relative agreement asked, default 1e-4), WORK (scratch folder, default mktemp -d).
# Exit code: 0 every frequency agrees within TOL, 1 some do not, 2 a run failed.
set -euo pipefail

cd "$(dirname "$0")/.."
BB=${BB:-build/solvers/bladebench}
CCX=${CCX:-ccx}
THREADS=${THREADS:-2}
TOL=${TOL:-1e-4}
WORK=${WORK:-$(mktemp -d /tmp/calculix_contact.XXXXXX)}
die() { echo "error: $*" >&2; exit 2; }
[[ -x $BB ]] || die "no bladebench binary at $BB"
command -v "$CCX" > /dev/null || die "no CalculiX binary '$CCX' (apt-get install calculix-ccx)"
mkdir -p "$WORK"
WORK=$(cd "$WORK" && pwd)

case_file=${1:-}
if [[ -z $case_file ]]; then
  case_file=$WORK/sec32_point.toml
  sed -e 's/^interference_m = .*/interference_m = [1e-4]/' -e 's/^penalty_factor = .*/penalty_factor = [1.0]/' \
      -e 's/^prestress = true/prestress = false/' -e 's/^glued_reference = true/glued_reference = false/' \
      -e '/^\[\[check\]\]/,$d' -e 's|"\.\./\.\./references/|"'"$PWD"'/references/|' \
      cases/thesis/sec32_root_contact_linear.toml > "$case_file"
fi
now() { date +%s.%N; }

"$BB" export-calculix "$case_file" --out "$WORK/point.inp" || die "export failed"
t0=$(now)
OMP_NUM_THREADS=$THREADS "$BB" run "$case_file" --no-plots --out "$WORK/bladebench" > "$WORK/bladebench.log" 2>&1 ||
  die "bladebench failed (see $WORK/bladebench.log)"
t1=$(now)
(cd "$WORK" && OMP_NUM_THREADS=$THREADS "$CCX" -i point > ccx.log 2>&1) || die "ccx failed (see $WORK/ccx.log)"
t2=$(now)

# The state point's frequencies: bladebench's frequencies_grid.csv rows of the exported point (one
# point in the default case), and ccx's eigenvalue table (CYCLES/TIME), sorted.
bb_f=$(awk -F, 'NR > 1 { print $5 }' "$WORK/bladebench/frequencies_grid.csv")
ccx_f=$(awk '/E I G E N V A L U E   O U T P U T/ { on = 1; next }
             on && /P A R T I C I P A T I O N/ { exit }
             on && $1 ~ /^[0-9]+$/ && NF >= 4 { printf "%.10g\n", $3 }' "$WORK/point.dat" | sort -g)
[[ -n $ccx_f ]] || die "no eigenvalue table in $WORK/point.dat"
awk -v tol="$TOL" -v bb="$(echo "$bb_f" | tr '\n' ' ')" -v cx="$(echo "$ccx_f" | tr '\n' ' ')" \
    -v tb="$(awk -v a="$t0" -v b="$t1" 'BEGIN { print b - a }')" -v tc="$(awk -v a="$t1" -v b="$t2" 'BEGIN { print b - a }')" '
  BEGIN {
    n = split(bb, b, " "); m = split(cx, c, " "); bad = 0
    printf "| mode | bladebench [Hz] | ccx [Hz] | relative difference |\n|---:|---:|---:|---:|\n"
    for (i = 1; i <= n && i <= m; ++i) {
      d = (b[i] - c[i]) / c[i]; if (d < 0 ? -d > tol : d > tol) bad = 1
      printf "| %d | %.4f | %.4f | %+.2e |\n", i, b[i], c[i], d
    }
    printf "\nwall time: bladebench %.2f s (static contact + modes, whole run), ccx %.2f s; ratio %.2f\n", tb, tc, tc / tb
    printf "verdict: %s within %g\n", bad ? "DISAGREE" : "agree", tol
    exit bad
  }'
