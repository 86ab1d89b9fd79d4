#!/usr/bin/env bash
# Does the surface have its skeleton's topology? On the robustness suite's perturbed scans
# (bench_robustness --write), each scan's own skeleton by the default pipeline, then the
# surface from it with the topology guarantee (the default) and with the paper's plain fit
# (--data-topology). A case matches when the surface is closed and has as many components
# as the skeleton and a genus equal to its independent cycles. Prints one row per case and
# the tally per condition.
# usage: bench/reconstruction_topology.sh [BUILD_DIR] [RESOLUTION]   (build, 128)
set -euo pipefail
BUILD="$(cd "${1:-$(dirname "$0")/../build}" && pwd)"; RESOLUTION="${2:-128}"
WORK="$(mktemp -d)"; trap 'rm -rf "$WORK"' EXIT
SHAPES=("straight tube" "Y branch" "tree" "ring" "genus 2 (figure eight)" "thin legs, thick body"
        "two close tubes" "genus 3 (three rings)" "elephant (libcgal-demo)" "knot1 (libcgal-demo)"
        "eight (libcgal-demo)" "hand (libcgal-demo)")
CONDITIONS=("noise 1%" "noise 2%" "misaligned 1%" "scan 1 view" "scan 4 views")

# "components genus closed" of a reconstruction report's result line; "parts cycles" of a skeleton's.
surface() { sed -n 's/^result: \([0-9]*\) components*, genus \([0-9]*\), \(closed\)*.*/\1 \2 \3/p' "$1"; }
skeleton() { sed -n 's/^Skeleton: .* \([0-9]*\) components*, \([0-9]*\) cycles*,.*/\1 \2/p' "$1"; }

echo "Surface topology = skeleton topology, resolution $RESOLUTION, $(nproc) cores"
printf '%-24s %-14s %9s %18s %18s %7s\n' shape condition skeleton guarantee "plain fit" seconds
declare -A kept plain total
for condition in "${CONDITIONS[@]}"; do
  for shape in "${SHAPES[@]}"; do
    "$BUILD/bench/bench_robustness" --write "$shape" "$condition" "$WORK/scan.ply" >/dev/null 2>&1 \
      || { echo "$shape / $condition: no such case (libcgal-demo installed?)"; continue; }
    start=$SECONDS
    "$BUILD/cli/pcskeleton" "$WORK/scan.ply" -o "$WORK/skeleton.ply" --surface "$WORK/kept.ply" \
      --resolution "$RESOLUTION" --force 2>"$WORK/kept.log" >/dev/null || { echo "$shape / $condition: failed"; continue; }
    "$BUILD/cli/pcskeleton" "$WORK/scan.ply" --skeleton "$WORK/skeleton.ply" --surface "$WORK/plain.ply" \
      --resolution "$RESOLUTION" --data-topology --force 2>"$WORK/plain.log" >/dev/null || true
    read -r parts cycles <<<"$(skeleton "$WORK/kept.log")"
    verdict() {  # log -> "ok|no components genus"
      local c g closed; read -r c g closed <<<"$(surface "$1")"
      if [ "${c:-x}" = "$parts" ] && [ "${g:-x}" = "$cycles" ] && [ "$closed" = closed ]; then echo "ok $c $g"; else echo "no ${c:--} ${g:--}"; fi
    }
    read -r k kc kg <<<"$(verdict "$WORK/kept.log")"; read -r p pc pg <<<"$(verdict "$WORK/plain.log")"
    total[$condition]=$(( ${total[$condition]:-0} + 1 ))
    [ "$k" = ok ] && kept[$condition]=$(( ${kept[$condition]:-0} + 1 ))
    [ "$p" = ok ] && plain[$condition]=$(( ${plain[$condition]:-0} + 1 ))
    printf '%-24s %-14s %4s/%-4s %8s %2s/%-5s %8s %2s/%-5s %7d\n' "$shape" "$condition" "$parts" "$cycles" \
      "$k" "$kc" "$kg" "$p" "$pc" "$pg" $((SECONDS - start))
  done
done
echo
printf '%-14s %10s %10s\n' condition guarantee "plain fit"
for condition in "${CONDITIONS[@]}"; do
  printf '%-14s %7d/%-2d %7d/%-2d\n' "$condition" "${kept[$condition]:-0}" "${total[$condition]:-0}" \
    "${plain[$condition]:-0}" "${total[$condition]:-0}"
done
