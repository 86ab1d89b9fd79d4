#!/usr/bin/env bash
# The library's folders are layers: each includes only the folders below it. Fails on an
# include that goes up (or sideways into a folder not listed) and names it.
set -euo pipefail
library="$1/pcskeleton"
# Bottom to top; the files at the top level (curve_skeleton, parameter_settings) may use all.
layers=(core internal contraction skeleton finishing editing reconstruction io)
rank() { local i; for i in "${!layers[@]}"; do [ "${layers[$i]}" = "$1" ] && { echo "$i"; return; }; done; echo -1; }
status=0
for folder in "$library"/*/; do
  name=$(basename "$folder")
  own=$(rank "$name")
  [ "$own" -ge 0 ] || { echo "the folder $name/ is not in the list of layers" >&2; status=1; continue; }
  while IFS= read -r line; do
    file=${line%%:*}
    target=$(sed -E 's#.*"pcskeleton/([a-z_]+)/.*#\1#' <<<"$line")
    [ "$target" = "$name" ] && continue
    if [ "$(rank "$target")" -lt 0 ] || [ "$(rank "$target")" -gt "$own" ]; then
      echo "upward include: ${file#$library/} includes pcskeleton/$target/ (order: ${layers[*]})" >&2
      status=1
    fi
  done < <(grep -HE '#include "pcskeleton/[a-z_]+/' "$folder"*.h "$folder"*.cpp 2>/dev/null || true)
  # A top-level header is above every folder.
  if grep -qE '#include "pcskeleton/[a-z_]+\.h"' "$folder"*.h "$folder"*.cpp 2>/dev/null; then
    echo "$name/ includes a top-level header: $(grep -lE '#include "pcskeleton/[a-z_]+\.h"' "$folder"* | tr '\n' ' ')" >&2
    status=1
  fi
done
[ "$status" = 0 ] && echo "every include goes down: ${layers[*]}"
exit "$status"
