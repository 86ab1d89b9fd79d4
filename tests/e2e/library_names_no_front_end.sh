#!/usr/bin/env bash
# vcg_ext words problems as kinds and remedies; only the front ends name menus, tools and
# options. Fails when a string literal in the library names one (comments may).
set -euo pipefail
library="$1"
found=$(grep -rnE '"[^"]*(Filters >|Edit Skeleton|Select Outliers|MeshLab|meshlab|this plugin|--[a-z])' \
          --include='*.h' --include='*.cpp' "$library" | grep -vE '^[^:]+:[0-9]+:[[:space:]]*//' || true)
if [ -n "$found" ]; then
  echo "vcg_ext names a front end in a message:" >&2
  echo "$found" >&2
  exit 1
fi
echo "vcg_ext's messages name no front end"
