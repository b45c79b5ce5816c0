#!/usr/bin/env bash
# One frame over 1, 2 and 4 MPI ranks on this machine (bench/README.md, "Distributed
# rendering"): the Cornell box at 256² × 256 spp in chunks of 16, one thread per rank,
# on the CPU and on lavapipe. Prints a markdown table; needs build/vkpt built with MPI.
set -euo pipefail
cd "$(dirname "$0")/.."
vkpt=build/vkpt
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
args=(--scene scenes/cornell.gltf --width 256 --height 256 --spp 256 --chunk 16 --threads 1 --seed 3)
echo "| backend | ranks | render s | speed-up | chunks per rank | bytes sent per other rank | image |"
echo "|---|---|---|---|---|---|---|"
for backend in cpu vulkan; do
  base=""
  for ranks in 1 2 4; do
    out="$tmp/$backend-$ranks.pfm"
    if [ "$ranks" = 1 ]; then
      log=$("$vkpt" "${args[@]}" --backend "$backend" --out "$out")
    else
      log=$(mpirun --oversubscribe --bind-to none -n "$ranks" "$vkpt" "${args[@]}" --backend "$backend" --out "$out")
    fi
    seconds=$(sed -n 's/^  time \([0-9.]*\) s.*/\1/p' <<<"$log")
    [ -z "$base" ] && base=$seconds
    chunks=$(sed -n 's/^  rank [0-9]* ([^)]*): \([0-9]*\) chunk.*/\1/p' <<<"$log" | paste -sd/ -)
    sent=$(sed -n 's/^  rank [1-9][0-9]* ([^)]*): .* s, \(.*\) sent$/\1/p' <<<"$log" | head -1)
    same="reference"
    [ "$ranks" != 1 ] && { cmp -s "$out" "$tmp/$backend-1.pfm" && same="identical" || same="DIFFERS"; }
    note=""
    [ "$ranks" -gt "$(nproc)" ] && note=" (oversubscribed)"
    printf '| %s | %s%s | %s | %.2f× | %s | %s | %s |\n' "$backend" "$ranks" "$note" "$seconds" \
      "$(awk -v a="$base" -v b="$seconds" 'BEGIN { print a / b }')" "${chunks:-16}" "${sent:--}" "$same"
  done
done
