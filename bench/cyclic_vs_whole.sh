#!/usr/bin/env bash
# One sector against the whole disk, in one run per thread setting: the cyclic modal case without
# its Campbell diagram, with `whole = true` (the sector's nodal diameters, then the whole disk built
# from the sector), once with one nodal diameter at a time (threads = 1) and once with the default
# (one per core). Prints both eigensolve times, their ratio and the largest frequency difference.
#
# usage: bench/cyclic_vs_whole.sh [CASE.toml]   (default cases/beyond/bladed_disk_cyclic_modal.toml)
# environment: BB (default build/solvers/bladebench), WORK scratch folder (default: mktemp -d, kept)
set -euo pipefail

cd "$(dirname "$0")/.."
BB=${BB:-build/solvers/bladebench}
WORK=${WORK:-$(mktemp -d /tmp/cyclic_vs_whole.XXXXXX)}
die() { echo "error: $*" >&2; exit 2; }
[[ -x $BB ]] || die "no bladebench binary at $BB (cmake --preset release && cmake --build build -j2)"
case_file=$(realpath "${1:-cases/beyond/bladed_disk_cyclic_modal.toml}")
[[ -f $case_file ]] || die "no case file $case_file"
for threads in 1 default; do
  copy="$WORK/whole_threads_$threads.toml"
  # References stay where the case points; the Campbell diagram and engine orders are left out.
  sed -e "s#\"\\.\\./\\.\\./references/#\"$(dirname "$(dirname "$(dirname "$case_file")")")/references/#" \
      -e '/^engine_orders/d' -e '/^max_speed_rpm/d' -e '/^speeds_rpm/d' -e '/^whole *=/d' -e '/^threads *=/d' \
      -e 's/^key_plots = .*/key_plots = ["nodal_diameter_map"]/' "$case_file" > "$copy"
  sed -i "s/^\\[analysis\\]\$/[analysis]\\nwhole = true/" "$copy"
  [[ $threads == default ]] || sed -i "s/^\\[analysis\\]\$/[analysis]\\nthreads = $threads/" "$copy"
  "$BB" run "$copy" --out "$WORK/out_$threads" --no-plots > "$WORK/log_$threads.txt" 2>&1 ||
    die "the run failed: $WORK/log_$threads.txt"
  python3 - "$WORK/out_$threads/summary.json" "$threads" << 'PY'
import json, re, sys
facts = json.load(open(sys.argv[1]))["facts"]
sector = float(facts["assembly / eigensolves [s]"].split("/")[1])
whole = facts["whole structure (N turned copies merged)"]
whole_s = float(re.search(r"DOFs, ([0-9.]+) s", whole).group(1))
diff = re.search(r"frequencies ([0-9.e+-]+)", whole).group(1)
print(f"threads {sys.argv[2]}: sector {sector:.2f} s, whole disk {whole_s:.1f} s, "
      f"ratio {whole_s / sector:.1f}x, largest relative frequency difference {diff}")
PY
done
echo "work folder $WORK" >&2
