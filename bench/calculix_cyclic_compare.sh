#!/usr/bin/env bash
# CalculiX's cyclic symmetry on the sector of a cyclic_modal case: `bladebench export-calculix`
# writes the deck (the same nodes, elements, clamp; *TIE, CYCLIC SYMMETRY between the case's
# faces, *CYCLIC SYMMETRY MODEL, *SELECT CYCLIC SYMMETRY MODES over the case's nodal diameters),
# ccx solves it, and the frequencies per nodal diameter are written as a CSV with the columns of
# the case's nodal_diameter_map (ccx returns each family twice, cosine and sine: one is kept).
# This is how references/verification/calculix_bladed_disk_cyclic.csv was made.
#
# usage: bench/calculix_cyclic_compare.sh CASE.toml OUT.csv
# environment: BB (default build/solvers/bladebench), CCX (default ccx; Debian calculix-ccx),
#              WORK scratch folder (default: a new mktemp -d folder, kept)
set -euo pipefail

cd "$(dirname "$0")/.."
BB=${BB:-build/solvers/bladebench}
CCX=${CCX:-ccx}
WORK=${WORK:-$(mktemp -d /tmp/calculix_cyclic.XXXXXX)}
die() { echo "error: $*" >&2; exit 2; }
(($# == 2)) || die "usage: $0 CASE.toml OUT.csv"
[[ -x $BB ]] || die "no bladebench binary at $BB (cmake --preset release && cmake --build build -j2)"
command -v "$CCX" > /dev/null || die "no CalculiX binary '$CCX' (apt-get install calculix-ccx)"
case_file=$1 out=$2
"$BB" export-calculix "$case_file" --out "$WORK/sector.inp"
(cd "$WORK" && OMP_NUM_THREADS=2 "$CCX" -i sector > ccx.log 2>&1) || die "ccx failed: $WORK/ccx.log"
# Eigenvalue rows: ND, mode number, eigenvalue, rad/time, cycles/time, imaginary part.
awk 'BEGIN { OFS = "," }
     /^ +[0-9]+ +[0-9]+ +[0-9.]+E[+-][0-9]+ +[0-9.]+E[+-][0-9]+ +[0-9.]+E[+-][0-9]+ +[0-9.]+E[+-][0-9]+ *$/ {
       if ($2 % 2 == 1) { f[$1, ($2 + 1) / 2] = $5; if ($1 > nd) nd = $1; if (($2 + 1) / 2 > nf) nf = ($2 + 1) / 2; seen[$1] = 1 }
     }
     END {
       printf "nodal_diameter"; for (m = 1; m <= nf; ++m) printf ",f%d_hz", m; printf "\n"
       for (k = 0; k <= nd; ++k) if (k in seen) {
         printf "%d", k; for (m = 1; m <= nf; ++m) printf ",%.7g", f[k, m]; printf "\n"
       }
     }' "$WORK/sector.dat" > "$out"
echo "ccx cyclic symmetry of $case_file -> $out (work folder $WORK)" >&2
