#!/usr/bin/env bash
# meshlabserver (the build tree's MeshLab prefix) runs the shipped .mlx on a real scan
# from Debian's libcgal-demo and on the paper's own input when ../shared is present.
# usage: meshlabserver_test.sh MESHLABSERVER MLX WORKDIR
set -euo pipefail
MESHLABSERVER="$1"; MLX="$2"; WORK="$3"
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
PAPER_INPUTS="$HERE/../../../shared/data/paper-inputs"
mkdir -p "$WORK"; cd "$WORK"

run() {  # input, name
  local input="$1" name="$2"
  xvfb-run -a "$MESHLABSERVER" -i "$input" -o "$name.in.ply" -l 0 -m sa -o "$name.out.ply" -l x -m sa \
    -s "$MLX" >"$name.log" 2>&1 || { cat "$name.log"; echo "FAIL: meshlabserver failed on $input"; exit 1; }
  grep -q "Contraction: .* iteration(s)" "$name.log" || { cat "$name.log"; echo "FAIL: no contraction log"; exit 1; }
  /usr/bin/python3 "$HERE/check_contracted.py" "$name.in.ply" "$name.out.ply"
}

tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz data/points_3/kitten.xyz
run data/points_3/kitten.xyz kitten

if [ -f "$PAPER_INPUTS/simplejoint_v4770.off" ]; then
  run "$PAPER_INPUTS/simplejoint_v4770.off" simplejoint
else
  echo "SKIP paper input: $PAPER_INPUTS not present (it is only beside the developers' checkout)"
fi
echo "meshlabserver end-to-end: OK"
